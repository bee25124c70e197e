"""The toolbox dialog of each algorithm, built offscreen and saved as PNG under tests/artifacts/."""

import pytest
from qgis.core import QgsApplication
from qgis.PyQt.QtGui import QImage
from qgis.PyQt.QtWidgets import QApplication


@pytest.mark.parametrize("algorithm_id", ["incircu:polygoncenterline", "incircu:linescenterline"])
def test_toolbox_dialog_renders(provider, artifacts, algorithm_id, qgis_parent, qgis_iface, monkeypatch):
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from qgis.gui import QgsBrowserGuiModel

    browser = QgsBrowserGuiModel()
    monkeypatch.setattr(qgis_iface, "browserModel", lambda: browser, raising=False)

    algorithm = QgsApplication.processingRegistry().createAlgorithmById(algorithm_id)
    dialog = AlgorithmDialog(algorithm, False, qgis_parent)
    dialog.resize(900, 1000)
    dialog.show()
    QApplication.processEvents()
    assert dialog.windowTitle() == algorithm.displayName()
    panel = dialog.mainWidget()
    for parameter in algorithm.parameterDefinitions():
        assert parameter.name() in panel.wrappers, parameter.name()
    path = artifacts / f"dialog_{algorithm.name()}.png"
    assert dialog.grab().save(str(path))
    image = QImage(str(path))
    assert image.width() == dialog.width() and image.height() == dialog.height()
    colours = {image.pixel(x, y) for x in range(0, image.width(), 7) for y in range(0, image.height(), 7)}
    assert len(colours) > 10, "the dialog image is blank"
    dialog.close()
    dialog.deleteLater()
    QApplication.processEvents()
