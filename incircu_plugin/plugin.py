"""The QGIS plugin object: registers the IncirCu Processing provider and its translations."""

from pathlib import Path

from qgis.core import QgsApplication, QgsSettings
from qgis.PyQt.QtCore import QCoreApplication, QLocale, QTranslator

from .provider import IncirCuProvider

I18N_FOLDER = Path(__file__).resolve().parent.parent / "i18n"


def user_locale():
    """Return the two-letter code of the language QGIS runs in (``locale/userLocale``, else the system's)."""
    return str(QgsSettings().value("locale/userLocale", "") or QLocale.system().name())[:2]


class IncirCuPlugin:
    """Plugin object created by ``classFactory``; ``iface`` is only used from ``initGui``."""

    def __init__(self, iface):
        self.iface = iface
        self.provider = None
        self.translator = QTranslator()
        if self.translator.load(str(I18N_FOLDER / f"incircu_{user_locale()}.qm")):
            QCoreApplication.installTranslator(self.translator)

    def initProcessing(self):
        """Register the Processing provider (called by QGIS, also under ``qgis_process``)."""
        if self.provider is None:
            self.provider = IncirCuProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)
            # The example models find their IncirCu steps only once the provider is registered.
            self.provider.refreshAlgorithms()

    def initGui(self):
        """Desktop start-up: the toolbox entries and the IncirCu expression functions."""
        from ..algorithms.expressions import register_functions

        self.initProcessing()
        register_functions()

    def unload(self):
        """Remove the provider, the expression functions and the translator."""
        from ..algorithms.expressions import unregister_functions

        unregister_functions()
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
        QCoreApplication.removeTranslator(self.translator)
