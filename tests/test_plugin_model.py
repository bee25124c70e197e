"""The committed graphical model "Fix geometries -> IncirCu -> Smooth", run headless two ways."""

import subprocess
import sys

import processing
from qgis.core import (
    QgsApplication,
    QgsFeature,
    QgsGeometry,
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


def test_model_validates_and_is_laid_out(provider):
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    valid, issues = model.validate()
    assert valid, issues
    components = [*model.parameterComponents().values(), *model.childAlgorithms().values()]
    components += [output for child in model.childAlgorithms().values() for output in child.modelOutputs().values()]
    positions = [(component.position().x(), component.position().y()) for component in components]
    assert len(components) == 6
    assert len(set(positions)) == len(positions), positions
    assert (0.0, 0.0) not in positions


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


#: The example models shipped with the plugin, by their name in the toolbox: inputs and outputs.
EXAMPLES = {
    "River widths": ({"rivers", "split_points", "transect_interval"}, {"incircu:centerlines", "incircu:transects"}),
    "Reservoir centerlines with guides": ({"reservoirs", "guide_lines"}, {"incircu:centerlines"}),
}


def example(provider, name):
    """The example model ``name`` as the toolbox lists it."""
    found = [algorithm for algorithm in provider.algorithms() if algorithm.displayName() == name]
    assert len(found) == 1, [algorithm.displayName() for algorithm in provider.algorithms()]
    return found[0]


def test_example_models_are_listed_valid_and_explained(provider):
    for name, (inputs, outputs) in EXAMPLES.items():
        model = example(provider, name)
        assert model.group() == "Example models"
        valid, issues = model.validate()
        assert valid, issues
        assert {
            definition.name() for definition in model.parameterDefinitions() if not definition.isDestination()
        } == inputs
        assert {definition.name() for definition in model.outputDefinitions()} >= outputs
        help_text = model.shortHelpString()
        assert "Fix geometries" in help_text
        for definition in model.parameterDefinitions():
            if not definition.isDestination():
                assert definition.description() in help_text, definition.name()


def test_the_river_widths_model_measures_the_sample_river(provider):
    feedback = RecordingFeedback()
    results = processing.run(
        example(provider, "River widths"),
        {
            "rivers": str(DATA / "river_2180.geojson"),
            "split_points": str(DATA / "split_points_2180.geojson"),
            "transect_interval": 100.0,
            "incircu:centerlines": "memory:",
            "incircu:transects": "memory:",
        },
        feedback=feedback,
    )
    centerlines, transects = results["incircu:centerlines"], results["incircu:transects"]
    meander = features_by(centerlines, "name")["Meander"]
    assert abs(meander["width_mean"] - RIVER_WIDTH) < 0.02 * RIVER_WIDTH
    assert fixture_polygon("Meander").buffer(0.01 * RIVER_WIDTH).contains(as_shapely(meander.geometry()))
    sections = [t for t in transects.getFeatures() if t["source_fid"] == meander["source_fid"]]
    assert abs(len(sections) - meander["length"] / 100.0) <= 2
    assert all(abs(t["width"] - RIVER_WIDTH) < 0.05 * RIVER_WIDTH for t in sections)


def test_the_reservoir_model_follows_its_guide(provider):
    # The island channel's guide runs along it: the ends are where the guide leaves the polygon.
    polygon = fixture_polygon("Island channel")
    west, south, east, north = polygon.bounds
    middle = (south + north) / 2.0
    guide = QgsVectorLayer("LineString?crs=EPSG:2180", "guide", "memory")
    line = QgsFeature()
    line.setGeometry(QgsGeometry.fromWkt(f"LINESTRING ({west - 50} {middle}, {east + 50} {middle})"))
    guide.dataProvider().addFeatures([line])
    results = processing.run(
        example(provider, "Reservoir centerlines with guides"),
        {"reservoirs": str(DATA / "river_2180.geojson"), "guide_lines": guide, "incircu:centerlines": "memory:"},
    )
    feature = features_by(results["incircu:centerlines"], "name")["Island channel"]
    assert feature["ends_from"] == "guide"


def test_example_model_outputs_are_styled_when_loaded(provider, layer_panel):
    from processing.gui.Postprocessing import handleAlgorithmResults
    from processing.tools import dataobjects
    from qgis.core import QgsProcessingFeedback, QgsProcessingOutputLayerDefinition, QgsProject

    project = QgsProject.instance()
    project.clear()
    feedback = QgsProcessingFeedback()
    context = dataobjects.createContext(feedback)
    context.setProject(project)
    model = example(provider, "River widths")
    parameters = {
        "rivers": str(DATA / "river_2180.geojson"),
        "split_points": str(DATA / "split_points_2180.geojson"),
        "transect_interval": 100.0,
        "incircu:centerlines": QgsProcessingOutputLayerDefinition("TEMPORARY_OUTPUT", project),
        "incircu:transects": QgsProcessingOutputLayerDefinition("TEMPORARY_OUTPUT", project),
    }
    results, ok = model.run(parameters, context, feedback)
    assert ok, results
    assert handleAlgorithmResults(model, context, feedback, parameters=results)
    layers = {layer.name(): layer for layer in project.mapLayers().values()}
    # Named after the layer IncirCu read: in this model, the output of Fix geometries.
    (centerlines,) = [layer for name, layer in layers.items() if name.endswith(" — centerlines (split points)")]
    (transects,) = [layer for name, layer in layers.items() if name.endswith(" — transects (split points)")]
    assert centerlines.renderer().symbol().symbolLayerCount() == 2, "the cased centerline of IncirCu's style"
    assert transects.renderer().symbol().color().name() == "#c85f00"
    project.clear()


def test_shipped_example_models_match_their_generator(tmp_path):
    import importlib.util

    from tests.support.project import REPOSITORY

    spec = importlib.util.spec_from_file_location("sample_data", REPOSITORY / "scripts" / "make_sample_data.py")
    sample_data = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(sample_data)
    # In a process of its own, as `make_sample_data.py` writes them: in this one IncirCu's provider may already be
    # registered, and a model then also stores the output layers' parameters its IncirCu step defines.
    script = (
        "import importlib.util, pathlib, sys; "
        "spec = importlib.util.spec_from_file_location('sample_data', sys.argv[1]); "
        "module = importlib.util.module_from_spec(spec); spec.loader.exec_module(module); "
        "module.write_example_models(pathlib.Path(sys.argv[2]))"
    )
    subprocess.run(
        [sys.executable, "-c", script, str(REPOSITORY / "scripts" / "make_sample_data.py"), str(tmp_path)],
        check=True,
        capture_output=True,
        timeout=300,
    )
    written = sorted(path.name for path in tmp_path.iterdir())
    assert written == sorted(path.name for path in sample_data.MODEL_FOLDER.glob("*.model3"))
    for name in written:
        # What the model holds, as QGIS reads it (each QGIS version writes its own XML around the same content).
        assert _model_content(tmp_path / name) == _model_content(sample_data.MODEL_FOLDER / name), name


def _model_content(path):
    """A model file's name, group, help, inputs, steps (with every parameter's sources) and outputs."""
    from qgis.core import QgsProcessingModelAlgorithm

    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(path)), path
    inputs = {
        name: (definition.type(), definition.description(), int(definition.flags()))
        for name in model.parameterComponents()
        for definition in [model.parameterDefinition(name)]
    }
    steps = {
        child_id: (
            child.algorithmId(),
            child.description(),
            {name: [source.toVariant() for source in sources] for name, sources in child.parameterSources().items()},
            {name: output.childOutputName() for name, output in child.modelOutputs().items()},
        )
        for child_id, child in model.childAlgorithms().items()
    }
    return model.name(), model.group(), model.helpContent(), inputs, steps
