"""The committed graphical model "Fix geometries -> IncirCu -> Smooth", run headless two ways."""

from qgis.core import (
    QgsApplication,
    QgsProcessingContext,
    QgsProcessingModelAlgorithm,
    QgsProcessingUtils,
    QgsVectorLayer,
)
from test_plugin_processing import RIVER_WIDTH, RecordingFeedback, as_shapely, features_by, fixture_polygon

from tests.support.project import DATA

MODEL = DATA / "fix_centerline_smooth.model3"
OUTPUT = "smooth:smoothed"


def check_smoothed(layer):
    """The smoothed meander centerline stays inside the river and keeps the attributes of IncirCu."""
    assert layer.crs().authid() == "EPSG:2180"
    meander = features_by(layer, "name")["Meander"]
    assert abs(meander["width_mean"] - RIVER_WIDTH) < 0.02 * RIVER_WIDTH
    line = as_shapely(meander.geometry())
    polygon = fixture_polygon("Meander")
    assert polygon.buffer(0.05 * RIVER_WIDTH).contains(line)
    assert abs(line.length - meander["length"]) < 0.02 * meander["length"]


def test_model_lists_the_three_steps():
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    algorithm_ids = sorted(child.algorithmId() for child in model.childAlgorithms().values())
    assert algorithm_ids == ["incircu:polygoncenterline", "native:fixgeometries", "native:smoothgeometry"]


def test_model_runs_in_process(provider, tmp_path):
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    model.setProvider(QgsApplication.processingRegistry().providerById("model"))
    context = QgsProcessingContext()
    feedback = RecordingFeedback()
    destination = str(tmp_path / "smoothed.gpkg")
    parameters = {
        "polygons": str(DATA / "river_2180.geojson"),
        "split_points": str(DATA / "split_points_2180.geojson"),
        OUTPUT: destination,
    }
    ok, message = model.checkParameterValues(parameters, context)
    assert ok, message
    results, ok = model.run(parameters, context, feedback)
    assert ok, feedback.warnings
    layer = QgsProcessingUtils.mapLayerFromString(results[OUTPUT], context) or QgsVectorLayer(results[OUTPUT])
    check_smoothed(layer)


def test_model_runs_in_qgis_process(qgis_process, tmp_path):
    destination = tmp_path / "smoothed.gpkg"
    done = qgis_process(
        "run",
        str(MODEL),
        "--",
        "polygons={}".format(DATA / "river_2180.geojson"),
        "split_points={}".format(DATA / "split_points_2180.geojson"),
        f"{OUTPUT}={destination}",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    layer = QgsVectorLayer(str(destination), "smoothed", "ogr")
    assert layer.isValid()
    check_smoothed(layer)
