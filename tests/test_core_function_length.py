"""No function or method of the plugin's packages is longer than :data:`LONGEST` lines (issue 39).

A long function does several jobs; a newcomer should be able to read each one on a screen. The packages are
parsed with ``ast`` (nothing is imported, so the test needs neither QGIS nor Shapely); a function's length runs
from its ``def`` line (decorators left out) to its last line, docstring and comments included. A function
nested in another counts inside its parent and on its own.
"""

import ast

import pytest

from tests.support.project import REPOSITORY

#: Most lines a function may have.
LONGEST = 80

#: The packages checked: the Processing layer, the plugin glue and the geometry core.
PACKAGES = ("algorithms", "incircu_plugin")


def function_lengths(folder):
    """Return ``{"path:line name": lines}`` (path from ``folder``) of every function of the ``.py`` files below
    ``folder``."""
    found = {}
    for path in sorted(folder.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), filename=str(path))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                found[f"{path.relative_to(folder).as_posix()}:{node.lineno} {node.name}"] = (
                    node.end_lineno - node.lineno + 1
                )
    return found


def long_functions(folder):
    """Return ``"path:line name (n lines)"`` for every function below ``folder`` longer than :data:`LONGEST`
    lines."""
    return [f"{place} ({lines} lines)" for place, lines in function_lengths(folder).items() if lines > LONGEST]


def test_the_check_finds_a_long_function_and_passes_one_of_80_lines(tmp_path):
    body = "".join(f"    x{i} = {i}\n" for i in range(LONGEST))
    (tmp_path / "long.py").write_text(f"def short():\n    pass\n\n\ndef long():\n{body}", encoding="utf-8")
    shorter = "".join(f"    x{i} = {i}\n" for i in range(LONGEST - 1))
    (tmp_path / "edge.py").write_text(f"def edge():\n{shorter}", encoding="utf-8")
    assert long_functions(tmp_path) == [f"long.py:5 long ({LONGEST + 1} lines)"]


@pytest.mark.parametrize("package", PACKAGES)
def test_no_function_is_longer_than_80_lines(package):
    assert long_functions(REPOSITORY / package) == []
