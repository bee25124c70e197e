"""Rings: the closed centerline of a polygon whose main feature is one hole.

A roundabout, a moat, an atoll or the letter "o" has no two ends: its skeleton is a cycle around the hole
(with, at most, short branches into bumps of its banks), and its natural centerline is that cycle closed on
itself. IncirCu traces it between the exterior ring and the hole's ring as two closed chains:

1. **Seam.** The closest pair of points ``P`` (on the exterior ring) and ``Q`` (on the hole's ring). The disk
   on ``PQ`` as diameter is empty (a boundary point inside it would be nearer to ``P`` or ``Q`` than they are
   to each other) and touches both rings, so its centre, the midpoint of ``PQ``, lies on the medial axis
   between them. ``P`` and ``Q`` become vertices of their rings.
2. **Chains.** Both rings counter-clockwise, the exterior from ``P`` round to ``P`` and the hole from ``Q``
   round to ``Q``: two closed chains facing each other, like two bank lines (open mode) whose start gap and
   end gap are both the seam ``PQ``. The engine traces the axis between them; the line runs from the seam's
   midpoint round to it again: a closed LineString, every vertex on the exact medial axis between the rings.
   (The line ordering takes both feet of a disk on the same lap of the rings, see :func:`.lines._in_region`.)

**Rule** (:func:`loop_is_main_feature`): without split points, a polygon with exactly one hole (islands
followed, no guide line that chose the path) gets its loop when the trunk the automatic ends would use (the
heaviest skeleton path, see :mod:`.ends`) is shorter than the hole's perimeter: a ring has no trunk at all, or
one between two bumps of its banks around part of the hole. A river with an island keeps its ends: its trunk
runs the river's length, past the island. A hole touching the exterior ring leaves no loop (the automatic
ends are used). With split points the line runs between them as for any polygon.
"""

import numpy as np
import shapely

from .chains import COINCIDENCE_TOLERANCE, _insert_at, clean_chain, extent_of, signed_area
from .engine import clean_chains_steps
from .errors import Message
from .polyline import cumulative_lengths, nearest_entries

#: Trunk length, as a share of the hole's perimeter, under which the loop around the hole is the polygon's
#: main feature (see :func:`loop_is_main_feature`).
RING_TRUNK_SHARE = 1.0

#: The note a ring's result carries.
RING_NOTE = Message("note_ring")


def loop_is_main_feature(polygon, ends):
    """Whether a polygon's centerline is the closed loop around its one hole (see the module docstring).

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, CRS units.
    ends : EndsResult
        Its automatic ends (:func:`.ends.find_ends`).

    Returns
    -------
    bool

    Examples
    --------
    >>> from shapely.geometry import Point, box
    >>> from incircu_plugin.core.ends import find_ends
    >>> moat = Point(0, 0).buffer(10).difference(Point(0, 0).buffer(5))
    >>> loop_is_main_feature(moat, find_ends(moat))
    True
    >>> river = box(0, 0, 100, 10).difference(box(40, 3, 50, 7))
    >>> loop_is_main_feature(river, find_ends(river))
    False
    """
    if len(polygon.interiors) != 1 or ends.guided:
        return False
    hole = polygon.interiors[0]
    trunk = 0.0 if ends.trunk is None else ends.trunk.length
    if trunk >= RING_TRUNK_SHARE * hole.length:
        return False
    seam = _seam(polygon)
    return bool(np.hypot(*(seam[0] - seam[1])) > COINCIDENCE_TOLERANCE * extent_of(shapely.get_coordinates(polygon)))


def _seam(polygon):
    """The closest pair of points of a one-hole polygon's exterior ring and hole, an array of shape (2, 2).

    A prepared copy of the exterior ring: GEOS then finds the pair with an index (20,000 vertices: 0.1 s, where
    the plain pairwise search takes 10 s); the caller's polygon is left as given.
    """
    exterior = shapely.linearrings(shapely.get_coordinates(polygon.exterior))
    shapely.prepare(exterior)
    return shapely.get_coordinates(shapely.shortest_line(exterior, polygon.interiors[0]))


def seam_chains(polygon):
    """The exterior ring and the hole's ring of a one-hole polygon as two closed chains from the seam.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon with one hole not touching its exterior ring, CRS units.

    Returns
    -------
    outer, inner : ndarray of shape (n, 2)
        Counter-clockwise, each starting and ending at its seam point (``P`` and ``Q``), clean
        (:func:`.chains.clean_chain`), CRS units.
    """
    rings = [shapely.get_coordinates(polygon.exterior), shapely.get_coordinates(polygon.interiors[0])]
    seam = _seam(polygon)
    coincidence = COINCIDENCE_TOLERANCE * extent_of(*rings)
    chains = []
    for ring, point in zip(rings, seam):
        if signed_area(ring) < 0:
            ring = ring[::-1]
        ring = np.concatenate([clean_chain(ring[:-1], "ring", coincidence), ring[:1]])
        positions = cumulative_lengths(ring)
        along = float(shapely.line_locate_point(shapely.linestrings(ring), shapely.points(point)))
        ring, positions = _insert_at(ring, positions, [along], coincidence)
        loop = ring[:-1]
        start = int(nearest_entries(positions, np.array([along]))[0]) % len(loop)
        chains.append(np.concatenate([loop[start:], loop[:start], loop[start : start + 1]]))
    return chains[0], chains[1]


def ring_centerline_steps(polygon, spacing=None, *, samples_per_chain=None, tolerance=None, progress=None):
    """The closed centerline between a one-hole polygon's exterior ring and its hole, as steps (see
    :func:`.engine.centerline_steps`; options as there).

    Returns
    -------
    CenterlineResult
        A closed line from the seam's midpoint round to it; ``foot_a`` on the exterior ring, ``foot_b`` on the
        hole; ``chains`` the two closed chains.
    """
    outer, inner = seam_chains(polygon)
    return (
        yield from clean_chains_steps(
            outer, inner, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress
        )
    )
