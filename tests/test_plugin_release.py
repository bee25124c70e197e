"""Release packaging and translations: the zip users install, and the Polish user interface."""

import ast
import configparser
import html
import json
import re
import string
import subprocess
import sys
import urllib.parse
import zipfile

import pytest
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


@pytest.fixture(scope="module")
def release_zip(tmp_path_factory):
    """The release zip ``make package`` builds, and the folder it is extracted to."""
    folder = tmp_path_factory.mktemp("release")
    subprocess.run(["make", "-s", "package", f"DIST={folder}"], cwd=REPOSITORY, check=True, capture_output=True)
    archive = folder / "{}-{}.zip".format(PLUGIN_NAME, metadata()["version"])
    extracted = folder / "extracted"
    with zipfile.ZipFile(archive) as release:
        release.extractall(extracted)
    return archive, extracted


#: What the QGIS plugin repository requires of ``metadata.txt`` (its upload validator), and its yes/no fields.
REQUIRED_METADATA = ("name", "description", "version", "qgisMinimumVersion", "author", "email", "about", "tracker")
REQUIRED_METADATA += ("repository",)
BOOLEAN_METADATA = ("experimental", "deprecated", "server", "supportsQt6")
#: File types the repository's scan treats as executables or compiled code.
SUSPICIOUS_SUFFIXES = (".pyc", ".pyo", ".exe", ".dll", ".so", ".dylib", ".bat", ".sh", ".ps1", ".cmd")


def test_release_zip_passes_the_plugin_repository_upload_rules(release_zip):
    """The rules of the repository's upload validator and its file analysis: size, paths, one PEP 8 top folder
    with ``__init__.py``, ``metadata.txt`` and ``LICENSE``, the required metadata, yes/no fields, real URLs, the
    icon; no compiled, executable, hidden or cache files."""
    archive, _ = release_zip
    assert archive.stat().st_size <= 25_000_000
    with zipfile.ZipFile(archive) as release:
        assert release.testzip() is None
        infos = release.infolist()
        names = [info.filename for info in infos]
        packaged = configparser.ConfigParser(interpolation=None)
        packaged.optionxform = str
        packaged.read_string(release.read(f"{PLUGIN_NAME}/metadata.txt").decode("utf-8"))
        general = packaged["general"]
        assert f"{PLUGIN_NAME}/{general['icon']}" in names
    assert PLUGIN_NAME.isidentifier() and re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]+", PLUGIN_NAME)
    for required in ("__init__.py", "metadata.txt", "LICENSE"):
        assert f"{PLUGIN_NAME}/{required}" in names, required
    for info in infos:
        parts = info.filename.split("/")
        assert parts[0] == PLUGIN_NAME and ".." not in parts and not info.filename.startswith("/"), info.filename
        assert not {"__MACOSX", ".git", "__pycache__"} & set(parts), info.filename
        assert not any(part.startswith(".") for part in parts), f"hidden file {info.filename}"
        assert not info.filename.lower().endswith(SUSPICIOUS_SUFFIXES), info.filename
        assert not (info.external_attr >> 16) & 0o111 or info.is_dir(), f"executable {info.filename}"
    for field in REQUIRED_METADATA:
        assert general.get(field, "").strip(), field
    for field in BOOLEAN_METADATA:
        assert general[field].strip().lower() in ("true", "false", "1", "0"), field
    assert "/" not in general["author"]
    for field in ("tracker", "repository", "homepage"):
        address = urllib.parse.urlparse(general[field])
        assert address.scheme == "https" and address.netloc, field


def bandit_findings(folder):
    """Bandit's findings over ``folder``, every one of its tests enabled (the repository enables nearly all)."""
    scan = subprocess.run(
        [sys.executable, "-m", "bandit", "-r", str(folder), "-f", "json", "-q"],
        capture_output=True,
        text=True,
        check=False,
    )
    report = json.loads(scan.stdout)
    assert not report["errors"], report["errors"]
    return [
        f"{item['test_id']} {item['filename']}:{item['line_number']} {item['issue_text']}" for item in report["results"]
    ]


def secrets_found(folder):
    """detect-secrets' findings over ``folder``, run as the repository runs it (every file, metadata.txt left out)."""
    scan = subprocess.run(
        [sys.executable, "-m", "detect_secrets", "scan", "--all-files", "--exclude-files", r"metadata\.txt", "."],
        cwd=folder,
        capture_output=True,
        text=True,
        check=True,
    )
    results = json.loads(scan.stdout)["results"]
    return [f"{name}:{item['line_number']} {item['type']}" for name, items in results.items() for item in items]


def test_the_security_scans_find_what_they_look_for(tmp_path):
    """Both scanners run and report: an ``eval`` of input and a hard-coded password, an AWS-style access key."""
    (tmp_path / "bad.py").write_text(
        'password = "correct horse battery"\nprint(eval(input()))\nKEY = "AKIA' + "IOSFODNN7" + 'EXAMPLE"\n'
    )
    assert {finding.split()[0] for finding in bandit_findings(tmp_path)} >= {"B105", "B307"}
    assert any("AWS Access Key" in finding for finding in secrets_found(tmp_path))


def test_release_zip_passes_the_plugin_repository_security_scan(release_zip):
    """Bandit and detect-secrets, which block a version on the repository at any finding, find nothing."""
    _, extracted = release_zip
    assert bandit_findings(extracted) == []
    assert secrets_found(extracted) == []


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
