"""Direct tests of the algorithm layer's pure helpers, with hand-computed values.

The helpers live in modules that import ``qgis``, so the plugin is loaded first (as QGIS imports it, as the
package ``incircu``) and the modules are taken from there.
"""

import importlib
import math

import numpy as np
import pytest
from qgis.core import QgsGeometry, QgsRectangle
from shapely.geometry import LineString


@pytest.fixture(scope="module")
def plugin_module(loaded_plugin):
    """Import a module of the loaded plugin by its name inside the plugin (``"algorithms.outputs"``)."""
    return lambda name: importlib.import_module(f"incircu.{name}")


def result(plugin_module, xs, radii, ends_found=False):
    """A centerline along the x axis through ``xs`` with the given incircle radii."""
    engine = plugin_module("incircu_plugin.core.engine")
    vertices = np.column_stack([xs, np.zeros(len(xs))]).astype(float)
    return engine.CenterlineResult(
        line=LineString(vertices),
        radii=np.asarray(radii, dtype=float),
        foot_a=vertices.copy(),
        foot_b=vertices.copy(),
        ends_found=ends_found,
    )


# width_statistics (algorithms/outputs.py) ---------------------------------------------------------------


def test_width_statistics_weights_the_mean_by_length(plugin_module):
    width_statistics = plugin_module("algorithms.outputs").width_statistics
    # Widths 0, 4, 8, 0 at chainages 0, 10, 20, 30: the ends (width 0) are left out, the mean is the
    # trapezoid integral over [10, 20], (4 + 8) / 2 * 10 = 60, over its length 10.
    statistics = width_statistics([result(plugin_module, [0, 10, 20, 30], [0, 2, 4, 0], ends_found=True)])
    assert statistics == {
        "length": 30.0,
        "width_min": 4.0,
        "width_mean": 6.0,
        "width_max": 8.0,
        "n_vertices": 4,
        "ends_found": True,
        "ends_from": None,
    }


def test_width_statistics_of_several_parts(plugin_module):
    width_statistics = plugin_module("algorithms.outputs").width_statistics
    first = result(plugin_module, [0, 10, 20, 30], [0, 2, 4, 0], ends_found=True)
    # Width 2 all along 15 units: integral 30.
    second = result(plugin_module, [0, 5, 10, 15], [1, 1, 1, 1], ends_found=False)
    statistics = width_statistics([first, second])
    assert statistics["length"] == 45.0
    assert statistics["n_vertices"] == 8
    assert (statistics["width_min"], statistics["width_max"]) == (2.0, 8.0)
    assert statistics["width_mean"] == pytest.approx((60.0 + 30.0) / (10.0 + 15.0), rel=1e-12)
    assert statistics["ends_found"] is False


def test_width_statistics_names_where_the_ends_came_from(plugin_module):
    width_statistics = plugin_module("algorithms.outputs").width_statistics
    polygon_result = plugin_module("incircu_plugin.core.api").PolygonCenterlineResult
    line = result(plugin_module, [0, 10], [1, 1])
    guided = polygon_result(line.line, line.radii, line.foot_a, line.foot_b, ends_from="guide")
    given = polygon_result(line.line, line.radii, line.foot_a, line.foot_b, ends_from="split_points")
    assert width_statistics([guided])["ends_from"] == "guide"
    assert width_statistics([guided, given, guided])["ends_from"] == "guide,split_points"


def test_width_statistics_with_one_or_no_positive_width(plugin_module):
    width_statistics = plugin_module("algorithms.outputs").width_statistics
    single = width_statistics([result(plugin_module, [0, 10, 20], [0, 3, 0])])
    assert (single["width_min"], single["width_mean"], single["width_max"]) == (6.0, 6.0, 6.0)
    none = width_statistics([result(plugin_module, [0, 10], [0, 0])])
    assert (none["width_min"], none["width_mean"], none["width_max"]) == (None, None, None)
    assert none["length"] == 10.0 and none["n_vertices"] == 2


# layer_margin (algorithms/split_points.py) --------------------------------------------------------------


def box_around_latitude(latitude):
    """A small square in degrees centred on longitude 20 and the given latitude."""
    return QgsGeometry.fromRect(QgsRectangle(19.9, latitude - 0.1, 20.1, latitude + 0.1))


def test_layer_margin_in_a_projected_layer_is_the_distance(plugin_module):
    layer_margin = plugin_module("algorithms.split_points").layer_margin
    assert layer_margin(25.0, box_around_latitude(52.0), False) == 25.0


@pytest.mark.parametrize(
    ("latitude", "expected_degrees"),
    [
        # 111 m is 0.001 degree of latitude (111 km per degree); the margin doubles it, and a degree of
        # longitude shrinks with cos(latitude): 0.002 at the equator, 0.004 at 60 degrees.
        (0.0, 0.002),
        (60.0, 0.004),
        # Near the pole cos(latitude) is clamped to 0.01: 0.002 / 0.01.
        (89.95, 0.2),
    ],
)
def test_layer_margin_in_a_geographic_layer_is_in_degrees(plugin_module, latitude, expected_degrees):
    layer_margin = plugin_module("algorithms.split_points").layer_margin
    geometry = box_around_latitude(latitude)
    assert geometry.boundingBox().center().y() == pytest.approx(latitude, abs=1e-12)
    assert layer_margin(111.0, geometry, True) == pytest.approx(expected_degrees, rel=1e-9)
    # Safe: the margin covers the distance along the parallel (the shorter degree) with room to spare.
    metres_per_degree = 111_000.0 * max(math.cos(math.radians(latitude)), 0.01)
    assert layer_margin(111.0, geometry, True) * metres_per_degree >= 111.0


# line_with_m (algorithms/convert.py) ----------------------------------------------------------------------


@pytest.mark.parametrize("as_array", [True, False])
def test_line_with_m_keeps_every_coordinate_and_width_exactly(plugin_module, as_array):
    line_with_m = plugin_module("algorithms.convert").line_with_m
    coordinates = [(0.1, 7.0), (1e6 + 0.3, -2.5), (3.0, 1e-7)]
    widths = [0.0, 12.25, 1.0 / 3.0]
    given = np.array(coordinates) if as_array else coordinates
    line = line_with_m(given, np.array(widths) if as_array else widths)
    assert line.isMeasure() and not line.is3D()
    assert [(vertex.x(), vertex.y(), vertex.m()) for vertex in line.vertices()] == [
        (x, y, m) for (x, y), m in zip(coordinates, widths)
    ]
    plain = line_with_m(given)
    assert not plain.isMeasure()
    assert [(vertex.x(), vertex.y()) for vertex in plain.vertices()] == coordinates
