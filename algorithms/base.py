"""Base class of the IncirCu algorithms: the run's frame, translation, instances, icon and output names."""

from pathlib import Path

from qgis.core import QgsProcessingAlgorithm
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from .help_page import anchor, help_url
from .parameters import SharedParameters
from .running import FeatureRun
from .styles import CENTERLINE, INCIRCLES, TRANSECTS, VERTICES

PLUGIN_FOLDER = Path(__file__).resolve().parent.parent
ICON_PATH = PLUGIN_FOLDER / "icons"


class IncirCuAlgorithm(SharedParameters, QgsProcessingAlgorithm):
    """Common behaviour of the IncirCu Processing algorithms.

    Subclasses define ``name``, ``displayName``, ``shortDescription``, ``summary``, ``centerline_output_name``,
    ``initAlgorithm`` and ``LENGTH_PARENT``; ``read_options`` (every parameter, read once into a frozen options
    object), ``open_writer`` (the output sinks) and ``process_features`` (the feature loop).
    """

    #: File name of the algorithm's icon under ``icons/``.
    ICON = "incircu.svg"

    def __init__(self):
        super().__init__()
        self.parameter_help = {}

    def processAlgorithm(self, parameters, context, feedback):
        """Read the parameters, open the outputs, run the features; close every output whatever happens."""
        run = FeatureRun(self, context, feedback)
        try:
            options = self.read_options(parameters, context, run.core)
            writer = self.open_writer(parameters, context, options)
            run.use_writer(writer, writer.crs)
            return self.process_features(run, options)
        finally:
            run.close()

    def read_options(self, parameters, context, core):
        """Return every parameter of the run but the output sinks, read once (a frozen dataclass of
        :mod:`.options`); ``core`` is the geometry core (its choices, in the drop-downs' order)."""
        raise NotImplementedError

    def open_writer(self, parameters, context, options):
        """Create the output sinks; return the writer (``crs``, ``write(feature, parts, frame)``...)."""
        raise NotImplementedError

    def process_features(self, run, options):
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

    def tr(self, text):
        """Translate ``text`` in the context of the class that says it: this class, then its bases
        (``PolygonCenterlineAlgorithm``, ``SharedParameters``...), and last ``IncirCuAlgorithm``."""
        for klass in type(self).__mro__:
            translated = QCoreApplication.translate(klass.__name__, text)
            if translated != text:
                return translated
        return text

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

    def helpUrl(self):
        """Return the section of the help page shipped with the plugin (opens offline)."""
        return help_url(anchor(self))

    def summary(self):
        """Return what the algorithm does, translated: the first paragraph of its help."""
        raise NotImplementedError

    def centerline_output_name(self):
        """Return the label of the centerline output, also the name of the layer it loads as."""
        raise NotImplementedError

    def centerline_output_help(self):
        """Return the help of the centerline output: the fields it writes, translated."""
        raise NotImplementedError

    def output_layer_words(self):
        """Return what each output holds, as its loaded layer's name says it: rank of :mod:`.styles` -> word."""
        return {
            CENTERLINE: self.tr("centerlines"),
            VERTICES: self.tr("vertices"),
            TRANSECTS: self.tr("transects"),
            INCIRCLES: self.tr("incircles"),
        }

    def output_layer_names(self, layer, rule):
        """Return the names of the loaded output layers and of their run's group: the input layer's name
        ``layer``, what the layer holds and the ``rule`` that decided the lines, if any ("reservoirs —
        centerlines (main stem)").

        Returns
        -------
        tuple of (dict, str)
            Rank of :mod:`.styles` (``CENTERLINE``...) -> layer name, and the group's name (the centerlines').
        """
        template = self.tr("{layer} — {output} ({rule})") if rule else self.tr("{layer} — {output}")
        words = self.output_layer_words()
        names = {rank: template.format(layer=layer, output=word, rule=rule) for rank, word in words.items()}
        return names, names[CENTERLINE]
