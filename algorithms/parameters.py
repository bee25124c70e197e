"""The parameters the IncirCu algorithms share, declared with their help text, and the help built from it."""

import html

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterDistance,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingUtils,
    QgsPropertyDefinition,
)

from .compat import DistanceUnit, ProcessingParameterFlag, ProcessingSourceType


def length_parameter(name, description, default, parent_layer, dynamic=False):
    """A non-negative length in the units of ``parent_layer``, or in metres when that layer is in degrees.

    A ``QgsProcessingParameterDistance`` tied to the layer (``qgis_process``, batch dialog and modeler show
    it as QGIS does); the toolbox dialog shows it with :class:`.length_widget.LengthWidgetWrapper`, QGIS's
    distance box with its unit drop-down, which reads a length in metres for a layer in degrees, where QGIS
    would read degrees.

    Parameters
    ----------
    name, description : str
        Parameter name and dialog label.
    default : float
        Default value, layer units (metres for a layer in degrees).
    parent_layer : str
        Name of the layer parameter the length refers to.
    dynamic : bool
        Offer a data-defined override: a value per feature of ``parent_layer`` (an expression or a field).

    Returns
    -------
    QgsProcessingParameterDistance
    """
    parameter = QgsProcessingParameterDistance(name, description, default, parent_layer, False, 0.0)
    parameter.setDefaultUnit(DistanceUnit.Meters)
    parameter.setMetadata({"widget_wrapper": {"class": f"{__package__}.length_widget.LengthWidgetWrapper"}})
    if dynamic:
        parameter.setIsDynamic(True)
        parameter.setDynamicPropertyDefinition(
            QgsPropertyDefinition(name, description, QgsPropertyDefinition.StandardPropertyTemplate.DoublePositive)
        )
        parameter.setDynamicLayerParameterName(parent_layer)
    return parameter


class SharedParameters:
    """Declarations of the parameters and outputs the algorithms share (mixed into :class:`.base.IncirCuAlgorithm`).

    :meth:`add_parameter` also records each parameter's help text; the dialog's help panel
    (``shortHelpString``) shows the summary and then every parameter and output with that text.
    """

    TOLERANCE = "TOLERANCE"
    SPACING = "SPACING"
    ADD_M = "ADD_M"
    TRANSECT_INTERVAL = "TRANSECT_INTERVAL"
    TRANSECT_STYLE = "TRANSECT_STYLE"
    END_CAP = "END_CAP"
    OUTPUT = "OUTPUT"
    OUTPUT_VERTICES = "OUTPUT_VERTICES"
    OUTPUT_CIRCLES = "OUTPUT_CIRCLES"
    OUTPUT_TRANSECTS = "OUTPUT_TRANSECTS"
    CENTERLINE_COUNT = "CENTERLINE_COUNT"
    SKIPPED_COUNT = "SKIPPED_COUNT"
    #: Name of the input layer whose units the length parameters are in (metres when it is in degrees).
    LENGTH_PARENT = ""

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

    def add_length_parameter(self, name, description, default, help_text, advanced=False, dynamic=False):
        """Add a non-negative length with its default, in the units of ``LENGTH_PARENT``.

        The dialog shows the unit next to the box (see :func:`length_parameter`); a layer in
        degrees is computed in metres. Not optional: it always has a value (0 is a choice, "automatic"), and
        a run that leaves it out gets the default.

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
        dynamic : bool
            Offer a data-defined override (a value per feature), read with :func:`.options.read_per_feature`.
        """
        self.add_parameter(
            length_parameter(name, description, default, self.LENGTH_PARENT, dynamic), help_text, advanced
        )

    def add_sampling_parameters(self):
        """Add ``TOLERANCE`` (adaptive sampling, the default) and ``SPACING`` (the paper's fixed sampling)."""
        self.add_length_parameter(
            self.TOLERANCE,
            self.tr("Largest deviation from the exact medial axis (0 = automatic)"),
            0.0,
            dynamic=True,
            help_text=self.tr(
                "Every vertex is the centre of a circle touching both sides; the line of the centres of all such "
                "circles is the exact medial axis. This is the largest distance between the centerline and that "
                "axis, in layer units (metres for a layer in degrees): the line keeps only the vertices it needs to "
                "stay that close, each lying exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the "
                "shape's typical width: the right choice for maps. It may differ per feature (data-defined).",
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

    def add_snap_tolerance_parameter(self, name="SNAP_TOLERANCE"):
        """Add the split point snapping tolerance (layer units or metres)."""
        self.add_length_parameter(
            name,
            self.tr("Split point snapping tolerance"),
            1.0,
            self.tr(
                "Largest distance between a split point and the polygon's exterior ring, layer units "
                "(metres for a layer in degrees); 0 = a millionth of the polygon's size. It may differ per "
                "feature (data-defined)."
            ),
            dynamic=True,
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
        self.add_parameter(
            QgsProcessingParameterEnum(name, self.tr("Islands (holes)"), choices, defaultValue=0),
            help_template.format(pass_through=pass_through, ignore=ignore, channels=choices[-1]),
        )

    def add_connect_touching_parameter(self):
        """Add ``CONNECT_TOUCHING`` (gates between touching features)."""
        self.add_parameter(
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

    def add_end_cap_parameter(self, where):
        """Add ``END_CAP`` (straight run-out or exact axis at each end), its choices in the order of the core's
        ``END_CAPS``.

        Parameters
        ----------
        where : str
            Where this algorithm's line ends, already translated (e.g. "a split point, or for automatic ends
            where that line meets the outline").
        """
        runout, axis = self.tr("Straight run-out (for maps)"), self.tr("Exact medial axis")
        self.add_parameter(
            QgsProcessingParameterEnum(self.END_CAP, self.tr("Line ends"), [runout, axis], defaultValue=0),
            self.tr(
                "How the line reaches its ends where the channel is cut at a slant. {runout}: straight on along "
                "the channel's axis from where the channel is first full width to {where}; its vertices there "
                "are not on the medial axis (their widths are interpolated). {axis}: the exact middle of the "
                "shape, which leaves a slanted end square to it and then bends onto the channel's axis."
            ).format(runout=runout, axis=axis, where=where),
        )

    def add_m_parameter(self):
        """Add ``ADD_M`` (store the local width as M value)."""
        self.add_parameter(
            QgsProcessingParameterBoolean(self.ADD_M, self.tr("Store the local width as M value"), True),
            self.tr(
                "Write the incircle diameter (local width, layer units or metres) as M value of each vertex.",
            ),
        )

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
                    "'Distance between transects', with their width, chainage and method (their 'Transect "
                    "shape': straight or nearest).",
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
                "degrees); 0 uses the mean width of each centerline. It may differ per feature (data-defined).",
            ),
            dynamic=True,
        )
        straight, nearest = self.tr("Straight, square to the centerline"), self.tr("To the nearest bank points")
        self.add_parameter(
            QgsProcessingParameterEnum(
                self.TRANSECT_STYLE, self.tr("Transect shape"), [straight, nearest], defaultValue=0
            ),
            self.tr(
                "{straight}: one straight cross-section square to the centerline's direction, smoothed over "
                "about one width, from where it first meets a bank or island on one side to the other: what is "
                "surveyed in the field; its width is its length, at least the local width (method 'straight'). "
                "{nearest}: from the centerline to the nearest point of each bank, the incircle's diameter; it "
                "bends at the centerline where the banks are not parallel (method 'nearest')."
            ).format(straight=straight, nearest=nearest),
        )
        self.add_count_outputs(self.tr("Number of centerlines"), self.tr("Number of centerline features written."))

    def add_count_outputs(self, description, help_text):
        """Declare ``CENTERLINE_COUNT`` (features written, described as given) and ``SKIPPED_COUNT``."""
        self.add_output(QgsProcessingOutputNumber(self.CENTERLINE_COUNT, description), help_text)
        self.add_output(
            QgsProcessingOutputNumber(self.SKIPPED_COUNT, self.tr("Number of skipped features")),
            self.tr("Number of input features (or parts) skipped with a warning."),
        )
