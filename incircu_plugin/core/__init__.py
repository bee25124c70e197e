"""IncirCu geometry core: the Curve of Incircles, an unbranched subset of the medial axis.

Imports only numpy, shapely (>= 2.0) and pyproj; never QGIS.

Example
-------
>>> from shapely.geometry import box
>>> from incircu_plugin.core import polygon_centerline
>>> result = polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)])
>>> result.line.length, float(result.widths.max())
(100.0, 10.0)
"""

from .api import (
    ISLAND_MODES,
    PartOutcome,
    PolygonCenterlineResult,
    lines_centerline,
    multipolygon_centerlines,
    polygon_centerline,
)
from .arms import ArmEnds, find_arm_ends
from .caps import END_CAPS
from .chains import orient_bank_lines, split_polygon
from .ends import END_RULES, EndsResult, find_ends, find_ends_together
from .engine import CenterlineResult, centerline_from_chains, default_spacing, default_tolerance
from .errors import (
    Cancelled,
    CenterlineError,
    ChainError,
    CrossingLinesError,
    IncirCuError,
    InvalidGeometryError,
    OptionError,
    SplitPointError,
)
from .frames import centerlines, frame_labels, networks
from .geodesy import LocalProjection
from .labels import LabelResult, curvature_radii, feature_label, label_lines
from .layers import LayerNetworks, layer_networks
from .network import NETWORK_ISLAND_MODES, NetworkBranch, NetworkResult, multipolygon_networks, polygon_network
from .touching import touching_gates
from .widths import Incircle, Transect, incircle_polygons, transects, vertex_chainages, width_statistics

__all__ = [
    "END_CAPS",
    "END_RULES",
    "ISLAND_MODES",
    "NETWORK_ISLAND_MODES",
    "ArmEnds",
    "Cancelled",
    "CenterlineError",
    "CenterlineResult",
    "ChainError",
    "CrossingLinesError",
    "EndsResult",
    "IncirCuError",
    "Incircle",
    "InvalidGeometryError",
    "LabelResult",
    "LayerNetworks",
    "LocalProjection",
    "NetworkBranch",
    "NetworkResult",
    "OptionError",
    "PartOutcome",
    "PolygonCenterlineResult",
    "SplitPointError",
    "Transect",
    "centerline_from_chains",
    "centerlines",
    "curvature_radii",
    "default_spacing",
    "default_tolerance",
    "feature_label",
    "find_arm_ends",
    "find_ends",
    "find_ends_together",
    "frame_labels",
    "incircle_polygons",
    "label_lines",
    "layer_networks",
    "lines_centerline",
    "multipolygon_centerlines",
    "multipolygon_networks",
    "networks",
    "orient_bank_lines",
    "polygon_centerline",
    "polygon_network",
    "split_polygon",
    "touching_gates",
    "transects",
    "vertex_chainages",
    "width_statistics",
]

#: Names of IncirCu 0.2 that are no longer public, and what replaces each: the step-generator protocol is
#: private (``_steps``); the public functions take an array of geometries instead.
_DEPRECATED = {
    "centerlines_together": "polygon_centerline(array)",
    "polygon_centerline_steps": "polygon_centerline(array)",
    "multipolygon_centerline_steps": "multipolygon_centerlines(array)",
    "lines_centerline_steps": "lines_centerline(arrays)",
    "label_line_steps": "label_lines(array)",
}


def __getattr__(name):
    """The 0.2 names of :data:`_DEPRECATED`, with a :class:`DeprecationWarning` naming what replaces them."""
    if name not in _DEPRECATED:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import warnings

    from . import _many, api, labels

    warnings.warn(
        f"incircu_plugin.core.{name} is deprecated since IncirCu 0.3 and will be removed; use {_DEPRECATED[name]}, "
        "which computes an array of geometries in batches traced together.",
        DeprecationWarning,
        stacklevel=2,
    )
    private = {
        "centerlines_together": _many.run_many_steps,
        "polygon_centerline_steps": api._polygon_centerline_steps,
        "multipolygon_centerline_steps": api._multipolygon_centerline_steps,
        "lines_centerline_steps": api._lines_centerline_steps,
        "label_line_steps": labels._label_line_steps,
    }
    return private[name]
