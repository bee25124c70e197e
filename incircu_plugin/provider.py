"""The IncirCu Processing provider: id ``incircu``, its icon, version and algorithms."""

import configparser
from pathlib import Path

from qgis.core import QgsProcessingModelAlgorithm, QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

PLUGIN_FOLDER = Path(__file__).resolve().parent.parent
#: The example models the toolbox lists under "Example models" (written by ``scripts/make_sample_data.py``).
MODEL_FOLDER = PLUGIN_FOLDER / "models"


def plugin_metadata():
    """Read ``metadata.txt`` of the plugin folder.

    Returns
    -------
    configparser.SectionProxy
        The ``[general]`` section (``name``, ``version``, ...).
    """
    parser = configparser.ConfigParser(interpolation=None)
    parser.read(PLUGIN_FOLDER / "metadata.txt", encoding="utf-8")
    return parser["general"]


class IncirCuProvider(QgsProcessingProvider):
    """Holds the IncirCu algorithms in the Processing registry."""

    def id(self):
        return "incircu"

    def name(self):
        return "IncirCu"

    def longName(self):
        return f"IncirCu {self.versionInfo()}"

    def icon(self):
        return QIcon(str(PLUGIN_FOLDER / "icons" / "incircu.svg"))

    def svgIconPath(self):
        return str(PLUGIN_FOLDER / "icons" / "incircu.svg")

    def versionInfo(self):
        return plugin_metadata()["version"]

    def loadAlgorithms(self):
        from ..algorithms.label_lines import LabelLinesAlgorithm
        from ..algorithms.lines_centerline import LinesCenterlineAlgorithm
        from ..algorithms.polygon_centerline import PolygonCenterlineAlgorithm
        from ..algorithms.polygon_network import PolygonNetworkAlgorithm

        self.addAlgorithm(PolygonCenterlineAlgorithm())
        self.addAlgorithm(LinesCenterlineAlgorithm())
        self.addAlgorithm(PolygonNetworkAlgorithm())
        self.addAlgorithm(LabelLinesAlgorithm())
        for path in sorted(MODEL_FOLDER.glob("*.model3")):
            model = QgsProcessingModelAlgorithm()
            if model.fromFile(str(path)):
                model.setSourceFilePath(str(path))
                self.addAlgorithm(model)
