"""Geographic input: the centerline of a lon/lat polygon is computed in a local azimuthal equidistant frame.

The Natural Earth Gambia in degrees is projected with :class:`LocalProjection`, its centerline computed in
metres and brought back to degrees. On the ground (pyproj's geodesic on WGS 84) each incircle radius must
equal the geodesic distance from its vertex to its touching points, up to the projection's distortion: an
azimuthal equidistant projection keeps distances from its centre true and stretches distances across by
``c / sin(c) - 1 ~ c**2 / 6`` at an angular distance ``c`` from the centre.
"""

import math

import numpy as np
import pyproj
import pytest
import shapely

from incircu_plugin.core import InvalidGeometryError, LocalProjection, polygon_centerline
from incircu_plugin.core.geodesy import degrees_covering
from tests.support import geometry_cases
from tests.support.oracle import check_centerline

EARTH_RADIUS = 6_371_000.0
GEOD = pyproj.Geod(ellps="WGS84")


@pytest.fixture(scope="module")
def gambia_lonlat():
    return geometry_cases.gambia(projected=False)


@pytest.fixture(scope="module")
def projected_result(gambia_lonlat):
    case = gambia_lonlat
    projection = LocalProjection.around(case.polygon, "EPSG:4326")
    local_polygon = projection.to_local(case.polygon)
    local_ends = [tuple(projection.to_local(np.asarray(p))) for p in case.split_points]
    local = polygon_centerline(local_polygon, local_ends, spacing=500.0)
    return projection, local_polygon, local_ends, local


def test_projection_round_trip_is_exact_to_a_nanodegree(gambia_lonlat):
    projection = LocalProjection.around(gambia_lonlat.polygon, "EPSG:4326")
    ring = np.asarray(gambia_lonlat.polygon.exterior.coords)
    back = projection.to_geographic(projection.to_local(ring))
    assert np.abs(back - ring).max() <= 1e-9


def test_local_frame_is_in_metres_and_centred(gambia_lonlat, projected_result):
    _, local_polygon, _, _ = projected_result
    x0, y0, x1, y1 = local_polygon.bounds
    # The Gambia is about 330 km east-west and 80 km north-south, centred on the projection's origin.
    assert 3.0e5 < x1 - x0 < 3.6e5 and 6.0e4 < y1 - y0 < 1.0e5
    assert abs(x0 + x1) < 0.1 * (x1 - x0) and abs(y0 + y1) < 0.1 * (y1 - y0)


def test_invariants_hold_in_the_local_frame(gambia_lonlat, projected_result):
    projection, local_polygon, local_ends, local = projected_result
    chain_a = projection.to_local(gambia_lonlat.chain_a)
    chain_b = projection.to_local(gambia_lonlat.chain_b)
    check_centerline(local, chain_a, chain_b, local_polygon, local_ends)


def test_radii_are_ground_distances_to_the_feet(gambia_lonlat, projected_result):
    projection, local_polygon, _, local = projected_result
    result = projection.result_to_geographic(local)
    vertices = np.asarray(result.line.coords)[1:-1]
    radii = result.radii[1:-1]
    # Largest angular distance of the shape from the projection centre, radians.
    x0, y0, x1, y1 = local_polygon.bounds
    reach = math.hypot(max(abs(x0), abs(x1)), max(abs(y0), abs(y1))) / EARTH_RADIUS
    stretch = reach / math.sin(reach) - 1.0
    for feet in (result.foot_a[1:-1], result.foot_b[1:-1]):
        _, _, ground = GEOD.inv(vertices[:, 0], vertices[:, 1], feet[:, 0], feet[:, 1])
        # Ellipsoid versus sphere in the stretch estimate: allow twice the spherical figure, plus a millimetre.
        assert np.all(np.abs(ground - radii) <= 2.0 * stretch * radii + 1e-3), float(np.max(np.abs(ground - radii)))


def test_line_comes_back_in_degrees_between_the_split_points(gambia_lonlat, projected_result):
    projection, _, _, local = projected_result
    result = projection.result_to_geographic(local)
    coords = np.asarray(result.line.coords)
    assert np.abs(coords[0] - gambia_lonlat.split_points[0]).max() <= 1e-9
    assert np.abs(coords[-1] - gambia_lonlat.split_points[1]).max() <= 1e-9
    assert shapely.distance(gambia_lonlat.polygon, shapely.points(coords)).max() <= 1e-9
    # The chains it lies between come back too: each is one side of the outline, in degrees.
    for chain in result.chains:
        assert shapely.distance(gambia_lonlat.polygon.exterior, shapely.points(chain)).max() <= 1e-9


def test_projected_crs_is_refused_as_geographic():
    with pytest.raises(InvalidGeometryError):
        LocalProjection("EPSG:32628", -15.0, 13.5)


def test_empty_geometry_has_no_centre():
    with pytest.raises(InvalidGeometryError):
        LocalProjection.around(shapely.Polygon(), "EPSG:4326")


@pytest.mark.parametrize("latitude", [0.0, 45.0, 70.0, -85.0])
def test_degrees_covering_spans_the_distance_in_both_directions(latitude):
    distance = 1500.0
    margin = float(degrees_covering(distance, latitude))
    projection = LocalProjection("EPSG:4326", 10.0, latitude)
    east, north = projection.to_local(np.array([[10.0 + margin, latitude], [10.0, min(latitude + margin, 90.0)]]))
    assert np.hypot(*east) >= distance
    assert np.hypot(*north) >= distance
