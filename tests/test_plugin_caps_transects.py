"""END_CAP and TRANSECT_STYLE through ``processing.run``: the run-out at a slanted cut (the default), the exact
axis on request, straight and nearest-bank transects with their ``method``; pictures of both, rendered by QGIS
offscreen, in ``tests/artifacts/`` (end_caps_*.png, transects_*.png)."""

import math

import numpy as np
import processing
import pytest
import shapely
from qgis.core import (
    QgsFeature,
    QgsFillSymbol,
    QgsGeometry,
    QgsLineSymbol,
    QgsProcessingFeedback,
    QgsRectangle,
    QgsSingleSymbolRenderer,
    QgsVectorLayer,
)
from qgis.PyQt.QtGui import QColor

from tests.support.maps import map_settings, render
from tests.support.project import DATA

WIDTH, LENGTH, SLANT = 40.0, 1000.0, math.radians(40.0)


def slanted_channel():
    """A channel along x, ``WIDTH`` wide, both ends cut 40 degrees off square, with its cuts' middles."""
    shift = math.tan(SLANT) * WIDTH / 2
    polygon = QgsVectorLayer("Polygon?crs=EPSG:2180", "channel", "memory")
    feature = QgsFeature()
    ring = f"{-shift} 0, {LENGTH - shift} 0, {LENGTH + shift} {WIDTH}, {shift} {WIDTH}, {-shift} 0"
    feature.setGeometry(QgsGeometry.fromWkt(f"POLYGON(({ring}))"))
    polygon.dataProvider().addFeatures([feature])
    ends = QgsVectorLayer("Point?crs=EPSG:2180", "ends", "memory")
    points = []
    for x in (0.0, LENGTH):
        point = QgsFeature()
        point.setGeometry(QgsGeometry.fromWkt(f"POINT({x} {WIDTH / 2})"))
        points.append(point)
    ends.dataProvider().addFeatures(points)
    return polygon, ends


def run(parameters):
    feedback = QgsProcessingFeedback()
    return processing.run("incircu:polygoncenterline", {"OUTPUT": "memory:", **parameters}, feedback=feedback)


def line_of(results):
    (feature,) = results["OUTPUT"].getFeatures()
    geometry = QgsGeometry(feature.geometry())
    geometry.get().dropMValue()
    return shapely.get_coordinates(shapely.from_wkb(bytes(geometry.asWkb())))


def first_turn(coordinates):
    """Angle, degrees, of the first and last segments to the channel's axis (the x axis)."""
    return [
        math.degrees(math.atan2(abs(step[1]), abs(step[0])))
        for step in (coordinates[1] - coordinates[0], coordinates[-1] - coordinates[-2])
    ]


def test_the_default_line_runs_out_along_the_axis_and_the_exact_axis_is_a_choice(provider):
    polygon, ends = slanted_channel()
    runout = line_of(run({"INPUT": polygon, "SPLIT_POINTS": ends}))
    exact = line_of(run({"INPUT": polygon, "SPLIT_POINTS": ends, "END_CAP": 1}))
    # The adaptive tolerance is WIDTH / 200: a run-out about a width long turns by at most about 1/100 rad.
    assert max(first_turn(runout)) <= 1.0
    assert min(first_turn(exact)) > 10.0
    assert np.allclose(runout[[0, -1]], [(0.0, WIDTH / 2), (LENGTH, WIDTH / 2)], atol=1e-6)
    assert np.array_equal(runout[[0, -1]], exact[[0, -1]])


@pytest.mark.parametrize(("style", "method"), ((0, "straight"), (1, "nearest"), (None, "straight")))
def test_transects_say_their_method(provider, style, method):
    polygon, ends = slanted_channel()
    parameters = {"INPUT": polygon, "SPLIT_POINTS": ends, "OUTPUT_TRANSECTS": "memory:", "TRANSECT_INTERVAL": 100.0}
    if style is not None:
        parameters["TRANSECT_STYLE"] = style
    transects = list(run(parameters)["OUTPUT_TRANSECTS"].getFeatures())
    assert len(transects) == 9
    for transect in transects:
        assert transect["method"] == method
        start, _, end = (np.array([point.x(), point.y()]) for point in transect.geometry().vertices())
        # On parallel banks both are square to them, WIDTH long, within the adaptive tolerance.
        assert transect["width"] == pytest.approx(WIDTH, abs=WIDTH / 100)
        assert abs(start[0] - end[0]) <= WIDTH / 100 and sorted([start[1], end[1]]) == pytest.approx(
            [0, WIDTH], abs=1e-6
        )


def styled(layer, symbol):
    layer.setRenderer(QgsSingleSymbolRenderer(symbol))
    return layer


def render_png(layers, extent, path):
    """Draw ``layers`` (the first on top) over ``extent`` to a 1000 x 700 PNG at ``path``; return the image."""
    return render(map_settings(layers, extent, (1000, 700)), path)


def water(layer):
    return styled(layer, QgsFillSymbol.createSimple({"color": "170,205,235", "outline_color": "60,90,140"}))


def red_line(layer):
    return styled(layer, QgsLineSymbol.createSimple({"line_color": "220,30,30", "line_width": "0.8"}))


def red_pixels(image):
    return sum(
        1
        for y in range(0, image.height(), 2)
        for x in range(0, image.width(), 2)
        if QColor(image.pixel(x, y)).red() > 170 and QColor(image.pixel(x, y)).green() < 80
    )


def test_screenshots_of_joined_reaches_at_a_slanted_cut(provider, artifacts):
    """Two reaches of one channel share a cut 40 degrees off square: the exact axis zig-zags at the joint, the
    run-out meets it in line. Written to tests/artifacts/end_caps_axis.png and end_caps_runout.png."""
    shift = math.tan(SLANT) * WIDTH / 2
    reaches = QgsVectorLayer("Polygon?crs=EPSG:2180", "reaches", "memory")
    features = []
    for start in (0.0, 300.0):
        feature = QgsFeature()
        end = start + 300.0
        ring = f"{start - shift} 0, {end - shift} 0, {end + shift} {WIDTH}, {start + shift} {WIDTH}, {start - shift} 0"
        feature.setGeometry(QgsGeometry.fromWkt(f"POLYGON(({ring}))"))
        features.append(feature)
    reaches.dataProvider().addFeatures(features)
    ends = QgsVectorLayer("Point?crs=EPSG:2180", "split points", "memory")
    points = []
    for x in (0.0, 300.0, 600.0):
        point = QgsFeature()
        point.setGeometry(QgsGeometry.fromWkt(f"POINT({x} {WIDTH / 2})"))
        points.append(point)
    ends.dataProvider().addFeatures(points)
    extent = QgsRectangle(300.0 - 3 * WIDTH, WIDTH / 2 - 2.1 * WIDTH, 300.0 + 3 * WIDTH, WIDTH / 2 + 2.1 * WIDTH)
    counts = {}
    for name, end_cap in (("axis", 1), ("runout", 0)):
        lines = red_line(run({"INPUT": reaches, "SPLIT_POINTS": ends, "END_CAP": end_cap})["OUTPUT"])
        counts[name] = red_pixels(render_png([lines, water(reaches)], extent, artifacts / f"end_caps_{name}.png"))
    # The straight run-out draws the shortest red path across the picture; the zig-zag a longer one.
    assert 0 < counts["runout"] < counts["axis"]


def test_screenshots_of_straight_and_nearest_transects_on_the_sample_river(provider, artifacts):
    """Written to tests/artifacts/transects_nearest.png and transects_straight.png."""
    river = QgsVectorLayer(str(DATA / "river_2180.geojson"), "river", "ogr")
    parameters = {
        "INPUT": river,
        "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
        "OUTPUT_TRANSECTS": "memory:",
        "TRANSECT_INTERVAL": 40.0,
    }
    # The reach with an island (a polygon with a hole), where the two styles differ most.
    (island_reach,) = [
        f
        for f in river.getFeatures()
        if f.geometry().constGet().exteriorRing() is not None and f.geometry().constGet().numInteriorRings()
    ]
    extent = island_reach.geometry().boundingBox()
    extent = extent.buffered(0.05 * extent.width())
    for name, style in (("nearest", 1), ("straight", 0)):
        results = run({**parameters, "TRANSECT_STYLE": style})
        transects = styled(
            results["OUTPUT_TRANSECTS"], QgsLineSymbol.createSimple({"line_color": "230,120,0", "line_width": "0.4"})
        )
        image = render_png(
            [transects, red_line(results["OUTPUT"]), water(river)], extent, artifacts / f"transects_{name}.png"
        )
        assert red_pixels(image) > 100
