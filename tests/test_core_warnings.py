"""No Python warnings on any polygon of ``tests/data``, computed as the plugin computes a layer.

QGIS shows every Python warning with its traceback in its log, so the core must raise none, also on the
system GEOS QGIS links (``make test`` runs this file again on QGIS's Shapely with warnings as errors). Each
layer goes through ``centerlines_together`` (the plugin's batches), once with automatic ends; layers in degrees
(a GeoJSON without ``crs``, coordinates within ±360) are moved to local metres first, as the plugin does.
"""

import json
import warnings

import numpy as np
import pytest
import shapely
from shapely.geometry import Point, Polygon

from incircu_plugin.core import LocalProjection, find_ends, polygon_centerline
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core.api import _multipolygon_centerline_steps
from tests.support.project import DATA


def polygon_layers():
    """The files of ``tests/data`` holding polygons, and their polygons (in local metres for degrees)."""
    layers = {}
    for path in sorted(DATA.glob("*.geojson")):
        collection = json.loads(path.read_text(encoding="utf-8"))
        features = collection.get("features", [collection])
        shapes = [
            shapely.geometry.shape(feature["geometry"])
            for feature in features
            if feature.get("geometry") and "Polygon" in feature["geometry"]["type"]
        ]
        if shapes:
            in_degrees = "crs" not in collection and max(max(map(abs, shape.bounds)) for shape in shapes) <= 360.0
            if in_degrees:
                shapes = [LocalProjection.around(shape).to_local(shape) for shape in shapes]
            layers[path.name] = shapes
    return layers


LAYERS = polygon_layers()


@pytest.mark.parametrize("name", sorted(LAYERS))
def test_no_warning_on_a_polygon_layer_of_the_test_data(name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        outcomes = list(run_many_steps([_multipolygon_centerline_steps(shape) for shape in LAYERS[name]]))
    raised = [outcome for outcome in outcomes if isinstance(outcome, Warning)]
    assert not raised, raised
    assert len(outcomes) == len(LAYERS[name])


def test_the_data_holds_every_kind_of_polygon_layer():
    # The guard above must not pass on an empty list: the reservoirs, the Gambia (projected and in degrees)
    # and the rivers are there.
    assert {"real_rivers_ne_lonlat.geojson", "gambia_ne10m_lonlat.geojson", "river_2180.geojson"} <= set(LAYERS)
    assert len(LAYERS["real_rivers_ne_lonlat.geojson"]) >= 10


def with_repeated_vertices(ring):
    """``ring`` (closed, an (n, 2) array) with each vertex given twice: zero-length segments everywhere."""
    return np.repeat(np.asarray(ring, dtype=float)[:-1], 2, axis=0).tolist() + [list(ring[0])]


def test_repeated_vertices_bring_no_warning():
    # A zero-length segment made GEOS 3.11 divide 0 by 0 while locating a point on the ring (the Cheboksary
    # reservoir of the real rivers has one): numpy warned from line_locate_point, QGIS showed the traceback.
    outline = [(0.0, 0.0), (100.0, 0.0), (100.0, 10.0), (50.0, 14.0), (0.0, 10.0), (0.0, 0.0)]
    island = [(40.0, 4.0), (60.0, 4.0), (60.0, 8.0), (40.0, 8.0), (40.0, 4.0)]
    polygon = Polygon(with_repeated_vertices(outline), [with_repeated_vertices(island)])
    assert polygon.is_valid
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ends = find_ends(polygon)
        automatic = polygon_centerline(polygon)
        given = polygon_centerline(polygon, [Point(0.0, 5.0), Point(100.0, 5.0)])
    width = 10.0
    assert ends.start.distance(ends.end) > 90.0
    for result in (automatic, given):
        assert result.line.length > 100.0 - 2.0 * width
        assert polygon.buffer(1e-9).contains(result.line)
