"""Geometry hand-over between QGIS and the core: WKB conversion and the local metric frame of geographic layers."""

import shapely
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsGeometry,
    QgsLineString,
    QgsMultiLineString,
)


def to_shapely(geometry):
    """Convert a QGIS geometry to a 2-D Shapely geometry through WKB.

    Parameters
    ----------
    geometry : QgsGeometry
        Any geometry; Z and M values are dropped.

    Returns
    -------
    shapely.Geometry
    """
    flat = QgsGeometry(geometry)
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
    xs = [float(x) for x, _ in coordinates]
    ys = [float(y) for _, y in coordinates]
    ms = [] if m_values is None else [float(m) for m in m_values]
    return QgsLineString(xs, ys, [], ms)


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


class WorkingFrame:
    """The coordinate frame the core computes in, and the way back to the layer's CRS.

    Projected layers are used as they are. A geographic layer (degrees) is computed in an azimuthal
    equidistant projection centred on each feature, so lengths, widths, ``SPACING`` and
    ``SNAP_TOLERANCE`` are in metres and distortion stays negligible at the scale of one river reach.

    Parameters
    ----------
    crs : QgsCoordinateReferenceSystem
        CRS of the layer.
    transform_context : QgsCoordinateTransformContext
    """

    def __init__(self, crs, transform_context):
        self.crs = crs
        self.transform_context = transform_context
        self.is_geographic = crs.isGeographic()
        self.forward = None
        self.backward = None

    def centre_on(self, geometry):
        """Centre the local projection on a geometry of the layer (no effect for projected layers).

        Parameters
        ----------
        geometry : QgsGeometry
            Geometry in the layer's CRS (degrees for geographic layers).
        """
        if not self.is_geographic:
            return
        centre = geometry.boundingBox().center()
        local = QgsCoordinateReferenceSystem.fromProj(
            "+proj=aeqd +lat_0={:.9f} +lon_0={:.9f} +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs".format(
                centre.y(), centre.x()
            )
        )
        self.forward = QgsCoordinateTransform(self.crs, local, self.transform_context)
        self.backward = QgsCoordinateTransform(local, self.crs, self.transform_context)

    def to_core(self, geometry):
        """Return a QGIS geometry of the layer as a Shapely geometry in the working frame."""
        if self.forward is None:
            return to_shapely(geometry)
        moved = QgsGeometry(geometry)
        moved.transform(self.forward)
        return to_shapely(moved)

    def to_layer(self, geometry):
        """Return a QGIS geometry of the working frame in the layer's CRS (a new geometry)."""
        moved = QgsGeometry(geometry)
        if self.backward is not None:
            moved.transform(self.backward)
        return moved
