"""What a result must satisfy: one simple, finite line inside its region (vertices and segments), ending at its
split points; traced together with other inputs in a batch, what it is alone up to the sampling tolerance; and,
checked against the exact medial axis (``--oracle``), within the tolerance of it.

Tolerances are relative to the input's extent (the inputs span many orders of magnitude).
"""

import dataclasses

import numpy as np
import shapely
from shapely.geometry import Polygon

#: Relative tolerance (of the input's extent) of the containment and end checks.
RELATIVE_TOLERANCE = 1e-7


def problems(case, result):
    """Return a list of what is wrong with ``result`` for ``case`` (empty when it is correct)."""
    if case.function == "find_ends":
        return _ends_problems(case, result) + _across_problems(case, [result.start.coords[0], result.end.coords[0]])
    if case.function == "multipolygon_centerlines":
        return _parts_problems(case, result)
    if case.function in ("polygon_centerline", "lines_centerline"):
        found = _line_problems(result.line, case.polygon, case.split_points, case.snap)
        if not found and case.function == "polygon_centerline":
            found = _across_problems(case, [result.line.coords[0], result.line.coords[-1]])
        if case.closed and not result.line.is_closed:
            found.append("a ring's line is not its closed loop")
        return found
    return []


#: Share of a compact shape's width (twice its centre's clearance) within which the segment between its
#: automatic ends must pass its centre: the ends are computed in closed form, but a long ellipse keeps the
#: skeleton path's ends, the apex of each rounded cap (within 2 % of the width, see ``tests/test_core_ends.py``).
ACROSS_SHARE = 0.02


def _across_problems(case, ends):
    """What is wrong with the automatic ends of a compact or star-like shape (``case.centre`` or ``case.tips``)."""
    if case.centre is None and case.tips is None:
        return []
    ends = np.asarray(ends, dtype=float)
    tolerance = 10.0 * _tolerance(case.polygon)
    found = []
    if case.centre is not None:
        centre = shapely.Point(case.centre)
        width = 2.0 * case.polygon.exterior.distance(centre)
        off = shapely.LineString(ends).distance(centre)
        if off > ACROSS_SHARE * width + tolerance:
            found.append(f"the ends pass {off:.3g} from the centre ({off / width:.2g} of the width)")
    if case.tips is not None:
        gaps = np.hypot(*(case.tips[None, :, :] - ends[:, None, :]).transpose(2, 0, 1))
        nearest = gaps.argmin(axis=1)
        if gaps.min(axis=1).max() > tolerance:
            found.append(f"an end is {gaps.min(axis=1).max():.3g} from the nearest tip")
        elif nearest[0] == nearest[1]:
            found.append("both ends are at the same tip")
    return found


#: Float64 steps (of the coordinates' magnitude) always allowed: a tiny shape far from the origin cannot place
#: a point closer than a step or two (the validation admits shapes down to 1e-9 of their magnitude).
ROUNDING_STEPS = 4


def _tolerance(geometry):
    bounds = np.asarray(geometry.bounds, dtype=float)
    relative = RELATIVE_TOLERANCE * float(np.hypot(*(bounds[2:] - bounds[:2])))
    return max(relative, ROUNDING_STEPS * float(np.spacing(np.abs(bounds).max())))


def _line_problems(line, region, split_points, snap):
    found = []
    if line.geom_type != "LineString" or line.is_empty or len(line.coords) < 2:
        return [f"not one line: {line.geom_type} with {len(shapely.get_coordinates(line))} vertices"]
    coordinates = shapely.get_coordinates(line)
    if not np.all(np.isfinite(coordinates)):
        return ["non-finite vertex"]
    if not line.is_simple:
        found.append("line crosses itself")
    if region is None:
        return found
    tolerance = _tolerance(region)
    outside = shapely.distance(region, shapely.points(coordinates))
    if outside.max() > tolerance:
        found.append(f"vertex {int(outside.argmax())} is {outside.max():.3g} outside the polygon")
    elif (farthest := _farthest_outside(line, region, tolerance)) > tolerance:
        found.append(f"a segment leaves the polygon by {farthest:.3g}")
    if split_points is not None:
        gaps = np.hypot(*(coordinates[[0, -1]] - np.asarray(split_points, dtype=float)[:2]).T)
        if gaps.max() > snap + tolerance:
            found.append(f"an end is {gaps.max():.3g} from its split point")
    else:
        off = shapely.distance(region.boundary, shapely.points(coordinates[[0, -1]]))
        if region.geom_type == "Polygon" and len(region.interiors) == 0 and off.max() > tolerance:
            found.append(f"an automatic end is {off.max():.3g} off the boundary")
    return found


def _farthest_outside(line, region, tolerance):
    """Largest distance from ``region`` of the parts of ``line`` outside it (sampled at 200 points per part, and
    at least every ``tolerance``); 0 when the line stays inside."""
    outside = shapely.difference(line, region)
    if outside.is_empty or outside.length <= tolerance:
        return 0.0
    points = shapely.get_coordinates(shapely.segmentize(outside, max(outside.length / 200.0, tolerance)))
    return float(shapely.distance(region, shapely.points(points)).max())


def _ends_problems(case, ends):
    polygon = case.args[0]
    tolerance = _tolerance(polygon)
    found = []
    for name, point in (("start", ends.start), ("end", ends.end)):
        if polygon.exterior.distance(point) > tolerance:
            found.append(f"{name} is {polygon.exterior.distance(point):.3g} off the exterior ring")
    if ends.start.distance(ends.end) <= tolerance:
        found.append("identical ends")
    return found


def _parts_problems(case, outcomes):
    parts = list(getattr(case.args[0], "geoms", [case.args[0]]))
    points = case.split_points
    found = []
    for outcome, part in zip(outcomes, parts):
        if outcome.result is None:
            continue
        mine = None
        if points is not None:
            near = shapely.distance(part.exterior, shapely.points(points)) <= _tolerance(part)
            mine = points[near] if near.sum() == 2 else None
            if mine is not None:
                start = np.asarray(outcome.result.line.coords[0])
                mine = mine if np.hypot(*(start - mine[0])) <= np.hypot(*(start - mine[1])) else mine[::-1]
        found += [f"part {outcome.part_index}: {p}" for p in _line_problems(outcome.result.line, part, mine, 0.0)]
    return found


def together_problems(case, together, alone):
    """Return a list of how ``together`` (the case's outcome in a batch of ``centerlines_together``) differs from
    ``alone`` (the plain function's result or exception), and of what is wrong with it (:func:`problems`).

    A feature's outcome does not depend on its batch: the two must be the same bytes (:func:`outcome_key`: the
    same exception and message, or lines, radii and feet of identical float64 values, the same notes and ends).
    """
    key_together, key_alone = outcome_key(together), outcome_key(alone)
    if key_together != key_alone:
        return [
            f"together {_outcome_name(together)}, alone {_outcome_name(alone)}: {_first_difference(key_together, key_alone)}"
        ]
    return [] if isinstance(together, Exception) else problems(case, together)


def outcome_key(outcome):
    """What must be identical in a feature's outcome wherever it is computed (alone, in any batch, in any order):
    an exception's type and message; every field of a result (geometries as WKB, arrays as float64 bytes,
    anything else as its repr), in the order of :func:`_first_difference`; a list of part outcomes part by part."""
    if isinstance(outcome, Exception):
        return ("error", type(outcome).__name__, str(outcome))
    if isinstance(outcome, list):
        return tuple((part.part_index, outcome_key(part.error or part.result)) for part in outcome)
    values = {field.name: getattr(outcome, field.name) for field in dataclasses.fields(outcome)}
    geometries = tuple(value.wkb for value in values.values() if isinstance(value, shapely.Geometry))
    arrays = tuple(value.tobytes() for value in values.values() if isinstance(value, np.ndarray))
    others = repr(tuple(value for value in values.values() if not isinstance(value, (shapely.Geometry, np.ndarray))))
    return ("result", type(outcome).__name__, geometries, arrays, others)


def _first_difference(one, other):
    """Where two :func:`outcome_key` values first differ, in words."""
    if one[0] != other[0] or len(one) != len(other):
        return "different kinds of outcome"
    # The result's geometries (its line), its arrays (radii and feet), its other fields (notes and ends).
    names = ("kind", "type", "line", "radii and feet", "notes and ends")
    for name, first, second in zip(names, one, other):
        if first != second:
            return f"{name} differ"
    return "parts differ"


def _outcome_name(outcome):
    if isinstance(outcome, Exception):
        return f"{type(outcome).__name__}: {outcome}"
    return type(outcome).__name__


def ends_in_concave_corner(region, line, rounding):
    """Whether an end of ``line`` is a concave corner of ``region`` (a polygon's vertex where its inside angle
    exceeds 180 degrees, to ``rounding``, CRS units).

    A split point there lies on both chains, and round it the axis between them forks (README, *Reliability*):
    which branch the line takes first is decided by rounding there, so a feature traced in a batch may take the
    other one than alone. Such lines are not compared.
    """
    if not isinstance(region, Polygon):
        return False
    ends = shapely.get_coordinates(line)[[0, -1]]
    for hole, ring in enumerate((region.exterior, *region.interiors)):
        corners = shapely.get_coordinates(ring)[:-1]
        if not ring.is_ccw:
            corners = corners[::-1]
        before, after = corners - np.roll(corners, 1, axis=0), np.roll(corners, -1, axis=0) - corners
        # The exterior counter-clockwise: a right turn is concave (a hole's ring, taken the same way, the reverse).
        turn = before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0]
        concave = corners[(turn > 0) if hole else (turn < 0)]
        if len(concave) and np.min(np.hypot(*(concave[:, None] - ends[None]).T)) <= rounding:
            return True
    return False


#: Most samples per line the oracle check takes (it samples the line at a tenth of the tolerance): a thin box
#: of aspect 1e-5 would need 10^8.
ORACLE_SAMPLES = 1e5

#: Oracle error bounds (its integer grid's rounding) under which a segment next to a split point is too short for
#: the oracle to place the split point's stub (a split point a hair from a vertex, far from the origin).
ORACLE_RESOLUTION = 1e3


def oracle_problems(case, result):
    """Return a list of how the line of a polygon without holes strays from the exact medial axis between its
    chains: a vertex whose disk is not empty or does not touch both chains (exact distances,
    ``tests/support/oracle.check_centerline``), a vertex off the axis of the segment Voronoi oracle
    (``MedialOracle``, which shares no code with the engine), or the line and that axis farther apart than the
    tolerance (given, or the default of the chains). Other cases and lines ending in a concave corner (where the
    axis between the chains forks) are not measured; lines longer than ``ORACLE_SAMPLES`` tolerances, or with a
    segment next to a split point shorter than ``ORACLE_RESOLUTION`` of the oracle's error bound, only exactly.
    """
    from incircu_plugin.core import default_tolerance, split_polygon
    from tests.support.oracle import MedialOracle, assert_within_tolerance, check_centerline

    polygon = case.args[0] if case.args else None
    measured = case.function == "polygon_centerline" and case.kwargs.get("spacing") is None
    if not measured or not isinstance(polygon, Polygon) or len(polygon.interiors):
        return []
    ends = shapely.get_coordinates(result.line)[[0, -1]]
    if ends_in_concave_corner(polygon, result.line, _tolerance(polygon)):
        return []
    chains = split_polygon(polygon, ends)
    tolerance = case.kwargs.get("tolerance") or default_tolerance(*chains)
    try:
        check_centerline(result, *chains, polygon, ends)
        if result.line.length > ORACLE_SAMPLES * tolerance:
            return []
        oracle = MedialOracle(*chains, region=polygon)
        if _split_point_gap(chains) <= ORACLE_RESOLUTION * oracle.error_bound:
            return []
        assert_within_tolerance(result, *chains, polygon, tolerance, oracle=oracle)
    except AssertionError as error:
        return [f"oracle: {error}"]
    return []


def _split_point_gap(chains):
    """Shortest segment of the chains next to a split point (their first and last ones), CRS units."""
    return min(
        float(np.hypot(*(chain[index] - chain[index + step]))) for chain in chains for index, step in ((0, 1), (-1, -1))
    )
