"""Release packaging and translations: the zip users install, and the Polish user interface."""

import configparser
import subprocess
import sys
import zipfile

from qgis.core import QgsApplication, QgsSettings

from tests.support.project import PLUGIN_NAME, REPOSITORY, metadata


def test_release_zip_layout(tmp_path):
    built = subprocess.run(
        ["make", "-s", "package", f"DIST={tmp_path}"],
        cwd=REPOSITORY,
        capture_output=True,
        text=True,
        check=False,
    )
    assert built.returncode == 0, built.stdout + built.stderr
    archive = tmp_path / "{}-{}.zip".format(PLUGIN_NAME, metadata()["version"])
    with zipfile.ZipFile(archive) as release:
        names = release.namelist()
        packaged_metadata = configparser.ConfigParser(interpolation=None)
        packaged_metadata.read_string(release.read("incircu/metadata.txt").decode("utf-8"))
    assert {name.split("/")[0] for name in names} == {PLUGIN_NAME}
    for required in (
        "metadata.txt",
        "LICENSE",
        "__init__.py",
        "incircu_plugin/plugin.py",
        "incircu_plugin/provider.py",
    ):
        assert f"{PLUGIN_NAME}/{required}" in names, required
    assert f"{PLUGIN_NAME}/i18n/incircu_pl.qm" in names
    assert any(name.startswith("incircu/incircu_plugin/core/") for name in names)
    assert any(name.startswith("incircu/algorithms/") for name in names)
    assert any(name.startswith("incircu/icons/") and name.endswith(".svg") for name in names)
    for excluded in ("/tests/", "__pycache__", ".pyc", "/.ci/", "/benchmarks/", "/scripts/", "/.venv", "Makefile"):
        assert not [name for name in names if excluded in name], excluded
    assert packaged_metadata["general"]["version"] == metadata()["version"]


def test_release_zip_plugin_imports_from_extracted_folder(tmp_path):
    subprocess.run(["make", "-s", "package", f"DIST={tmp_path}"], cwd=REPOSITORY, check=True)
    archive = tmp_path / "{}-{}.zip".format(PLUGIN_NAME, metadata()["version"])
    extracted = tmp_path / "plugins"
    with zipfile.ZipFile(archive) as release:
        release.extractall(extracted)
    probe = subprocess.run(
        [sys.executable, "-c", "import incircu, incircu.incircu_plugin.core as core; print(core.polygon_centerline)"],
        cwd=extracted,
        capture_output=True,
        text=True,
        check=False,
    )
    assert probe.returncode == 0, probe.stderr
    assert (extracted / PLUGIN_NAME / "icons" / "incircu.svg").is_file()


def test_compiled_translations_match_their_sources(tmp_path):
    for source in sorted((REPOSITORY / "i18n").glob("*.ts")):
        compiled = tmp_path / (source.stem + ".qm")
        subprocess.run(["lrelease", "-silent", str(source), "-qm", str(compiled)], check=True)
        assert compiled.read_bytes() == source.with_suffix(".qm").read_bytes(), "run `make transcompile`"


def test_polish_locale_translates_the_toolbox(provider, qgis_iface):
    import qgis.utils

    registry = QgsApplication.processingRegistry()
    algorithm = registry.algorithmById("incircu:polygoncenterline")
    assert algorithm.displayName() == "Centerline of polygons (IncirCu)"
    settings = QgsSettings()
    previous = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "pl_PL")
    try:
        polish_plugin = sys.modules[PLUGIN_NAME].classFactory(qgis.utils.iface)
        try:
            assert algorithm.displayName() == "Linia środkowa poligonów (IncirCu)"
            assert algorithm.group() == "Linie środkowe"
            assert algorithm.shortHelpString().startswith("Wyznacza jedną nierozgałęzioną linię środkową")
            fresh = registry.createAlgorithmById("incircu:polygoncenterline")
            assert fresh.parameterDefinition("SPLIT_POINTS").description() == "Punkty podziału"
            lines = registry.algorithmById("incircu:linescenterline")
            assert lines.displayName() == "Linia środkowa między dwiema liniami (IncirCu)"
        finally:
            polish_plugin.unload()
    finally:
        settings.setValue("locale/userLocale", previous)
    assert algorithm.displayName() == "Centerline of polygons (IncirCu)"
