"""The plugin as QGIS sees it: loading through classFactory, version range, metadata, provider, help."""

import re
from pathlib import Path

from qgis.core import Qgis, QgsApplication

from tests.support.project import metadata, version_number

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
    assert "supportsQt6" not in general


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


def test_provider_identity(provider):
    assert provider.id() == "incircu"
    assert provider.name() == "IncirCu"
    assert provider.versionInfo() == metadata()["version"]
    assert not provider.icon().isNull()
    ids = sorted(algorithm.id() for algorithm in provider.algorithms())
    assert ids == ["incircu:linescenterline", "incircu:polygoncenterline"]


def test_algorithms_document_every_parameter(provider):
    registry = QgsApplication.processingRegistry()
    for algorithm_id in ("incircu:polygoncenterline", "incircu:linescenterline"):
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
        "SPACING",
        "ADD_M",
        "OUTPUT",
        "OUTPUT_VERTICES",
        "OUTPUT_CIRCLES",
        "OUTPUT_TRANSECTS",
        "TRANSECT_INTERVAL",
    }
    assert {p.name() for p in polygon.parameterDefinitions()} == common | {
        "INPUT",
        "SPLIT_POINTS",
        "SNAP_TOLERANCE",
        "ISLANDS",
        "SEPARATE_PARTS",
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
