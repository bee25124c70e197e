"""Base class of the IncirCu algorithms: translation, instances, help, icon and shared parameters."""

from pathlib import Path

from qgis.core import (
    QgsProcessing,
    QgsProcessingAlgorithm,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterNumber,
    QgsProcessingUtils,
)
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from .running import FeatureRun

ICON_PATH = Path(__file__).resolve().parent.parent / "icons"


class IncirCuAlgorithm(QgsProcessingAlgorithm):
    """Common behaviour of the IncirCu Processing algorithms.

    Subclasses define ``name``, ``displayName``, ``shortHelpString`` and ``initAlgorithm`` and add their
    parameters with :meth:`add_parameter`, which also records the parameter's help text.
    """

    SPACING = "SPACING"
    ADD_M = "ADD_M"
    TRANSECT_INTERVAL = "TRANSECT_INTERVAL"
    OUTPUT = "OUTPUT"
    OUTPUT_VERTICES = "OUTPUT_VERTICES"
    OUTPUT_CIRCLES = "OUTPUT_CIRCLES"
    OUTPUT_TRANSECTS = "OUTPUT_TRANSECTS"
    CENTERLINE_COUNT = "CENTERLINE_COUNT"
    SKIPPED_COUNT = "SKIPPED_COUNT"

    #: File name of the algorithm's icon under ``icons/``.
    ICON = "incircu.svg"

    def __init__(self):
        super().__init__()
        self.parameter_help = {}

    def processAlgorithm(self, parameters, context, feedback):
        """Run :meth:`process_features` and close every output whatever happens (end, cancel, error)."""
        run = FeatureRun(self, parameters, context, feedback)
        try:
            return self.process_features(run, parameters, context, feedback)
        finally:
            run.close()

    def process_features(self, run, parameters, context, feedback):
        """Compute and write the outputs through ``run`` (a ``FeatureRun``); return the result map."""
        raise NotImplementedError

    def tr(self, text):
        """Translate ``text`` with the class name as context.

        Strings of this base class are translated in its own context, ``IncirCuAlgorithm``.
        """
        translated = QCoreApplication.translate(type(self).__name__, text)
        if translated == text:
            translated = QCoreApplication.translate("IncirCuAlgorithm", text)
        return translated

    def createInstance(self):
        return type(self)()

    def group(self):
        return self.tr("Centerlines")

    def groupId(self):
        return "centerlines"

    def icon(self):
        return QIcon(self.svgIconPath())

    def svgIconPath(self):
        return str(ICON_PATH / self.ICON)

    def helpString(self):
        help_map = {"ALG_DESC": self.shortHelpString(), "ALG_CREATOR": "IncirCu", **self.parameter_help}
        return QgsProcessingUtils.formatHelpMapAsHtml(help_map, self)

    def add_parameter(self, parameter, help_text, advanced=False):
        """Add a parameter with its help text (tooltip in the dialog, section of the help page).

        Parameters
        ----------
        parameter : QgsProcessingParameterDefinition
        help_text : str
            Short, exact description, already translated.
        advanced : bool
            Show the parameter under "Advanced parameters".
        """
        if advanced:
            parameter.setFlags(parameter.flags() | parameter.Flag.FlagAdvanced)
        if hasattr(parameter, "setHelp"):
            parameter.setHelp(help_text)
        self.parameter_help[parameter.name()] = help_text
        self.addParameter(parameter)

    def add_output(self, output, help_text):
        """Declare a non-layer output with its help text."""
        self.parameter_help[output.name()] = help_text
        self.addOutput(output)

    @staticmethod
    def length_parameter(name, description, default):
        """A non-negative length in layer units, or in metres for a layer in degrees.

        A plain number rather than ``QgsProcessingParameterDistance``: for a layer in degrees that widget
        would label the value "degrees", while IncirCu computes geographic layers in metres.
        """
        return QgsProcessingParameterNumber(
            name, description, QgsProcessingParameterNumber.Type.Double, default, minValue=0.0
        )

    def add_spacing_parameter(self):
        """Add ``SPACING`` (distance between boundary samples, layer units or metres)."""
        self.add_parameter(
            self.length_parameter(self.SPACING, self.tr("Boundary sampling distance (0 = automatic)"), 0.0),
            self.tr(
                "Distance between consecutive samples of the boundary, in layer units (metres for a layer in "
                "degrees). 0 chooses it from the shape. Smaller values give a smoother, slower centerline.",
            ),
        )

    def add_result_parameters(self):
        """Add ``ADD_M``, the four output layers, ``TRANSECT_INTERVAL`` and the two count outputs."""
        self.add_parameter(
            QgsProcessingParameterBoolean(self.ADD_M, self.tr("Store the local width as M value"), True),
            self.tr(
                "Write the incircle diameter (local width, layer units or metres) as M value of each vertex.",
            ),
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT,
                self.tr("Centerlines"),
                QgsProcessing.SourceType.TypeVectorLine,
            ),
            self.tr(
                "Line layer: input attributes plus length, width_min, width_mean, width_max (incircle "
                "diameters over the vertices with a positive width), n_vertices and ends_found.",
            ),
        )
        optional_layers = (
            (
                self.OUTPUT_VERTICES,
                self.tr("Centerline vertices"),
                QgsProcessing.SourceType.TypeVectorPoint,
                self.tr("Optional point layer: every centerline vertex with its chainage, incircle radius and width."),
            ),
            (
                self.OUTPUT_CIRCLES,
                self.tr("Incircles"),
                QgsProcessing.SourceType.TypeVectorPolygon,
                self.tr("Optional polygon layer: the incircle of every vertex, with its radius and chainage."),
            ),
            (
                self.OUTPUT_TRANSECTS,
                self.tr("Transects"),
                QgsProcessing.SourceType.TypeVectorLine,
                self.tr(
                    "Optional line layer: cross-sections from bank to bank through the centerline, every "
                    "TRANSECT_INTERVAL, with their width and chainage.",
                ),
            ),
        )
        for name, description, layer_type, help_text in optional_layers:
            self.add_parameter(
                QgsProcessingParameterFeatureSink(name, description, layer_type, optional=True, createByDefault=False),
                help_text,
            )
        self.add_parameter(
            self.length_parameter(self.TRANSECT_INTERVAL, self.tr("Distance between transects (0 = mean width)"), 0.0),
            self.tr(
                "Distance along the centerline between two transects, layer units (metres for a layer in "
                "degrees); 0 uses the mean width of each centerline.",
            ),
            advanced=True,
        )
        self.add_output(
            QgsProcessingOutputNumber(self.CENTERLINE_COUNT, self.tr("Number of centerlines")),
            self.tr("Number of centerline features written."),
        )
        self.add_output(
            QgsProcessingOutputNumber(self.SKIPPED_COUNT, self.tr("Number of skipped features")),
            self.tr("Number of input features (or parts) skipped with a warning."),
        )
