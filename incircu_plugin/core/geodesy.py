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

from dataclasses import replace

import numpy as np
import pyproj
import shapely
from pyproj.crs.coordinate_operation import AzimuthalEquidistantConversion

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
        geographic = pyproj.CRS(geographic_crs)
        if not geographic.is_geographic:
            raise InvalidGeometryError(f"{geographic.name} is not a geographic CRS.")
        conversion = AzimuthalEquidistantConversion(
            latitude_natural_origin=float(latitude), longitude_natural_origin=float(longitude)
        )
        local = pyproj.crs.ProjectedCRS(conversion=conversion, geodetic_crs=geographic.geodetic_crs)
        self._forward = pyproj.Transformer.from_crs(geographic, local, always_xy=True)
        self._inverse = pyproj.Transformer.from_crs(local, geographic, always_xy=True)

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

    @staticmethod
    def _apply(transformer, geometry):
        if isinstance(geometry, shapely.Geometry):
            return shapely.transform(geometry, lambda xy: _transform_array(transformer, xy))
        return _transform_array(transformer, np.asarray(geometry, dtype=float))

    def to_local(self, geometry):
        """Project a geometry or an ``(n, 2)`` array from degrees to local metres."""
        return self._apply(self._forward, geometry)

    def to_geographic(self, geometry):
        """Bring a geometry or an ``(n, 2)`` array from local metres back to degrees."""
        return self._apply(self._inverse, geometry)

    def result_to_geographic(self, result):
        """Bring a :class:`CenterlineResult` back to degrees; its radii stay in metres."""
        return replace(
            result,
            line=self.to_geographic(result.line),
            foot_a=self.to_geographic(result.foot_a),
            foot_b=self.to_geographic(result.foot_b),
        )


def _transform_array(transformer, xy):
    flat = np.asarray(xy, dtype=float).reshape(-1, 2)
    # pyproj takes a one-element array for a scalar (deprecated in numpy); give it at least two points.
    padded = np.concatenate([flat, flat[:1]]) if len(flat) == 1 else flat
    x, y = transformer.transform(padded[:, 0], padded[:, 1])
    return np.stack([x, y], axis=-1)[: len(flat)].reshape(np.shape(xy))
