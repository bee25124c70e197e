"""Feature driver shared by the algorithms: inputs, progress, cancel, warnings, outputs and counts.

The centerline algorithms compute their features in batches traced together (:meth:`FeatureRun.run_batches`,
the core's ``centerlines_together``); the network algorithm computes one feature at a time
(:meth:`FeatureRun.features` and :meth:`FeatureRun.compute`).
"""

from dataclasses import dataclass
from typing import Any, Callable, Optional

from qgis.core import QgsFeatureRequest, QgsProcessingException, QgsWkbTypes
from qgis.PyQt.QtCore import QCoreApplication

from .compat import GeometryType, ProcessingFeatureSourceFlag
from .dependencies import require_core
from .messages import core_text

GEOMETRY_TYPE_NAMES = {
    GeometryType.Point: "point",
    GeometryType.Line: "line",
    GeometryType.Polygon: "polygon",
}


@dataclass
class FeatureTask:
    """One input feature's work in :meth:`FeatureRun.run_batches`.

    Attributes
    ----------
    feature : QgsFeature
        The feature written with the result (its attributes and id).
    steps : generator or None
        The core's step generator (``*_centerline_steps``); None when the feature is skipped.
    parts : callable or None
        ``parts(result)`` -> list of ``(part_index, CenterlineResult)`` to write, from what the generator
        returned; it may warn about the feature (through the run, in input order).
    vertices : int
        The feature's boundary vertices, for the batch bounds.
    projection : LocalProjection or None
        The working frame's projection the feature is computed in (None for a projected layer).
    skip_reason : str or None
        Why the feature is skipped without computing.
    """

    feature: Any
    steps: Any = None
    parts: Optional[Callable[[Any], list]] = None
    vertices: int = 0
    projection: Any = None
    skip_reason: Optional[str] = None


def part_number(part_index):
    """Return how messages and the ``part`` fields number the part the core indexes ``part_index`` (from 0): from
    1, as QGIS counts parts elsewhere ("part 1" is the first)."""
    return part_index + 1


def no_geometry():
    """Why a feature without geometry is skipped (translated)."""
    return QCoreApplication.translate("IncirCuAlgorithm", "the feature has no geometry")


class FeatureRun:
    """State of one run of an IncirCu algorithm.

    Construction imports the geometry core (raising an actionable ``QgsProcessingException`` when Shapely 2
    is missing). Per-feature problems become warnings naming the feature id (and part) and are counted in
    ``SKIPPED_COUNT``; layer-level problems raise ``QgsProcessingException``.

    Parameters
    ----------
    algorithm : IncirCuAlgorithm
    parameters : dict
    context : QgsProcessingContext
    feedback : QgsProcessingFeedback
    """

    def __init__(self, algorithm, parameters, context, feedback):
        self.core = require_core()
        self.algorithm = algorithm
        self.parameters = parameters
        self.context = context
        self.feedback = feedback
        self.frame = None
        self.writer = None
        self.skipped = 0
        self.z_warned = False
        #: ``value(feature)`` of ``TRANSECT_INTERVAL`` once the centerline outputs are open (None before).
        self.transect_interval_of = None
        self.progress_base = 0.0
        self.progress_step = 100.0

    def source(self, name, geometry_type):
        """Return the feature source of parameter ``name`` after checking its geometry type.

        Raises
        ------
        QgsProcessingException
            When the layer cannot be opened or holds another geometry type.
        """
        source = self.algorithm.parameterAsSource(self.parameters, name, self.context)
        if source is None:
            raise QgsProcessingException(self.algorithm.invalidSourceError(self.parameters, name))
        actual = QgsWkbTypes.geometryType(source.wkbType())
        if actual != geometry_type:
            raise QgsProcessingException(
                QCoreApplication.translate(
                    "IncirCuAlgorithm", "{} must be a {} layer, but '{}' holds {} geometries."
                ).format(
                    self.algorithm.parameter_label(name),
                    GEOMETRY_TYPE_NAMES[geometry_type],
                    source.sourceName(),
                    GEOMETRY_TYPE_NAMES.get(actual, "no"),
                )
            )
        return source

    def warn_dropped_z(self, source):
        """Warn, once per run, when ``source`` has Z values: the core computes in the plane and drops them."""
        if self.z_warned or not QgsWkbTypes.hasZ(source.wkbType()):
            return
        self.z_warned = True
        # fmt: off
        # (No comma after the text: pylupdate5 would not read the call.)
        message = QCoreApplication.translate(
            "IncirCuAlgorithm",
            "Z values are ignored: '{}' has Z, but the centerline is computed in the plane and written without Z "
            "(its M values, when stored, are the local width)."
        )
        # fmt: on
        self.warn(message.format(source.sourceName()))

    def open_outputs(self, fields, crs, multi):
        """Create the output sinks and the working frame of the layer's CRS."""
        # Imported only now: it needs Shapely, whose presence require_core has checked.
        from .outputs import CenterlineWriter

        algorithm, parameters, context = self.algorithm, self.parameters, self.context
        self.transect_interval_of = algorithm.length_of_feature(parameters, algorithm.TRANSECT_INTERVAL, context)
        interval = algorithm.parameterAsDouble(parameters, algorithm.TRANSECT_INTERVAL, context)
        add_m = algorithm.parameterAsBoolean(parameters, algorithm.ADD_M, context)
        self.use_writer(CenterlineWriter(algorithm, parameters, context, fields, crs, multi, add_m, interval), crs)

    def use_writer(self, writer, crs):
        """Write results through ``writer`` and compute in the working frame of ``crs``.

        ``writer`` has ``sink`` (None when it could not be created), ``write(attributes, source_fid, parts,
        frame)``, ``destinations()`` and ``centerline_count``, like :class:`CenterlineWriter`.
        """
        from .convert import WorkingFrame  # needs Shapely, checked by require_core

        if writer.sink is None:
            raise QgsProcessingException(self.algorithm.invalidSinkError(self.parameters, self.algorithm.OUTPUT))
        self.writer = writer
        self.frame = WorkingFrame(crs)

    def features(self, source, request=None):
        """Yield the features of ``source`` with progress, stopping when the user cancels.

        Features without geometry are skipped with a warning. Processing's invalid-geometry filter is
        bypassed: the core checks validity itself and the warning then says what is wrong and where.
        """
        total = source.featureCount()
        self.progress_step = 100.0 / total if total > 0 else 0.0
        for current, feature in enumerate(self.source_features(source, request)):
            self.progress_base = current * self.progress_step
            self.feedback.setProgress(self.progress_base)
            if not self.has_geometry(feature):
                self.skip(feature.id(), no_geometry())
                continue
            yield feature

    def source_features(self, source, request=None):
        """Yield every feature of ``source`` (also those without geometry), stopping when the user cancels.

        Processing's invalid-geometry filter is bypassed (see :meth:`features`).
        """
        features = source.getFeatures(
            request or QgsFeatureRequest(), ProcessingFeatureSourceFlag.SkipGeometryValidityChecks
        )
        for feature in features:
            if self.feedback.isCanceled():
                break
            yield feature

    @staticmethod
    def has_geometry(feature):
        """True when ``feature`` has a non-empty geometry."""
        return feature.hasGeometry() and not feature.geometry().isEmpty()

    def report_progress(self, fraction):
        """Progress callback for the core: ``fraction`` of the current feature done; False cancels."""
        self.feedback.setProgress(self.progress_base + fraction * self.progress_step)
        return not self.feedback.isCanceled()

    def skip(self, feature_id, reason, part_index=None):
        """Warn that a feature (or one of its parts) is skipped, and count it; ``reason`` may be the core's
        (its error or message, worded in the user's language)."""
        self.skipped += 1
        self.warn(
            QCoreApplication.translate("IncirCuAlgorithm", "Feature {} skipped: {}").format(
                self.where(feature_id, part_index), self.named_lengths(reason)
            )
        )

    def warn_feature(self, feature_id, message, part_index=None):
        """Warn about a feature (or one of its parts) that is still written; ``message`` may be the core's."""
        self.warn(
            QCoreApplication.translate("IncirCuAlgorithm", "Feature {}: {}").format(
                self.where(feature_id, part_index), self.named_lengths(message)
            )
        )

    def named_lengths(self, message):
        """Return ``message`` (the core's ``Message`` or error, or text) in the user's language (see
        :func:`.messages.core_text`), its lengths named in the working frame's unit (once there is one)."""
        text = core_text(message, None if self.frame is None else self.frame.unit)
        return text if self.frame is None else self.frame.named_lengths(text)

    def warn(self, message):
        """Show a warning in the log."""
        self.feedback.pushWarning(message)

    @staticmethod
    def where(feature_id, part_index):
        """Return ``"7"``, or ``"7 (part 1)"`` for the first part (``part_index`` 0), for messages."""
        if part_index is None:
            return str(feature_id)
        return QCoreApplication.translate("IncirCuAlgorithm", "{} (part {})").format(
            feature_id, part_number(part_index)
        )

    def compute(self, feature_id, part_index, function, *args, **kwargs):
        """Call a core function for one feature (part); a core error becomes a skip warning.

        Returns
        -------
        object or None
            What ``function`` returns; ``None`` when the feature (part) was skipped or the user cancelled.
        """
        try:
            return function(*args, progress=self.report_progress, **kwargs)
        except self.core.Cancelled:
            return None
        except Exception as error:  # noqa: BLE001 - one bad feature must not abort a run of thousands
            self.skip_failed(feature_id, error, part_index)
        return None

    def skip_failed(self, feature_id, error, part_index=None):
        """Skip a feature (part) whose computation raised ``error``: a core error says why; another exception
        is unexpected and asks for a report."""
        if isinstance(error, self.core.IncirCuError):
            self.skip(feature_id, error, part_index)
            return
        self.skip(
            feature_id,
            QCoreApplication.translate(
                "IncirCuAlgorithm", "unexpected {}: {} (please report this with the feature)"
            ).format(type(error).__name__, error),
            part_index,
        )

    def task(self, feature, steps, parts, vertices):
        """A :class:`FeatureTask` computed in the working frame as it is now (centred on the feature).

        Parameters
        ----------
        feature : QgsFeature
            Written with the result.
        steps : generator
            The core's step generator; give it ``progress=run.keep_going`` so a cancel stops it.
        parts : callable
            See :class:`FeatureTask`.
        vertices : int
            The feature's boundary vertices.
        """
        return FeatureTask(feature, steps, parts, vertices, self.frame.projection)

    @staticmethod
    def skip_task(feature, reason):
        """A :class:`FeatureTask` skipping ``feature`` for ``reason`` (warned in input order)."""
        return FeatureTask(feature, skip_reason=reason)

    def keep_going(self, fraction):
        """Progress callback of one feature's steps in a batch: only says whether to go on (False cancels)."""
        return not self.feedback.isCanceled()

    def run_batches(self, tasks, total):
        """Compute ``tasks`` in batches traced together; write each feature's outcome in input order.

        A feature whose computation fails is skipped with a warning (see :meth:`skip_failed`); the others go
        on. Progress runs over the whole layer; a cancel stops between batches and inside one (the batch being
        computed is then not written).

        Parameters
        ----------
        tasks : iterable of FeatureTask
            In input order, read lazily (one batch at a time, see the core's ``batches``).
        total : int
            Number of tasks, for the progress.
        """
        from ..incircu_plugin.core._many import batches  # needs Shapely, checked by require_core

        self.progress_step = 100.0 / total if total > 0 else 0.0
        done = 0
        for batch in batches(tasks, lambda task: task.vertices):
            if self.feedback.isCanceled():
                return
            outcomes = self._computed(batch, done)
            if outcomes is None:
                return
            for task, outcome in zip(batch, outcomes):
                self._finish(task, outcome)
            done += len(batch)

    def _computed(self, batch, done):
        """The outcome of every task of ``batch`` (None for a skipped one); None when the user cancelled."""
        self.progress_base = done * self.progress_step
        span = len(batch) * self.progress_step
        try:
            computed = iter(
                self.core._many.run_many_steps(
                    [task.steps for task in batch if task.steps is not None],
                    lambda fraction: self._batch_progress(fraction, span),
                )
            )
        except self.core.Cancelled:
            return None
        return [None if task.steps is None else next(computed) for task in batch]

    def _batch_progress(self, fraction, span):
        """Progress callback of a batch starting at ``progress_base`` and ``span`` percent long."""
        self.feedback.setProgress(min(self.progress_base + fraction * span, 100.0))
        return not self.feedback.isCanceled()

    def _finish(self, task, outcome):
        """Skip or write one task's feature, given what its steps returned or raised."""
        feature_id = task.feature.id()
        if task.skip_reason is not None:
            self.skip(feature_id, task.skip_reason)
        elif isinstance(outcome, Exception):
            self.skip_failed(feature_id, outcome)
        else:
            # The results are in the frame the feature was computed in; the frame has moved on since.
            self.frame.projection = task.projection
            self.write(task.feature, task.parts(outcome))

    def write(self, feature, parts):
        """Write the results of one input feature (its transects at its own interval where it is data-defined)."""
        if self.transect_interval_of is not None:
            self.writer.transect_interval = self.transect_interval_of(feature)
        self.writer.write(feature.attributes(), feature.id(), parts, self.frame)

    def close(self):
        """Close every output now, whatever happened in the run (see ``CenterlineWriter.close``)."""
        if self.writer is not None:
            self.writer.close()

    def finish(self):
        """Return the algorithm's result map and report the totals."""
        self.feedback.setProgress(100.0)
        # Named as the count outputs are (centerlines, or a network's branches): no plural to get wrong.
        counts = (
            (self.algorithm.CENTERLINE_COUNT, self.writer.centerline_count),
            (self.algorithm.SKIPPED_COUNT, self.skipped),
        )
        self.feedback.pushInfo(
            "; ".join(f"{self.algorithm.outputDefinition(name).description()}: {count}" for name, count in counts)
        )
        results = {name: value for name, value in self.writer.destinations().items() if value}
        results[self.algorithm.CENTERLINE_COUNT] = self.writer.centerline_count
        results[self.algorithm.SKIPPED_COUNT] = self.skipped
        return results
