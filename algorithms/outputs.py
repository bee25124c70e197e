"""Output layers of the IncirCu algorithms: fields, statistics and the writing of core results."""

import numpy as np
import shapely
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsField,
    QgsFields,
    QgsGeometry,
    QgsPointXY,
    QgsProcessingException,
    QgsProcessingUtils,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QCoreApplication

from ..incircu_plugin.core.widths import (
    incircle_polygons,
    transects,
    vertex_chainages,
    width_statistics,
)
from .compat import FieldType, WkbType
from .convert import collect_lines, from_shapely, line_with_m
from .running import part_number
from .styles import CENTERLINE, INCIRCLES, TRANSECTS, VERTICES, readable_scale, style_outputs_on_load
from .units import length_decimals, metres_per_unit, rounded

DOUBLE, INTEGER, BOOLEAN, STRING = FieldType.Double, FieldType.Int, FieldType.Bool, FieldType.QString
#: A feature id: 64 bits, as QGIS's (a GeoPackage's fid may pass 2**31).
FEATURE_ID = FieldType.LongLong


def make_fields(definitions):
    """Build a ``QgsFields`` from ``(name, type)`` pairs."""
    fields = QgsFields()
    for name, field_type in definitions:
        fields.append(QgsField(name, field_type))
    return fields


#: Fields added to the input attributes on every centerline (lengths and widths in layer units, metres when geographic).
#: ``source_fid`` is the id of the input feature, as on the optional outputs; ``part`` (on those) numbers a
#: feature's parts from 1, as messages do. Lengths, widths, chainages and radii are rounded to the millimetre
#: (:func:`.units.length_decimals`).
CENTERLINE_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("length", DOUBLE),
    ("width_min", DOUBLE),
    ("width_mean", DOUBLE),
    ("width_max", DOUBLE),
    ("n_vertices", INTEGER),
    ("ends_found", BOOLEAN),
    ("ends_from", STRING),
)
VERTEX_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("part", INTEGER),
    ("vertex", INTEGER),
    ("chainage", DOUBLE),
    ("radius", DOUBLE),
    ("width", DOUBLE),
)
CIRCLE_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("part", INTEGER),
    ("chainage", DOUBLE),
    ("radius", DOUBLE),
)
TRANSECT_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("part", INTEGER),
    ("chainage", DOUBLE),
    ("width", DOUBLE),
    ("method", STRING),
)


#: The attributes of :func:`width_statistics` that are lengths (rounded to :func:`.units.length_decimals`).
LENGTH_STATISTICS = ("length", "width_min", "width_mean", "width_max")


def rounded_statistics(results, decimals):
    """Return the core's ``width_statistics`` of ``results`` with its lengths rounded to ``decimals``."""
    statistics = width_statistics(results)
    return {
        name: rounded(value, decimals) if name in LENGTH_STATISTICS else value for name, value in statistics.items()
    }


def release_sinks(writer, names):
    """Flush and drop the sinks held in the attributes ``names`` of ``writer``; safe to call twice.

    QGIS finalises an output when its sink is destroyed; dropping the writer's references here makes that
    happen now rather than whenever the writer itself is collected.
    """
    for name in names:
        sink = getattr(writer, name)
        setattr(writer, name, None)
        if sink is not None:
            sink.flushBuffer()
        del sink


def primary_key_sink(algorithm, parameters, context, fields, wkb_type, crs):
    """Create the ``OUTPUT`` sink of ``algorithm`` with a primary key of its own; return (sink, destination id).

    Raises ``QgsProcessingException`` when the sink cannot be created.

    The output copies the input attributes, but one input feature can give several output features (parts
    written separately, branches), and an input's ``fid`` need not be unique. A GeoPackage takes a field named
    ``fid`` as its primary key and would refuse a repeated value, so the sink numbers the features afresh
    (``RegeneratePrimaryKey``, as QGIS's own algorithms that split features do); ``source_fid`` keeps the link
    to the input.
    """
    sink, destination = algorithm.parameterAsSink(
        parameters,
        algorithm.OUTPUT,
        context,
        fields,
        wkb_type,
        crs,
        QgsFeatureSink.SinkFlag.RegeneratePrimaryKey,
    )
    if sink is None:
        raise QgsProcessingException(algorithm.invalidSinkError(parameters, algorithm.OUTPUT))
    return sink, destination


class CenterlineWriter:
    """Creates the output sinks of an algorithm and writes centerline results into them.

    Parameters
    ----------
    algorithm : IncirCuAlgorithm
        The running algorithm (parameter lookup).
    parameters, context : dict, QgsProcessingContext
        As passed to ``processAlgorithm`` (for the sinks).
    input_fields : QgsFields
        Attributes copied from the input features.
    crs : QgsCoordinateReferenceSystem
        CRS of every output.
    multi : bool
        Write MultiLineString centerlines (one feature per input feature).
    options : OutputOptions
        M values, the transects' interval (per feature, working-frame units; 0 = the mean width of each
        centerline) and style, the loaded layers' names.
    """

    def __init__(self, algorithm, parameters, context, input_fields, crs, multi, options):
        self.algorithm = algorithm
        self.crs = crs
        self.add_m = add_m = options.add_m
        self.multi = multi
        self.transect_interval = options.transect_interval
        self.transect_style = options.transect_style
        self.decimals = length_decimals(crs)
        line_type = WkbType.MultiLineString if multi else WkbType.LineString
        if add_m:
            line_type = QgsWkbTypes.addM(line_type)
        self.fields = QgsProcessingUtils.combineFields(input_fields, make_fields(CENTERLINE_FIELDS))
        self.sink, self.sink_id = primary_key_sink(algorithm, parameters, context, self.fields, line_type, crs)
        self.vertices, self.vertices_id = algorithm.parameterAsSink(
            parameters, algorithm.OUTPUT_VERTICES, context, make_fields(VERTEX_FIELDS), WkbType.Point, crs
        )
        self.circles, self.circles_id = algorithm.parameterAsSink(
            parameters, algorithm.OUTPUT_CIRCLES, context, make_fields(CIRCLE_FIELDS), WkbType.Polygon, crs
        )
        self.transects, self.transects_id = algorithm.parameterAsSink(
            parameters,
            algorithm.OUTPUT_TRANSECTS,
            context,
            make_fields(TRANSECT_FIELDS),
            WkbType.LineString,
            crs,
        )
        self.centerline_count = 0
        self.metres_per_unit = metres_per_unit(crs)
        #: Per part written, the median spacing of its vertices and the median diameter of its incircles.
        self.vertex_spacings, self.circle_diameters = [], []
        self.stylers = style_outputs_on_load(
            context,
            {
                CENTERLINE: self.sink_id,
                VERTICES: self.vertices_id,
                TRANSECTS: self.transects_id,
                INCIRCLES: self.circles_id,
            },
            options.layer_names,
            options.group,
            metres_per_unit=self.metres_per_unit,
        )

    def close(self):
        """Flush and release every sink, which closes (commits) its file; safe to call twice. The vertices and
        incircles, once loaded, are shown only at the scales where they can be read (:func:`.styles.readable_scale`
        of the typical vertex spacing and incircle diameter)."""
        release_sinks(self, ("sink", "vertices", "circles", "transects"))
        scales = {
            name: readable_scale(float(np.median(lengths)), self.metres_per_unit) if lengths else 0.0
            for name, lengths in (("spacing", self.vertex_spacings), ("diameter", self.circle_diameters))
        }
        if VERTICES in self.stylers:
            self.stylers[VERTICES].minimum_scale = scales["spacing"]
        if INCIRCLES in self.stylers:
            # A circle is read where it is wide enough and apart enough from the next (they overlap).
            readable = [scale for scale in scales.values() if scale > 0.0]
            self.stylers[INCIRCLES].minimum_scale = min(readable, default=0.0)

    def destinations(self):
        """Return the output ids keyed by parameter name, for ``processAlgorithm``'s result."""
        algorithm = self.algorithm
        return {
            algorithm.OUTPUT: self.sink_id,
            algorithm.OUTPUT_VERTICES: self.vertices_id,
            algorithm.OUTPUT_CIRCLES: self.circles_id,
            algorithm.OUTPUT_TRANSECTS: self.transects_id,
        }

    def write(self, feature, parts, frame):
        """Write the centerline(s) of one input feature and its optional outputs.

        Parameters
        ----------
        feature : QgsFeature
            The input feature: its attributes are copied, its id written in every output's ``source_fid``, its
            transects spaced at its own interval (where data-defined).
        parts : sequence of (int, CenterlineResult)
            Part index and result of every successful part.
        frame : WorkingFrame
            Frame the results are expressed in.
        """
        if not parts:
            return
        attributes, source_fid = feature.attributes(), feature.id()
        groups = [parts] if self.multi else [[part] for part in parts]
        for group in groups:
            lines = []
            for _, result in group:
                coordinates = frame.to_layer(shapely.get_coordinates(result.line))
                lines.append(line_with_m(coordinates, result.widths if self.add_m else None))
            geometry = collect_lines(lines) if self.multi else QgsGeometry(lines[0])
            statistics = rounded_statistics([result for _, result in group], self.decimals)
            feature = QgsFeature(self.fields)
            feature.setGeometry(geometry)
            added = {"source_fid": source_fid, **statistics}
            feature.setAttributes([*attributes, *(added[name] for name, _ in CENTERLINE_FIELDS)])
            if not self.sink.addFeature(feature, QgsFeatureSink.Flag.FastInsert):
                raise QgsProcessingException(
                    QCoreApplication.translate("IncirCuAlgorithm", "Could not write a centerline: {}").format(
                        self.sink.lastError()
                    )
                )
            self.centerline_count += 1
        interval = self.transect_interval(feature)
        for part_index, result in parts:
            self._write_extras(source_fid, part_index, result, frame, interval)

    def _write_extras(self, source_fid, part_index, result, frame, interval):
        part, decimals = part_number(part_index), self.decimals
        if VERTICES in self.stylers or INCIRCLES in self.stylers:
            spacings = np.diff(vertex_chainages(result))
            if np.any(spacings > 0.0):
                self.vertex_spacings.append(float(np.median(spacings[spacings > 0.0])))
        if INCIRCLES in self.stylers and np.any(result.radii > 0.0):
            self.circle_diameters.append(2.0 * float(np.median(result.radii[result.radii > 0.0])))
        if self.vertices is not None:
            coordinates = frame.to_layer(shapely.get_coordinates(result.line))
            for index, ((x, y), chainage, radius) in enumerate(
                zip(coordinates, vertex_chainages(result), result.radii)
            ):
                point = QgsFeature()
                point.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(float(x), float(y))))
                point.setAttributes(
                    [
                        source_fid,
                        part,
                        index,
                        rounded(chainage, decimals),
                        rounded(radius, decimals),
                        rounded(2.0 * float(radius), decimals),
                    ]
                )
                self.vertices.addFeature(point, QgsFeatureSink.Flag.FastInsert)
        if self.circles is not None:
            for circle in incircle_polygons(result):
                disc = QgsFeature()
                disc.setGeometry(from_shapely(frame.to_layer(circle.polygon)))
                disc.setAttributes(
                    [source_fid, part, rounded(circle.chainage, decimals), rounded(circle.radius, decimals)]
                )
                self.circles.addFeature(disc, QgsFeatureSink.Flag.FastInsert)
        if self.transects is not None:
            interval = interval or width_statistics([result])["width_mean"] or 0.0
            if interval <= 0:
                return
            for transect in transects(result, interval, style=self.transect_style):
                section = QgsFeature()
                section.setGeometry(from_shapely(frame.to_layer(transect.line)))
                section.setAttributes(
                    [
                        source_fid,
                        part,
                        rounded(transect.chainage, decimals),
                        rounded(transect.width, decimals),
                        self.transect_style,
                    ]
                )
                self.transects.addFeature(section, QgsFeatureSink.Flag.FastInsert)
