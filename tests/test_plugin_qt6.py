"""Ready for QGIS 3.40 and QGIS 4 (Qt 6): no PyQt5-only idioms, no enum names QGIS has deprecated.

The scan follows what QGIS's migration script ``scripts/pyqt5_to_pyqt6/pyqt5_to_pyqt6.py`` rewrites: direct
PyQt5 imports, ``exec_()``, ``QVariant`` field types, unscoped Qt enums, and the QGIS enums that moved to
``Qgis`` (``QgsWkbTypes.Type.X`` -> ``Qgis.WkbType.X``, ``QgsProcessing.TypeVectorX`` ->
``Qgis.ProcessingSourceType.VectorX``...). ``algorithms/compat.py`` is the one module allowed to name the
QGIS 3.22 spellings, as fallbacks.
"""

import re

import pytest
from conftest import REPOSITORY
from qgis.core import Qgis

#: (pattern, what to write instead); patterns are matched against code with comments and strings removed.
RULES = (
    (r"\bPyQt5\b", "import from qgis.PyQt"),
    (r"\bexec_\s*\(", "exec()"),
    (r"\bQVariant\b", "compat.FieldType (QMetaType.Type)"),
    (r"\bQRegExp\b", "QRegularExpression"),
    (r"\bQt\.[A-Za-z]+\b(?!\s*\.)", "the scoped Qt enum, e.g. Qt.AlignmentFlag.AlignLeft"),
    (r"\bQgsWkbTypes\.(Type\b|[A-Z]\w*Geometry\b|GeometryType\b)", "compat.WkbType / compat.GeometryType"),
    (r"\bQgsProcessing\.(SourceType\b|Type[A-Z]\w*)", "compat.ProcessingSourceType"),
    (r"\bQgsProcessingParameterNumber\.(Type\b|Double\b|Integer\b)", "QgsProcessingParameterDistance"),
    (r"\bFlag(Optional|Advanced|Hidden|IsModelOutput)\b", "compat.ProcessingParameterFlag"),
    (r"\bFlagSkipGeometryValidityChecks\b", "compat.ProcessingFeatureSourceFlag"),
    (r"\bQgsUnitTypes\.(Distance|Render|Area)\w*", "Qgis.DistanceUnit / Qgis.RenderUnit (compat)"),
    (r"\bWktVariant\b", "compat.CrsWktVariant"),
    (r"\bQgsMapLayerType\b", "Qgis.LayerType"),
    (r"\bQgis\.(Info|Warning|Critical|Success)\b", "Qgis.MessageLevel.X"),
    (r"\bQgsFeatureSink\.FastInsert\b", "QgsFeatureSink.Flag.FastInsert"),
    (r"\bQgsFeatureSink\.RegeneratePrimaryKey\b", "QgsFeatureSink.SinkFlag.RegeneratePrimaryKey"),
)
#: The one home of the QGIS 3.22 fallbacks.
COMPAT = REPOSITORY / "algorithms" / "compat.py"


def plugin_sources():
    """Every Python file a user installs (the plugin folder without tests, scripts, benchmarks)."""
    files = [REPOSITORY / "__init__.py"]
    for folder in ("algorithms", "incircu_plugin"):
        files += sorted((REPOSITORY / folder).rglob("*.py"))
    return files


def code_only(text):
    """Blank out comments and string literals (docstrings included), keeping line numbers."""
    strings = r"(\"\"\"[\s\S]*?\"\"\"|'''[\s\S]*?'''|\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*')"
    text = re.sub(strings, lambda match: re.sub(r"[^\n]", " ", match.group(0)), text)
    return re.sub(r"#[^\n]*", "", text)


def findings(text):
    """Return ``(line number, offending text, replacement)`` for every rule broken in ``text``."""
    code = code_only(text)
    found = []
    for pattern, replacement in RULES:
        for match in re.finditer(pattern, code):
            found.append((code.count("\n", 0, match.start()) + 1, match.group(0), replacement))
    return found


@pytest.mark.parametrize(
    "snippet",
    [
        "from PyQt5.QtCore import QVariant",
        "dialog.exec_()",
        "QgsField('a', QVariant.Double)",
        "label.setAlignment(Qt.AlignLeft)",
        "QgsWkbTypes.Type.LineString",
        "QgsWkbTypes.PolygonGeometry",
        "[QgsProcessing.TypeVectorLine]",
        "QgsProcessing.SourceType.TypeVectorLine",
        "QgsProcessingParameterNumber.Double",
        "parameter.Flag.FlagAdvanced",
        "QgsProcessingFeatureSource.Flag.FlagSkipGeometryValidityChecks",
        "QgsUnitTypes.DistanceMeters",
        "Qgis.Warning",
    ],
)
def test_the_scan_catches_each_old_idiom(snippet):
    assert findings(snippet), snippet


def test_the_scan_ignores_current_names_comments_and_strings():
    current = (
        "from qgis.PyQt.QtCore import Qt\n"
        "x = Qt.AlignmentFlag.AlignLeft\n"
        "y = Qgis.WkbType.LineString  # not QgsWkbTypes.Type.LineString\n"
        "z = 'exec_() in a string'\n"
    )
    assert findings(current) == []


@pytest.mark.parametrize("path", plugin_sources(), ids=lambda path: str(path.relative_to(REPOSITORY)))
def test_plugin_sources_use_current_names(path):
    if path == COMPAT:
        pytest.skip("the one home of the QGIS 3.22 fallbacks")
    problems = findings(path.read_text(encoding="utf-8"))
    assert problems == [], "\n".join(f"line {line}: {text} -> {instead}" for line, text, instead in problems)


def test_compat_gives_the_running_qgis_its_own_enums(provider):
    from incircu.algorithms import compat

    if Qgis.QGIS_VERSION_INT >= 33600:
        assert compat.ProcessingSourceType is Qgis.ProcessingSourceType
        assert compat.WkbType is Qgis.WkbType
    assert compat.WkbType.LineString == compat.WkbType.LineString
    assert int(compat.ProcessingSourceType.VectorPolygon) == 2
    assert int(compat.GeometryType.Polygon) == 2
    assert compat.ProcessingParameterFlag.Optional != compat.ProcessingParameterFlag.Advanced
