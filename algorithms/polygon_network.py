"""Processing algorithm ``incircu:polygonnetwork``: the medial-axis tree between the ends of a polygon's arms."""

from functools import partial

from qgis.core import (
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsProcessingParameterNumber,
)

from .base import IncirCuAlgorithm
from .compat import GeometryType, ProcessingNumberParameterType, ProcessingSourceType
from .options import (
    NetworkOptions,
    read_choice,
    read_field,
    read_optional_source,
    read_outputs,
    read_per_feature,
    read_sampling,
    read_source,
)
from .running import FeatureTask, no_geometry
from .split_points import SplitPoints
from .styles import CENTERLINE


class PolygonNetworkAlgorithm(IncirCuAlgorithm):
    """Network of each polygon between its split points: one branch per pair of outline chains it separates."""

    INPUT = "INPUT"
    SPLIT_POINTS = "SPLIT_POINTS"
    SPLIT_ID_FIELD = "SPLIT_ID_FIELD"
    SNAP_TOLERANCE = "SNAP_TOLERANCE"
    ISLANDS = "ISLANDS"
    MIN_ARM_RATIO = "MIN_ARM_RATIO"
    MIN_ARM_LENGTH = "MIN_ARM_LENGTH"
    OUTPUT_NODES = "OUTPUT_NODES"
    CONNECT_TOUCHING = "CONNECT_TOUCHING"

    ICON = "polygonnetwork.svg"
    #: Section of the README (for the help URL) and the layer the lengths refer to.
    LENGTH_PARENT = INPUT

    def name(self):
        return "polygonnetwork"

    def displayName(self):
        return self.tr("Centerline network of polygons")

    def shortDescription(self):
        return self.tr("The medial-axis tree between the arm ends of a confluence, a delta or a road junction.")

    def centerline_output_name(self):
        """Return the label of the branch output."""
        return self.tr("Network branches")

    def tags(self):
        return self.tr("network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width").split(",")

    def summary(self):
        return (
            self.tr(
                "Computes, for each polygon (each part of a multipart polygon), lines down the middle of its arms (the "
                "arms of a confluence, a lake, a delta or a road junction), joined where the arms meet. The ends cut "
                "the outline into pieces, the chains; each line runs through the centres of circles touching two "
                "chains, a path of the shape's medial axis (the line of the centres of all circles touching two "
                "sides): a tree with one end at each arm and junctions where a circle touches three chains, without "
                "side branches. The ends are the 'Split points' on the outline when a part has two or "
                "more; otherwise they are found automatically (one given split point replaces the automatic end nearest"
                " to it): an arm counts when it reaches beyond the circle of the junction it leaves by at least 'Minimum"
                " arm length, in junction widths' (bank noise and small bays do not). Each branch is one line feature "
                "with its node ids (from_node, to_node, shared by the branches that meet), its kind, the ids of the "
                "split points at its ends ('gate' at a gate, 'auto' at an automatic end, 'junction' at a junction), the "
                "chains on its "
                "right and left, its length and widths; the M value of each vertex is the local width. Two split points"
                " give exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or "
                "ignored."
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
                self.SPLIT_POINTS, self.tr("Split points"), [ProcessingSourceType.VectorPoint], optional=True
            ),
            self.tr(
                "The ends of the network, within 'Split point snapping tolerance' of a part's exterior ring, "
                "typically one across each arm's end. A part with two or more uses exactly these; a part with none "
                "or one gets its arm ends automatically (the one given replaces the automatic end nearest to it, "
                "when within that arm's width). Another CRS is reprojected to the polygon layer's."
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
                "computing. {channels}: every island at least as long as the river around it is wide (its own "
                "width plus twice its distance to the nearest bank or island) gets a branch on each side, so the network has a "
                "loop around it with exact junctions up- and downstream (branches of kind 'loop'); smaller "
                "islands are passed on the side of the wider channel."
            ),
            self.ISLANDS,
            channels=True,
        )
        self.add_end_cap_parameter(self.tr("the split point (junctions are left as they are)"))
        self.add_parameter(
            QgsProcessingParameterNumber(
                self.MIN_ARM_RATIO,
                self.tr("Minimum arm length, in junction widths"),
                ProcessingNumberParameterType.Double,
                1.0,
                minValue=0.0,
            ),
            self.tr(
                "Automatic ends: an arm is kept when it reaches beyond the circle of the junction it leaves by at "
                "least this many widths of that junction (1: bank bumps, digitising steps and bays shallower than "
                "the river is wide make no branch; a tributary does)."
            ),
        )
        self.add_length_parameter(
            self.MIN_ARM_LENGTH,
            self.tr("Minimum arm length"),
            0.0,
            self.tr(
                "Automatic ends: an arm is kept only when it also reaches at least this far beyond its junction's "
                "circle, layer units (metres for a layer in degrees); 0 = no such limit. For generalisation."
            ),
            advanced=True,
        )
        self.add_connect_touching_parameter()
        self.add_network_outputs()

    def add_network_outputs(self):
        """Add ``ADD_M``, the branch and node layers and the two counts."""
        self.add_m_parameter()
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT, self.centerline_output_name(), ProcessingSourceType.VectorLine
            ),
            self.tr(
                "Line layer, one feature per branch: input attributes plus source_fid (the polygon's feature id, "
                "to join the branch back to it), from_point, to_point (split point ids, 'gate', 'auto' or 'junction'), "
                "from_node, to_node (node ids shared by the branches that meet, also across polygons whose ends "
                "coincide), kind (arm, inner or loop), right_chain, left_chain (each chain named 'a-b' after the "
                "ends at its ends, counter-clockwise), length, width_min, width_mean, width_max (incircle "
                "diameters over the vertices with a positive width; layer units, metres for a layer in degrees) "
                "and n_vertices."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT_NODES,
                self.tr("Network nodes"),
                ProcessingSourceType.VectorPoint,
                optional=True,
                createByDefault=False,
            ),
            self.tr(
                "Optional point layer: every end and junction with its node id, degree (number of branch ends), "
                "radius (the junction's circle; 0 at an end) and kind (end or junction)."
            ),
        )
        self.add_count_outputs(self.tr("Number of branches"), self.tr("Number of branch features written."))

    def output_layer_words(self):
        return {**super().output_layer_words(), CENTERLINE: self.tr("centerline network")}

    def read_options(self, parameters, context, core):
        """Return the run's :class:`.options.NetworkOptions`."""
        source = read_source(self, parameters, self.INPUT, GeometryType.Polygon, context)
        split_points = read_optional_source(self, parameters, self.SPLIT_POINTS, GeometryType.Point, context)
        id_field = (
            "" if split_points is None else read_field(self, parameters, self.SPLIT_ID_FIELD, split_points, context)
        )
        return NetworkOptions(
            source=source,
            split_points=split_points,
            id_field=id_field,
            snap_tolerance=read_per_feature(self, parameters, self.SNAP_TOLERANCE, context),
            sampling=read_sampling(self, parameters, context),
            # The enums' choices are in the order of the core's NETWORK_ISLAND_MODES and END_CAPS.
            islands=read_choice(self, parameters, self.ISLANDS, core.NETWORK_ISLAND_MODES, context),
            end_cap=read_choice(self, parameters, self.END_CAP, core.END_CAPS, context),
            min_arm_ratio=self.parameterAsDouble(parameters, self.MIN_ARM_RATIO, context),
            min_arm_length=self.parameterAsDouble(parameters, self.MIN_ARM_LENGTH, context) or None,
            connect_touching=self.parameterAsBoolean(parameters, self.CONNECT_TOUCHING, context),
            outputs=read_outputs(self, parameters, context, source.sourceName()),
        )

    def open_writer(self, parameters, context, options):
        from .network_outputs import NetworkWriter  # needs Shapely, checked by require_core

        return NetworkWriter(self, parameters, context, options)

    def process_features(self, run, options):
        source = options.source
        run.warn_dropped_z(source)
        gates = run.layer_gates(source) if options.connect_touching else None
        split_points = SplitPoints(options.split_points, source.sourceCrs(), run.context, options.id_field)
        task = partial(self._task, run, options, gates, split_points)
        run.run_batches("network", map(task, run.source_features(source)), source.featureCount())
        return run.finish()

    def _task(self, run, options, gates, split_points, feature):
        """The :class:`.running.FeatureTask` of one polygon feature: its geometry and split points in its frame,
        its gates (``CONNECT_TOUCHING``), the network options."""
        from ..incircu_plugin.core.touching import bounding_diagonal  # needs Shapely, checked by require_core

        if not run.has_geometry(feature):
            return run.skip_task(feature, no_geometry())
        geometry, frame, snap_tolerance, candidates, ids = run.located(feature, options, split_points)
        core_geometry, core_gates, layer_gates, extent = None, [], [], 0.0
        if gates is not None:
            core_geometry, core_gates, layer_gates = gates.of(feature.id(), frame)
            extent = bounding_diagonal(gates.layer_geometry(feature.id()))
        keywords = dict(
            options.sampling.of(feature),
            gates=core_gates,
            snap_tolerance=snap_tolerance or None,
            islands=options.islands,
            end_cap=options.end_cap,
            min_arm_ratio=options.min_arm_ratio,
            min_arm_length=options.min_arm_length,
        )
        inputs = (frame.to_core(geometry) if core_geometry is None else core_geometry, candidates)
        parts = partial(self._parts, run, feature.id(), ids, layer_gates, extent)
        return FeatureTask(feature, frame, inputs, keywords, parts, geometry.constGet().nCoordinates())

    @staticmethod
    def _parts(run, feature_id, ids, layer_gates, extent, outcomes):
        """The networks of a feature's successful parts, with what the writer numbers their nodes by."""
        return [
            (outcome.part_index, outcome.result, ids, layer_gates, extent)
            for outcome, _ in run.successful_parts(feature_id, outcomes)
        ]
