"""Base class of the IncirCu algorithms: translation, instances, help, icon and shared parameters."""

import configparser
import html
from pathlib import Path

from qgis.core import (
    QgsProcessingAlgorithm,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterDistance,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingUtils,
)
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from .compat import DistanceUnit, ProcessingParameterFlag, ProcessingSourceType
from .running import FeatureRun

PLUGIN_FOLDER = Path(__file__).resolve().parent.parent
ICON_PATH = PLUGIN_FOLDER / "icons"


def homepage():
    """Return the project's web address (``homepage`` of ``metadata.txt``), where the README is shown."""
    parser = configparser.ConfigParser(interpolation=None)
    parser.read(PLUGIN_FOLDER / "metadata.txt", encoding="utf-8")
    return parser["general"]["homepage"]


def length_parameter(name, description, default, parent_layer):
    """A non-negative length in the units of ``parent_layer``, or in metres when that layer is in degrees.

    A ``QgsProcessingParameterDistance`` tied to the layer (``qgis_process``, batch dialog and modeler show
    it as QGIS does); the toolbox dialog shows it with :class:`.length_widget.LengthWidgetWrapper`, which
    names the layer's unit next to the box and "meters" for a layer in degrees, where QGIS would say
    "degrees".

    Parameters
    ----------
    name, description : str
        Parameter name and dialog label.
    default : float
        Default value, layer units (metres for a layer in degrees).
    parent_layer : str
        Name of the layer parameter the length refers to.

    Returns
    -------
    QgsProcessingParameterDistance
    """
    parameter = QgsProcessingParameterDistance(name, description, default, parent_layer, True, 0.0)
    parameter.setDefaultUnit(DistanceUnit.Meters)
    parameter.setMetadata({"widget_wrapper": {"class": f"{__package__}.length_widget.LengthWidgetWrapper"}})
    return parameter


class IncirCuAlgorithm(QgsProcessingAlgorithm):
    """Common behaviour of the IncirCu Processing algorithms.

    Subclasses define ``name``, ``displayName``, ``shortDescription``, ``summary``,
    ``centerline_output_name``, ``initAlgorithm``, ``HELP_ANCHOR`` and ``LENGTH_PARENT``, and add their
    parameters with :meth:`add_parameter`, which also records the parameter's help text; the dialog's help
    panel (``shortHelpString``) shows the summary and then every parameter and output with that text.
    """

    TOLERANCE = "TOLERANCE"
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
    #: Anchor of the algorithm's section in the README (GitHub's heading slug).
    HELP_ANCHOR = ""
    #: Name of the input layer whose units the length parameters are in (metres when it is in degrees).
    LENGTH_PARENT = ""

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

    def parameter_label(self, name):
        """Return how messages name parameter ``name``: its dialog label, then its name for ``qgis_process``.

        ``'Second lines (bank B)' (LINES_B)``; the bare name for a parameter the algorithm does not have.
        """
        definition = self.parameterDefinition(name)
        if definition is None:
            return name
        return f"'{definition.description()}' ({name})"

    def field_parameter(self, parameters, name, source, context):
        """Return the field named by parameter ``name`` (empty when none is given), checked against ``source``.

        Parameters
        ----------
        parameters : dict
        name : str
            A ``QgsProcessingParameterField`` of the algorithm.
        source : QgsProcessingFeatureSource
            The layer of its parent parameter.
        context : QgsProcessingContext

        Raises
        ------
        QgsProcessingException
            When ``source`` has no field of that name (``qgis_process`` and models accept any text).
        """
        field = self.parameterAsString(parameters, name, context)
        if field and source.fields().lookupField(field) < 0:
            parent = self.parameterDefinition(name).parentLayerParameterName()
            raise QgsProcessingException(
                self.tr("{}: {} has no field '{}'; its fields are: {}.").format(
                    self.parameter_label(name),
                    self.parameter_label(parent),
                    field,
                    ", ".join(source.fields().names()) or self.tr("none"),
                )
            )
        return field

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

    def centerline_output_name(self):
        """Return the label of the centerline output, also the name of the layer it loads as."""
        raise NotImplementedError

    def helpUrl(self):
        return f"{homepage()}#{self.HELP_ANCHOR}"

    def summary(self):
        """Return what the algorithm does, translated: the first paragraph of its help."""
        raise NotImplementedError

    def shortHelpString(self):
        """Return the help of the dialog's side panel: the summary, then the parameters and outputs.

        Each parameter and output is listed under its dialog label with its help text (the tooltip, units
        included), in the order the dialog shows them: parameters, advanced parameters, outputs.
        """
        parameters, advanced, outputs = [], [], []
        for definition in self.parameterDefinitions():
            if definition.isDestination():
                outputs.append(definition)
            elif definition.flags() & ProcessingParameterFlag.Advanced:
                advanced.append(definition)
            else:
                parameters.append(definition)
        destinations = {definition.name() for definition in outputs}
        outputs += [output for output in self.outputDefinitions() if output.name() not in destinations]
        sections = (
            (self.tr("Parameters"), parameters),
            (self.tr("Advanced parameters"), advanced),
            (self.tr("Outputs"), outputs),
        )
        listed = "".join(self._help_section(title, definitions) for title, definitions in sections if definitions)
        return self.summary() + "\n" + listed

    def _help_section(self, title, definitions):
        """Return one heading of the help panel and a line per parameter or output: label in bold, help."""
        lines = "".join(
            "<p style='margin: 3px 0'><b>{}</b>: {}</p>".format(
                html.escape(definition.description(), quote=False),
                html.escape(self.parameter_help.get(definition.name(), ""), quote=False),
            )
            for definition in definitions
        )
        return f"<h3>{html.escape(title, quote=False)}</h3>{lines}"

    def helpString(self):
        help_map = {"ALG_DESC": self.summary(), "ALG_CREATOR": "IncirCu", **self.parameter_help}
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
            parameter.setFlags(parameter.flags() | ProcessingParameterFlag.Advanced)
        parameter.setHelp(help_text)
        self.parameter_help[parameter.name()] = help_text
        self.addParameter(parameter)

    def add_output(self, output, help_text):
        """Declare a non-layer output with its help text."""
        self.parameter_help[output.name()] = help_text
        self.addOutput(output)

    def add_length_parameter(self, name, description, default, help_text, advanced=False):
        """Add an optional, non-negative length with its default, in the units of ``LENGTH_PARENT``.

        The dialog shows the unit next to the box (see :func:`length_parameter`); a layer in
        degrees is computed in metres. Optional because it has a default, so the modeler does not require it.

        Parameters
        ----------
        name, description : str
            Parameter name and (translated) dialog label.
        default : float
            Default length, layer units (metres for a layer in degrees).
        help_text : str
            As for :meth:`add_parameter`.
        advanced : bool
            Show the parameter under "Advanced parameters".
        """
        self.add_parameter(length_parameter(name, description, default, self.LENGTH_PARENT), help_text, advanced)

    def add_optional_parameter(self, parameter, help_text, advanced=False):
        """Add a parameter that has a default as optional, so the modeler does not require a value for it."""
        parameter.setFlags(parameter.flags() | ProcessingParameterFlag.Optional)
        self.add_parameter(parameter, help_text, advanced)

    def add_sampling_parameters(self):
        """Add ``TOLERANCE`` (adaptive sampling, the default) and ``SPACING`` (the paper's fixed sampling)."""
        self.add_length_parameter(
            self.TOLERANCE,
            self.tr("Largest deviation from the exact medial axis (0 = automatic)"),
            0.0,
            self.tr(
                "Largest distance between the centerline and the exact medial axis, in layer units (metres for "
                "a layer in degrees): the line keeps only the vertices it needs to stay that close, each lying "
                "exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the "
                "shape's typical width: the right choice for maps.",
            ),
        )
        self.add_length_parameter(
            self.SPACING,
            self.tr("Fixed boundary sampling distance (0 = adaptive)"),
            0.0,
            self.tr(
                "The paper's fixed sampling: a sample every this distance along both sides, in layer units "
                "(metres for a layer in degrees), giving many evenly spaced vertices. Use it to reproduce the "
                "paper or for a dense line; 0 uses the adaptive sampling bounded by the largest deviation. "
                "Give either this or the largest deviation, not both.",
            ),
            advanced=True,
        )

    def sampling_options(self, parameters, context):
        """Return the core's ``tolerance`` and ``spacing`` keywords (``None`` for 0).

        Raises
        ------
        QgsProcessingException
            When both a largest deviation and a fixed sampling distance are given.
        """
        tolerance = self.parameterAsDouble(parameters, self.TOLERANCE, context) or None
        spacing = self.parameterAsDouble(parameters, self.SPACING, context) or None
        if tolerance is not None and spacing is not None:
            raise QgsProcessingException(
                self.tr(
                    "Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary "
                    "sampling distance, not both; set the other one to 0."
                )
            )
        return {"tolerance": tolerance, "spacing": spacing}

    def add_snap_tolerance_parameter(self, name="SNAP_TOLERANCE"):
        """Add the split point snapping tolerance (layer units or metres)."""
        self.add_length_parameter(
            name,
            self.tr("Split point snapping tolerance"),
            1.0,
            self.tr(
                "Largest distance between a split point and the polygon's exterior ring, layer units "
                "(metres for a layer in degrees); 0 = a millionth of the polygon's size."
            ),
        )

    def add_islands_parameter(self, help_template, name="ISLANDS", channels=False):
        """Add the island mode, its choices in the order of the core's ``ISLAND_MODES`` (``NETWORK_ISLAND_MODES``
        with ``channels``).

        Parameters
        ----------
        help_template : str
            What the choices do in this algorithm, already translated, naming them ``{pass_through}`` and
            ``{ignore}`` (and ``{channels}``): the help then names them exactly as the drop-down does, in every
            language.
        name : str
            Parameter name.
        channels : bool
            Offer the third choice, channels on both sides of the large islands (networks).
        """
        pass_through, ignore = self.tr("Pass through the main channel"), self.tr("Ignore islands")
        choices = [pass_through, ignore]
        if channels:
            choices.append(self.tr("Channels on both sides of large islands"))
        self.add_optional_parameter(
            QgsProcessingParameterEnum(name, self.tr("Islands (holes)"), choices, defaultValue=0),
            help_template.format(pass_through=pass_through, ignore=ignore, channels=choices[-1]),
        )

    def add_connect_touching_parameter(self):
        """Add ``CONNECT_TOUCHING`` (gates between touching features)."""
        self.add_optional_parameter(
            QgsProcessingParameterBoolean(
                self.CONNECT_TOUCHING, self.tr("Connect features that share a boundary"), False
            ),
            self.tr(
                "Where two polygons of the layer share a stretch of boundary (a river cut into reaches, water or "
                "road-area pieces), the middle of that stretch becomes an end of both, so their lines meet there "
                "exactly (and, in a network, share the node id). A polygon with one such gate gets its other "
                "end(s) automatically."
            ),
        )

    def add_m_parameter(self):
        """Add ``ADD_M`` (store the local width as M value)."""
        self.add_optional_parameter(
            QgsProcessingParameterBoolean(self.ADD_M, self.tr("Store the local width as M value"), True),
            self.tr(
                "Write the incircle diameter (local width, layer units or metres) as M value of each vertex.",
            ),
        )

    def centerline_output_help(self):
        """Return the help of the centerline output: the fields it writes, translated."""
        raise NotImplementedError

    def add_result_parameters(self):
        """Add ``ADD_M``, the four output layers, ``TRANSECT_INTERVAL`` and the two count outputs."""
        self.add_m_parameter()
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.OUTPUT,
                self.centerline_output_name(),
                ProcessingSourceType.VectorLine,
            ),
            self.centerline_output_help(),
        )
        optional_layers = (
            (
                self.OUTPUT_VERTICES,
                self.tr("Centerline vertices"),
                ProcessingSourceType.VectorPoint,
                self.tr("Optional point layer: every centerline vertex with its chainage, incircle radius and width."),
            ),
            (
                self.OUTPUT_CIRCLES,
                self.tr("Incircles"),
                ProcessingSourceType.VectorPolygon,
                self.tr("Optional polygon layer: the incircle of every vertex, with its radius and chainage."),
            ),
            (
                self.OUTPUT_TRANSECTS,
                self.tr("Transects"),
                ProcessingSourceType.VectorLine,
                self.tr(
                    "Optional line layer: cross-sections from bank to bank through the centerline, one every "
                    "'Distance between transects', with their width and chainage.",
                ),
            ),
        )
        for name, description, layer_type, help_text in optional_layers:
            self.add_parameter(
                QgsProcessingParameterFeatureSink(name, description, layer_type, optional=True, createByDefault=False),
                help_text,
            )
        self.add_length_parameter(
            self.TRANSECT_INTERVAL,
            self.tr("Distance between transects (0 = mean width)"),
            0.0,
            self.tr(
                "Distance along the centerline between two transects, layer units (metres for a layer in "
                "degrees); 0 uses the mean width of each centerline.",
            ),
            advanced=True,
        )
        self.add_count_outputs(self.tr("Number of centerlines"), self.tr("Number of centerline features written."))

    def add_count_outputs(self, description, help_text):
        """Declare ``CENTERLINE_COUNT`` (features written, described as given) and ``SKIPPED_COUNT``."""
        self.add_output(QgsProcessingOutputNumber(self.CENTERLINE_COUNT, description), help_text)
        self.add_output(
            QgsProcessingOutputNumber(self.SKIPPED_COUNT, self.tr("Number of skipped features")),
            self.tr("Number of input features (or parts) skipped with a warning."),
        )
