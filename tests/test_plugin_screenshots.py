"""Screenshots of IncirCu in a real QGIS (offscreen), one or more per point of issue 42, in ``tests/artifacts/``.

Each test also checks what its picture shows: the toolbox dialog run with the samples' defaults and its log,
the log of a run on every reservoir (no Python warning), the attribute table (rounded values, parts from 1),
the layer tree after two runs, the styles at world scale, a skip reason in Polish, the toolbox with the example
models and the help page. (The styled outputs at street scale and the length boxes are drawn by
``test_plugin_styles.py`` and ``test_plugin_dialogs.py``.)
"""

import sys
import tempfile
import time
import warnings
from pathlib import Path

import pytest
from qgis.core import QgsApplication, QgsProject, QgsSettings, QgsVectorLayer
from qgis.PyQt.QtCore import QCoreApplication, QTranslator, QUrl
from qgis.PyQt.QtWidgets import QApplication, QTextBrowser

from tests.support.project import DATA, PLUGIN_NAME, REPOSITORY

SAMPLES = REPOSITORY / "scripts" / "data"


@pytest.fixture
def dialog_run(provider, qgis_parent, qgis_iface, layer_panel, monkeypatch):
    """Open an algorithm's toolbox dialog, set parameters, press Run and wait; return the dialog on its log."""
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from processing.tools.dataobjects import createContext
    from qgis.gui import QgsBrowserGuiModel

    browser = QgsBrowserGuiModel()
    monkeypatch.setattr(qgis_iface, "browserModel", lambda: browser, raising=False)
    dialogs = []

    def run(algorithm_id, values):
        algorithm = QgsApplication.processingRegistry().createAlgorithmById(algorithm_id)
        dialog = AlgorithmDialog(algorithm, False, qgis_parent)
        dialog.resize(1000, 760)
        dialog.show()
        QApplication.processEvents()
        context = createContext()
        for name, value in values.items():
            dialog.mainWidget().wrappers[name].setParameterValue(value, context)
        dialog.runAlgorithm()
        deadline = time.monotonic() + 120
        while dialog.context is not None and time.monotonic() < deadline:
            QApplication.processEvents()
            time.sleep(0.02)
        assert dialog.context is None, "the run did not finish"
        QApplication.processEvents()
        dialogs.append(dialog)
        return dialog

    yield run
    for dialog in dialogs:
        dialog.close()
        dialog.deleteLater()
    QgsProject.instance().clear()
    QApplication.processEvents()


def layer(path, name):
    """A vector layer added to the project."""
    opened = QgsVectorLayer(str(path), name, "ogr")
    assert opened.isValid(), path
    QgsProject.instance().addMapLayer(opened)
    return opened


def log_text(dialog):
    """The text of the dialog's Log tab (as its "Save log" writes it)."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "log.txt"
        dialog.saveLogToFile(str(path), dialog.LogFormat.FormatPlainText)
        return path.read_text(encoding="utf-8")


def test_a_bank_line_sample_runs_with_the_dialogs_defaults(dialog_run, artifacts):
    QgsProject.instance().clear()
    banks_a, banks_b = (layer(SAMPLES / f"banks_{side}.geojson", f"banks_{side}") for side in "ab")
    dialog = dialog_run("incircu:linescenterline", {"LINES_A": banks_a, "LINES_B": banks_b})
    text = log_text(dialog)
    assert "lines are paired by its values" in text and "'reach'" in text, text
    assert "Number of centerlines: 2; Number of skipped features: 0" in text, text
    assert dialog.grab().save(str(artifacts / "issue42_A_bank_sample_defaults_log.png"))


def test_no_python_warning_on_the_reservoirs(dialog_run, artifacts):
    QgsProject.instance().clear()
    reservoirs = layer(f"{DATA / 'real_rivers_ne_lonlat.geojson'}|geometrytype=Polygon", "reservoirs")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        dialog = dialog_run("incircu:polygoncenterline", {"INPUT": reservoirs})
    text = log_text(dialog)
    assert "Number of skipped features: 0" in text, text
    assert not [str(warning.message) for warning in caught if issubclass(warning.category, RuntimeWarning)]
    assert "Warning" not in text and "Traceback" not in text
    assert dialog.grab().save(str(artifacts / "issue42_B_reservoirs_log_without_warnings.png"))


def test_attribute_table_shows_millimetres_and_parts_from_one(provider, artifacts):
    import processing
    from qgis.core import QgsVectorLayerCache
    from qgis.gui import (
        QgsAttributeTableFilterModel,
        QgsAttributeTableModel,
        QgsAttributeTableView,
        QgsMapCanvas,
    )

    results = processing.run(
        "incircu:polygoncenterline",
        {
            "INPUT": str(DATA / "multipart_2180.geojson"),
            "SEPARATE_PARTS": True,
            "OUTPUT": "memory:",
            "OUTPUT_TRANSECTS": "memory:",
        },
    )
    views = []  # kept until the test ends: each view draws from its model and cache
    for name in ("OUTPUT", "OUTPUT_TRANSECTS"):
        output = results[name]
        for feature in output.getFeatures():
            for field in ("length", "width_mean", "chainage", "width"):
                if output.fields().lookupField(field) >= 0:
                    assert round(feature[field], 3) == feature[field]
        canvas = QgsMapCanvas()
        cache = QgsVectorLayerCache(output, 1000)
        model = QgsAttributeTableModel(cache)
        model.loadLayer()
        filtered = QgsAttributeTableFilterModel(canvas, model)
        view = QgsAttributeTableView()
        view.setModel(filtered)
        view.resize(1000, 260)
        view.show()
        QApplication.processEvents()
        path = artifacts / f"issue42_C_attributes_{name.lower()}.png"
        assert view.grab().save(str(path))
        views.append((view, canvas, cache, model, filtered))
    assert {feature["part"] for feature in results["OUTPUT_TRANSECTS"].getFeatures()} == {1, 2}


def test_layer_tree_keeps_each_run_together_newest_on_top(dialog_run, artifacts):
    from qgis.core import QgsLayerTreeModel
    from qgis.gui import QgsLayerTreeView

    project = QgsProject.instance()
    project.clear()
    reservoirs = layer(DATA / "river_2180.geojson", "reservoirs")
    outputs = {name: "TEMPORARY_OUTPUT" for name in ("OUTPUT", "OUTPUT_TRANSECTS", "OUTPUT_CIRCLES")}
    dialog_run("incircu:polygoncenterline", {"INPUT": reservoirs, **outputs})
    dialog_run("incircu:polygoncenterline", {"INPUT": reservoirs, "END_RULE": 1, **outputs})
    groups = [node.name() for node in project.layerTreeRoot().children()]
    assert groups[:2] == ["reservoirs — centerlines (longest path)", "reservoirs — centerlines (main stem)"], groups
    model = QgsLayerTreeModel(project.layerTreeRoot())
    view = QgsLayerTreeView()
    view.setModel(model)
    view.expandAll()
    view.resize(420, 300)
    view.show()
    QApplication.processEvents()
    assert view.grab().save(str(artifacts / "issue42_D_layer_tree_two_runs.png"))


def test_styles_at_world_scale_leave_the_reservoirs_visible(provider, artifacts, layer_panel):
    from processing.gui.Postprocessing import handleAlgorithmResults
    from processing.tools import dataobjects
    from qgis.core import (
        QgsFillSymbol,
        QgsMapRendererParallelJob,
        QgsMapSettings,
        QgsProcessingFeedback,
        QgsProcessingOutputLayerDefinition,
        QgsRectangle,
        QgsSingleSymbolRenderer,
    )
    from qgis.PyQt.QtCore import QSize
    from qgis.PyQt.QtGui import QColor

    project = QgsProject.instance()
    project.clear()
    reservoirs = layer(f"{DATA / 'real_rivers_ne_lonlat.geojson'}|geometrytype=Polygon", "reservoirs")
    reservoirs.setRenderer(
        QgsSingleSymbolRenderer(QgsFillSymbol.createSimple({"color": "110,160,220", "outline_style": "no"}))
    )
    algorithm = QgsApplication.processingRegistry().createAlgorithmById("incircu:polygoncenterline")
    feedback = QgsProcessingFeedback()
    context = dataobjects.createContext(feedback)
    context.setProject(project)
    parameters = {"INPUT": reservoirs}
    for name in ("OUTPUT", "OUTPUT_VERTICES", "OUTPUT_CIRCLES", "OUTPUT_TRANSECTS"):
        parameters[name] = QgsProcessingOutputLayerDefinition("TEMPORARY_OUTPUT", project)
    results, ok = algorithm.run(parameters, context, feedback)
    assert ok
    assert handleAlgorithmResults(algorithm, context, feedback, parameters=results)
    layers = project.layerTreeRoot().layerOrder()
    shown = []
    for extent, name in (
        (QgsRectangle(-180, -60, 180, 80), "world"),
        (QgsRectangle(30, 45, 60, 61), "volga_and_dnieper"),
        (reservoirs.getFeature(1).geometry().boundingBox().buffered(0.02), "one_reservoir"),
    ):
        settings = QgsMapSettings()
        settings.setLayers(layers)
        settings.setDestinationCrs(reservoirs.crs())
        settings.setOutputSize(QSize(1400, 800))
        settings.setOutputDpi(96)
        settings.setBackgroundColor(QColor("white"))
        settings.setExtent(extent)
        job = QgsMapRendererParallelJob(settings)
        job.start()
        job.waitForFinished()
        image = job.renderedImage()
        assert image.save(str(artifacts / f"issue42_E_styles_{name}.png"))
        visible = [item for item in layers if item.isInScaleRange(settings.scale())]
        shown.append((settings.scale(), {item.customProperty("incircu/rank") for item in visible}))
    world_scale, world_ranks = shown[0]
    assert world_scale > 1e7
    assert 0 not in world_ranks and 3 not in world_ranks, "no vertex dots nor incircles at world scale"


def test_a_skip_reason_reads_in_polish(dialog_run, artifacts, qgis_iface):
    import qgis.utils

    settings = QgsSettings()
    previous = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "pl_PL")
    qgis_polish = QTranslator()
    assert qgis_polish.load("qgis_pl", QgsApplication.i18nPath())
    QCoreApplication.installTranslator(qgis_polish)
    polish_plugin = sys.modules[PLUGIN_NAME].classFactory(qgis.utils.iface)
    try:
        QgsProject.instance().clear()
        bad = layer(DATA / "bad_polygons_2180.geojson", "bad polygons")
        dialog = dialog_run("incircu:polygoncenterline", {"INPUT": bad})
        text = log_text(dialog)
        assert dialog.grab().save(str(artifacts / "issue42_F_polish_skip_reason.png"))
    finally:
        polish_plugin.unload()
        QCoreApplication.removeTranslator(qgis_polish)
        settings.setValue("locale/userLocale", previous)
    assert "Napraw geometrie" in text and "Poligon jest nieprawidłowy" in text, text


def test_toolbox_lists_the_example_models_and_the_help_page_opens(provider, artifacts):
    from incircu.algorithms.help_page import HELP_FILE
    from qgis.gui import QgsProcessingToolboxTreeView

    view = QgsProcessingToolboxTreeView(None, QgsApplication.processingRegistry())
    view.setFilterString("incircu")
    view.expandAll()
    view.resize(420, 360)
    view.show()
    QApplication.processEvents()
    assert view.grab().save(str(artifacts / "issue42_H_toolbox_example_models.png"))
    model = view.model()
    names = []
    stack = [model.index(row, 0) for row in range(model.rowCount())]
    while stack:
        index = stack.pop()
        names.append(index.data())
        stack += [model.index(row, 0, index) for row in range(model.rowCount(index))]
    assert {"Example models", "River widths", "Reservoir centerlines with guides"} <= set(names), names
    browser = QTextBrowser()
    browser.setSource(QUrl.fromLocalFile(str(HELP_FILE)))
    browser.resize(900, 900)
    browser.show()
    QApplication.processEvents()
    assert "Words used here" in browser.toPlainText()
    assert browser.grab().save(str(artifacts / "issue42_H_help_page.png"))
