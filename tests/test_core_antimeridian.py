"""Geographic input across the antimeridian: the line's longitudes stay continuous, never wrap round the globe.

A 0.14-degree channel on the equator centred on 180 degrees, stored unwrapped (179.93 to 180.07) or wrapped
(179.93 to 180, then -180 to -179.93). Its centerline runs along the equator, about 15.6 km on the ground.
"""

import numpy as np
import pyproj
import pytest
import shapely

from incircu_plugin.core import InvalidGeometryError, LocalProjection, polygon_centerline
from incircu_plugin.core.geodesy import central_longitude

WEST, EAST, HALF_WIDTH = 179.93, 180.07, 0.0005
GEOD = pyproj.Geod(ellps="WGS84")


def wrap(longitudes):
    return (np.asarray(longitudes) + 180.0) % 360.0 - 180.0


def channel(wrapped):
    ring = shapely.segmentize(shapely.box(WEST, -HALF_WIDTH, EAST, HALF_WIDTH), 0.01)
    if wrapped:
        ring = shapely.transform(ring, lambda xy: np.stack([wrap(xy[:, 0]), xy[:, 1]], axis=1))
    return ring


@pytest.mark.parametrize("wrapped", [False, True], ids=["unwrapped", "wrapped"])
def test_centerline_across_the_antimeridian_is_continuous(wrapped):
    polygon = channel(wrapped)
    ends = np.array([[WEST, 0.0], [wrap(EAST) if wrapped else EAST, 0.0]])
    projection = LocalProjection.around(polygon, "EPSG:4326")
    local = polygon_centerline(projection.to_local(polygon), projection.to_local(ends), spacing=50.0)
    line = np.asarray(projection.result_to_geographic(local).line.coords)
    # Continuous: the whole line within the channel's 0.14 degrees of longitude (a wrapped one spans 360).
    assert np.ptp(line[:, 0]) == pytest.approx(EAST - WEST, abs=1e-9)
    assert np.abs(wrap(line[[0, -1], 0]) - wrap(ends[:, 0])).max() < 1e-9
    _, _, ground = GEOD.inv(WEST, 0.0, EAST, 0.0)
    assert local.length == pytest.approx(ground, rel=1e-3)


def test_central_longitude_of_a_wrapped_shape_is_near_180():
    assert abs(wrap(central_longitude(wrap([179.93, 180.0, 180.07])) - 180.0)) < 1e-9
    assert central_longitude([10.0, 20.0]) == 15.0
    # Spanning more than 180 degrees either way: the bounding box's middle.
    assert central_longitude([-170.0, 0.0, 170.0]) == 0.0


@pytest.mark.parametrize("centre", [(float("nan"), 0.0), (0.0, 95.0), (float("inf"), 0.0)])
def test_projection_centre_must_be_a_longitude_and_a_latitude(centre):
    with pytest.raises(InvalidGeometryError, match="not a longitude and a latitude"):
        LocalProjection("EPSG:4326", *centre)


def test_unknown_crs_is_a_typed_error():
    with pytest.raises(InvalidGeometryError, match="Unknown CRS"):
        LocalProjection("EPSG:999999", 0.0, 0.0)


@pytest.mark.parametrize("point", [(float("nan"), 0.0), (0.0, 91.0)], ids=["nan", "beyond-pole"])
def test_point_that_cannot_be_projected_is_a_typed_error(point):
    with pytest.raises(InvalidGeometryError, match="could not be projected"):
        LocalProjection("EPSG:4326", 0.0, 0.0).to_local(np.array([point, (1.0, 1.0)]))
