"""The unit IncirCu reads a length in for a layer, and how messages name it (no Shapely needed: dialogs use it)."""

from qgis.core import QgsUnitTypes
from qgis.PyQt.QtCore import QCoreApplication

from .compat import DistanceUnit

#: How the core names the unit of the lengths in its messages: that of the coordinates it is given.
CORE_LENGTH_UNIT = "CRS units"


def reading_unit(crs):
    """Return the distance unit IncirCu reads a length in for a layer of ``crs``: its map unit, metres for a
    layer in degrees (computed in a local metric projection, see :class:`.convert.WorkingFrame`)."""
    return DistanceUnit.Meters if crs.isGeographic() else crs.mapUnits()


def length_unit(crs):
    """Return :func:`reading_unit` abbreviated for messages ("m", "ft"...); "layer units" (translated) when QGIS
    has no name for it."""
    fallback = QCoreApplication.translate("IncirCuAlgorithm", "layer units")
    return (crs.isValid() and QgsUnitTypes.toAbbreviatedString(reading_unit(crs))) or fallback
