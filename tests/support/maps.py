"""Maps drawn by QGIS itself (offscreen) for the plugin tests: the settings of a picture and its rendering."""

from qgis.core import QgsMapRendererParallelJob, QgsMapSettings
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor


def map_settings(layers, extent, size=(1400, 900)):
    """Map settings drawing ``layers`` (the first on top, in the CRS of the last) over ``extent`` (a
    ``QgsRectangle``) on a white ``size`` pixel picture at 96 dpi."""
    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(layers[-1].crs())
    settings.setOutputSize(QSize(*size))
    settings.setOutputDpi(96)
    settings.setBackgroundColor(QColor("white"))
    settings.setExtent(extent)
    return settings


def render(settings, path=None):
    """Draw the layers of ``settings`` to an image, saved as a PNG at ``path`` if given."""
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage()
    if path is not None:
        assert image.save(str(path))
    return image
