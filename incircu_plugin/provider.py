"""The IncirCu Processing provider: id ``incircu``, its icon, version and algorithms."""

import configparser
from pathlib import Path

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

PLUGIN_FOLDER = Path(__file__).resolve().parent.parent


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

    def id(self):  # noqa: A003 - QGIS API name
        return "incircu"

    def name(self):
        return "IncirCu"

    def longName(self):  # noqa: N802 - QGIS API name
        return f"IncirCu {self.versionInfo()}"

    def icon(self):
        return QIcon(str(PLUGIN_FOLDER / "icons" / "incircu.svg"))

    def svgIconPath(self):  # noqa: N802 - QGIS API name
        return str(PLUGIN_FOLDER / "icons" / "incircu.svg")

    def versionInfo(self):  # noqa: N802 - QGIS API name
        return plugin_metadata()["version"]

    def loadAlgorithms(self):  # noqa: N802 - QGIS API name
        from ..algorithms.lines_centerline import LinesCenterlineAlgorithm
        from ..algorithms.polygon_centerline import PolygonCenterlineAlgorithm

        self.addAlgorithm(PolygonCenterlineAlgorithm())
        self.addAlgorithm(LinesCenterlineAlgorithm())
