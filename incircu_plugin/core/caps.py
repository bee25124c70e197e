"""End caps of a centerline: the exact axis to its ends, or a straight run-out along the channel's axis.

Near a split point the channel has an *end cap*: the stretch of the boundary between the banks, where the
incircles touch the cut rather than both banks. Where the cut is slanted (a reach cut by a map sheet, a river
cut square to north rather than to its banks), the exact medial axis there leaves the end square to the cut
and then bends onto the channel's axis: a stub and a kink. The *run-out* replaces the line across the cap
with one straight segment from where the cap ends (the first vertex whose incircle spans the channel from
bank to bank, as :func:`.widths.transects` finds it) to the end: the given split point itself, or, for
automatic ends, the point where the channel's axis, continued straight from there, meets the boundary. Two
reaches sharing a split point in the middle of a slanted cut then meet in line, without a zig-zag.
"""

from dataclasses import replace

import numpy as np
import shapely
from shapely.geometry import LineString

from .errors import IncirCuError, Message
from .polyline import chord_directions, cumulative_lengths
from .widths import end_cap_vertices, measured_stretch

#: The ways a centerline ends: ``"runout"``, straight along the channel's axis from where the end cap ends to
#: the end; ``"axis"``, the exact medial axis to the end (with its bend across a slanted cap).
END_CAPS = ("runout", "axis")


def check_end_cap(end_cap):
    """Raise :class:`IncirCuError` unless ``end_cap`` is one of :data:`END_CAPS`."""
    if end_cap not in END_CAPS:
        raise IncirCuError(Message("unknown_end_cap", cap=end_cap, choices=", ".join(END_CAPS)))


def run_out_ends(result, region, move_ends=False, open_ends=False):
    """Return ``result`` with its line straight across each end cap (see the module docstring).

    Ends with a zero radius (split points) have a cap; with ``open_ends``, every end. At each, the vertices
    between the end and the first vertex ``P`` of the measured stretch (:func:`.widths.measured_stretch`: where
    the incircle first spans the channel; the next vertex where that one was moved off the axis onto the
    cap's end) are dropped and ``P`` is joined straight to the end. With ``move_ends`` (ends found
    automatically) the end moves to where the line's direction at ``P``, continued straight back
    (:func:`_aimed_end`), first meets the boundary of ``region``, when that point lies within
    ``|P - end| + r(P)`` of the old end; an automatic end without end-cap vertices
    (:func:`.widths.end_cap_vertices`: a tip where the banks meet, or the acute corner of a cut slanted so
    far that the end was found there) keeps the exact axis.

    ``P`` is on the medial axis and the end on the boundary; the run-out between them is not on the axis:
    the end keeps its radius (0 at a split point, its feet the end itself; half the gap at an open end), ``P``
    its incircle, and nothing is computed between them (a width read along the segment, as the M values, is
    interpolated between the two). An end whose run-out would leave ``region``, meet the rest of the line
    elsewhere than at ``P`` or make it not simple keeps the exact axis.

    Parameters
    ----------
    result : CenterlineResult
        A polygon's centerline, CRS units.
    region : Polygon
        The polygon the line lies in (holes are islands), CRS units.
    move_ends : bool
        The ends were found automatically: aim them along the axis.
    open_ends : bool
        The line lies between two bank lines (``result.chains``), its ends at the middle of the gaps between
        their ends (positive radius): the cap is where an incircle touches a bank line's end vertex, the
        run-out joins the first vertex whose incircle touches neither, and the end keeps its values.

    Returns
    -------
    CenterlineResult
        Of the same class, with the same ``chains``; ``result`` itself when neither end changes.
    """
    vertices = shapely.get_coordinates(result.line)
    if len(vertices) < 3:
        return result
    radii = np.asarray(result.radii, dtype=float)
    original = [radii, np.asarray(result.foot_a, dtype=float), np.asarray(result.foot_b, dtype=float)]
    chainages = cumulative_lengths(vertices)
    stretch = measured_stretch(vertices, radii, chainages, *original[1:])
    if stretch.empty:
        return result
    first, last = (int(index) for index in np.searchsorted(stretch.chainages, [stretch.low, stretch.high]))
    if first >= last:
        return result
    # Where the stretch's end vertex was moved onto the segment where the cap ends, the run-out joins the next
    # vertex, on the axis (the moved one lies off it, on the line across the cap).
    joints = [
        first + 1 if not np.array_equal(stretch.vertices[first], vertices[first]) else first,
        last - 1 if not np.array_equal(stretch.vertices[last], vertices[last]) else last,
    ]
    # An automatic end in a tip (where the banks meet; its line has no end-cap vertex) keeps the exact axis:
    # it runs along the tip's middle into it, and a straight line from farther in would miss the tip.
    capped = [len(indices) > 0 for indices in end_cap_vertices(vertices, radii, chainages, *original[1:])]
    if open_ends and result.chains is not None:
        joints = _open_joints(vertices, original, result.chains, joints)
    ends = []
    for side, end_index in enumerate((0, len(vertices) - 1)):
        end, joint = vertices[end_index], joints[side]
        if (
            (radii[end_index] > 0.0 and not open_ends)
            or (move_ends and not capped[side])
            or joints[0] > joints[1]
            or joint == end_index
        ):
            ends.append(None)
            continue
        if move_ends:
            end = _aimed_end(end, vertices, chainages, joint, -1 if side == 0 else 1, radii[joint], region.boundary)
        rest = vertices[joints[0] : joints[1] + 1]
        ends.append(end if _runs_out(end, vertices[joint], rest, region) else None)
    if ends[0] is None and ends[1] is None:
        return result
    return _with_run_outs(result, vertices, original, joints, ends)


def _with_run_outs(result, vertices, original, joints, ends):
    """``result`` with each end of ``ends`` that is not None joined straight to its joint (the exact axis to the
    stretch's end vertex elsewhere); ``result`` itself when that line is not simple. ``original`` holds the radii
    and both feet of ``vertices``; CRS units."""
    radii = original[0]
    low_index = joints[0] if ends[0] is not None else 0
    high_index = joints[1] if ends[1] is not None else len(vertices) - 1
    pieces = [vertices[low_index : high_index + 1], *(value[low_index : high_index + 1] for value in original)]
    for side, end in enumerate(ends):
        if end is None:
            continue
        end_index = 0 if side == 0 else -1
        if radii[end_index] > 0.0:
            extra = [end[None], *(value[end_index][None] for value in original)]
        else:
            extra = [end[None], np.zeros(1), end[None], end[None]]
        pieces = [
            np.concatenate([added, piece] if side == 0 else [piece, added]) for added, piece in zip(extra, pieces)
        ]
    line = LineString(pieces[0])
    if not line.is_simple:
        return result
    return replace(result, line=line, radii=pieces[1], foot_a=pieces[2], foot_b=pieces[3])


def _open_joints(vertices, values, chains, joints):
    """The last vertex, from each end, of the run of inner vertices whose incircle touches a bank line's end
    vertex (open mode): where the axis of that vertex and the other line meets the channel's axis. An end
    without such a run gets the end itself (no cap)."""
    scale = max(float(np.ptp(vertices, axis=0).max()), float(np.max(values[0])), np.finfo(float).tiny)
    slack = 1e-9 * scale
    chain_a, chain_b = (np.asarray(chain, dtype=float) for chain in chains)
    found = list(joints)
    ends = ((0, 1, chain_a[0], chain_b[0]), (len(vertices) - 1, -1, chain_a[-1], chain_b[-1]))
    for side, (index, step, a_end, b_end) in enumerate(ends):
        on_ends = (np.hypot(*(values[1] - a_end).T) <= slack) | (np.hypot(*(values[2] - b_end).T) <= slack)
        joint = index
        while 0 < joint + step < len(vertices) - 1 and on_ends[joint + step]:
            joint += step
        found[side] = joint
    return found


def _aimed_end(end, vertices, chainages, joint, backwards, radius, boundary):
    """Return where the line's direction at vertex ``joint``, continued straight from it towards the end
    (``backwards`` = -1: the start, 1: the last vertex), meets ``boundary``; ``end`` when that point is
    farther than ``|joint - end| + radius`` from ``end`` (CRS units).

    The direction is the chord from the vertex to the line's point a radius farther from the end (the axis's
    tangent within about ``radius / (2 R)`` on a bend of radius ``R``, wherever the next vertex is farther).
    """
    point = vertices[joint]
    here = chainages[joint]
    ahead = np.array([here - backwards * max(radius, np.finfo(float).tiny)])
    direction = -chord_directions(vertices, chainages, np.array([here]), ahead)[0]
    if not np.isfinite(direction).all():
        return end
    reach = float(np.hypot(*(point - end))) + radius
    ray = LineString([point, point + 2.0 * reach * direction])
    hits = shapely.get_coordinates(shapely.intersection(ray, boundary))
    if len(hits) == 0:
        return end
    hit = hits[int(np.argmin(np.hypot(*(hits - point).T)))]
    if float(np.hypot(*(hit - end))) > reach:
        return end
    return hit


def _runs_out(end, joint, rest, region):
    """True when the segment from ``end`` to ``joint`` lies in ``region`` and meets ``rest`` (the kept line,
    starting or ending at ``joint``) only at ``joint``.

    The end lies on the boundary up to rounding (a split point within the snap tolerance of it): the segment
    may meet the boundary only within twice the end's distance from it (and ``1e-9`` of its length).
    """
    segment = LineString([end, joint])
    slack = 2.0 * float(shapely.distance(region.boundary, shapely.points(end))) + 1e-9 * segment.length
    hits = shapely.get_coordinates(shapely.intersection(segment, region.boundary))
    if np.any(np.hypot(*(hits - end).T) > slack):
        return False
    if not shapely.contains_xy(region, *(0.5 * (end + joint))):
        return False
    if len(rest) < 2:
        return True
    common = shapely.get_coordinates(shapely.intersection(segment, LineString(rest)))
    return bool(np.all(np.hypot(*(common - joint).T) <= 1e-9 * max(segment.length, np.finfo(float).tiny)))
