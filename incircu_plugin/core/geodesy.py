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
import math
from dataclasses import replace

import numpy as np
import shapely

from .errors import InvalidGeometryError, Message

#: Directions of a PROJ transformation, as ``pyproj``'s ``Transformer.transform`` takes them.
FORWARD, INVERSE = "FORWARD", "INVERSE"


def _pyproj():
    """The ``pyproj`` module, imported on first use: only longitude/latitude data needs it, and importing it
    costs about 0.1 s of every run on projected data."""
    import pyproj

    return pyproj


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
        if not (math.isfinite(longitude) and math.isfinite(latitude) and abs(latitude) <= 90.0):
            raise InvalidGeometryError(Message("centre_not_degrees", longitude=longitude, latitude=latitude))
        self.longitude = float(longitude)
        # A bare PROJ pipeline on the CRS's ellipsoid: building CRS objects and transformers between them would
        # cost some 40 ms per feature.
        self._transformer = _pyproj().Transformer.from_pipeline(
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
        if geometry is None:
            raise InvalidGeometryError(Message("centre_null"))
        if not isinstance(geometry, shapely.Geometry):
            raise TypeError(f"Expected a shapely geometry in degrees, got {type(geometry).__name__}.")
        if geometry.is_empty:
            raise InvalidGeometryError(Message("centre_empty"))
        coordinates = shapely.get_coordinates(geometry)
        if not np.all(np.isfinite(coordinates)):
            raise InvalidGeometryError(Message("centre_not_finite"))
        _, south, _, north = geometry.bounds
        return cls(geographic_crs, central_longitude(coordinates[:, 0]), (south + north) / 2.0)

    def _apply(self, direction, geometry):
        if isinstance(geometry, shapely.Geometry):
            return shapely.transform(geometry, lambda xy: self._transform(xy, direction))
        return self._transform(np.asarray(geometry, dtype=float), direction)

    def _transform(self, xy, direction):
        transformed = _transform_array(self._transformer, xy, direction)
        if direction == INVERSE:
            # PROJ returns longitudes in [-180, 180]; keep them within 180 degrees of the centre instead, so a
            # shape across the antimeridian stays continuous (longitudes beyond 180 or below -180).
            longitude = transformed[..., 0]
            transformed[..., 0] = self.longitude + (longitude - self.longitude + 180.0) % 360.0 - 180.0
        elif not np.all(np.isfinite(transformed)):
            raise InvalidGeometryError(Message("point_not_projected"))
        return transformed

    def to_local(self, geometry):
        """Project a geometry or an ``(n, 2)`` array from degrees to local metres.

        Longitudes are taken modulo 360 degrees, so a shape across the antimeridian may be stored either way
        (179.9 to 180.1, or wrapped as 179.9 and -179.9).
        """
        return self._apply(FORWARD, geometry)

    def to_geographic(self, geometry):
        """Bring a geometry or an ``(n, 2)`` array from local metres back to degrees.

        Longitudes lie within 180 degrees of the projection centre: a line across the antimeridian comes back
        continuous (for example from 179.9 to 180.1), never wrapped round the globe.
        """
        return self._apply(INVERSE, geometry)

    def result_to_geographic(self, result):
        """Bring a :class:`CenterlineResult` back to degrees (its line, feet and chains); its radii stay in
        metres."""
        chains = None if result.chains is None else tuple(self.to_geographic(chain) for chain in result.chains)
        return replace(
            result,
            line=self.to_geographic(result.line),
            foot_a=self.to_geographic(result.foot_a),
            foot_b=self.to_geographic(result.foot_b),
            chains=chains,
        )


def central_longitude(longitudes):
    """Return the middle of the shortest longitude interval holding every given longitude, degrees.

    A shape across the antimeridian stored wrapped (longitudes near 180 and near -180, spanning less than 180
    degrees the short way) gets a centre near 180, not near 0 as its bounding box would give; any other shape
    gets its bounding box's middle.

    Parameters
    ----------
    longitudes : array_like of float
        Degrees.

    Returns
    -------
    float
        Degrees: the bounding box's middle, or for a wrapped shape a value in (-180, 180].
    """
    values = np.asarray(longitudes, dtype=float).ravel()
    west, east = float(values.min()), float(values.max())
    around = np.sort(values % 360.0)
    gaps = np.diff(np.concatenate([around, around[:1] + 360.0]))
    widest = int(np.argmax(gaps))
    if 360.0 - gaps[widest] >= min(east - west, 180.0):
        return (west + east) / 2.0
    start = around[(widest + 1) % len(around)]
    middle = start + (360.0 - gaps[widest]) / 2.0
    return float(180.0 - (180.0 - middle) % 360.0)


@functools.lru_cache(maxsize=16)
def _ellipsoid(geographic_crs):
    """PROJ ellipsoid parameters (``+a=... +rf=...``) of a geographic CRS, checked to be geographic."""
    pyproj = _pyproj()
    try:
        geographic = pyproj.CRS(geographic_crs)
    except pyproj.exceptions.CRSError as error:
        raise InvalidGeometryError(Message("unknown_crs", crs=geographic_crs, error=str(error))) from None
    if not geographic.is_geographic:
        raise InvalidGeometryError(Message("not_geographic_crs", name=geographic.name))
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
