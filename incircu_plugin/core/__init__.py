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
    centerlines_together,
    lines_centerline,
    lines_centerline_steps,
    multipolygon_centerline_steps,
    multipolygon_centerlines,
    polygon_centerline,
    polygon_centerline_steps,
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
from .labels import LabelResult, curvature_radii, feature_label, label_line_steps, label_lines
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
    "centerlines_together",
    "curvature_radii",
    "default_spacing",
    "default_tolerance",
    "feature_label",
    "find_arm_ends",
    "find_ends",
    "find_ends_together",
    "frame_labels",
    "incircle_polygons",
    "label_line_steps",
    "label_lines",
    "layer_networks",
    "lines_centerline",
    "lines_centerline_steps",
    "multipolygon_centerline_steps",
    "multipolygon_centerlines",
    "multipolygon_networks",
    "networks",
    "orient_bank_lines",
    "polygon_centerline",
    "polygon_centerline_steps",
    "polygon_network",
    "split_polygon",
    "touching_gates",
    "transects",
    "vertex_chainages",
    "width_statistics",
]
