"""Output layers of ``incircu:labellines``: the label lines and the label points, with the same fields."""

from qgis.core import QgsFeature, QgsFeatureSink, QgsProcessingException, QgsProcessingUtils
from qgis.PyQt.QtCore import QCoreApplication

from .compat import WkbType
from .convert import from_shapely
from .outputs import DOUBLE, FEATURE_ID, INTEGER, STRING, make_fields, primary_key_sink, release_sinks
from .styles import CENTERLINE, LABEL_POINTS, style_outputs_on_load

#: Fields added to the input attributes on both outputs (lengths in layer units, metres when geographic):
#: ``source_fid`` (the input feature's id), ``part`` (the polygon part, from 0), ``length`` (of the label line;
#: 0 for a point), ``width_min`` (narrowest width along the label stretch: the tallest lettering that fits; for
#: a point, the widest incircle's diameter), ``elongation`` (main-stem length over mean width) and ``kind``
#: (``line`` or ``point``).
LABEL_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("part", INTEGER),
    ("length", DOUBLE),
    ("width_min", DOUBLE),
    ("elongation", DOUBLE),
    ("kind", STRING),
)


class LabelWriter:
    """Creates the two outputs of the label algorithm and writes each part's label line or point.

    Parameters
    ----------
    algorithm : IncirCuAlgorithm
        With ``OUTPUT`` (lines) and ``OUTPUT_POINTS``.
    parameters, context : dict, QgsProcessingContext
        For the sinks.
    options : PolygonOptions
        The run's options (``source``: the polygon layer, ``outputs``: the loaded layers' names).
    """

    def __init__(self, algorithm, parameters, context, options):
        input_fields, crs = options.source.fields(), options.source.sourceCrs()
        self.algorithm = algorithm
        self.crs = crs
        self.fields = QgsProcessingUtils.combineFields(input_fields, make_fields(LABEL_FIELDS))
        self.sink, self.sink_id = primary_key_sink(algorithm, parameters, context, self.fields, WkbType.LineString, crs)
        self.points, self.points_id = algorithm.parameterAsSink(
            parameters, algorithm.OUTPUT_POINTS, context, self.fields, WkbType.Point, crs
        )
        self.centerline_count = 0
        destinations = {CENTERLINE: self.sink_id, LABEL_POINTS: self.points_id}
        style_outputs_on_load(context, destinations, options.outputs.layer_names, options.outputs.group)

    def close(self):
        """Flush and release both sinks, which closes (commits) their files; safe to call twice."""
        release_sinks(self, ("sink", "points"))

    def destinations(self):
        """Return the output ids keyed by parameter name."""
        return {self.algorithm.OUTPUT: self.sink_id, self.algorithm.OUTPUT_POINTS: self.points_id}

    def write(self, feature, parts, frame):
        """Write the label of every successful part of one input feature.

        Parameters
        ----------
        feature : QgsFeature
            The input feature (its attributes are copied, its id is ``source_fid``).
        parts : sequence of (int, LabelResult)
        frame : WorkingFrame
            Frame the labels are expressed in.
        """
        attributes, source_fid = feature.attributes(), feature.id()
        for part_index, label in parts:
            sink = self.sink if label.kind == "line" else self.points
            if sink is None:
                continue
            written = QgsFeature(self.fields)
            written.setGeometry(from_shapely(frame.to_layer(label.geometry)))
            added = [source_fid, part_index, label.length, label.width_min, label.elongation, label.kind]
            written.setAttributes([*attributes, *added])
            if not sink.addFeature(written, QgsFeatureSink.Flag.FastInsert):
                raise QgsProcessingException(
                    QCoreApplication.translate("IncirCuAlgorithm", "Could not write a label: {}").format(
                        sink.lastError()
                    )
                )
            self.centerline_count += 1
