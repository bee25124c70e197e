"""Geographic input: compute in a local azimuthal equidistant projection, so circles are circles on the ground.

Example
-------
>>> from shapely.geometry import box
>>> from incircu_plugin.core import polygon_centerline
>>> river = box(19.90, 50.05, 19.95, 50.0505)                  # lon/lat, about 3.6 km by 55 m
>>> projection = LocalProjection.around(river, "EPSG:4326")
>>> local = polygon_centerline(projection.to_local(river),
...                            [projection.to_local(p) for p in ((19.90, 50.05025), (19.95, 50.05025))],
...                            spacing=5.0)                    # metres
>>> result = projection.result_to_geographic(local)            # line in lon/lat, radii in metres
>>> 27 < float(result.radii[1:-1].mean()) < 28.5
True
"""

import functools
from dataclasses import replace

import numpy as np
import pyproj
import shapely
from pyproj.enums import TransformDirection

from .errors import InvalidGeometryError


class LocalProjection:
    """A pair of transformations between a geographic CRS and an azimuthal equidistant projection.

    Distances from the projection centre are true on the ellipsoid, and within a few hundred kilometres
    every distance and angle is close to true, so the engine's circles and ``spacing`` are in metres.

    Parameters
    ----------
    geographic_crs : str, int or pyproj.CRS
        The geographic CRS of the input (anything ``pyproj.CRS`` accepts: ``"EPSG:4326"``, WKT, ...).
    longitude, latitude : float
        Centre of the projection, degrees.
    """

    def __init__(self, geographic_crs, longitude, latitude):
        # A bare PROJ pipeline on the CRS's ellipsoid: building CRS objects and transformers between them would
        # cost some 40 ms per feature.
        self._transformer = pyproj.Transformer.from_pipeline(
            "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
            f"+step +proj=aeqd +lat_0={float(latitude)!r} +lon_0={float(longitude)!r} {_ellipsoid(geographic_crs)}"
        )

    @classmethod
    def around(cls, geometry, geographic_crs="EPSG:4326"):
        """Build the projection centred on the middle of a geometry's bounding box.

        Parameters
        ----------
        geometry : shapely.Geometry
            In longitude/latitude, degrees.
        geographic_crs : str, int or pyproj.CRS

        Returns
        -------
        LocalProjection
        """
        if geometry is None or geometry.is_empty:
            raise InvalidGeometryError("Cannot centre a projection on an empty geometry.")
        west, south, east, north = geometry.bounds
        return cls(geographic_crs, (west + east) / 2.0, (south + north) / 2.0)

    def _apply(self, direction, geometry):
        if isinstance(geometry, shapely.Geometry):
            return shapely.transform(geometry, lambda xy: _transform_array(self._transformer, xy, direction))
        return _transform_array(self._transformer, np.asarray(geometry, dtype=float), direction)

    def to_local(self, geometry):
        """Project a geometry or an ``(n, 2)`` array from degrees to local metres."""
        return self._apply(TransformDirection.FORWARD, geometry)

    def to_geographic(self, geometry):
        """Bring a geometry or an ``(n, 2)`` array from local metres back to degrees."""
        return self._apply(TransformDirection.INVERSE, geometry)

    def result_to_geographic(self, result):
        """Bring a :class:`CenterlineResult` back to degrees; its radii stay in metres."""
        return replace(
            result,
            line=self.to_geographic(result.line),
            foot_a=self.to_geographic(result.foot_a),
            foot_b=self.to_geographic(result.foot_b),
        )


@functools.lru_cache(maxsize=16)
def _ellipsoid(geographic_crs):
    """PROJ ellipsoid parameters (``+a=... +rf=...``) of a geographic CRS, checked to be geographic."""
    geographic = pyproj.CRS(geographic_crs)
    if not geographic.is_geographic:
        raise InvalidGeometryError(f"{geographic.name} is not a geographic CRS.")
    ellipsoid = geographic.ellipsoid
    if ellipsoid.inverse_flattening:
        return f"+a={ellipsoid.semi_major_metre!r} +rf={ellipsoid.inverse_flattening!r}"
    return f"+R={ellipsoid.semi_major_metre!r}"


def _transform_array(transformer, xy, direction):
    flat = np.asarray(xy, dtype=float).reshape(-1, 2)
    # pyproj takes a one-element array for a scalar (deprecated in numpy); give it at least two points.
    padded = np.concatenate([flat, flat[:1]]) if len(flat) == 1 else flat
    x, y = transformer.transform(padded[:, 0], padded[:, 1], direction=direction)
    return np.stack([x, y], axis=-1)[: len(flat)].reshape(np.shape(xy))


def degrees_covering(distance, latitude):
    """Return an angle, degrees, that spans at least ``distance`` metres east-west and north-south.

    A safe bounding-box margin in longitude/latitude around a feature at ``latitude`` (poles capped at a
    hundredth of the equator's scale).

    Parameters
    ----------
    distance : float or ndarray
        Metres.
    latitude : float or ndarray
        Degrees.

    Returns
    -------
    float or ndarray
        Degrees, twice the equatorial equivalent divided by the cosine of the latitude.
    """
    return 2.0 * distance / (111_000.0 * np.maximum(np.cos(np.radians(latitude)), 0.01))
