"""The plugin as QGIS sees it: loading through classFactory, version range, metadata, provider, help."""

import re
from pathlib import Path

from qgis.core import Qgis, QgsApplication, QgsProcessingModelAlgorithm
from qgis.PyQt.QtCore import QCoreApplication, QTranslator

from tests.support.project import REPOSITORY, metadata, version_number

#: Fields plugins.qgis.org refuses a plugin without, and the ones this project promises.
REQUIRED_FIELDS = (
    "name",
    "qgisMinimumVersion",
    "description",
    "about",
    "version",
    "author",
    "email",
    "repository",
)
PROMISED_FIELDS = ("tracker", "homepage", "license", "tags", "icon", "experimental", "hasProcessingProvider")


def test_metadata_has_every_field_the_repository_requires():
    general = metadata()
    missing = [field for field in REQUIRED_FIELDS + PROMISED_FIELDS if not general.get(field, "").strip()]
    assert missing == []
    assert re.fullmatch(r"\d+\.\d+\.\d+", general["version"])
    assert general["qgisMinimumVersion"] == "3.22"
    assert general["qgisMaximumVersion"] == "4.99"
    assert general["hasProcessingProvider"] == "yes"
    assert general["repository"].startswith("https://")
    # QGIS 4 loads a plugin whose maximum is 4.0 or more; the Qt 6 builds of QGIS 3.x read supportsQt6.
    assert general["supportsQt6"] == "True"


def test_metadata_icon_and_licence_exist():
    from conftest import REPOSITORY

    assert (REPOSITORY / metadata()["icon"]).is_file()
    assert (REPOSITORY / "LICENSE").is_file()


def test_running_qgis_lies_within_the_metadata_range(loaded_plugin, monkeypatch):
    monkeypatch.syspath_prepend(str(Path(QgsApplication.pkgDataPath()) / "python"))
    from pyplugin_installer.version_compare import isCompatible, pyQgisVersion

    general = metadata()
    running = Qgis.QGIS_VERSION_INT
    assert version_number(general["qgisMinimumVersion"]) <= running
    assert running <= version_number(general["qgisMaximumVersion"]) + 99
    # the check the QGIS plugin manager itself applies
    assert isCompatible(pyQgisVersion(), general["qgisMinimumVersion"], general["qgisMaximumVersion"])


def test_class_factory_plugin_registers_and_removes_the_provider(loaded_plugin):
    import qgis.utils

    registry = QgsApplication.processingRegistry()
    assert "incircu" in qgis.utils.active_plugins
    assert registry.providerById("incircu") is loaded_plugin.provider
    loaded_plugin.unload()
    assert registry.providerById("incircu") is None
    loaded_plugin.initProcessing()
    assert registry.providerById("incircu") is not None


def own_algorithms(provider):
    """The provider's algorithms but the example models."""
    return [algorithm for algorithm in provider.algorithms() if not isinstance(algorithm, QgsProcessingModelAlgorithm)]


def test_provider_identity(provider):
    assert provider.id() == "incircu"
    assert provider.name() == "IncirCu"
    assert provider.versionInfo() == metadata()["version"]
    assert not provider.icon().isNull()
    ids = sorted(
        algorithm.id() for algorithm in provider.algorithms() if not isinstance(algorithm, QgsProcessingModelAlgorithm)
    )
    assert ids == [
        "incircu:labellines",
        "incircu:linescenterline",
        "incircu:polygoncenterline",
        "incircu:polygonnetwork",
    ]
    examples = sorted(
        algorithm.displayName()
        for algorithm in provider.algorithms()
        if isinstance(algorithm, QgsProcessingModelAlgorithm)
    )
    assert examples == ["Reservoir centerlines with guides", "River widths"]


def test_algorithms_document_every_parameter(provider):
    registry = QgsApplication.processingRegistry()
    for algorithm_id in (
        "incircu:polygoncenterline",
        "incircu:linescenterline",
        "incircu:polygonnetwork",
        "incircu:labellines",
    ):
        algorithm = registry.algorithmById(algorithm_id)
        assert algorithm.group() == "Centerlines"
        assert algorithm.shortHelpString()
        assert algorithm.tags()
        help_html = algorithm.helpString()
        for parameter in algorithm.parameterDefinitions():
            assert parameter.description() in help_html, parameter.name()
        for output in algorithm.outputDefinitions():
            assert output.description() in help_html, output.name()
        assert not algorithm.icon().isNull()


def test_public_parameter_names(provider):
    registry = QgsApplication.processingRegistry()
    polygon = registry.algorithmById("incircu:polygoncenterline")
    lines = registry.algorithmById("incircu:linescenterline")
    common = {
        "TOLERANCE",
        "SPACING",
        "ADD_M",
        "OUTPUT",
        "OUTPUT_VERTICES",
        "OUTPUT_CIRCLES",
        "OUTPUT_TRANSECTS",
        "TRANSECT_INTERVAL",
        "TRANSECT_STYLE",
        "END_CAP",
    }
    assert {p.name() for p in polygon.parameterDefinitions()} == common | {
        "INPUT",
        "SPLIT_POINTS",
        "SNAP_TOLERANCE",
        "ISLANDS",
        "END_RULE",
        "GUIDE_LINES",
        "SEPARATE_PARTS",
        "CONNECT_TOUCHING",
    }
    assert {p.name() for p in lines.parameterDefinitions()} == common | {
        "LINES_A",
        "LINES_B",
        "PAIR_FIELD_A",
        "PAIR_FIELD_B",
    }
    for algorithm in (polygon, lines):
        assert {o.name() for o in algorithm.outputDefinitions()} >= {"OUTPUT", "CENTERLINE_COUNT", "SKIPPED_COUNT"}
    assert (
        polygon.parameterDefinition("SPLIT_POINTS").flags()
        & polygon.parameterDefinition("SPLIT_POINTS").Flag.FlagOptional
    )


def test_help_button_opens_the_algorithms_section_of_the_shipped_page(provider):
    from incircu.algorithms.help_page import HELP_FILE
    from qgis.PyQt.QtCore import QUrl

    text = HELP_FILE.read_text(encoding="utf-8")
    readme = (REPOSITORY / "README.md").read_text(encoding="utf-8")
    for algorithm in provider.algorithms():
        if isinstance(algorithm, QgsProcessingModelAlgorithm):
            continue
        address, _, anchor = algorithm.helpUrl().partition("#")
        url = QUrl(address)
        assert url.isLocalFile() and url.toLocalFile() == str(HELP_FILE), "offline: a page shipped in the plugin"
        assert f'<section id="{anchor}"><h2>{algorithm.displayName()}</h2>' in text
        # the README's section carries the name the toolbox shows
        assert f"### {algorithm.displayName()} — `{algorithm.id()}`" in readme.splitlines()
        assert algorithm.shortDescription().endswith(".")


def test_the_shipped_help_page_is_up_to_date(provider):
    from incircu.algorithms.help_page import HELP_FILE, page

    assert HELP_FILE.read_text(encoding="utf-8") == page(provider.algorithms()), "run `make help-page`"


def test_help_says_what_a_term_means_before_using_it(provider):
    from incircu.algorithms.help_page import HELP_FILE

    text = HELP_FILE.read_text(encoding="utf-8")
    words = text.index("<h2>Words used here</h2>")
    for term in ("medial axis", "chain", "incircle", "chainage", "transect"):
        assert text.lower().index(term) > words, term
    for algorithm in provider.algorithms():
        help_text = algorithm.shortHelpString().lower()
        if "medial axis" in help_text:
            before = help_text[: help_text.index("medial axis")]
            assert "centre" in before and "circle" in before, algorithm.id()
    for spelling in ("meters", "center", "centers"):
        assert not re.search(rf"\b{spelling}\b", text), spelling
        assert "IncirCu" not in algorithm.displayName()


def test_metadata_names_every_algorithm_the_provider_registers(provider):
    about = metadata()["about"]
    names = [
        algorithm.displayName()
        for algorithm in provider.algorithms()
        if not isinstance(algorithm, QgsProcessingModelAlgorithm)
    ]
    count = {2: "two", 3: "three", 4: "four", 5: "five"}[len(names)]
    assert f"adds {count} Processing algorithms" in about
    for name in names:
        assert f'"{name}"' in about, name


def test_every_algorithm_has_its_own_icon(provider):
    from conftest import REPOSITORY

    icons = [Path(algorithm.svgIconPath()) for algorithm in own_algorithms(provider)]
    assert all(icon.is_file() and icon.parent == REPOSITORY / "icons" for icon in icons)
    assert len(set(icons)) == len(icons) and Path(provider.svgIconPath()) not in icons


def test_dialog_help_panel_lists_every_parameter_and_output_with_its_help(provider):
    for algorithm in own_algorithms(provider):
        panel = algorithm.shortHelpString()
        assert panel.startswith(algorithm.summary())
        definitions = list(algorithm.parameterDefinitions()) + list(algorithm.outputDefinitions())
        for definition in definitions:
            help_text = algorithm.parameter_help[definition.name()]
            assert f"<b>{definition.description()}</b>: {help_text}" in panel, definition.name()
        assert algorithm.summary() in algorithm.helpString()


def test_enum_help_names_the_choices_as_the_drop_down_does(provider):
    for algorithm in own_algorithms(provider):
        for definition in algorithm.parameterDefinitions():
            if definition.type() == "enum":
                for option in definition.options():
                    assert f"{option}:" in definition.help(), (algorithm.id(), option)


#: The island choices translated, as by a translation whose help strings lag behind.
ISLAND_CHOICES = {
    "Pass through the main channel": "Main-channel route",
    "Ignore islands": "Islands dropped",
    "Channels on both sides of large islands": "Braided",
}


class ChoiceTranslator(QTranslator):
    """Translates only the island choices (:data:`ISLAND_CHOICES`)."""

    def translate(self, context, source, disambiguation=None, n=-1):
        return ISLAND_CHOICES.get(source)  # None: untranslated (an empty string would be a translation)

    def isEmpty(self):
        return False


def test_island_help_follows_the_translated_choices(provider):
    registry = QgsApplication.processingRegistry()
    translator = ChoiceTranslator()
    QCoreApplication.installTranslator(translator)
    try:
        for algorithm_id in ("incircu:polygoncenterline", "incircu:polygonnetwork"):
            algorithm = registry.createAlgorithmById(algorithm_id)
            islands = algorithm.parameterDefinition("ISLANDS")
            # The network has the third choice, channels on both sides of large islands.
            count = 3 if algorithm_id == "incircu:polygonnetwork" else 2
            assert islands.options() == list(ISLAND_CHOICES.values())[:count]
            for option in islands.options():
                assert f"{option}:" in islands.help(), (algorithm_id, option)
    finally:
        QCoreApplication.removeTranslator(translator)


def test_output_help_lists_the_fields_written(provider):
    from incircu.algorithms.network_outputs import BRANCH_FIELDS
    from incircu.algorithms.outputs import CENTERLINE_FIELDS

    registry = QgsApplication.processingRegistry()
    for algorithm_id, fields in (
        ("incircu:polygoncenterline", CENTERLINE_FIELDS),
        ("incircu:linescenterline", CENTERLINE_FIELDS),
        ("incircu:polygonnetwork", BRANCH_FIELDS),
    ):
        help_text = registry.algorithmById(algorithm_id).parameterDefinition("OUTPUT").help()
        for name in ["source_fid"] + [name for name, _ in fields]:
            assert re.search(rf"\b{name}\b", help_text), (algorithm_id, name)
    lines_help = registry.algorithmById("incircu:linescenterline").parameterDefinition("OUTPUT").help()
    assert "polygon's" not in lines_help


def test_help_names_parameters_by_their_dialog_labels(provider):
    registry = QgsApplication.processingRegistry()
    for algorithm_id in ("incircu:polygoncenterline", "incircu:linescenterline"):
        algorithm = registry.algorithmById(algorithm_id)
        names = [definition.name() for definition in algorithm.parameterDefinitions()]
        texts = [algorithm.shortHelpString(), algorithm.helpString()]
        texts += [definition.help() for definition in algorithm.parameterDefinitions()]
        for text in texts:
            used = [name for name in names if re.search(rf"\b{name}\b", text)]
            assert used == [], (used, text)


def test_distances_carry_the_unit_of_the_input_layer(provider):
    from incircu.algorithms.compat import ProcessingParameterFlag

    registry = QgsApplication.processingRegistry()
    for algorithm_id, layer, distances in (
        ("incircu:polygoncenterline", "INPUT", ("SNAP_TOLERANCE", "TOLERANCE", "SPACING", "TRANSECT_INTERVAL")),
        ("incircu:linescenterline", "LINES_A", ("TOLERANCE", "SPACING", "TRANSECT_INTERVAL")),
        ("incircu:polygonnetwork", "INPUT", ("SNAP_TOLERANCE", "TOLERANCE", "SPACING")),
    ):
        algorithm = registry.algorithmById(algorithm_id)
        for name in distances:
            definition = algorithm.parameterDefinition(name)
            assert definition.type() == "distance", name
            assert definition.parentParameterName() == layer, name
            assert definition.minimum() == 0.0
            assert definition.defaultValue() is not None
            assert not definition.flags() & ProcessingParameterFlag.Optional, "a length always has a value"
