"""The unit IncirCu reads a length in for a layer, and how messages name it (no Shapely needed: dialogs use it)."""

import math

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


#: The smallest length the attributes resolve, metres: a millimetre, finer than any map or survey of a channel.
ATTRIBUTE_RESOLUTION = 0.001


def length_decimals(crs):
    """Return the decimals the lengths, widths, chainages and radii of the output attributes are rounded to for a
    layer of ``crs``: as many as resolve a millimetre in :func:`reading_unit` (3 for metres, and so for a layer
    in degrees, whose lengths are metres; 3 for feet; 6 for kilometres); None (not rounded) when the unit is
    unknown."""
    metres = metres_per_unit(crs)
    if metres is None:
        return None
    return max(0, math.ceil(-math.log10(ATTRIBUTE_RESOLUTION / metres) - 1e-9))


def metres_per_unit(crs):
    """Return the metres in one :func:`reading_unit` of a layer of ``crs``; None when the unit is unknown (or
    not a length)."""
    if not crs.isValid():
        return None
    unit = reading_unit(crs)
    metres = QgsUnitTypes.fromUnitToUnitFactor(unit, DistanceUnit.Meters)
    if QgsUnitTypes.unitType(unit) != QgsUnitTypes.unitType(DistanceUnit.Meters) or not metres > 0.0:
        return None
    return metres


def rounded(value, decimals):
    """Return ``value`` (a float, or None) rounded to ``decimals`` (None: as it is)."""
    if value is None or decimals is None:
        return value
    return round(float(value), decimals)
