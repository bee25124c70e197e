"""Shared fixtures of the plugin tests: the plugin loaded exactly as QGIS loads it, and its provider.

pytest-qgis starts a ``QgsApplication`` before this file is imported (offscreen when ``QT_QPA_PLATFORM`` is
``offscreen``, which ``make test`` sets). The repository root is the plugin folder; QGIS imports it as the
package ``incircu``, so the fixtures put a folder holding an ``incircu`` symlink to the repository on the
plugin path and ``sys.path``. The core tests use none of these fixtures and run without QGIS (``make
test-core`` turns pytest-qgis off); shared helpers live in :mod:`tests.support`.
"""

import gc
import os
import shutil
import subprocess
import sys

import pytest

from tests.support.project import ARTIFACTS, PLUGIN_NAME, QGIS_SITE, REPOSITORY


def pytest_configure(config):
    """A deprecated QGIS API called from the plugin's own modules fails the test that runs it: QGIS 4 removed the
    API QGIS 3.x deprecated, and QGIS's bindings warn at each call of it ("X.y() is deprecated")."""
    config.addinivalue_line("filterwarnings", r"error:.* is deprecated:DeprecationWarning:incircu\.")


@pytest.fixture(scope="session", autouse=True)
def qgis_objects_of_failed_tests_go_before_qgis(request):
    """Release what the last failed test's traceback holds while QGIS still runs.

    pytest keeps the last failure in ``sys.last_traceback`` (``sys.last_exc`` from Python 3.12) for post-mortem
    debugging, and with it the test's frame and its locals: a ``QgsVectorLayer`` on OGR there outlives
    ``exitQgis()`` (pytest-qgis's ``qgis_app`` teardown) and is freed at interpreter exit, after GDAL's drivers,
    which crashed the process ("Segmentation fault", exit 139, once "GDALGetDriverShortName: Pointer 'hDriver' is
    NULL") instead of reporting the failure. This fixture asks for ``qgis_app``, so it is torn down first; without
    pytest-qgis (``-p no:pytest_qgis``: the core tests) there is no QGIS to outlive.
    """
    if request.config.pluginmanager.hasplugin("pytest_qgis"):
        request.getfixturevalue("qgis_app")
    yield
    for name in ("last_type", "last_value", "last_traceback", "last_exc"):
        if hasattr(sys, name):
            setattr(sys, name, None)
    gc.collect()


@pytest.fixture(scope="session")
def plugin_folder(tmp_path_factory):
    """A folder holding only an ``incircu`` symlink to the repository (what ``QGIS_PLUGINPATH`` points at)."""
    folder = tmp_path_factory.mktemp("plugins")
    (folder / PLUGIN_NAME).symlink_to(REPOSITORY, target_is_directory=True)
    return folder


@pytest.fixture(scope="session")
def loaded_plugin(qgis_app, qgis_processing, qgis_iface, plugin_folder):
    """The IncirCu plugin object, imported and started by ``qgis.utils`` as the QGIS desktop does."""
    import qgis.utils

    sys.path.insert(0, str(plugin_folder))
    qgis.utils.plugin_paths.insert(0, str(plugin_folder))
    qgis.utils.iface = qgis_iface
    qgis.utils.updateAvailablePlugins()
    assert PLUGIN_NAME in qgis.utils.available_plugins
    assert qgis.utils.loadPlugin(PLUGIN_NAME)
    assert qgis.utils.startPlugin(PLUGIN_NAME)
    yield qgis.utils.plugins[PLUGIN_NAME]
    qgis.utils.unloadPlugin(PLUGIN_NAME)


@pytest.fixture
def provider(loaded_plugin):
    """The registered IncirCu Processing provider."""
    from qgis.core import QgsApplication

    registered = QgsApplication.processingRegistry().providerById(PLUGIN_NAME)
    assert registered is not None
    return registered


@pytest.fixture(scope="session")
def artifacts():
    """Folder for files a person may want to look at after the tests (dialog screenshots)."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    return ARTIFACTS


def qgis_process_executable():
    """Return the ``qgis_process`` binary (Debian's wrapper script is broken, its ``.bin`` works)."""
    for name in ("qgis_process.bin", "qgis_process"):
        found = shutil.which(name)
        if found:
            return found
    raise RuntimeError("qgis_process is not installed: run `make setup`")


@pytest.fixture(scope="session")
def qgis_process(plugin_folder, tmp_path_factory):
    """Run ``qgis_process`` with the plugin enabled in an isolated profile, as a user's QGIS would.

    QGIS's embedded Python gets only ``QGIS_SITE`` on its path (no venv packages: wheels bundling GEOS or
    PROJ clash with the libraries QGIS links).

    Returns
    -------
    callable
        ``run(*arguments)`` -> ``subprocess.CompletedProcess`` (text output, never raising on failure).
    """
    profile = tmp_path_factory.mktemp("qgis_profile")
    # Empty where the distribution's Shapely is Shapely 2 (Debian 13): QGIS's Python then imports that one.
    probe = subprocess.run(
        ["/usr/bin/python3", "-c", "import shapely"],
        env={**os.environ, "PYTHONPATH": str(QGIS_SITE)},
        capture_output=True,
        check=False,
    )
    assert probe.returncode == 0, "Shapely for QGIS's Python is missing: run `make setup`"
    environment = dict(os.environ)
    environment.update(
        {
            "QT_QPA_PLATFORM": "offscreen",
            "QGIS_CUSTOM_CONFIG_PATH": str(profile),
            "QGIS_PLUGINPATH": str(plugin_folder),
            "PYTHONPATH": str(QGIS_SITE),
        }
    )
    executable = qgis_process_executable()

    def run(*arguments):
        return subprocess.run(
            [executable, *arguments], env=environment, capture_output=True, text=True, timeout=600, check=False
        )

    enabled = run("plugins", "enable", PLUGIN_NAME)
    assert enabled.returncode == 0, enabled.stdout + enabled.stderr
    return run


@pytest.fixture
def layer_panel(qgis_iface, monkeypatch):
    """A real layer panel for ``iface.layerTreeView()``: from QGIS 3.44 the post-processing hands it to C++.

    The view shows the project's layer tree, as the desktop's *Layers* panel does; it owns its model and both are
    deleted when the test ends, while QGIS still runs.
    """
    from qgis.core import QgsLayerTreeModel, QgsProject
    from qgis.gui import QgsLayerTreeView
    from qgis.PyQt import sip

    view = QgsLayerTreeView()
    view.setModel(QgsLayerTreeModel(QgsProject.instance().layerTreeRoot(), view))
    monkeypatch.setattr(qgis_iface, "layerTreeView", lambda: view, raising=False)
    yield view
    sip.delete(view)
