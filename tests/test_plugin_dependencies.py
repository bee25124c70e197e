"""Shapely is judged by its API, not its version string, and the install message fits the user's system.

Debian's ``python3-shapely`` 2.2 (sid, forky) reports ``__version__ == "0+unknown"``: the plugin must take it
for the Shapely 2 it is, and must still stop, with a command that works here, on Shapely 1.8 or none.
"""

import importlib
import re
import shutil
import subprocess
import sys
import types

import pytest
import shapely

from tests.support.project import REPOSITORY

#: Shapely's own sub-modules, named as ``shapely.<module>`` in the sources but not part of the function API.
SUBMODULES = {"errors", "geometry", "ops", "wkb", "wkt", "affinity", "validation", "prepared"}


@pytest.fixture(scope="module")
def dependencies(loaded_plugin):
    return importlib.import_module("incircu.algorithms.dependencies")


def shapely_names_used():
    """Every ``shapely.<name>`` the plugin's sources (core and algorithms) mention, and those guarded by hasattr."""
    used, guarded = set(), set()
    for folder in ("incircu_plugin", "algorithms"):
        for path in (REPOSITORY / folder).rglob("*.py"):
            text = path.read_text(encoding="utf-8")
            used |= set(re.findall(r"\bshapely\.([A-Za-z_][A-Za-z0-9_]*)", text))
            guarded |= set(re.findall(r"hasattr\(shapely, \"([A-Za-z_][A-Za-z0-9_]*)\"\)", text))
    return used - SUBMODULES, guarded


def module_like(source, version, names):
    """A stand-in for the ``shapely`` module with ``version`` and only ``names`` of ``source``."""
    fake = types.ModuleType("shapely")
    for name in names:
        setattr(fake, name, getattr(source, name))
    fake.__version__ = version
    return fake


def test_the_api_list_is_what_the_plugin_calls(dependencies):
    used, guarded = shapely_names_used()
    assert guarded, "the hasattr guard of polyline.py was not found: update this test"
    assert set(dependencies.SHAPELY2_API) == used - guarded
    assert [name for name in dependencies.SHAPELY2_API if not hasattr(shapely, name)] == []


def test_the_installed_shapely_is_usable(dependencies):
    assert dependencies.shapely_problem() is None


def test_a_distribution_build_reporting_an_unknown_version_is_shapely_2(dependencies, monkeypatch):
    debian = module_like(shapely, "0+unknown", dir(shapely))
    monkeypatch.setitem(sys.modules, "shapely", debian)
    assert dependencies.shapely_problem() is None


def test_shapely_1_8_is_refused_with_its_version_and_a_command(dependencies, monkeypatch):
    # Shapely 1.8 has the geometry classes in shapely.geometry and no module-level functions.
    old = module_like(shapely, "1.8.5", ["geometry", "errors"])
    monkeypatch.setitem(sys.modules, "shapely", old)
    problem = dependencies.shapely_problem()
    assert problem.startswith("IncirCu needs Shapely 2.0 or newer, but Shapely 1.8.5 is installed.")
    assert problem.endswith(dependencies.install_hint())


def test_a_shapely_2_lacking_one_function_is_refused(dependencies, monkeypatch):
    names = [name for name in dir(shapely) if name != "shortest_line"]
    monkeypatch.setitem(sys.modules, "shapely", module_like(shapely, "2.0.0", names))
    assert dependencies.missing_shapely2_api(sys.modules["shapely"]) == ["shortest_line"]
    assert "Shapely 2.0.0 is installed" in dependencies.shapely_problem()


def test_a_missing_shapely_is_named_with_the_command(dependencies, monkeypatch):
    monkeypatch.setitem(sys.modules, "shapely", None)  # import shapely raises ImportError
    problem = dependencies.shapely_problem()
    assert problem.startswith("IncirCu needs the Python package Shapely 2, which is not installed.")
    assert problem.endswith(dependencies.install_hint())


APT = "'sudo apt install python3-shapely'"


@pytest.mark.parametrize(
    ("platform", "release", "managed", "expected", "absent"),
    [
        ("linux", {"ID": "debian", "VERSION_ID": "12"}, True, "--user --break-system-packages --no-binary", APT),
        ("linux", {"ID": "ubuntu", "VERSION_ID": "22.04"}, False, "--user --no-binary shapely", "--break"),
        ("linux", {"ID": "debian", "VERSION_ID": "13"}, True, APT, "pip"),
        ("linux", {"ID": "debian"}, True, APT, "pip"),  # testing and unstable have no VERSION_ID
        ("linux", {"ID": "ubuntu", "VERSION_ID": "24.04"}, True, APT, "pip"),
        ("linux", {"ID": "fedora", "VERSION_ID": "41"}, False, "libgeos-dev", APT),
        ("win32", {}, False, "OSGeo4W Shell", "apt"),
        ("darwin", {}, False, 'python -m pip install "shapely>=2"', "apt"),
    ],
)
def test_the_install_hint_fits_the_system(dependencies, platform, release, managed, expected, absent):
    hint = dependencies.install_hint(platform, release, managed)
    assert expected in hint
    assert absent not in hint


@pytest.mark.skipif(shutil.which("apt-cache") is None, reason="not a Debian or Ubuntu system")
def test_the_hint_here_names_the_package_apt_has(dependencies):
    """Where the hint says ``apt install python3-shapely``, apt's candidate is Shapely 2, and the other way round."""
    policy = subprocess.run(
        ["apt-cache", "policy", "python3-shapely"], capture_output=True, text=True, check=True
    ).stdout
    candidate = re.search(r"Candidate:\s*(\S+)", policy)
    has_shapely2 = candidate is not None and re.match(r"[2-9]\.", candidate.group(1)) is not None
    assert (APT in dependencies.install_hint()) == has_shapely2, policy


def test_os_release_is_read_with_quotes_removed(dependencies, tmp_path):
    release = tmp_path / "os-release"
    release.write_text('PRETTY_NAME="Debian GNU/Linux 12 (bookworm)"\nID=debian\nVERSION_ID="12"\n\n# comment\n')
    assert dependencies.os_release(str(release)) == {
        "PRETTY_NAME": "Debian GNU/Linux 12 (bookworm)",
        "ID": "debian",
        "VERSION_ID": "12",
    }
    assert dependencies.os_release(str(tmp_path / "absent")) == {}
    assert dependencies.release_numbers("24.04") == (24, 4)
    assert dependencies.release_numbers("") == ()
