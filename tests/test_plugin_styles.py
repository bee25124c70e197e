"""Outputs as a user first sees them: loaded the way the toolbox dialog loads them, styled, drawn to a PNG.

The run mimics ``AlgorithmDialog``: every output is a temporary layer to open in the project, the algorithm
runs with a context from ``processing.tools.dataobjects.createContext`` and the Processing plugin's own
``handleAlgorithmResults`` loads the results (and calls the algorithm's layer post-processors). The map is
then rendered in layer-tree order to ``tests/artifacts/styled_<algorithm>.png`` and read as a user reads it: the
centerline shows, the vertex dots show above it, the river keeps its colour, the incircles' symbol in the layer panel shows.
"""

import numpy as np
import pytest
from conftest import REPOSITORY
from qgis.core import (
    QgsApplication,
    QgsExpressionContext,
    QgsExpressionContextScope,
    QgsFillSymbol,
    QgsLayerTreeModel,
    QgsLineSymbol,
    QgsProcessingFeedback,
    QgsProcessingOutputLayerDefinition,
    QgsProject,
    QgsRectangle,
    QgsSingleSymbolRenderer,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import Qt
from qgis.PyQt.QtGui import QColor

from tests.support.maps import map_settings as support_map_settings
from tests.support.maps import render

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
        "river — {} (split points)",
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
        "banks_a / banks_b — {}",
    ),
}


def run_as_the_dialog_does(algorithm_id, parameters, project, outputs=OUTPUTS):
    """Run an algorithm and load its results (the ``outputs``) into ``project`` as the toolbox dialog does."""
    from processing.gui.Postprocessing import handleAlgorithmResults
    from processing.tools import dataobjects

    algorithm = QgsApplication.processingRegistry().createAlgorithmById(algorithm_id)
    feedback = QgsProcessingFeedback()
    context = dataobjects.createContext(feedback)
    context.setProject(project)
    for name in outputs:
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
    return support_map_settings(layers, extent.buffered(0.03 * extent.width()))


def legend_icon(project, layer):
    """The image of ``layer``'s symbol as the layer panel shows it next to the layer's name."""
    model = QgsLayerTreeModel(project.layerTreeRoot())
    node = project.layerTreeRoot().findLayer(layer.id())
    legend_node = model.legendNodeEmbeddedInParent(node) or model.layerLegendNodes(node, True)[0]
    return legend_node.data(Qt.DecorationRole).toImage()


def close(colour, expected, tolerance=40):
    """Whether two colours differ by at most ``tolerance`` (0-255) on each of red, green and blue."""
    return all(abs(a - b) <= tolerance for a, b in zip(colour.getRgb()[:3], expected.getRgb()[:3]))


def width_at_scale(symbol_layer, scale, feature=None):
    """The stroke width, millimetres, ``symbol_layer`` draws at the map scale 1:``scale`` (for ``feature``)."""
    from incircu.algorithms.compat import SymbolLayerProperty

    prop = symbol_layer.dataDefinedProperties().property(SymbolLayerProperty.StrokeWidth)
    context = QgsExpressionContext()
    scope = QgsExpressionContextScope()
    scope.setVariable("map_scale", scale)
    context.appendScope(scope)
    if feature is not None:
        context.setFeature(feature)
        context.setFields(feature.fields())
    value, ok = prop.valueAsDouble(context, symbol_layer.width())
    assert ok
    return value


def colour_distance(one, other):
    """Euclidean distance between two colours in red, green, blue (0-255 each)."""
    return sum((a - b) ** 2 for a, b in zip(one.getRgb()[:3], other.getRgb()[:3])) ** 0.5


def typical_vertex_spacing(vertices):
    """The median, over the parts, of the median distance along the line between a part's vertices."""
    chainages = {}
    for feature in vertices.getFeatures():
        chainages.setdefault((feature["source_fid"], feature["part"]), []).append(feature["chainage"])
    medians = []
    for values in chainages.values():
        steps = np.diff(sorted(values))
        medians.append(np.median(steps[steps > 0]))
    return float(np.median(medians))


def dots_shown(vertices, settings, image):
    """The share of the vertices drawn in ``image`` (its pixel at a vertex has the dots' colour) among those
    within the map; rounded to 0 or 1 when at most a tenth of them are the exception."""
    dot_colour = vertices.renderer().symbol().color()
    extent = settings.visibleExtent()
    points = [feature.geometry().asPoint() for feature in vertices.getFeatures()]
    centres = [settings.mapToPixel().transform(point) for point in points if extent.contains(point)]
    assert centres
    shown = sum(close(QColor(image.pixel(round(centre.x()), round(centre.y()))), dot_colour) for centre in centres)
    share = shown / len(centres)
    return 1.0 if share >= 0.9 else 0.0 if share <= 0.1 else share


def sampled_pixels(image, step=2):
    """The colours of every ``step``-th pixel of ``image`` in both directions, row by row."""
    return [QColor(image.pixel(x, y)) for y in range(0, image.height(), step) for x in range(0, image.width(), step)]


def test_a_new_run_comes_in_its_own_group_above_the_last(provider, layer_panel):
    project = QgsProject.instance()
    project.clear()
    river = QgsVectorLayer(str(DATA / "river_2180.geojson"), "reservoirs", "ogr")
    project.addMapLayer(river)
    run_as_the_dialog_does("incircu:polygoncenterline", {"INPUT": river}, project)
    run_as_the_dialog_does("incircu:polygoncenterline", {"INPUT": river, "END_RULE": 1}, project)
    groups = [node for node in project.layerTreeRoot().children() if node.nodeType() == 0]
    assert [group.name() for group in groups] == [
        "reservoirs — centerlines (longest path)",
        "reservoirs — centerlines (main stem)",
    ]
    for group, rule in zip(groups, ("longest path", "main stem")):
        names = [node.name() for node in group.children()]
        assert names == [
            f"reservoirs — {word} ({rule})" for word in ("vertices", "centerlines", "transects", "incircles")
        ]
    assert project.layerTreeRoot().children()[-1].name() == "reservoirs", "the input stays below the results"
    project.clear()


def test_label_outputs_are_named_and_grouped_per_run(provider, layer_panel):
    project = QgsProject.instance()
    project.clear()
    river = QgsVectorLayer(str(DATA / "river_2180.geojson"), "reservoirs", "ogr")
    project.addMapLayer(river)
    results = run_as_the_dialog_does("incircu:labellines", {"INPUT": river}, project, ("OUTPUT", "OUTPUT_POINTS"))
    assert results["CENTERLINE_COUNT"] >= 1
    [group] = [node for node in project.layerTreeRoot().children() if node.nodeType() == 0]
    assert group.name() == "reservoirs — label lines (main stem)"
    assert [node.name() for node in group.children()] == [
        "reservoirs — label lines (main stem)",
        "reservoirs — label points (main stem)",
    ]
    from incircu.algorithms.styles import CENTERLINE_COLOUR

    points = group.children()[1].layer()
    assert points.renderer().symbol().color().name() == QColor(*map(int, CENTERLINE_COLOUR.split(","))).name()
    project.clear()


def test_outputs_loaded_into_an_earlier_runs_group_go_above_it(provider):
    """QGIS (3.44; the desktop before) loads outputs above the layer panel's current node, which after a run is
    that run's group: the outputs of the next run, grouped or alone, go just above that group, not into it."""
    from incircu.algorithms.styles import RANK_PROPERTY, RUN_PROPERTY, order_run_layers

    project = QgsProject.instance()
    project.clear()

    def load(run, rank, group):
        layer = QgsVectorLayer("LineString?crs=EPSG:2180", f"{run} {rank}", "memory")
        layer.setCustomProperty(RUN_PROPERTY, run)
        layer.setCustomProperty(RANK_PROPERTY, rank)
        project.addMapLayer(layer, False)
        group.insertLayer(0, layer)

    mine = project.layerTreeRoot().insertGroup(0, "mine")
    earlier = mine.insertGroup(0, "earlier run")
    earlier.setCustomProperty(RUN_PROPERTY, "earlier")
    for rank in (1, 0):
        load("earlier", rank, earlier)
    for rank in (0, 1):
        load("later", rank, earlier)
    order_run_layers(project, "later", "later run")
    load("alone", 0, earlier)
    order_run_layers(project, "alone")

    assert [node.name() for node in project.layerTreeRoot().children()] == ["mine"], "the user's group is kept"
    assert [node.name() for node in mine.children()] == ["later run", "alone 0", "earlier run"]
    assert [node.name() for node in mine.children()[0].children()] == ["later 0", "later 1"]
    assert [node.name() for node in earlier.children()] == ["earlier 0", "earlier 1"]
    project.clear()


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
    expected = [centerline_name.format(word) for word in ("vertices", "centerlines", "transects", "incircles")]
    assert names[: len(expected)] == expected, "the vertices lie on the centerline: they must be drawn above it"
    group = project.layerTreeRoot().children()[0]
    assert group.name() == centerline_name.format("centerlines")
    assert [node.name() for node in group.children()] == expected, "the outputs of a run are kept together"
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
    assert (casing.width() - line.width()) / 2 >= 1.5 * PIXEL_MM, "the casing must show on both sides of the line"
    for symbol_layer in (casing, line):
        at_world_scale = width_at_scale(symbol_layer, 5e7)
        assert at_world_scale <= 0.5 * symbol_layer.width(), "a line as wide at world scale hides the rivers"
        assert width_at_scale(symbol_layer, 1e4) == pytest.approx(symbol_layer.width())
    # Within its channel at every scale: the line a quarter of the drawn mean width at most (never under a
    # hairline), the casing as much again.
    feature = next(centerline.getFeatures())
    for scale in (1e3, 1e4, 1e5, 1e6, 1e7):
        channel = feature["width_mean"] * 1000.0 / scale
        drawn = width_at_scale(line, scale, feature)
        assert drawn <= max(0.15, 0.25 * channel) + 1e-9, scale
        assert width_at_scale(casing, scale, feature) <= drawn + 0.25 * channel + 1e-9, scale
    assert width_at_scale(line, 1e3, feature) == pytest.approx(line.width()), "full width where the channel is wide"
    transect_colour = transects.renderer().symbol().color()
    for water in (RIVER_FILL, QColor(100, 160, 220), QColor(120, 180, 140), QColor(20, 60, 160)):
        assert colour_distance(transect_colour, water) >= 150, f"transects vanish on {water.name()} water"
    for layer in (vertices, circles):
        assert layer.hasScaleBasedVisibility() and layer.minimumScale() > 0, layer.name()
        assert layer.maximumScale() == 0, "shown at every larger scale"
    spacing = typical_vertex_spacing(vertices)
    assert spacing / vertices.minimumScale() * 1000.0 == pytest.approx(3.0, rel=0.01), "dots readable, no further"
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
    readable = settings.scale() <= vertices.minimumScale()
    assert dots_shown(vertices, settings, image) == (1.0 if readable else 0.0), "dots where they can be read"
    # Zoomed in to where the dots can be read, they show (and the centerline still does).
    zoomed = map_settings(project, layers)
    zoom = min(1.0, 0.8 * vertices.minimumScale() / zoomed.scale())
    zoomed.setExtent(zoomed.extent().scaled(zoom))
    zoomed_image = render(zoomed, artifacts / f"styled_{algorithm_name}_zoomed.png")
    assert zoomed.scale() <= vertices.minimumScale()
    assert dots_shown(vertices, zoomed, zoomed_image) == 1.0, "the vertex dots are hidden"

    rivers = [layer for layer in layers if layer.name() == "river"]
    if rivers:
        river_alone = sampled_pixels(render(map_settings(project, rivers)))
        inside = [colour for colour, alone in zip(pixels, river_alone) if close(alone, RIVER_FILL, 2)]
        assert inside, "the river is not drawn"
        keeps_fill = sum(1 for colour in inside if close(colour, RIVER_FILL, 12))
        assert keeps_fill >= 0.5 * len(inside), "the outputs hide the colour of the polygon they were made from"
    project.clear()
