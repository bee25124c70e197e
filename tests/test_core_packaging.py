"""The pip-installable core: ``pyproject.toml`` builds a wheel of ``incircu_plugin/core`` as the package
``incircu``, which installs and runs in a fresh virtual environment without QGIS.

The wheel is built with the hatchling of the test environment (no build isolation, so nothing is downloaded
for the build); installing it fetches numpy, Shapely and pyproj from the package index like any user's
``pip install`` (the test skips when the index cannot be reached).
"""

import email
import subprocess
import sys
import textwrap
import venv
import zipfile

import pytest

from tests.support.project import REPOSITORY, metadata

CORE = REPOSITORY / "incircu_plugin" / "core"

RUN_IN_FRESH_VENV = textwrap.dedent(
    """
    import sys

    try:
        import qgis  # noqa: F401
    except ImportError:
        pass
    else:
        raise SystemExit("QGIS is importable: the environment is not fresh")
    import incircu
    from shapely.geometry import box

    assert "site-packages" in incircu.__file__, incircu.__file__
    result = incircu.polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=1.0)
    assert result.line.coords[0] == (0.0, 5.0) and result.line.coords[-1] == (100.0, 5.0), list(result.line.coords)
    assert abs(float(result.widths.max()) - 10.0) < 1e-9
    assert callable(incircu.centerlines) and callable(incircu.frame_labels)
    leaked = sorted(name for name in sys.modules if name.split(".")[0] in ("geopandas", "pandas", "qgis"))
    assert not leaked, leaked
    print("incircu", incircu.__name__, "ok")
    """
)


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    """The core's wheel, built from the repository."""
    pytest.importorskip("hatchling")
    folder = tmp_path_factory.mktemp("wheel")
    built = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-w", str(folder), str(REPOSITORY)],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert built.returncode == 0, built.stdout + built.stderr
    wheels = sorted(folder.glob("incircu-*.whl"))
    assert len(wheels) == 1, wheels
    return wheels[0]


def test_wheel_holds_the_core_as_incircu_and_nothing_of_qgis(wheel):
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        wheel_metadata = email.message_from_bytes(
            archive.read(next(n for n in names if n.endswith(".dist-info/METADATA")))
        )
    modules = sorted(name for name in names if not name.split("/")[0].endswith(".dist-info"))
    expected = sorted(f"incircu/{path.relative_to(CORE).as_posix()}" for path in CORE.rglob("*.py"))
    assert modules == expected
    assert wheel_metadata["Name"] == "incircu"
    assert wheel_metadata["Version"] == metadata()["version"]
    requirements = wheel_metadata.get_all("Requires-Dist")
    assert {r.split(";")[0].split(">")[0].split("=")[0].strip() for r in requirements if "extra" not in r} == {
        "numpy",
        "shapely",
        "pyproj",
    }
    assert {"geopandas", "dask"} <= set(wheel_metadata.get_all("Provides-Extra"))


@pytest.mark.slow
def test_wheel_installs_and_runs_in_a_fresh_venv_without_qgis(wheel, tmp_path):
    environment = tmp_path / "venv"
    venv.EnvBuilder(with_pip=True, system_site_packages=False).create(environment)
    python = environment / "bin" / "python"
    installed = subprocess.run(
        [str(python), "-m", "pip", "install", "--disable-pip-version-check", "--quiet", str(wheel)],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    if installed.returncode != 0 and any(
        sign in installed.stderr for sign in ("No matching distribution", "Could not find a version", "connection")
    ):
        pytest.skip("the package index cannot be reached: " + installed.stderr[-300:])
    assert installed.returncode == 0, installed.stdout + installed.stderr
    run = subprocess.run(
        [str(python), "-c", RUN_IN_FRESH_VENV], capture_output=True, text=True, timeout=120, cwd=tmp_path, check=False
    )
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.strip() == "incircu incircu ok"
