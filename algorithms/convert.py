"""Geometry hand-over between QGIS and the core: WKB conversion and the local metric frame of geographic layers."""

from dataclasses import dataclass, replace
from typing import Optional

import numpy as np
import shapely
from qgis.core import (
    QgsGeometry,
    QgsLineString,
    QgsMultiLineString,
    QgsWkbTypes,
)

from ..incircu_plugin.core.geodesy import LocalProjection
from .compat import CrsWktVariant
from .units import CORE_LENGTH_UNIT, length_unit


def to_shapely(geometry):
    """Convert a QGIS geometry to a 2-D Shapely geometry through WKB.

    Parameters
    ----------
    geometry : QgsGeometry
        Any geometry; curves are approximated by straight segments (QGIS's default tolerance), Z and M values
        are dropped.

    Returns
    -------
    shapely.Geometry
    """
    flat = QgsGeometry(geometry)
    if QgsWkbTypes.isCurvedType(flat.wkbType()):
        flat.convertToStraightSegment()
    flat.get().dropZValue()
    flat.get().dropMValue()
    return shapely.from_wkb(bytes(flat.asWkb()))


def from_shapely(geometry):
    """Convert a Shapely geometry to a QGIS geometry through WKB.

    Parameters
    ----------
    geometry : shapely.Geometry

    Returns
    -------
    QgsGeometry
    """
    converted = QgsGeometry()
    converted.fromWkb(shapely.to_wkb(geometry))
    return converted


def line_with_m(coordinates, m_values=None):
    """Build a QGIS line string, with M values when given.

    Parameters
    ----------
    coordinates : array_like of shape (n, 2)
        Vertices, CRS units.
    m_values : array_like of shape (n,), optional
        One M value per vertex (IncirCu stores the local width there).

    Returns
    -------
    QgsLineString
    """
    # Columns to Python floats in one call each (a Python loop over numpy rows costs about 1 µs per vertex).
    coordinates = np.asarray(coordinates, dtype=float).reshape(-1, 2)
    ms = [] if m_values is None else np.asarray(m_values, dtype=float).tolist()
    return QgsLineString(coordinates[:, 0].tolist(), coordinates[:, 1].tolist(), [], ms)


def collect_lines(lines):
    """Put several QGIS line strings into one multi-line geometry.

    Parameters
    ----------
    lines : iterable of QgsLineString

    Returns
    -------
    QgsGeometry
        A MultiLineString (with M when the lines have M).
    """
    multi = QgsMultiLineString()
    for line in lines:
        multi.addGeometry(line)
    return QgsGeometry(multi)


@dataclass(frozen=True)
class WorkingFrame:
    """The coordinate frame the core computes in, and the way back to the layer's CRS; a value.

    Projected layers are used as they are. A geographic layer (degrees) is computed in the core's
    :class:`LocalProjection`, an azimuthal equidistant projection centred on each feature, so lengths,
    widths, ``SPACING`` and ``SNAP_TOLERANCE`` are in metres: :meth:`around` returns the frame of one feature
    (the layer's frame is never changed).

    Attributes
    ----------
    unit : str
        Abbreviation of the unit of the frame's lengths, for messages (:func:`length_unit`).
    geographic_crs : str or None
        The layer's CRS (an EPSG code or WKT) when it is in degrees.
    projection : LocalProjection or None
        The feature's local projection (None for a projected layer, or the layer's frame).
    """

    unit: str
    geographic_crs: Optional[str] = None
    projection: Optional[LocalProjection] = None

    @classmethod
    def of_layer(cls, crs):
        """The frame of a layer in ``crs`` (a ``QgsCoordinateReferenceSystem``), before any feature."""
        geographic_crs = None
        if crs.isGeographic():
            authority = crs.authid()
            geographic_crs = authority if authority.upper().startswith("EPSG:") else crs.toWkt(CrsWktVariant.Wkt2_2019)
        return cls(length_unit(crs), geographic_crs)

    def named_lengths(self, message):
        """Return a core message with its lengths' unit named as the frame's (the core says "CRS units": of the
        coordinates it computed in, metres for a layer in degrees)."""
        return message.replace(CORE_LENGTH_UNIT, self.unit)

    @property
    def is_geographic(self):
        """True when the layer is in degrees and results are computed in metres."""
        return self.geographic_crs is not None

    def around(self, geometry):
        """Return the frame of one feature: centred on ``geometry`` (a ``QgsGeometry`` of the layer, degrees for
        a geographic layer); the layer's frame itself for a projected layer."""
        if not self.is_geographic:
            return self
        # Not the bounding box's centre: a shape across the antimeridian may be stored wrapped (-180..180).
        return replace(self, projection=LocalProjection.around(to_shapely(geometry), self.geographic_crs))

    def to_core(self, geometry):
        """Return a QGIS geometry of the layer as a Shapely geometry in the working frame."""
        shape = to_shapely(geometry)
        return shape if self.projection is None else self.projection.to_local(shape)

    def coordinates_to_core(self, coordinates):
        """Return layer coordinates (a sequence of (x, y) pairs) as an ``(n, 2)`` array in the working frame
        (metres for a geographic layer)."""
        coordinates = np.asarray(coordinates, dtype=float).reshape(-1, 2)
        return coordinates if self.projection is None else self.projection.to_local(coordinates)

    def to_layer(self, shape):
        """Return a Shapely geometry or ``(n, 2)`` array of the working frame in the layer's CRS."""
        return shape if self.projection is None else self.projection.to_geographic(shape)
