"""Processing algorithm ``incircu:linescenterline``: the centerline between two bank lines."""

from functools import partial

from qgis.core import (
    NULL,
    QgsFeatureRequest,
    QgsGeometry,
    QgsProcessingException,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
)

from .base import IncirCuAlgorithm
from .compat import GeometryType, ProcessingFeatureSourceFlag, ProcessingSourceType
from .options import LinesOptions, read_choice, read_field, read_outputs, read_sampling, read_source
from .running import FeatureTask


class LinesCenterlineAlgorithm(IncirCuAlgorithm):
    """Centerline between the lines of two layers, paired by attribute or one line per layer."""

    LINES_A = "LINES_A"
    LINES_B = "LINES_B"
    PAIR_FIELD_A = "PAIR_FIELD_A"
    PAIR_FIELD_B = "PAIR_FIELD_B"

    ICON = "linescenterline.svg"
    LENGTH_PARENT = LINES_A

    def name(self):
        return "linescenterline"

    def displayName(self):
        return self.tr("Centerline between two lines")

    def shortDescription(self):
        return self.tr("One unbranched centerline between two lines, such as the two banks of a river.")

    def centerline_output_name(self):
        return self.tr("Centerline between lines")

    def centerline_output_help(self):
        return self.tr(
            "Line layer, one line per pair of lines: the attributes of the first lines plus source_fid (the "
            "id of the pair's first feature in the first lines), length, width_min, width_mean, width_max "
            "(incircle diameters over the vertices with a positive width; layer units, metres for a layer in "
            "degrees) and n_vertices. Its ends_found (always false) and ends_from (always empty) are there only "
            "so that it has the fields of 'Centerline of polygons'."
        )

    def tags(self):
        return self.tr("centerline,centreline,medial axis,banks,river,road,width,incircle").split(",")

    def summary(self):
        return (
            self.tr(
                "Computes one unbranched centerline between two lines (for example the two banks of a river) "
                "with the Curve of Incircles: every vertex is the centre of a circle touching both lines. Lines "
                "are paired by equal values of the two pairing fields (or of a field both layers have); without "
                "them each layer holds one line (its features and parts are merged). The lines must not cross. The M value of each vertex is "
                "the local width. The second lines are reprojected to the CRS of the first; geographic layers are "
                "computed in a local metric projection and distances are then in metres."
            )
            + " "
            + self.tr(
                "A line doubling back over itself (a zero-width spike, or an end coming back) loses that part first, "
                "with a warning naming where."
            )
        )

    def initAlgorithm(self, configuration=None):
        line = [ProcessingSourceType.VectorLine]
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.LINES_A, self.tr("First lines (bank A)"), line),
            self.tr(
                "Line layer of one side; the output has its CRS and its attributes. Z values (of both layers) are "
                "ignored: the centerline is computed in the plane."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.LINES_B, self.tr("Second lines (bank B)"), line),
            self.tr("Line layer of the other side; reprojected to the CRS of the first lines when needed."),
        )
        self.add_parameter(
            QgsProcessingParameterField(
                self.PAIR_FIELD_A,
                self.tr("Pairing field of the first lines"),
                parentLayerParameterName=self.LINES_A,
                optional=True,
            ),
            self.tr(
                "Optional; a line of the first lines is paired with the line of the second lines that has the same "
                "value in 'Pairing field of the second lines'. Left empty, a field both layers have with values "
                "found in both pairs them (the log names it)."
            ),
        )
        self.add_parameter(
            QgsProcessingParameterField(
                self.PAIR_FIELD_B,
                self.tr("Pairing field of the second lines"),
                parentLayerParameterName=self.LINES_B,
                optional=True,
            ),
            self.tr("Optional; required together with 'Pairing field of the first lines'."),
        )
        self.add_sampling_parameters()
        self.add_end_cap_parameter(self.tr("the middle of the gap between the two lines' ends"))
        self.add_result_parameters()

    def read_options(self, parameters, context, core):
        """Return the run's :class:`.options.LinesOptions`."""
        source_a = read_source(self, parameters, self.LINES_A, GeometryType.Line, context)
        source_b = read_source(self, parameters, self.LINES_B, GeometryType.Line, context)
        field_a = read_field(self, parameters, self.PAIR_FIELD_A, source_a, context)
        field_b = read_field(self, parameters, self.PAIR_FIELD_B, source_b, context)
        guessed = not field_a and not field_b
        if guessed:
            field_a = field_b = self.guessed_pair_field(source_a, source_b)
        if bool(field_a) != bool(field_b):
            raise QgsProcessingException(
                self.tr("Give both {} and {}, or neither (then each layer holds one line).").format(
                    self.parameter_label(self.PAIR_FIELD_A), self.parameter_label(self.PAIR_FIELD_B)
                )
            )
        return LinesOptions(
            source_a,
            source_b,
            field_a,
            field_b,
            guessed and bool(field_a),
            read_sampling(self, parameters, context),
            read_choice(self, parameters, self.END_CAP, core.END_CAPS, context),
            # The output layers' names start with both line layers' names, "banks_a / banks_b".
            read_outputs(self, parameters, context, f"{source_a.sourceName()} / {source_b.sourceName()}"),
        )

    def open_writer(self, parameters, context, options):
        from .outputs import CenterlineWriter  # needs Shapely, checked by require_core

        fields, crs = options.source_a.fields(), options.source_a.sourceCrs()
        return CenterlineWriter(self, parameters, context, fields, crs, False, options.outputs)

    def process_features(self, run, options):
        source_a, source_b, field_a, field_b = options.source_a, options.source_b, options.field_a, options.field_b
        run.warn_dropped_z(source_a)
        run.warn_dropped_z(source_b)
        if options.guessed_field:
            run.feedback.pushInfo(
                self.tr(
                    "No pairing fields given: both layers have the field '{}', so lines are paired by its "
                    "values (give {} and {} to pair them otherwise)."
                ).format(field_a, self.parameter_label(self.PAIR_FIELD_A), self.parameter_label(self.PAIR_FIELD_B))
            )
        groups_a = self.group_features(source_a, field_a, QgsFeatureRequest())
        request_b = QgsFeatureRequest().setDestinationCrs(source_a.sourceCrs(), run.context.transformContext())
        groups_b = self.group_features(source_b, field_b, request_b)
        if not field_a:
            self.check_single_lines(groups_a, groups_b)
        tasks = (
            self._task(run, options, key, first, geometries, groups_b) for key, (first, geometries) in groups_a.items()
        )
        run.run_batches("lines", tasks, len(groups_a))
        for key, (first, _) in groups_b.items():
            if key not in groups_a:
                run.warn(
                    self.tr("No line in {} has {} = {!r}; line {} of {} unused.").format(
                        self.parameter_label(self.LINES_A), field_a, key, first.id(), self.parameter_label(self.LINES_B)
                    )
                )
        return run.finish()

    def check_single_lines(self, groups_a, groups_b):
        """Raise ``QgsProcessingException`` unless each layer (grouped without a pairing field) holds one line."""
        for name, groups in ((self.LINES_A, groups_a), (self.LINES_B, groups_b)):
            if not groups:
                raise QgsProcessingException(self.tr("{} holds no line.").format(self.parameter_label(name)))
            merged = self.merged_line(groups[None][1])
            if merged.isMultipart() and len(merged.asGeometryCollection()) > 1:
                raise QgsProcessingException(
                    self.tr(
                        "{} holds {} separate lines that do not join into one; give {} and {} to pair them, "
                        "or merge them into one line."
                    ).format(
                        self.parameter_label(name),
                        len(merged.asGeometryCollection()),
                        self.parameter_label(self.PAIR_FIELD_A),
                        self.parameter_label(self.PAIR_FIELD_B),
                    )
                )

    def _task(self, run, options, key, first, geometries, groups_b):
        """The :class:`.running.FeatureTask` of one pair of lines: ``first`` feature of LINES_A, its lines."""
        if key not in groups_b:
            return run.skip_task(
                first,
                self.tr("no line in {} has {} = {!r}").format(self.parameter_label(self.LINES_B), options.field_b, key),
            )
        line_a = self.merged_line(geometries)
        line_b = self.merged_line(groups_b[key][1])
        if line_a.isMultipart() and len(line_a.asGeometryCollection()) > 1:
            return run.skip_task(first, self.not_joined(self.LINES_A))
        if line_b.isMultipart() and len(line_b.asGeometryCollection()) > 1:
            return run.skip_task(first, self.not_joined(self.LINES_B))
        frame = run.frame.around(QgsGeometry.collectGeometry([line_a, line_b]))
        keywords = dict(options.sampling.of(first), end_cap=options.end_cap)
        vertices = line_a.constGet().nCoordinates() + line_b.constGet().nCoordinates()
        inputs = (frame.to_core(line_a), frame.to_core(line_b))
        return FeatureTask(first, frame, inputs, keywords, partial(self._parts, run, first.id()), vertices)

    def not_joined(self, name):
        """Why a pair is skipped when its lines of layer parameter ``name`` do not join into one (translated)."""
        return self.tr("the lines of {} with this pairing value do not join into one").format(
            self.parameter_label(name)
        )

    def _parts(self, run, feature_id, result):
        """The pair's centerline to write; warn about what the core noted (banks of very different lengths)."""
        for note in result.notes:
            run.warn_feature(feature_id, note)
        return [(0, result)]

    @classmethod
    def guessed_pair_field(cls, source_a, source_b):
        """The field to pair the lines by when no pairing field is given: of the field names both layers have
        (but ``fid``, a GeoPackage's feature id), the one with the most values found in both; ties go to the
        first in the first layer's order. Empty when no shared field has a value in both layers.

        Parameters
        ----------
        source_a, source_b : QgsProcessingFeatureSource
            The first and second lines.

        Returns
        -------
        str
        """
        shared = [
            name
            for name in source_a.fields().names()
            if name.lower() != "fid" and source_b.fields().lookupField(name) >= 0
        ]
        if not shared:
            return ""
        values_a, values_b = cls.field_values(source_a, shared), cls.field_values(source_b, shared)
        common = {name: len(values_a[name] & values_b[name]) for name in shared}
        best = max(shared, key=lambda name: common[name])
        return best if common[best] else ""

    @staticmethod
    def field_values(source, names):
        """The set of non-null values of each field in ``names`` over the features of ``source``."""
        request = QgsFeatureRequest().setSubsetOfAttributes(names, source.fields())
        indices = {name: source.fields().lookupField(name) for name in names}
        values = {name: set() for name in names}
        for feature in source.getFeatures(request, ProcessingFeatureSourceFlag.SkipGeometryValidityChecks):
            attributes = feature.attributes()
            for name, index in indices.items():
                if attributes[index] != NULL:
                    values[name].add(attributes[index])
        return values

    @staticmethod
    def group_features(source, field_name, request):
        """Group the line geometries of a layer by the value of ``field_name`` (one group when empty).

        Returns
        -------
        dict
            Value -> (first feature, list of QgsGeometry), in the order values first appear.
        """
        groups = {}
        index = source.fields().lookupField(field_name) if field_name else -1
        for feature in source.getFeatures(request, ProcessingFeatureSourceFlag.SkipGeometryValidityChecks):
            if not feature.hasGeometry() or feature.geometry().isEmpty():
                continue
            key = feature.attributes()[index] if index >= 0 else None
            groups.setdefault(key, (feature, []))[1].append(feature.geometry())
        return groups

    @staticmethod
    def merged_line(geometries):
        """Merge line geometries (and multi-line parts) into as few lines as they form when joined end to end."""
        return QgsGeometry.collectGeometry(geometries).mergeLines()
