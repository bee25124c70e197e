"""Release packaging and translations: the zip users install, and the Polish user interface."""

import ast
import configparser
import html
import re
import string
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


def test_packaged_readme_references_only_what_the_zip_holds_or_absolute_addresses(tmp_path):
    subprocess.run(["make", "-s", "package", f"DIST={tmp_path}"], cwd=REPOSITORY, check=True, capture_output=True)
    archive = tmp_path / "{}-{}.zip".format(PLUGIN_NAME, metadata()["version"])
    with zipfile.ZipFile(archive) as release:
        names = set(release.namelist())
        readme = release.read(f"{PLUGIN_NAME}/README.md").decode("utf-8")
    targets = re.findall(r"!?\[[^\]]*\]\(([^)\s]+)\)", readme)
    assert any(target.endswith("scripts/demo.png") for target in targets)
    for target in targets:
        if re.match(r"^(https?:|mailto:|#)", target):
            continue
        assert f"{PLUGIN_NAME}/{target.split('#')[0]}" in names, target
    repository = metadata()["repository"]
    assert f"{repository}/raw/main/scripts/demo.png" in targets


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


def translatable_literals(path):
    """The texts given to ``tr(text)``, ``translate(context, text)`` and ``QT_TRANSLATE_NOOP(context, text)`` (the
    core's messages) in a Python file, read with ``ast``."""
    texts = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and isinstance(node.func, (ast.Attribute, ast.Name)):
            called = node.func.attr if isinstance(node.func, ast.Attribute) else node.func.id
            position = {"tr": 0, "translate": 1, "QT_TRANSLATE_NOOP": 1}.get(called)
            if position is not None and len(node.args) > position:
                text = node.args[position]
                if isinstance(text, ast.Constant) and isinstance(text.value, str):
                    texts.add(text.value)
    return texts


#: The files ``make transup`` reads: the plugin, its algorithms and the core's messages.
TRANSLATED_SOURCES = [
    REPOSITORY / "incircu_plugin" / "plugin.py",
    REPOSITORY / "incircu_plugin" / "provider.py",
    REPOSITORY / "incircu_plugin" / "core" / "errors.py",
    *sorted((REPOSITORY / "algorithms").glob("*.py")),
]


def polish_messages(context):
    """The messages of ``context`` in ``i18n/incircu_pl.ts``: source -> (translation, finished)."""
    text = (REPOSITORY / "i18n" / "incircu_pl.ts").read_text(encoding="utf-8")
    block = re.search(rf"<context>\s*<name>{context}</name>(.*?)</context>", text, re.DOTALL)
    assert block, context
    found = re.findall(
        r"<source>(.*?)</source>\s*<translation( type=\"unfinished\")?>(.*?)</translation>", block.group(1), re.DOTALL
    )
    return {
        html.unescape(source): (html.unescape(translation), not unfinished) for source, unfinished, translation in found
    }


def fields(template):
    """The names of the ``str.format`` fields of ``template``."""
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def test_every_core_message_code_has_polish_text():
    from incircu_plugin.core.errors import CONTEXT, MESSAGES

    polish = polish_messages(CONTEXT)
    for code, template in MESSAGES.items():
        assert template in polish, f"no Polish for the core message {code!r}: run `make transup`"
        translation, finished = polish[template]
        assert finished and translation, code
        assert fields(translation) <= fields(template), f"{code}: the Polish names a value the message has not"


def test_a_core_error_reads_in_polish_with_qgis_polish_tool_name(provider, qgis_iface):
    import processing
    import qgis.utils
    from qgis.core import QgsProcessingFeedback
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    class Warnings(QgsProcessingFeedback):
        def __init__(self):
            super().__init__()
            self.warnings = []

        def pushWarning(self, message):
            self.warnings.append(message)

    settings = QgsSettings()
    previous = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "pl_PL")
    qgis_polish = QTranslator()
    assert qgis_polish.load("qgis_pl", QgsApplication.i18nPath()), "QGIS's Polish translation is installed with QGIS"
    QCoreApplication.installTranslator(qgis_polish)
    try:
        polish_plugin = sys.modules[PLUGIN_NAME].classFactory(qgis.utils.iface)
        try:
            feedback = Warnings()
            processing.run(
                "incircu:polygoncenterline",
                {"INPUT": str(REPOSITORY / "tests" / "data" / "bad_polygons_2180.geojson"), "OUTPUT": "memory:"},
                feedback=feedback,
            )
        finally:
            polish_plugin.unload()
    finally:
        QCoreApplication.removeTranslator(qgis_polish)
        settings.setValue("locale/userLocale", previous)
    invalid = [warning for warning in feedback.warnings if "Napraw geometrie" in warning]
    assert invalid, feedback.warnings
    assert invalid[0].startswith("Obiekt ") and "Poligon jest nieprawidłowy" in invalid[0], invalid[0]
    assert not any("The polygon" in warning or "split point" in warning for warning in feedback.warnings)


def test_every_translatable_string_has_its_polish_translation(tmp_path):
    """``pylupdate5`` over the files ``make transup`` reads finds exactly the messages of ``i18n/incircu_pl.ts``
    (no string added, changed or mis-read since the last ``make transup``), every text the code translates is
    one of them (a call ``pylupdate5`` cannot read is not skipped silently), and each one is translated."""
    committed = REPOSITORY / "i18n" / "incircu_pl.ts"
    fresh = tmp_path / committed.name
    fresh.write_bytes(committed.read_bytes())
    sources = TRANSLATED_SOURCES
    subprocess.run(["pylupdate5", "-noobsolete", *map(str, sources), "-ts", str(fresh)], check=True)

    def messages(path):
        text = path.read_text(encoding="utf-8")
        found = re.findall(r"<source>(.*?)</source>\s*<translation( type=\"unfinished\")?>", text, re.DOTALL)
        return [(html.unescape(source), unfinished) for source, unfinished in found]

    assert sorted(source for source, _ in messages(fresh)) == sorted(source for source, _ in messages(committed)), (
        "run `make transup`"
    )
    in_code = set().union(*map(translatable_literals, sources))
    assert in_code - {source for source, _ in messages(committed)} == set()
    assert [source for source, unfinished in messages(committed) if unfinished] == []


def test_polish_locale_translates_the_toolbox(provider, qgis_iface):
    import qgis.utils

    registry = QgsApplication.processingRegistry()
    algorithm = registry.algorithmById("incircu:polygoncenterline")
    assert algorithm.displayName() == "Centerline of polygons"
    settings = QgsSettings()
    previous = settings.value("locale/userLocale", "")
    settings.setValue("locale/userLocale", "pl_PL")
    try:
        polish_plugin = sys.modules[PLUGIN_NAME].classFactory(qgis.utils.iface)
        try:
            assert algorithm.displayName() == "Linia środkowa poligonów"
            assert algorithm.group() == "Linie środkowe"
            assert algorithm.shortHelpString().startswith("Wyznacza jedną nierozgałęzioną linię środkową")
            fresh = registry.createAlgorithmById("incircu:polygoncenterline")
            assert fresh.parameterDefinition("SPLIT_POINTS").description() == "Punkty podziału"
            lines = registry.algorithmById("incircu:linescenterline")
            assert lines.displayName() == "Linia środkowa między dwiema liniami"
        finally:
            polish_plugin.unload()
    finally:
        settings.setValue("locale/userLocale", previous)
    assert algorithm.displayName() == "Centerline of polygons"
