"""Processing algorithm ``incircu:polygonnetwork``: the medial-axis tree between two or more split points."""

from qgis.core import (
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
)

from .base import IncirCuAlgorithm
from .compat import GeometryType, ProcessingSourceType
from .split_points import SplitPoints


class PolygonNetworkAlgorithm(IncirCuAlgorithm):
    """Network of each polygon between its split points: one branch per pair of outline chains it separates."""

    INPUT = "INPUT"
    SPLIT_POINTS = "SPLIT_POINTS"
    SPLIT_ID_FIELD = "SPLIT_ID_FIELD"
    SNAP_TOLERANCE = "SNAP_TOLERANCE"
    ISLANDS = "ISLANDS"

    ICON = "polygonnetwork.svg"
    #: Section of the README (for the help URL) and the layer the lengths refer to.
    LENGTH_PARENT = INPUT

    def name(self):
        return "polygonnetwork"

    def displayName(self):
        return self.tr("Centerline network of polygons")

    def shortDescription(self):
        return self.tr("The medial-axis tree between the arm ends of a confluence, a delta or a road junction.")

    def centerline_layer_word(self):
        return self.tr("centerline network")

    def centerline_output_name(self):
        """Return the label of the branch output."""
        return self.tr("Network branches")

    def tags(self):
        return self.tr("network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width").split(",")

    def summary(self):
        return (
            self.tr(
                "Computes, for each polygon (each part of a multipart polygon) with two or more 'Split points' on its "
                "outline (the ends of the arms of a confluence, a delta or a road junction), lines down the middle of "
                "its arms, joined where the arms meet. The split points cut the outline into pieces, the chains, one "
                "between each two neighbouring points; each line runs through the centres of circles touching two "
                "chains, a path of the shape's medial axis (the line of the centres of all circles touching two sides): "
                "a tree with one end at each split point and junctions where a circle touches three chains, without side"
                " branches. Each branch is one line "
                "feature with the ids of the split points at its ends ('junction' at a junction), the chains on its right"
                " and left, its length and widths; the M value of each vertex is the local width. Two split points give "
                "exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or ignored."
                " Geographic layers are computed in a local metric projection; distances are then in metres. A polygon "
                "that cannot be processed is skipped with a warning naming its id and the reason."
            )
            + " "
            + self.tr(
                "Zero-width spikes of the outline (going out and back along themselves) are removed first, with a "
                "warning naming where."
            )
        )

    def initAlgorithm(self, configuration=None):
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.INPUT, self.tr("Polygon layer"), [ProcessingSourceType.VectorPolygon]
            ),
            self.tr(
                "Polygons with several arms (confluences, deltas, road junctions); each part gets its network. Z "
                "values are ignored: the network is computed in the plane."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.SPLIT_POINTS, self.tr("Split points"), [ProcessingSourceType.VectorPoint]
            ),
            self.tr(
                "The ends of the network: at least two per polygon part, within 'Split point snapping "
                "tolerance' of its exterior ring, typically one across each arm's end. A part with fewer is "
                "skipped. Another CRS is reprojected to the polygon layer's."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterField(
                self.SPLIT_ID_FIELD,
                self.tr("Split point id field"),
                parentLayerParameterName=self.SPLIT_POINTS,
                optional=True,
            ),
            self.tr(
                "Attribute naming each split point in from_point, to_point and the chains; default: its feature id."
            ),
        )
        self.add_snap_tolerance_parameter(self.SNAP_TOLERANCE)
        self.add_sampling_parameters()
        self.add_islands_parameter(
            self.tr(
                "{pass_through}: no branch crosses an island; each island belongs to the chain it is nearer to, "
                "so the branches go round it on the side of the wider channel. {ignore}: holes are filled before "
                "computing."
            ),
            self.ISLANDS,
        )
        self.add_end_cap_parameter(self.tr("the split point (junctions are left as they are)"))
        self.add_m_parameter()
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT, self.centerline_output_name(), ProcessingSourceType.VectorLine
            ),
            self.tr(
                "Line layer, one feature per branch: input attributes plus source_fid (the polygon's feature id, "
                "to join the branch back to it), from_point, to_point (split point ids or 'junction'), "
                "right_chain, left_chain (each chain named 'a-b' after the split points at its ends, "
                "counter-clockwise), length, width_min, width_mean, width_max (incircle diameters over the "
                "vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices."
            ),
        )
        self.add_count_outputs(self.tr("Number of branches"), self.tr("Number of branch features written."))

    def process_features(self, run, parameters, context, feedback):
        from .network_outputs import NetworkWriter  # after FeatureRun: it needs Shapely, checked there

        source = run.source(self.INPUT, GeometryType.Polygon)
        crs = source.sourceCrs()
        run.warn_dropped_z(source)
        split_source = run.source(self.SPLIT_POINTS, GeometryType.Point)
        id_field = self.field_parameter(parameters, self.SPLIT_ID_FIELD, split_source, context)
        snap_tolerance_of = self.length_of_feature(parameters, self.SNAP_TOLERANCE, context)
        sampling_of = self.feature_sampling(parameters, context)
        # The enum's choices are in the order of the core's ISLAND_MODES.
        islands = run.core.ISLAND_MODES[self.parameterAsEnum(parameters, self.ISLANDS, context)]
        add_m = self.parameterAsBoolean(parameters, self.ADD_M, context)
        run.use_writer(NetworkWriter(self, parameters, context, source.fields(), crs, add_m), crs)
        split_points = SplitPoints(split_source, crs, context, id_field)

        for feature in run.features(source):
            snap_tolerance = snap_tolerance_of(feature)
            geometry = feature.geometry()
            run.frame.centre_on(geometry)
            candidates, ids = split_points.near(geometry, snap_tolerance, run.frame)
            outcomes = run.compute(
                feature.id(),
                None,
                run.core.multipolygon_networks,
                run.frame.to_core(geometry),
                candidates,
                snap_tolerance=snap_tolerance or None,
                **sampling_of(feature),
                islands=islands,
                end_cap=self.end_cap_option(run, parameters, context),
            )
            several = len(outcomes or ()) > 1
            parts = []
            for outcome in outcomes or ():
                if outcome.error is not None:
                    run.skip(feature.id(), outcome.error, outcome.part_index if several else None)
                    continue
                for note in outcome.result.notes:
                    run.warn_feature(feature.id(), note, outcome.part_index if several else None)
                parts.append((outcome.part_index, outcome.result, ids))
            run.write(feature, parts)
        return run.finish()
