"""Feature driver shared by the algorithms: progress, cancel, warnings, outputs and counts, and the one place
the algorithms call the core's computations.

The centerline algorithms describe each feature as a :class:`FeatureTask` (the core function's inputs, in the
feature's working frame) and compute them in batches (:meth:`FeatureRun.run_batches`: one call of the core's
public function on the arrays of a batch's inputs, traced together, the same call a Python user makes); the
network algorithm too (each network traces its own runs).
"""

from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from qgis.core import QgsFeatureRequest, QgsWkbTypes
from qgis.PyQt.QtCore import QCoreApplication

from .compat import ProcessingFeatureSourceFlag
from .dependencies import require_core
from .messages import core_text

#: The core's public functions a :class:`FeatureTask` may name (its ``kind``); each takes arrays of inputs.
ARRAY_FUNCTIONS = {
    "polygon": "multipolygon_centerlines",
    "label": "label_lines",
    "lines": "lines_centerline",
    "network": "multipolygon_networks",
}


@dataclass
class FeatureTask:
    """One input feature's work in :meth:`FeatureRun.run_batches`.

    Attributes
    ----------
    feature : QgsFeature
        The feature written with the result (its attributes and id).
    frame : WorkingFrame or None
        The feature's working frame: its inputs and results are in it.
    inputs : tuple
        The core function's positional arguments (geometries in ``frame``).
    keywords : dict
        The core function's keywords (its options for this feature).
    parts : callable or None
        ``parts(result)`` -> list of ``(part_index, CenterlineResult)`` to write, from what the core
        returned; it may warn about the feature (through the run, in input order).
    vertices : int
        The feature's boundary vertices, for the batch bounds.
    skip_reason : str or None
        Why the feature is skipped without computing.
    """

    feature: Any
    frame: Any = None
    inputs: tuple = ()
    keywords: dict = field(default_factory=dict)
    parts: Optional[Callable[[Any], list]] = None
    vertices: int = 0
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
    context : QgsProcessingContext
    feedback : QgsProcessingFeedback
    """

    def __init__(self, algorithm, context, feedback):
        self.core = require_core()
        self.algorithm = algorithm
        self.context = context
        self.feedback = feedback
        #: The layer's working frame (a feature's is ``frame.around(geometry)``), once the outputs are open.
        self.frame = None
        self.writer = None
        self.skipped = 0
        self.z_warned = False
        self.progress_base = 0.0
        self.progress_step = 100.0

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

    def use_writer(self, writer, crs):
        """Write results through ``writer`` and compute in the working frame of ``crs``.

        ``writer`` has ``write(feature, parts, frame)``, ``destinations()``, ``close()`` and
        ``centerline_count``, like :class:`.outputs.CenterlineWriter`.
        """
        from .convert import WorkingFrame  # needs Shapely, checked by require_core

        self.writer = writer
        self.frame = WorkingFrame.of_layer(crs)

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

    def layer_gates(self, source):
        """Return the :class:`.touching.LayerGates` of a polygon source (``CONNECT_TOUCHING``), read once."""
        from .touching import LayerGates  # needs Shapely, checked by require_core

        ids, shapes = LayerGates.read(self, source)
        failed = []
        with_gates, gates = self.core.touching_gates(shapes, errors=failed)
        for index, error in failed:
            # The feature is still computed, without the gates GEOS could not find.
            self.warn_feature(ids[index], error)
        return LayerGates(ids, with_gates, gates)

    def successful_parts(self, feature_id, outcomes):
        """Return ``(outcome, part_index)`` for every successful part of a feature (``outcomes``: the core's
        ``PartOutcome`` list), ``part_index`` None for a single part (how messages name it); skip the others
        with their error and warn about the core's notes."""
        several = len(outcomes) > 1
        successful = []
        for outcome in outcomes:
            part_index = outcome.part_index if several else None
            if outcome.error is not None:
                self.skip(feature_id, outcome.error, part_index)
                continue
            for note in getattr(outcome.result, "notes", ()):
                self.warn_feature(feature_id, note, part_index)
            successful.append((outcome, part_index))
        return successful

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

    def located(self, feature, options, split_points):
        """A polygon feature's geometry, its working frame, its snap tolerance (``options.snap_tolerance``) and
        the split points near it in that frame with their ids (``split_points``: a ``SplitPoints``)."""
        geometry = feature.geometry()
        frame = self.frame.around(geometry)
        snap_tolerance = options.snap_tolerance(feature)
        candidates, ids = split_points.near(geometry, snap_tolerance, frame)
        return geometry, frame, snap_tolerance, candidates, ids

    @staticmethod
    def skip_task(feature, reason):
        """A :class:`FeatureTask` skipping ``feature`` for ``reason`` (warned in input order)."""
        return FeatureTask(feature, skip_reason=reason)

    def run_batches(self, kind, tasks, total):
        """Compute ``tasks`` in batches traced together; write each feature's outcome in input order.

        A feature whose computation fails is skipped with a warning (see :meth:`skip_failed`); the others go
        on. Progress runs over the whole layer; a cancel stops between batches and inside one (the batch being
        computed is then not written).

        Parameters
        ----------
        kind : str
            The core function every task's inputs are for: a key of :data:`ARRAY_FUNCTIONS`.
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
            outcomes = self._computed(getattr(self.core, ARRAY_FUNCTIONS[kind]), batch, done)
            if outcomes is None:
                return
            for task, outcome in zip(batch, outcomes):
                self._finish(task, outcome)
            done += len(batch)

    def _computed(self, function, batch, done):
        """The outcome of every task of ``batch`` (None for a skipped one) by one call of the core's array
        ``function`` on the computed tasks' inputs and keywords (every task of a run has the same keywords);
        None when the user cancelled."""
        self.progress_base = done * self.progress_step
        span = len(batch) * self.progress_step
        tasks = [task for task in batch if task.skip_reason is None]
        if not tasks:
            return [None] * len(batch)
        inputs = [list(column) for column in zip(*(task.inputs for task in tasks))]
        keywords = {name: [task.keywords[name] for task in tasks] for name in tasks[0].keywords}
        try:
            computed = iter(
                function(*inputs, **keywords, progress=lambda fraction: self._batch_progress(fraction, span))
            )
        except self.core.Cancelled:
            return None
        return [None if task.skip_reason is not None else next(computed) for task in batch]

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
            self.write(task.feature, task.parts(outcome), task.frame)

    def write(self, feature, parts, frame):
        """Write the results of one input feature, expressed in its working frame ``frame``."""
        self.writer.write(feature, parts, frame)

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
