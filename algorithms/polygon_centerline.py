"""Processing algorithm ``incircu:polygoncenterline``: one unbranched centerline per polygon (part)."""

from functools import partial

from qgis.core import (
    QgsFeatureRequest,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSource,
    QgsSpatialIndex,
    QgsWkbTypes,
)

from .base import IncirCuAlgorithm
from .compat import GeometryType, ProcessingSourceType
from .options import (
    PolygonOptions,
    read_choice,
    read_optional_source,
    read_outputs,
    read_per_feature,
    read_sampling,
    read_source,
)
from .running import FeatureTask, no_geometry
from .split_points import SplitPoints


class PolygonCenterlineAlgorithm(IncirCuAlgorithm):
    """Centerline of each polygon, between two split points on its outline or between automatic ends."""

    INPUT = "INPUT"
    SPLIT_POINTS = "SPLIT_POINTS"
    SNAP_TOLERANCE = "SNAP_TOLERANCE"
    ISLANDS = "ISLANDS"
    SEPARATE_PARTS = "SEPARATE_PARTS"
    CONNECT_TOUCHING = "CONNECT_TOUCHING"
    END_RULE = "END_RULE"
    GUIDE_LINES = "GUIDE_LINES"

    ICON = "polygoncenterline.svg"
    LENGTH_PARENT = INPUT

    def name(self):
        return "polygoncenterline"

    def displayName(self):
        return self.tr("Centerline of polygons")

    def shortDescription(self):
        return self.tr("One unbranched centerline through each elongated polygon (river, road, dike).")

    def centerline_output_name(self):
        return self.tr("Centerlines of polygons")

    def centerline_output_help(self):
        return self.tr(
            "Line layer: input attributes plus source_fid (the polygon's feature id, to join the line back to "
            "it), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive "
            "width; layer units, metres for a layer in degrees), n_vertices, ends_found (true when no split "
            "points were used) and ends_from (split_points, guide, automatic, or split_points_and_automatic for one given split point)."
        )

    def tags(self):
        return self.tr("centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle").split(",")

    def summary(self):
        return (
            self.tr(
                "Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) "
                "with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the "
                "outline. The line runs between the two 'Split points' lying on the polygon's outline, or, "
                "without them, between automatic ends: those of the internal path along the 'Guide lines', else of "
                "the main stem (or the longest internal path, see 'Automatic ends'). Islands (holes) are passed on "
                "the side of the wider channel, or ignored. The M value of each vertex is the local width. "
                "Geographic layers are computed in a local metric projection; distances are then in metres. "
                "A polygon that cannot be processed is skipped with a warning naming its id and the reason."
            )
            + " "
            + self.tr(
                "A ring around one island (a roundabout, a moat, an atoll) gets, without split points, the closed loop "
                "around the island, from and back to its narrowest place. Zero-width spikes of the outline (going out "
                "and back along themselves) are removed first, with a warning naming where."
            )
        )

    def initAlgorithm(self, configuration=None):
        self.add_polygon_parameters()
        self.add_end_cap_parameter(self.tr("the split point, or for automatic ends where that line meets the outline"))
        self.add_parameter(
            QgsProcessingParameterBoolean(self.SEPARATE_PARTS, self.tr("One feature per polygon part"), False),
            self.tr(
                "Write one line feature per part of a multipart polygon instead of one MultiLineString per "
                "input feature."
            ),
        )
        self.add_connect_touching_parameter()
        self.add_result_parameters()

    def add_polygon_parameters(self):
        """Add the inputs shared with the label algorithm: polygons, split points, sampling, islands, ends."""
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.INPUT, self.tr("Polygon layer"), [ProcessingSourceType.VectorPolygon]
            ),
            self.tr(
                "Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part. Z values "
                "are ignored: the centerline is computed in the plane."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.SPLIT_POINTS,
                self.tr("Split points"),
                [ProcessingSourceType.VectorPoint],
                optional=True,
            ),
            self.tr(
                "Points marking where each centerline starts and ends: two per polygon part, within "
                "'Split point snapping tolerance' of its exterior ring. A part with none gets automatic ends; a part with one "
                "starts there and ends at the far end of its main stem; a part with more than two is skipped. Another "
                "CRS is reprojected to the polygon layer's."
            ),
        )
        self.add_snap_tolerance_parameter(self.SNAP_TOLERANCE)
        self.add_sampling_parameters()
        self.add_islands_parameter(
            self.tr(
                "{pass_through}: the line never crosses an island and goes round it on the side of the wider "
                "channel. {ignore}: holes are filled before computing."
            ),
            self.ISLANDS,
        )
        main_stem, longest_path = self.tr("Main stem (widest path)"), self.tr("Longest path")
        self.add_parameter(
            QgsProcessingParameterEnum(
                self.END_RULE, self.tr("Automatic ends"), [main_stem, longest_path], defaultValue=0
            ),
            self.tr(
                "For polygons without split points. {main_stem}: the internal path that sweeps the largest "
                "channel area (length times width), so a wide main river wins over a longer but narrow side "
                "arm. {longest_path}: the tips of the two longest arms."
            ).format(main_stem=main_stem, longest_path=longest_path),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(
                self.GUIDE_LINES,
                self.tr("Guide lines"),
                [ProcessingSourceType.VectorLine],
                optional=True,
            ),
            self.tr(
                "Rough river lines (a national network, OpenStreetMap waterways) for polygons without split "
                "points: the ends are those of the internal path that best covers the guide lines near the "
                "polygon. Gaps, offsets, generalised pieces and tributaries are fine. Another CRS is reprojected."
            ),
        )

    def read_options(self, parameters, context, core):
        """Return the run's :class:`.options.PolygonOptions`."""
        source = read_source(self, parameters, self.INPUT, GeometryType.Polygon, context)
        has = self.parameterDefinition
        options = {
            "source": source,
            "split_points": read_optional_source(self, parameters, self.SPLIT_POINTS, GeometryType.Point, context),
            "guide_lines": read_optional_source(self, parameters, self.GUIDE_LINES, GeometryType.Line, context),
            "snap_tolerance": read_per_feature(self, parameters, self.SNAP_TOLERANCE, context),
            "sampling": read_sampling(self, parameters, context),
            # The enums' choices are in the order of the core's ISLAND_MODES, END_RULES and END_CAPS.
            "islands": read_choice(self, parameters, self.ISLANDS, core.ISLAND_MODES, context),
            "end_rule": read_choice(self, parameters, self.END_RULE, core.END_RULES, context),
            # The label algorithm has neither an end cap choice (its line is trimmed) nor parts nor gates.
            "end_cap": read_choice(self, parameters, self.END_CAP, core.END_CAPS, context)
            if has(self.END_CAP)
            else "axis",
            "separate_parts": bool(has(self.SEPARATE_PARTS))
            and self.parameterAsBoolean(parameters, self.SEPARATE_PARTS, context),
            "connect_touching": bool(has(self.CONNECT_TOUCHING))
            and self.parameterAsBoolean(parameters, self.CONNECT_TOUCHING, context),
        }
        rule = self.rule_name(options["split_points"], options["guide_lines"], options["end_rule"], core)
        outputs = read_outputs(self, parameters, context, source.sourceName(), rule)
        return PolygonOptions(**options, outputs=outputs, label=self.label_options(parameters, context))

    def label_options(self, parameters, context):
        """Return the core's label keywords as ``(name, value)`` pairs: none for centerlines."""
        return ()

    def rule_name(self, split_points, guide_lines, end_rule, core):
        """Return where the ends of this run come from, for the output layers' names: "split points", "guide
        lines", or the automatic rule (``end_rule``, one of ``core.END_RULES``)."""
        if split_points is not None:
            return self.tr("split points")
        if guide_lines is not None:
            return self.tr("guide lines")
        return dict(zip(core.END_RULES, (self.tr("main stem"), self.tr("longest path"))))[end_rule]

    def open_writer(self, parameters, context, options):
        from .outputs import CenterlineWriter  # needs Shapely, checked by require_core

        source = options.source
        multi = not options.separate_parts and QgsWkbTypes.isMultiType(source.wkbType())
        fields, crs = source.fields(), source.sourceCrs()
        return CenterlineWriter(self, parameters, context, fields, crs, multi, options.outputs)

    #: The core function the features are computed with (a key of ``running.ARRAY_FUNCTIONS``).
    CORE_FUNCTION = "polygon"

    def process_features(self, run, options):
        """Compute every polygon in batches and write it through ``run``'s writer."""
        source = options.source
        run.warn_dropped_z(source)
        crs, context = source.sourceCrs(), run.context
        split_points = SplitPoints(options.split_points, crs, context)
        guides = GuideLines(options.guide_lines, crs, context)
        gates = run.layer_gates(source) if options.connect_touching else None
        tasks = (
            self._task(run, options, feature, split_points, guides, gates) for feature in run.source_features(source)
        )
        run.run_batches(self.CORE_FUNCTION, tasks, source.featureCount())
        return run.finish()

    def _task(self, run, options, feature, split_points, guides, gates):
        """The :class:`.running.FeatureTask` of one polygon feature, in its own working frame."""
        if not run.has_geometry(feature):
            return run.skip_task(feature, no_geometry())
        geometry, frame, snap_tolerance, candidates, _ = run.located(feature, options, split_points)
        core_geometry = None
        if gates is not None:
            # The gates are split points; the geometry carries them as vertices, so the line ends there.
            core_geometry, core_gates, _ = gates.of(feature.id(), frame)
            candidates = [*candidates, *core_gates]
        if core_geometry is None:
            core_geometry = frame.to_core(geometry)
        keywords = dict(
            options.sampling.of(feature),
            islands=options.islands,
            end_rule=options.end_rule,
            end_cap=options.end_cap,
            snap_tolerance=snap_tolerance or None,
            guide=guides.near(geometry, frame),
            **dict(options.label),
        )
        given = split_points if options.split_points is not None else None
        parts = partial(self._parts, run, feature.id(), given, snap_tolerance, core_geometry, frame)
        inputs = (core_geometry, candidates if len(candidates) else None)
        return FeatureTask(feature, frame, inputs, keywords, parts, geometry.constGet().nCoordinates())

    def _parts(self, run, feature_id, split_points, snap_tolerance, geometry, frame, outcomes):
        """The successful parts of a polygon to write; warn about the others and about automatic ends.

        Parameters
        ----------
        run : FeatureRun
        feature_id : int
        split_points : SplitPoints or None
            The layer's split points; None when no split point layer is given.
        snap_tolerance : float
            ``SNAP_TOLERANCE`` as given, layer units (metres for a layer in degrees); 0: the core's default.
        geometry : Polygon or MultiPolygon
            The feature's geometry in the working frame it was computed in.
        frame : WorkingFrame
            That frame.
        outcomes : list of PartOutcome
        """
        import shapely  # after require_core, like the core: a missing Shapely gets its install message

        parts = []
        for outcome, part_index in run.successful_parts(feature_id, outcomes):
            if outcome.result.ends_found and split_points is not None:
                part = shapely.get_parts(geometry)[outcome.part_index]
                nearest = split_points.nearest_distance(part.exterior, frame)
                message = self._no_split_point(nearest, snap_tolerance, frame.unit)
                run.warn_feature(
                    feature_id, self.tr("{} Its ends were found automatically.").format(message), part_index
                )
            parts.append((outcome.part_index, outcome.result))
        return parts

    def _no_split_point(self, nearest, snap_tolerance, unit):
        """Say that a polygon (part) has no split point within the snap tolerance, and how far the nearest is.

        Parameters
        ----------
        nearest : float or None
            Distance from the outline to the nearest split point, ``unit``; None when the layer has none.
        snap_tolerance : float
            As given, ``unit``; 0: the core's default.
        unit : str
            Name of the unit of the lengths.
        """
        if snap_tolerance > 0:
            tolerance = f"{snap_tolerance:.6g} {unit}"
        else:
            tolerance = self.tr("0: a millionth of the polygon's size")
        if nearest is None:
            return self.tr("{} holds no point.").format(self.parameter_label(self.SPLIT_POINTS))
        return self.tr("no split point lies within {} of its outline, the {}; the nearest is {:.6g} {} away.").format(
            tolerance, self.parameter_label(self.SNAP_TOLERANCE), nearest, unit
        )


class GuideLines:
    """The lines of ``GUIDE_LINES`` (``source``, None without), reprojected to the polygon layer's ``crs`` with
    the transformations of ``context``, read once and found per polygon by a spatial index."""

    def __init__(self, source, crs, context):
        self.lines, self.index = [], QgsSpatialIndex()
        if source is None:
            return
        request = QgsFeatureRequest().setDestinationCrs(crs, context.transformContext())
        for feature in source.getFeatures(request):
            if feature.hasGeometry():
                self.index.addFeature(len(self.lines), feature.geometry().boundingBox())
                self.lines.append(feature.geometry())

    def near(self, geometry, frame):
        """Return the guide lines whose box meets the polygon's grown box, as one MultiLineString of the
        working frame ``frame`` (the polygon's); None without guide lines there.

        The box grows by the core's ``GUIDE_SEARCH_SHARE`` of its larger side; the core keeps only the guide
        lying near the polygon.
        """
        if not self.lines:
            return None
        # Imported here, like the core (see ``running.FeatureRun``), so a missing Shapely gets its install message.
        import shapely

        from ..incircu_plugin.core.ends import GUIDE_SEARCH_SHARE

        box = geometry.boundingBox()
        grown = box.buffered(GUIDE_SEARCH_SHARE * max(box.width(), box.height()))
        parts = [
            part
            for found in self.index.intersects(grown)
            for part in shapely.get_parts(frame.to_core(self.lines[found]))
            if part.geom_type == "LineString" and not part.is_empty
        ]
        return shapely.MultiLineString(parts) if parts else None
