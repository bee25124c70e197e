"""END_CAP and TRANSECT_STYLE through ``processing.run``: the run-out at a slanted cut (the default), the exact
axis on request, straight and nearest-bank transects with their ``method``."""

import math

import numpy as np
import processing
import pytest
import shapely
from qgis.core import QgsFeature, QgsGeometry, QgsProcessingFeedback, QgsVectorLayer

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
