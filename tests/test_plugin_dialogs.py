"""The toolbox dialog of each algorithm, built offscreen and saved as PNG under tests/artifacts/."""

import pytest
from conftest import REPOSITORY
from qgis.core import QgsApplication, QgsProject, QgsVectorLayer
from qgis.PyQt.QtGui import QImage
from qgis.PyQt.QtWidgets import QApplication, QDialogButtonBox

DATA = REPOSITORY / "tests" / "data"

#: Algorithm, the input layer put in the project (selected by the dialog) and its distance parameters.
DIALOGS = {
    "polygoncenterline": ("river", ("SNAP_TOLERANCE", "TOLERANCE", "SPACING", "TRANSECT_INTERVAL")),
    "linescenterline": ("banks_a", ("TOLERANCE", "SPACING", "TRANSECT_INTERVAL")),
    "polygonnetwork": ("river", ("SNAP_TOLERANCE", "TOLERANCE", "SPACING")),
}


@pytest.fixture
def toolbox_dialog(provider, qgis_parent, qgis_iface, monkeypatch):
    """Build the toolbox dialog of an algorithm with one layer in the project; close it afterwards."""
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from qgis.gui import QgsBrowserGuiModel

    browser = QgsBrowserGuiModel()
    monkeypatch.setattr(qgis_iface, "browserModel", lambda: browser, raising=False)
    dialogs = []

    def build(algorithm_name, layer_file):
        project = QgsProject.instance()
        project.clear()
        project.addMapLayer(QgsVectorLayer(str(DATA / layer_file), layer_file.split(".")[0], "ogr"))
        algorithm = QgsApplication.processingRegistry().createAlgorithmById(f"incircu:{algorithm_name}")
        dialog = AlgorithmDialog(algorithm, False, qgis_parent)
        dialog.resize(900, 1000)
        dialog.show()
        QApplication.processEvents()
        dialogs.append(dialog)
        return algorithm, dialog

    yield build
    for dialog in dialogs:
        dialog.close()
        dialog.deleteLater()
    QgsProject.instance().clear()
    QApplication.processEvents()


def unit_shown(dialog, name):
    """Return the unit selected in the drop-down next to the box of parameter ``name``, as a list."""
    return [dialog.mainWidget().wrappers[name].unit_box.currentText()]


@pytest.mark.parametrize("algorithm_name", sorted(DIALOGS))
def test_toolbox_dialog_renders_with_help_and_units(toolbox_dialog, artifacts, algorithm_name):
    layer, distances = DIALOGS[algorithm_name]
    algorithm, dialog = toolbox_dialog(algorithm_name, f"{layer}_2180.geojson")
    assert dialog.windowTitle().endswith(algorithm.displayName())  # QGIS 3.40 puts the group first
    panel = dialog.mainWidget()
    for parameter in algorithm.parameterDefinitions():
        assert parameter.name() in panel.wrappers, parameter.name()
    assert dialog.buttonBox().button(QDialogButtonBox.StandardButton.Help) is not None
    for name in distances:
        assert unit_shown(dialog, name) == ["metres"], name
    path = artifacts / f"dialog_{algorithm.name()}.png"
    assert dialog.grab().save(str(path))
    image = QImage(str(path))
    assert image.width() == dialog.width() and image.height() == dialog.height()
    colours = {image.pixel(x, y) for x in range(0, image.width(), 7) for y in range(0, image.height(), 7)}
    assert len(colours) > 10, "the dialog image is blank"


def test_lengths_of_a_layer_in_degrees_are_metres(toolbox_dialog, artifacts):
    _, dialog = toolbox_dialog("polygoncenterline", "river_4326.geojson")
    for name in DIALOGS["polygoncenterline"][1]:
        assert unit_shown(dialog, name) == ["metres"], name
    dialog.mainWidget().wrappers["SNAP_TOLERANCE"].setValue(2.5)
    parameters = dialog.createProcessingParameters()
    assert parameters["SNAP_TOLERANCE"] == 2.5
    assert dialog.grab().save(str(artifacts / "dialog_polygoncenterline_degrees.png"))


def test_batch_dialog_keeps_the_qgis_distance_widget(provider, qgis_parent, qgis_iface, monkeypatch):
    from processing.gui.BatchAlgorithmDialog import BatchAlgorithmDialog
    from processing.gui.wrappers import WidgetWrapper
    from qgis.gui import QgsBrowserGuiModel

    browser = QgsBrowserGuiModel()
    monkeypatch.setattr(qgis_iface, "browserModel", lambda: browser, raising=False)
    algorithm = QgsApplication.processingRegistry().createAlgorithmById("incircu:polygoncenterline")
    dialog = BatchAlgorithmDialog(algorithm, qgis_parent)
    dialog.show()
    QApplication.processEvents()
    wrappers = dialog.mainWidget().wrappers[0]
    snap = next(wrapper for wrapper in wrappers if wrapper.parameterDefinition().name() == "SNAP_TOLERANCE")
    assert not isinstance(snap, WidgetWrapper)
    assert snap.parameterDefinition().type() == "distance"
    dialog.close()
    dialog.deleteLater()
    QApplication.processEvents()


def test_modeler_keeps_the_qgis_distance_widget_with_model_inputs(provider):
    from processing.modeler.ModelerParametersDialog import ModelerParametersDialog
    from qgis.core import QgsProcessingModelAlgorithm
    from qgis.gui import QgsProcessingModelerParameterWidget

    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(DATA / "fix_centerline_smooth.model3"))
    algorithm = QgsApplication.processingRegistry().createAlgorithmById("incircu:polygoncenterline")
    dialog = ModelerParametersDialog(algorithm, model, "centerline")
    QApplication.processEvents()
    snap = dialog.widget.widget.wrappers["SNAP_TOLERANCE"]
    assert isinstance(snap, QgsProcessingModelerParameterWidget)
    assert snap.value().staticValue() == 1.0
    dialog.close()
    dialog.deleteLater()
    QApplication.processEvents()


def parameter_label(dialog, name):
    """Return the label the dialog shows above parameter ``name`` (QGIS's wrappers and the plugin's alike)."""
    wrapper = dialog.mainWidget().wrappers[name]
    return wrapper.label if hasattr(wrapper, "label") else wrapper.wrappedLabel()


@pytest.mark.parametrize("algorithm_name", sorted(DIALOGS))
def test_length_labels_show_the_help_as_every_other_label(toolbox_dialog, algorithm_name):
    layer, distances = DIALOGS[algorithm_name]
    algorithm, dialog = toolbox_dialog(algorithm_name, f"{layer}_2180.geojson")
    for name in distances:
        definition = algorithm.parameterDefinition(name)
        label = parameter_label(dialog, name)
        assert label.toolTip() == definition.toolTip(), name
        assert definition.help() and definition.help() in label.toolTip(), name
    other = "PAIR_FIELD_A" if algorithm_name == "linescenterline" else "ISLANDS"
    assert parameter_label(dialog, other).toolTip() == algorithm.parameterDefinition(other).toolTip()


@pytest.fixture
def qgis_polish():
    """QGIS's own Polish translation installed in the application (what ``qgis --lang pl`` loads)."""
    from qgis.PyQt.QtCore import QTranslator

    path = QgsApplication.i18nPath()
    translator = QTranslator()
    if not translator.load("qgis_pl", path):
        pytest.skip(f"QGIS's Polish translation is not installed in {path}")
    QApplication.installTranslator(translator)
    yield translator
    QApplication.removeTranslator(translator)


def label_suffix(dialog, name):
    """What the label of parameter ``name`` adds to its description (QGIS's "[optional]")."""
    description = dialog.mainWidget().wrappers[name].parameterDefinition().description()
    return parameter_label(dialog, name).text().replace(description, "").strip()


def test_optional_only_where_a_value_may_be_absent(toolbox_dialog):
    _, dialog = toolbox_dialog("polygoncenterline", "river_2180.geojson")
    for name in ("SPLIT_POINTS", "GUIDE_LINES"):
        assert label_suffix(dialog, name) == "[optional]", name
    for name in (*DIALOGS["polygoncenterline"][1], "ISLANDS", "END_RULE"):
        assert label_suffix(dialog, name) == "", name


def test_polish_labels_say_optional_as_qgis_does(toolbox_dialog, qgis_polish):
    _, dialog = toolbox_dialog("polygoncenterline", "river_2180.geojson")
    optional = label_suffix(dialog, "SPLIT_POINTS")
    assert optional and "[optional]" not in optional, "QGIS's Polish translation gives another suffix"
    assert label_suffix(dialog, "TOLERANCE") == ""


def test_a_length_in_another_unit_is_read_in_the_layers(toolbox_dialog):
    _, dialog = toolbox_dialog("polygoncenterline", "river_2180.geojson")
    wrapper = dialog.mainWidget().wrappers["TRANSECT_INTERVAL"]
    units = [wrapper.unit_box.itemText(index) for index in range(wrapper.unit_box.count())]
    assert units[0] == "metres" and {"kilometres", "feet"} <= set(units)
    wrapper.setValue(0.25)
    wrapper.unit_box.setCurrentIndex(units.index("kilometres"))
    assert dialog.createProcessingParameters()["TRANSECT_INTERVAL"] == pytest.approx(250.0)
    wrapper.unit_box.setCurrentIndex(units.index("feet"))
    assert dialog.createProcessingParameters()["TRANSECT_INTERVAL"] == pytest.approx(0.25 * 0.3048)


def test_tolerances_and_the_transect_interval_take_a_value_per_feature(toolbox_dialog, artifacts):
    from qgis.core import QgsProperty

    algorithm, dialog = toolbox_dialog("polygoncenterline", "river_2180.geojson")
    wrappers = dialog.mainWidget().wrappers
    for name in ("TOLERANCE", "SNAP_TOLERANCE", "TRANSECT_INTERVAL"):
        assert algorithm.parameterDefinition(name).isDynamic(), name
        assert wrappers[name].override is not None, name
        assert wrappers[name].override.vectorLayer() is not None, "the override lists the input's fields"
    assert wrappers["SPACING"].override is None
    wrappers["TRANSECT_INTERVAL"].setValue(QgsProperty.fromField("interval"))
    assert not wrappers["TRANSECT_INTERVAL"].spin_box.isEnabled()
    value = dialog.createProcessingParameters()["TRANSECT_INTERVAL"]
    assert isinstance(value, QgsProperty) and value.field() == "interval"
    assert dialog.grab().save(str(artifacts / "dialog_polygoncenterline_data_defined.png"))


def test_the_transect_interval_is_beside_the_transects_output(provider):
    from incircu.algorithms.compat import ProcessingParameterFlag

    for name in ("polygoncenterline", "linescenterline"):
        algorithm = QgsApplication.processingRegistry().algorithmById(f"incircu:{name}")
        interval = algorithm.parameterDefinition("TRANSECT_INTERVAL")
        assert not interval.flags() & ProcessingParameterFlag.Advanced, name


def test_length_boxes_show_only_the_significant_decimals(toolbox_dialog):
    _, dialog = toolbox_dialog("polygoncenterline", "river_2180.geojson")
    wrappers = dialog.mainWidget().wrappers
    assert wrappers["SNAP_TOLERANCE"].spin_box.text() == "1"
    assert wrappers["TOLERANCE"].spin_box.text() == "0"
    wrappers["SPACING"].setValue(0.125)
    assert wrappers["SPACING"].spin_box.text() == "0.125"
    wrappers["TRANSECT_INTERVAL"].setValue(12.000001)
    assert wrappers["TRANSECT_INTERVAL"].spin_box.text() == "12.000001"
    parameters = dialog.createProcessingParameters()
    assert parameters["SPACING"] == 0.125
    assert parameters["TRANSECT_INTERVAL"] == pytest.approx(12.000001, abs=1e-9)
