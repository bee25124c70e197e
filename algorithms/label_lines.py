"""Processing algorithm ``incircu:labellines``: the line a curved lake or river name follows, or a label point."""

from qgis.core import QgsProcessingParameterFeatureSink, QgsProcessingParameterNumber

from .compat import ProcessingNumberParameterType, ProcessingSourceType
from .dependencies import shapely_problem
from .polygon_centerline import PolygonCenterlineAlgorithm
from .styles import CENTERLINE, LABEL_POINTS

#: Just under the middle of the polygon: the largest clearance a label line can keep (half the width).
LARGEST_CLEARANCE = 0.49


def core_defaults():
    """The core's label options' defaults by name (``trim``, ...); empty without a usable Shapely, when the
    dialog shows no default and a run stops with the install message."""
    if shapely_problem() is not None:
        return {}
    from ..incircu_plugin.core import labels

    return {
        "trim": labels.TRIM,
        "clearance": labels.CLEARANCE,
        "bend": labels.BEND,
        "smoothing": labels.SMOOTHING,
        "min_elongation": labels.MIN_ELONGATION,
    }


class LabelLinesAlgorithm(PolygonCenterlineAlgorithm):
    """Label line of each polygon part along its main stem: trimmed, smoothed, inside with a clearance."""

    TRIM = "TRIM"
    CLEARANCE = "CLEARANCE"
    BEND = "BEND"
    SMOOTHING = "SMOOTHING"
    MIN_ELONGATION = "MIN_ELONGATION"
    OUTPUT_POINTS = "OUTPUT_POINTS"

    ICON = "labellines.svg"
    HELP_ANCHOR = "label-lines-of-polygons--incirculabellines"

    def name(self):
        return "labellines"

    def displayName(self):
        return self.tr("Label lines of polygons")

    def shortDescription(self):
        return self.tr("The line a curved lake or river name follows, or a label point for a round lake.")

    def centerline_output_name(self):
        return self.tr("Label lines")

    def centerline_output_help(self):
        return self.tr(
            "Line layer: one label line per elongated polygon part, reading from left to right, with the input "
            "attributes plus source_fid, part, length, width_min (the narrowest width along the line: the "
            "tallest lettering that fits; layer units, metres for a layer in degrees), elongation and kind "
            "(line)."
        )

    def tags(self):
        return self.tr("label,labels,lake,reservoir,river,name,curved,centerline,placement,cartography").split(",")

    def summary(self):
        return self.tr(
            "Computes, for each polygon part, the line a curved label should follow: the main stem (as "
            "'Centerline of polygons' finds it, between split points, along guide lines or between automatic "
            "ends), trimmed at both ends to where the polygon is at least 'Trim' times its widest width, "
            "smoothed so that it bends no tighter than 'Bend' times the local width, and checked to keep "
            "'Clearance' times the local width off the shore at every segment (where it cannot, the longest "
            "piece that can is kept). Lines read from left to right (west to east; south to north when "
            "vertical). A part whose main stem is shorter than 'Minimum elongation' times its mean width gets "
            "a label point instead: the centre of its largest incircle. Geographic layers are computed in a "
            "local metric projection; lengths are then in metres."
        )

    def initAlgorithm(self, configuration=None):
        self.add_polygon_parameters()
        defaults = core_defaults()
        shares = (
            (
                self.TRIM,
                self.tr("Trim: ends where the width falls below this share of the widest"),
                defaults.get("trim"),
                0.95,
                self.tr(
                    "Both ends of the main stem are cut back to the first and last point where the polygon is at "
                    "least this share of its widest width: out of the narrow tips and bays. 0 keeps the whole "
                    "main stem."
                ),
            ),
            (
                self.CLEARANCE,
                self.tr("Clearance from the shore, share of the local width"),
                defaults.get("clearance"),
                LARGEST_CLEARANCE,
                self.tr(
                    "Every segment of a label line is at least this share of the local width away from the "
                    "outline (0.25: the line keeps to the middle half)."
                ),
            ),
            (
                self.BEND,
                self.tr("Tightest bend: radius of curvature, share of the local width"),
                defaults.get("bend"),
                None,
                self.tr(
                    "The radius of curvature at every vertex is at least this share of the local width: a "
                    "label bends gently where the lake is wide."
                ),
            ),
            (
                self.MIN_ELONGATION,
                self.tr("Minimum elongation for a line"),
                defaults.get("min_elongation"),
                None,
                self.tr(
                    "A part whose main-stem length over mean width (its area over that length) is below this "
                    "gets a label point, the centre of its largest incircle (a disc: 1.27; a 3:1 ellipse: 3.8)."
                ),
            ),
            (
                self.SMOOTHING,
                self.tr("Smoothing, share of the local width"),
                defaults.get("smoothing"),
                None,
                self.tr(
                    "Standard deviation of the Gaussian smoothing along the main stem, as a share of the local "
                    "width; it is lowered where the line would come too near the shore and raised where it "
                    "would bend too tightly."
                ),
            ),
        )
        for name, description, default, largest, help_text in shares:
            parameter = QgsProcessingParameterNumber(
                name, description, ProcessingNumberParameterType.Double, default, True, 0.0
            )
            if largest is not None:
                parameter.setMaximum(largest)
            self.add_parameter(parameter, help_text, advanced=name == self.SMOOTHING)
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT, self.centerline_output_name(), ProcessingSourceType.VectorLine
            ),
            self.centerline_output_help(),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT_POINTS, self.tr("Label points"), ProcessingSourceType.VectorPoint
            ),
            self.tr(
                "Point layer: one label point per compact polygon part (the centre of its largest incircle), "
                "with the same fields (length 0, width_min the incircle's diameter, kind point)."
            ),
        )
        self.add_count_outputs(self.tr("Number of labels"), self.tr("Number of label lines and points written."))

    #: The core function the features are computed with (a key of ``running.ARRAY_FUNCTIONS``).
    CORE_FUNCTION = "label"

    def label_options(self, parameters, context):
        """Return the core's label keywords (``trim``...) as ``(name, value)`` pairs."""
        names = (
            ("trim", self.TRIM),
            ("clearance", self.CLEARANCE),
            ("bend", self.BEND),
            ("smoothing", self.SMOOTHING),
            ("min_elongation", self.MIN_ELONGATION),
        )
        return tuple((keyword, self.parameterAsDouble(parameters, name, context)) for keyword, name in names)

    def output_layer_words(self):
        """The label lines and the label points, as their loaded layers' names say them."""
        return {CENTERLINE: self.tr("label lines"), LABEL_POINTS: self.tr("label points")}

    def open_writer(self, parameters, context, options):
        from .label_outputs import LabelWriter  # needs Shapely, checked by require_core

        return LabelWriter(self, parameters, context, options)
