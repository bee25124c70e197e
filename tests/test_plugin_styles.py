"""Outputs as a user first sees them: loaded the way the toolbox dialog loads them, styled, drawn to a PNG.

The run mimics ``AlgorithmDialog``: every output is a temporary layer to open in the project, the algorithm
runs with a context from ``processing.tools.dataobjects.createContext`` and the Processing plugin's own
``handleAlgorithmResults`` loads the results (and calls the algorithm's layer post-processors). The map is
then rendered in layer-tree order to ``tests/artifacts/styled_<algorithm>.png`` and read as a user reads it: the
centerline shows, the vertex dots show above it, the river keeps its colour, the incircles' symbol in the layer panel shows.
"""

import pytest
from conftest import REPOSITORY
from qgis.core import (
    QgsApplication,
    QgsFillSymbol,
    QgsLayerTreeModel,
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
from qgis.PyQt.QtCore import QSize, Qt
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


#: One pixel of a screen at 96 dpi, in millimetres: the least a mark must show to be seen.
PIXEL_MM = 25.4 / 96
#: Colour of the river polygon under the outputs (a light blue, far from every output's colour).
RIVER_FILL = QColor(170, 205, 235)


def map_settings(project, layers):
    """Map settings drawing ``layers`` over the extent of the project's layers, 1400 x 900 px at 96 dpi."""
    extent = QgsRectangle()
    for layer in project.layerTreeRoot().layerOrder():
        extent.combineExtentWith(layer.extent())
    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(layers[-1].crs())
    settings.setOutputSize(QSize(1400, 900))
    settings.setOutputDpi(96)
    settings.setBackgroundColor(QColor("white"))
    settings.setExtent(extent.buffered(0.03 * extent.width()))
    return settings


def render(settings, path=None):
    """Draw the layers of ``settings`` (the first on top) to an image, saved as a PNG at ``path`` if given."""
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage()
    if path is not None:
        assert image.save(str(path))
    return image


def legend_icon(project, layer):
    """The image of ``layer``'s symbol as the layer panel shows it next to the layer's name."""
    model = QgsLayerTreeModel(project.layerTreeRoot())
    node = project.layerTreeRoot().findLayer(layer.id())
    legend_node = model.legendNodeEmbeddedInParent(node) or model.layerLegendNodes(node, True)[0]
    return legend_node.data(Qt.DecorationRole).toImage()


def close(colour, expected, tolerance=40):
    """Whether two colours differ by at most ``tolerance`` (0-255) on each of red, green and blue."""
    return all(abs(a - b) <= tolerance for a, b in zip(colour.getRgb()[:3], expected.getRgb()[:3]))


def sampled_pixels(image, step=2):
    """The colours of every ``step``-th pixel of ``image`` in both directions, row by row."""
    return [QColor(image.pixel(x, y)) for y in range(0, image.height(), step) for x in range(0, image.width(), step)]


@pytest.fixture
def layer_panel(qgis_iface, monkeypatch):
    """A real layer panel for ``iface.layerTreeView()``: from QGIS 3.44 the post-processing hands it to C++.

    The view shows the project's layer tree, as the desktop's *Layers* panel does; it owns its model and both are
    deleted when the test ends, while QGIS still runs.
    """
    from qgis.gui import QgsLayerTreeView
    from qgis.PyQt import sip

    view = QgsLayerTreeView()
    view.setModel(QgsLayerTreeModel(QgsProject.instance().layerTreeRoot(), view))
    monkeypatch.setattr(qgis_iface, "layerTreeView", lambda: view, raising=False)
    yield view
    sip.delete(view)


@pytest.mark.parametrize("algorithm_name", sorted(CASES))
def test_loaded_outputs_are_styled_named_and_ordered(provider, artifacts, layer_panel, algorithm_name):
    parameters, inputs, centerline_name = CASES[algorithm_name]
    project = QgsProject.instance()
    project.clear()
    for file_name in inputs:
        source = QgsVectorLayer(str(DATA / file_name), file_name.split("_2180")[0], "ogr")
        if file_name.startswith("river"):
            source.setRenderer(
                QgsSingleSymbolRenderer(QgsFillSymbol.createSimple({"color": RIVER_FILL.name(), "outline_style": "no"}))
            )
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
    expected = ["Centerline vertices", centerline_name, "Transects", "Incircles"]
    assert names[: len(expected)] == expected, "the vertices lie on the centerline: they must be drawn above it"
    assert len(set(names)) == len(names)
    vertices, centerline, transects, circles = layers[:4]
    for layer, symbol_type in ((centerline, "line"), (vertices, "marker"), (transects, "line"), (circles, "fill")):
        renderer = layer.renderer()
        assert renderer.type() == "singleSymbol", layer.name()
        assert type(renderer.symbol()).__name__.lower() == f"qgs{symbol_type}symbol", layer.name()

    line_symbol = centerline.renderer().symbol()
    centerline_layers = line_symbol.symbolLayers()
    assert [symbol_layer.layerType() for symbol_layer in centerline_layers] == ["SimpleLine", "SimpleLine"], (
        "the centerline is a cased line, without a band that repaints the polygon"
    )
    casing, line = centerline_layers
    assert centerline.renderer().usingSymbolLevels() and casing.renderingPass() < line.renderingPass(), (
        "every casing must be drawn before any line, so lines meeting at a junction stay joined"
    )
    assert line.width() > 2 * transects.renderer().symbol().width()
    assert line.color().hue() != transects.renderer().symbol().color().hue(), "transects look like the centerline"
    dot_size = vertices.renderer().symbol().size()
    assert (dot_size - casing.width()) / 2 >= PIXEL_MM, "a vertex dot must stand out of the line on both sides"

    circle_outline = circles.renderer().symbol().symbolLayer(0)
    assert circle_outline.brushStyle() == 0, "incircles must not be filled"
    assert circle_outline.strokeWidth() >= 0.75 * PIXEL_MM, "incircle outlines thinner than a pixel fade out"
    assert circle_outline.strokeColor().alphaF() >= 0.5, "incircle outlines fainter than half opaque fade out"
    icon = legend_icon(project, circles)
    icon_colours = [QColor.fromRgba(icon.pixel(x, y)) for x in range(icon.width()) for y in range(icon.height())]
    strong = sum(1 for colour in icon_colours if colour.alpha() > 100 and colour.saturation() > 100)
    assert strong >= icon.width(), "the incircles' symbol in the layer panel looks blank"

    settings = map_settings(project, layers)
    image = render(settings, artifacts / f"styled_{algorithm_name}.png")
    pixels = sampled_pixels(image)
    red = sum(1 for colour in pixels if colour.red() > 170 and colour.green() < 80)
    assert red > 200, "the centerline is not visible"
    dot_colour = vertices.renderer().symbol().color()
    centres = [settings.mapToPixel().transform(feature.geometry().asPoint()) for feature in vertices.getFeatures()]
    shown = [close(QColor(image.pixel(round(centre.x()), round(centre.y()))), dot_colour) for centre in centres]
    assert sum(shown) >= 0.9 * len(shown), "the vertex dots are hidden"

    rivers = [layer for layer in layers if layer.name() == "river"]
    if rivers:
        river_alone = sampled_pixels(render(map_settings(project, rivers)))
        inside = [colour for colour, alone in zip(pixels, river_alone) if close(alone, RIVER_FILL, 2)]
        assert inside, "the river is not drawn"
        keeps_fill = sum(1 for colour in inside if close(colour, RIVER_FILL, 12))
        assert keeps_fill >= 0.5 * len(inside), "the outputs hide the colour of the polygon they were made from"
    project.clear()
