"""The geometry core never needs QGIS: it imports and runs with ``qgis`` (and PyQt) unavailable.

The run happens in a fresh interpreter whose import system refuses ``qgis``, ``PyQt5``, ``PyQt6`` and
``processing``: the test Python here has QGIS on its path (it is the system Python's site-packages), so
only a blocker proves the core does not reach for it. A static scan of every module under
``incircu_plugin/core`` complements it (an import inside a function would escape the run).
"""

import ast
import subprocess
import sys
import textwrap
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parent.parent
CORE = REPOSITORY / "incircu_plugin" / "core"

#: Top-level packages the core may import besides the standard library and itself.
ALLOWED_THIRD_PARTY = {"numpy", "shapely", "pyproj"}
#: Optional packages of the data-frame API (``incircu[geopandas]``): imported only inside its functions.
LAZY_OPTIONAL = {"geopandas", "pandas", "dask_geopandas"}
FORBIDDEN = ("qgis", "PyQt5", "PyQt6", "sip", "processing", "osgeo")

BLOCKED_RUN = textwrap.dedent(
    """
    import importlib.abc
    import sys

    FORBIDDEN = {forbidden!r}

    class Blocker(importlib.abc.MetaPathFinder):
        def find_spec(self, name, path=None, target=None):
            if name.split(".")[0] in FORBIDDEN:
                raise ImportError("blocked for this test: " + name)
            return None

    sys.meta_path.insert(0, Blocker())
    for name in list(sys.modules):
        if name.split(".")[0] in FORBIDDEN:
            del sys.modules[name]
    try:
        import qgis  # noqa: F401
    except ImportError:
        pass
    else:
        raise SystemExit("the blocker does not work")

    sys.path.insert(0, {repository!r})
    from incircu_plugin.core import polygon_centerline, lines_centerline
    from shapely.geometry import box

    result = polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=1.0)
    assert result.line.coords[0] == (0.0, 5.0) and result.line.coords[-1] == (100.0, 5.0)
    lines_centerline([(0, 0), (100, 0)], [(0, 8), (100, 8)], spacing=1.0)
    leaked = sorted(name for name in sys.modules if name.split(".")[0] in FORBIDDEN)
    if leaked:
        raise SystemExit("imported: " + ", ".join(leaked))
    print("core ok")
    """
)


def test_core_imports_and_runs_with_qgis_blocked():
    script = BLOCKED_RUN.format(forbidden=set(FORBIDDEN), repository=str(REPOSITORY))
    completed = subprocess.run(
        [sys.executable, "-c", script],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=str(REPOSITORY.parent),
        check=False,
    )
    assert completed.returncode == 0, completed.stderr + completed.stdout
    assert completed.stdout.strip().endswith("core ok")


def test_core_imports_with_qgis_set_to_none_in_sys_modules():
    script = textwrap.dedent(
        """
        import sys
        sys.modules["qgis"] = None
        sys.path.insert(0, {repository!r})
        import incircu_plugin.core
        print("core ok")
        """
    ).format(repository=str(REPOSITORY))
    completed = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, check=False)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip() == "core ok"


def imported_top_level_names(path, module_level_only=False):
    """Absolute top-level module names imported in a file (relative imports excluded).

    Anywhere in the file, or with ``module_level_only`` only outside function bodies (what importing it runs).
    """
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    in_functions = set()
    if module_level_only:
        for function in ast.walk(tree):
            if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
                in_functions.update(id(node) for node in ast.walk(function))
    names = set()
    for node in (node for node in ast.walk(tree) if id(node) not in in_functions):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
        elif isinstance(node, ast.Call) and getattr(node.func, "attr", getattr(node.func, "id", None)) in (
            "import_module",
            "__import__",
        ):
            names.add("<dynamic import>")
    return names


def test_no_core_module_imports_qgis_or_anything_but_numpy_shapely_pyproj():
    modules = sorted(CORE.rglob("*.py"))
    assert len(modules) >= 3
    standard_library = set(sys.stdlib_module_names)
    for path in modules:
        names = imported_top_level_names(path)
        relative = path.relative_to(REPOSITORY)
        assert not names & set(FORBIDDEN), f"{relative} imports {sorted(names & set(FORBIDDEN))}"
        outside = names - standard_library - ALLOWED_THIRD_PARTY - LAZY_OPTIONAL
        assert not outside, f"{relative} imports {sorted(outside)}"
        eager = imported_top_level_names(path, module_level_only=True) & LAZY_OPTIONAL
        assert not eager, f"{relative} imports {sorted(eager)} on import; import them inside the function"


def test_the_package_above_the_core_does_not_import_qgis_either():
    # Importing incircu_plugin.core runs incircu_plugin/__init__.py first.
    names = imported_top_level_names(REPOSITORY / "incircu_plugin" / "__init__.py")
    assert not names & set(FORBIDDEN)
