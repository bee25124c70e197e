"""IncirCu geometry core: the Curve of Incircles, an unbranched subset of the medial axis.

Imports only numpy, shapely (>= 2.0) and pyproj; never QGIS.
"""

from .chains import orient_bank_lines, split_polygon
from .engine import Cancelled, CenterlineResult, centerline_from_chains, default_spacing
from .errors import ChainError, CrossingLinesError, IncirCuError, InvalidGeometryError, SplitPointError

__all__ = [
    "Cancelled",
    "CenterlineResult",
    "ChainError",
    "CrossingLinesError",
    "IncirCuError",
    "InvalidGeometryError",
    "SplitPointError",
    "centerline_from_chains",
    "default_spacing",
    "orient_bank_lines",
    "split_polygon",
]
