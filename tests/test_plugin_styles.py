"""Outputs as a user first sees them: loaded the way the toolbox dialog loads them, styled, drawn to a PNG.

The run mimics ``AlgorithmDialog``: every output is a temporary layer to open in the project, the algorithm
runs with a context from ``processing.tools.dataobjects.createContext`` and the Processing plugin's own
``handleAlgorithmResults`` loads the results (and calls the algorithm's layer post-processors). The map is
then rendered in layer-tree order to ``tests/artifacts/styled_<algorithm>.png``.
"""

import pytest
from conftest import REPOSITORY
from qgis.core import (
    QgsApplication,
    QgsFillSymbol,
    QgsLineSymbol,
    QgsMapRendererParallelJob,
    QgsMapSettings,
    QgsProcessingFeedback,
    QgsProcessingOutputLayerDefinition,
    QgsProject,
    QgsRectangle,
    QgsSingleSymbolRenderer,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor

DATA = REPOSITORY / "tests" / "data"

OUTPUTS = ("OUTPUT", "OUTPUT_VERTICES", "OUTPUT_TRANSECTS", "OUTPUT_CIRCLES")

CASES = {
    "polygoncenterline": (
        {
            "INPUT": str(DATA / "river_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
            "TRANSECT_INTERVAL": 150.0,
        },
        ["river_2180.geojson"],
        "Centerlines of polygons",
    ),
    "linescenterline": (
        {
            "LINES_A": str(DATA / "banks_a_2180.geojson"),
            "LINES_B": str(DATA / "banks_b_2180.geojson"),
            "PAIR_FIELD_A": "reach",
            "PAIR_FIELD_B": "reach",
            "TRANSECT_INTERVAL": 150.0,
        },
        ["banks_a_2180.geojson", "banks_b_2180.geojson"],
        "Centerline between lines",
    ),
}


def run_as_the_dialog_does(algorithm_id, parameters, project):
    """Run an algorithm and load its results into ``project`` as the toolbox dialog does."""
    from processing.gui.Postprocessing import handleAlgorithmResults
    from processing.tools import dataobjects

    algorithm = QgsApplication.processingRegistry().createAlgorithmById(algorithm_id)
    feedback = QgsProcessingFeedback()
    context = dataobjects.createContext(feedback)
    context.setProject(project)
    for name in OUTPUTS:
        parameters[name] = QgsProcessingOutputLayerDefinition("TEMPORARY_OUTPUT", project)
    results, ok = algorithm.run(parameters, context, feedback)
    assert ok, results
    assert handleAlgorithmResults(algorithm, context, feedback, parameters=results)
    return results


def render(project, path):
    """Draw the project's layers in layer-tree order (top layer drawn last) to a PNG; return the image."""
    layers = project.layerTreeRoot().layerOrder()
    extent = QgsRectangle()
    for layer in layers:
        extent.combineExtentWith(layer.extent())
    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(layers[0].crs())
    settings.setOutputSize(QSize(1400, 900))
    settings.setBackgroundColor(QColor("white"))
    settings.setExtent(extent.buffered(0.03 * extent.width()))
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage()
    assert image.save(str(path))
    return image


@pytest.mark.parametrize("algorithm_name", sorted(CASES))
def test_loaded_outputs_are_styled_named_and_ordered(provider, artifacts, algorithm_name):
    parameters, inputs, centerline_name = CASES[algorithm_name]
    project = QgsProject.instance()
    project.clear()
    for file_name in inputs:
        source = QgsVectorLayer(str(DATA / file_name), file_name.split("_2180")[0], "ogr")
        if file_name.startswith("river"):
            source.setRenderer(QgsSingleSymbolRenderer(QgsFillSymbol.createSimple({"color": "170,205,235,255"})))
        else:
            source.setRenderer(
                QgsSingleSymbolRenderer(
                    QgsLineSymbol.createSimple({"line_color": "20,60,160,255", "line_width": "0.6"})
                )
            )
        project.addMapLayer(source)
    run_as_the_dialog_does(f"incircu:{algorithm_name}", dict(parameters), project)

    layers = project.layerTreeRoot().layerOrder()
    names = [layer.name() for layer in layers]
    expected = [centerline_name, "Centerline vertices", "Transects", "Incircles"]
    assert names[: len(expected)] == expected
    assert len(set(names)) == len(names)
    centerline, vertices, transects, circles = layers[:4]
    for layer, symbol_type in ((centerline, "line"), (vertices, "marker"), (transects, "line"), (circles, "fill")):
        renderer = layer.renderer()
        assert renderer.type() == "singleSymbol", layer.name()
        assert type(renderer.symbol()).__name__.lower() == f"qgs{symbol_type}symbol", layer.name()
    centerline_layers = [symbol_layer.layerType() for symbol_layer in centerline.renderer().symbol().symbolLayers()]
    assert centerline_layers == ["GeometryGenerator", "SimpleLine", "SimpleLine"]
    assert centerline.renderer().symbol().symbolLayer(2).width() > 2 * transects.renderer().symbol().width()
    circle_fill = circles.renderer().symbol().symbolLayer(0)
    assert circle_fill.brushStyle() == 0, "incircles must not be filled"
    assert circle_fill.strokeColor().alpha() < 255

    image = render(project, artifacts / f"styled_{algorithm_name}.png")
    red = sum(
        1
        for x in range(0, image.width(), 3)
        for y in range(0, image.height(), 3)
        if QColor(image.pixel(x, y)).red() > 170 and QColor(image.pixel(x, y)).green() < 80
    )
    assert red > 200, "the centerline is not visible on top"
    project.clear()
