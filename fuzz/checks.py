"""What a result must satisfy: one simple, finite line inside its region (vertices and segments), ending at its
split points.

Tolerances are relative to the input's extent (the inputs span many orders of magnitude).
"""

import numpy as np
import shapely

#: Relative tolerance (of the input's extent) of the containment and end checks.
RELATIVE_TOLERANCE = 1e-7


def problems(case, result):
    """Return a list of what is wrong with ``result`` for ``case`` (empty when it is correct)."""
    if case.function == "find_ends":
        return _ends_problems(case, result)
    if case.function == "multipolygon_centerlines":
        return _parts_problems(case, result)
    if case.function in ("polygon_centerline", "lines_centerline"):
        return _line_problems(result.line, case.polygon, case.split_points, case.snap)
    return []


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
