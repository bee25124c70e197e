"""Processing algorithm ``incircu:polygoncenterline``: one unbranched centerline per polygon (part)."""

import math

from qgis.core import (
    QgsFeatureRequest,
    QgsGeometry,
    QgsPointXY,
    QgsProcessing,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSource,
    QgsRectangle,
    QgsSpatialIndex,
    QgsWkbTypes,
)

from .base import IncirCuAlgorithm


class PolygonCenterlineAlgorithm(IncirCuAlgorithm):
    """Centerline of each polygon, between two split points on its outline or between automatic ends."""

    INPUT = "INPUT"
    SPLIT_POINTS = "SPLIT_POINTS"
    SNAP_TOLERANCE = "SNAP_TOLERANCE"
    ISLANDS = "ISLANDS"
    SEPARATE_PARTS = "SEPARATE_PARTS"

    ICON = "polygoncenterline.svg"

    def name(self):
        return "polygoncenterline"

    def displayName(self):
        return self.tr("Centerline of polygons (IncirCu)")

    def tags(self):
        return self.tr("centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle").split(",")

    def shortHelpString(self):
        return self.tr(
            "Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) "
            "with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the "
            "outline. The line runs between the two SPLIT_POINTS lying on the polygon's outline, or, without "
            "them, between the two ends of the shape's longest internal path. Islands (holes) are passed on "
            "the side of the wider channel, or ignored. The M value of each vertex is the local width. "
            "Geographic layers are computed in a local metric projection; distances are then in metres. "
            "A polygon that cannot be processed is skipped with a warning naming its id and the reason."
        )

    def initAlgorithm(self, configuration=None):
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.INPUT, self.tr("Polygon layer"), [QgsProcessing.SourceType.TypeVectorPolygon]
            ),
            self.tr("Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part."),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.SPLIT_POINTS,
                self.tr("Split points"),
                [QgsProcessing.SourceType.TypeVectorPoint],
                optional=True,
            ),
            self.tr(
                "Points marking where each centerline starts and ends: two per polygon part, within "
                "SNAP_TOLERANCE of its exterior ring. A part with none gets automatic ends; a part with one "
                "or more than two is skipped. Another CRS is reprojected to the polygon layer's."
            ),
        )
        self.add_parameter(
            self.length_parameter(self.SNAP_TOLERANCE, self.tr("Split point snapping tolerance"), 1.0),
            self.tr(
                "Largest distance between a split point and the polygon's exterior ring, layer units "
                "(metres for a layer in degrees); 0 = a millionth of the polygon's size."
            ),
        )
        self.add_spacing_parameter()
        self.add_parameter(
            QgsProcessingParameterEnum(
                self.ISLANDS,
                self.tr("Islands (holes)"),
                [self.tr("Pass through the main channel"), self.tr("Ignore islands")],
                defaultValue=0,
            ),
            self.tr(
                "Pass through the main channel: the line never crosses an island and goes round it on the "
                "side of the wider channel. Ignore islands: holes are filled before computing."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterBoolean(self.SEPARATE_PARTS, self.tr("One feature per polygon part"), False),
            self.tr(
                "Write one line feature per part of a multipart polygon instead of one MultiLineString per "
                "input feature."
            ),
        )
        self.add_result_parameters()

    def process_features(self, run, parameters, context, feedback):
        source = run.source(self.INPUT, QgsWkbTypes.GeometryType.PolygonGeometry)
        crs = source.sourceCrs()
        split_source = None
        if parameters.get(self.SPLIT_POINTS) not in (None, ""):
            split_source = run.source(self.SPLIT_POINTS, QgsWkbTypes.GeometryType.PointGeometry)
        snap_tolerance = self.parameterAsDouble(parameters, self.SNAP_TOLERANCE, context)
        spacing = self.parameterAsDouble(parameters, self.SPACING, context) or None
        # The enum's choices are in the order of the core's ISLAND_MODES.
        islands = run.core.ISLAND_MODES[self.parameterAsEnum(parameters, self.ISLANDS, context)]
        separate = self.parameterAsBoolean(parameters, self.SEPARATE_PARTS, context)
        run.open_outputs(source.fields(), crs, multi=not separate and QgsWkbTypes.isMultiType(source.wkbType()))

        points, index = [], QgsSpatialIndex()
        if split_source is not None:
            request = QgsFeatureRequest().setDestinationCrs(crs, context.transformContext())
            for feature in split_source.getFeatures(request):
                for vertex in feature.geometry().vertices():
                    index.addFeature(len(points), QgsRectangle(vertex.x(), vertex.y(), vertex.x(), vertex.y()))
                    points.append(vertex)

        for feature in run.features(source):
            geometry = feature.geometry()
            run.frame.centre_on(geometry)
            shape = run.frame.to_core(geometry)
            margin = _layer_margin(snap_tolerance, geometry, crs.isGeographic())
            nearby = [points[i] for i in index.intersects(geometry.boundingBox().buffered(margin))]
            candidates = [
                run.frame.to_core(QgsGeometry.fromPointXY(QgsPointXY(point.x(), point.y()))) for point in nearby
            ]
            outcomes = run.compute(
                feature.id(),
                None,
                run.core.multipolygon_centerlines,
                shape,
                candidates or None,
                snap_tolerance=snap_tolerance or None,
                spacing=spacing,
                islands=islands,
            )
            several = len(outcomes or ()) > 1
            parts = []
            for outcome in outcomes or ():
                part_index = outcome.part_index if several else None
                if outcome.error is not None:
                    run.skip(feature.id(), str(outcome.error), part_index)
                    continue
                for note in getattr(outcome.result, "notes", ()):
                    run.warn(self.tr("Feature {}: {}").format(run.where(feature.id(), part_index), note))
                if outcome.result.ends_found and split_source is not None:
                    run.note(feature.id(), self.tr("no split points given, ends found automatically"), part_index)
                parts.append((outcome.part_index, outcome.result))
            run.write(feature, parts)
        return run.finish()


def _layer_margin(distance, geometry, geographic):
    """Return ``distance`` (metres when ``geographic``) as a safe bounding-box margin in layer units."""
    if not geographic:
        return distance
    latitude = geometry.boundingBox().center().y()
    return 2.0 * distance / (111_000.0 * max(math.cos(math.radians(latitude)), 0.01))
