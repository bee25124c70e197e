"""Per-feature driver shared by the algorithms: inputs, progress, cancel, warnings, outputs and counts."""

from qgis.core import QgsFeatureRequest, QgsProcessingException, QgsWkbTypes
from qgis.PyQt.QtCore import QCoreApplication

from .compat import GeometryType, ProcessingFeatureSourceFlag
from .dependencies import require_core

GEOMETRY_TYPE_NAMES = {
    GeometryType.Point: "point",
    GeometryType.Line: "line",
    GeometryType.Polygon: "polygon",
}


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
                    name,
                    GEOMETRY_TYPE_NAMES[geometry_type],
                    source.sourceName(),
                    GEOMETRY_TYPE_NAMES.get(actual, "no"),
                )
            )
        return source

    def open_outputs(self, fields, crs, multi):
        """Create the output sinks and the working frame of the layer's CRS."""
        # Imported only now: it needs Shapely, whose presence require_core has checked.
        from .outputs import CenterlineWriter

        algorithm, parameters, context = self.algorithm, self.parameters, self.context
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
        features = source.getFeatures(
            request or QgsFeatureRequest(), ProcessingFeatureSourceFlag.SkipGeometryValidityChecks
        )
        for current, feature in enumerate(features):
            if self.feedback.isCanceled():
                break
            self.progress_base = current * self.progress_step
            self.feedback.setProgress(self.progress_base)
            if not feature.hasGeometry() or feature.geometry().isEmpty():
                self.skip(feature.id(), QCoreApplication.translate("IncirCuAlgorithm", "the feature has no geometry"))
                continue
            yield feature

    def report_progress(self, fraction):
        """Progress callback for the core: ``fraction`` of the current feature done; False cancels."""
        self.feedback.setProgress(self.progress_base + fraction * self.progress_step)
        return not self.feedback.isCanceled()

    def skip(self, feature_id, reason, part_index=None):
        """Warn that a feature (or one of its parts) is skipped, and count it."""
        self.skipped += 1
        self.warn(
            QCoreApplication.translate("IncirCuAlgorithm", "Feature {} skipped: {}").format(
                self.where(feature_id, part_index), reason
            )
        )

    def note(self, feature_id, message, part_index=None):
        """Tell the user something about a feature that is still processed."""
        self.feedback.pushInfo(
            QCoreApplication.translate("IncirCuAlgorithm", "Feature {}: {}").format(
                self.where(feature_id, part_index), message
            )
        )

    def warn(self, message):
        """Show a warning in the log."""
        self.feedback.pushWarning(message)

    @staticmethod
    def where(feature_id, part_index):
        """Return ``"7"`` or ``"7 (part 1)"`` for messages."""
        if part_index is None:
            return str(feature_id)
        return QCoreApplication.translate("IncirCuAlgorithm", "{} (part {})").format(feature_id, part_index)

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
        except self.core.IncirCuError as error:
            self.skip(feature_id, str(error), part_index)
        except Exception as error:  # noqa: BLE001 - one bad feature must not abort a run of thousands
            self.skip(
                feature_id,
                QCoreApplication.translate(
                    "IncirCuAlgorithm", "unexpected {}: {} (please report this with the feature)"
                ).format(type(error).__name__, error),
                part_index,
            )
        return None

    def write(self, feature, parts):
        """Write the results of one input feature."""
        self.writer.write(feature.attributes(), feature.id(), parts, self.frame)

    def close(self):
        """Close every output now, whatever happened in the run (see ``CenterlineWriter.close``)."""
        if self.writer is not None:
            self.writer.close()

    def finish(self):
        """Return the algorithm's result map and report the totals."""
        self.feedback.setProgress(100.0)
        self.feedback.pushInfo(
            QCoreApplication.translate(
                "IncirCuAlgorithm", "{} centerlines written, {} features or parts skipped."
            ).format(self.writer.centerline_count, self.skipped)
        )
        results = {name: value for name, value in self.writer.destinations().items() if value}
        results[self.algorithm.CENTERLINE_COUNT] = self.writer.centerline_count
        results[self.algorithm.SKIPPED_COUNT] = self.skipped
        return results
