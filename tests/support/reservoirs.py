"""Synthetic rivers and reservoirs with side arms, and rough guide lines, for the end-rule tests.

Each builder returns ``(polygon, main_ends, cap_widths, arm_tip)``: the main stem's two ends (the middles
of the main river's flat caps), the widths of those caps, and the tip of the arm that the longest path
takes instead. All lengths in CRS units.
"""

import math

import numpy as np
import shapely
import shapely.ops
from shapely.geometry import LineString, Polygon
from shapely.ops import unary_union


def arm(points, width):
    """A flat-capped channel of constant ``width`` around a polyline."""
    return LineString(points).buffer(width / 2.0, cap_style="flat", join_style="mitre")


def straight_river_with_long_arm():
    """A 1000 x 40 river and a 900 x 6 arm leaving it at x = 600: arm + west reach is the longest path."""
    polygon = unary_union([arm([(0.0, 0.0), (1000.0, 0.0)], 40.0), arm([(600.0, 0.0), (600.0, 900.0)], 6.0)])
    return polygon, [(0.0, 0.0), (1000.0, 0.0)], [40.0, 40.0], (600.0, 900.0)


def widening_reservoir():
    """A reservoir widening from 20 (inflow) to 100 (dam) over 1500, with two arms 1200 x 8 and 1000 x 10."""
    valley = Polygon([(0.0, -10.0), (1500.0, -50.0), (1500.0, 50.0), (0.0, 10.0)])
    arms = [arm([(400.0, 0.0), (400.0, 1200.0)], 8.0), arm([(900.0, 0.0), (700.0, -1000.0)], 10.0)]
    return unary_union([valley, *arms]), [(0.0, 0.0), (1500.0, 0.0)], [20.0, 100.0], (400.0, 1200.0)


def dendritic_axes():
    """The axes of :func:`dendritic_reservoir`: its main river, its 8-wide arm and the arm's 5-wide branch."""
    x = np.linspace(0.0, 3000.0, 301)
    axis = np.c_[x, 150.0 * np.sin(2.0 * math.pi * x / 1500.0)]
    first = axis[120]
    return (
        axis,
        np.array([first, first + (100.0, 700.0), first + (300.0, 1400.0)]),
        np.array([first + (100.0, 700.0), first + (-300.0, 1500.0), first + (-500.0, 2000.0)]),
    )


def dendritic_reservoir():
    """A meandering 3 km river, 60 wide, with a branching 2.2 km arm system 5 to 8 wide and a 1 km arm."""
    axis, arm_axis, branch_axis = dendritic_axes()
    second = axis[200]
    branches = [arm(arm_axis, 8.0), arm(branch_axis, 5.0), arm([second, second + (300.0, 900.0)], 6.0)]
    polygon = unary_union([arm(axis, 60.0), *branches])
    return polygon, [tuple(axis[0]), tuple(axis[-1])], [60.0, 60.0], tuple(branch_axis[-1])


RESERVOIRS = {
    "straight river, long arm": straight_river_with_long_arm,
    "widening reservoir": widening_reservoir,
    "dendritic reservoir": dendritic_reservoir,
}


def rough_guide(path, width, piece=150.0, gap=50.0, grid=None):
    """A guide line made rough on purpose from an exact axis ``path``.

    The axis is extended by two widths beyond both ends (out of the polygon), cut into ``piece``-long
    pieces with ``gap``-long gaps, each piece offset by 0.75 ``width`` to alternate sides (out of the
    polygon: farther than the bank), and its vertices rounded to a ``grid`` (a third of the width).

    Returns
    -------
    list of LineString
    """
    path = np.asarray(path, dtype=float)
    head = (path[0] - path[1]) / np.hypot(*(path[0] - path[1]))
    tail = (path[-1] - path[-2]) / np.hypot(*(path[-1] - path[-2]))
    line = LineString(np.vstack([path[0] + 2.0 * width * head, path, path[-1] + 2.0 * width * tail]))
    grid = grid or width / 3.0
    pieces = []
    for index, start in enumerate(np.arange(0.0, line.length, piece + gap)):
        cut = shapely.ops.substring(line, start, min(start + piece, line.length))
        if cut.length <= 0.0:
            continue
        shifted = cut.offset_curve((0.75 if index % 2 else -0.75) * width)
        for part in shapely.get_parts(shifted):
            if part.length > 0.0:
                pieces.append(LineString(np.round(np.asarray(part.coords) / grid) * grid))
    return pieces
