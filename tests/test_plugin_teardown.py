"""A failing test that holds a QGIS layer is reported as a failure, not as a crash at the end of the session."""

import os
import subprocess
import sys

from tests.support.project import DATA, REPOSITORY

FAILING_TEST = f"""
from qgis.core import QgsVectorLayer


def test_fails_holding_an_ogr_layer():
    layer = QgsVectorLayer({str(DATA / "river_2180.geojson")!r}, "river", "ogr")
    assert layer.isValid()
    assert layer.featureCount() == -1
"""


def test_a_failure_holding_a_layer_ends_the_session_cleanly(tmp_path):
    """Without ``qgis_objects_of_failed_tests_go_before_qgis`` (tests/conftest.py) pytest exits with 139."""
    (tmp_path / "test_holding.py").write_text(FAILING_TEST, encoding="utf-8")
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-p", "tests.conftest", "-q", "test_holding.py"],
        cwd=tmp_path,
        env={**os.environ, "PYTHONPATH": str(REPOSITORY), "QT_QPA_PLATFORM": "offscreen"},
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert run.returncode == 1, run.stdout[-2000:] + run.stderr[-2000:]
    assert "1 failed" in run.stdout
