"""Ready for QGIS 3.40 and QGIS 4 (Qt 6): no PyQt5-only idioms, no enum names QGIS has deprecated.

The scan follows what QGIS's migration script ``scripts/pyqt5_to_pyqt6/pyqt5_to_pyqt6.py`` rewrites: direct
PyQt5 imports, ``exec_()``, ``QVariant`` field types, unscoped Qt enums, and the QGIS enums that moved to
``Qgis`` (``QgsWkbTypes.Type.X`` -> ``Qgis.WkbType.X``, ``QgsProcessing.TypeVectorX`` ->
``Qgis.ProcessingSourceType.VectorX``...). ``algorithms/compat.py`` is the one module allowed to name the
QGIS 3.22 spellings, as fallbacks.
"""

import enum
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


@pytest.mark.parametrize(
    "path", [path for path in plugin_sources() if path != COMPAT], ids=lambda path: str(path.relative_to(REPOSITORY))
)
def test_plugin_sources_use_current_names(path):
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


#: What QGIS writes in the docstring of an API it has deprecated; QGIS 4 removes the deprecated API of 3.x.
DEPRECATED = re.compile(r"\.\. deprecated::|\bdeprecated\b", re.IGNORECASE)


def qgis_names(text):
    """The dotted QGIS names (``QgsWkbTypes.addM``, ``Qgis.WkbType.LineString``) a module's code spells out."""
    return set(re.findall(r"\b(?:Qgs[A-Za-z0-9]+|Qgis)(?:\.[A-Za-z_][A-Za-z0-9_]*)+", code_only(text)))


def resolve(dotted):
    """Follow a dotted name from ``qgis.core``, ``qgis.gui`` or ``qgis.analysis``: ``[(name, object), ...]``."""
    import qgis.analysis
    import qgis.core
    import qgis.gui

    first, *rest = dotted.split(".")
    found = [getattr(module, first) for module in (qgis.core, qgis.gui, qgis.analysis) if hasattr(module, first)]
    assert found, f"{first} is in none of qgis.core, qgis.gui, qgis.analysis"
    chain, current, name = [(first, found[0])], found[0], first
    for attribute in rest:
        assert hasattr(current, attribute), f"{name}.{attribute} does not exist in QGIS {Qgis.QGIS_VERSION}"
        current, name = getattr(current, attribute), f"{name}.{attribute}"
        chain.append((name, current))
    return chain


def deprecation_note(value):
    """The docstring of a class, function or enum member if QGIS marks it deprecated, else ``None``."""
    if isinstance(value, (int, float, str)) and not isinstance(value, enum.Enum):
        return None  # a plain constant: its docstring is the type's
    documentation = getattr(value, "__doc__", None) or ""
    if isinstance(value, enum.Enum) and documentation == (type(value).__doc__ or ""):
        return None  # a member without its own docstring
    if isinstance(value, type):
        # A class's docstring holds one block per constructor overload: one deprecated overload (the CRS from a
        # QGIS-internal id) is not a deprecated class; every overload deprecated is.
        blocks = re.split(rf"^(?={re.escape(value.__name__)}\()", documentation, flags=re.MULTILINE)
        blocks = [block for block in blocks if block.strip()]
        if blocks and not all(DEPRECATED.search(block) for block in blocks):
            return None
    marker = DEPRECATED.search(documentation)
    return documentation[max(0, marker.start() - 200) : marker.end() + 200] if marker else None


def test_a_class_is_deprecated_only_when_every_constructor_is():
    assert deprecation_note(resolve("QgsCoordinateReferenceSystem")[0][1]) is None  # one overload deprecated

    class QgsOld:
        """QgsOld(a: int)\n.. deprecated:: QGIS 3.10\n\nQgsOld(b: str)\n.. deprecated:: QGIS 3.12"""

    assert deprecation_note(QgsOld) is not None


def test_the_deprecation_scan_catches_a_deprecated_method():
    chain = resolve("QgsCoordinateReferenceSystem.toProj4")
    assert deprecation_note(chain[-1][1]) is not None
    assert deprecation_note(resolve("QgsCoordinateReferenceSystem.toWkt")[-1][1]) is None


@pytest.mark.parametrize(
    "path", [path for path in plugin_sources() if path != COMPAT], ids=lambda path: str(path.relative_to(REPOSITORY))
)
def test_no_qgis_api_the_plugin_names_is_deprecated(path):
    """Every QGIS class, method and enum the plugin spells out exists in the running QGIS and is not deprecated
    there: QGIS 4 removes what 3.x deprecated. (The 3.22 fallbacks of ``algorithms/compat.py`` are left out; its
    branch for the running QGIS is checked through the names it gives the rest of the plugin.)"""
    problems = []
    for dotted in sorted(qgis_names(path.read_text(encoding="utf-8"))):
        for name, value in resolve(dotted):
            note = deprecation_note(value)
            if note is not None:
                problems.append(f"{name}: {note}")
    assert problems == [], "\n".join(problems)


def test_compat_names_are_current_on_this_qgis(provider):
    """The names ``compat`` hands the plugin are the running QGIS's current, not deprecated, ones."""
    from incircu.algorithms import compat

    for name in ("WkbType", "GeometryType", "DistanceUnit", "ProcessingSourceType", "ProcessingParameterFlag"):
        value = getattr(compat, name)
        if isinstance(value, type):
            assert deprecation_note(value) is None, name


def test_calling_deprecated_qgis_api_from_the_plugin_fails_the_tests():
    """``tests/conftest.py`` turns QGIS's own deprecation warnings raised from the plugin's modules into errors,
    so every test that runs plugin code also proves it calls no deprecated QGIS API (QGIS 4 removed it)."""
    from qgis.core import QgsCoordinateReferenceSystem

    code = compile("crs.toProj4()", "incircu/algorithms/probe.py", "exec")
    with pytest.raises(DeprecationWarning, match="is deprecated"):
        exec(code, {"__name__": "incircu.algorithms.probe", "crs": QgsCoordinateReferenceSystem("EPSG:4326")})  # noqa: S102
