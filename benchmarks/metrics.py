"""Metrics of one centerline output against its polygon, ends and reference axis.

All lengths are in the polygon's units unless a name says ``_rel`` (then: divided by the case width).
"""

import statistics
import time
from dataclasses import dataclass
from typing import Optional

import numpy as np
import shapely
from peers import line_parts
from shapely import STRtree


def segments_of(geometry):
    """Every straight segment of the lines in ``geometry`` as an array of 2-point LineStrings."""
    segments = []
    for line in line_parts(geometry):
        coords = np.asarray(line.coords)[:, :2]
        if len(coords) >= 2:
            segments.append(np.stack([coords[:-1], coords[1:]], axis=1))
    if not segments:
        return np.empty(0, dtype=object)
    return shapely.linestrings(np.concatenate(segments))


class NearestDistance:
    """Distances from many points to a fixed set of lines, through an STRtree of its segments."""

    def __init__(self, reference):
        self.segments = segments_of(reference)
        self.tree = STRtree(self.segments)

    def __call__(self, points_xy):
        """Distance from each of ``points_xy`` (n, 2) to the nearest reference segment."""
        points = shapely.points(np.asarray(points_xy, dtype=float))
        _, distances = self.tree.query_nearest(points, return_distance=True, all_matches=False)
        return np.asarray(distances, dtype=float)


def vertices_of(geometry):
    """All vertices (x, y) of the lines in ``geometry``, as an (n, 2) array."""
    parts = line_parts(geometry)
    if not parts:
        return np.empty((0, 2))
    return np.concatenate([np.asarray(part.coords)[:, :2] for part in parts])


def densified_points(geometry, step):
    """Points along the lines of ``geometry``, no two consecutive ones farther apart than ``step``."""
    return vertices_of(shapely.segmentize(shapely.MultiLineString(line_parts(geometry)), step))


def topology(geometry):
    """Parts (connected components) and branches (edges between nodes of degree != 2) of the lines.

    The lines are noded (``union_all``) and merged through degree-2 nodes (``line_merge``); a clean
    centerline has one part and one branch.
    """
    parts = line_parts(geometry)
    if not parts:
        return 0, 0
    merged = line_parts(shapely.line_merge(shapely.union_all(shapely.MultiLineString(parts))))
    parent = {}

    def find(node):
        while parent.setdefault(node, node) != node:
            parent[node] = parent[parent[node]]
            node = parent[node]
        return node

    for line in merged:
        first, last = tuple(line.coords[0][:2]), tuple(line.coords[-1][:2])
        parent[find(first)] = find(last)
    components = len({find(node) for node in list(parent)})
    return components, len(merged)


@dataclass
class Measurement:
    """What the tables show for one tool on one case."""

    tool: str
    case: str
    seconds: Optional[float]
    runs: int
    parts: int = 0
    branches: int = 0
    mean_dev_rel: Optional[float] = None
    max_dev_rel: Optional[float] = None
    max_vertex_dev_rel: Optional[float] = None
    mean_analytic_dev_rel: Optional[float] = None
    end_gap_rel: Optional[tuple] = None
    outside_rel: Optional[float] = None
    length: float = 0.0
    error: str = ""


def time_call(function, argument, budget_seconds=2.0, max_runs=7, min_runs=3):
    """Run ``function(argument)`` several times; return (last result, median seconds, runs).

    The number of runs adapts to the cost: as many as fit in ``budget_seconds`` (at least
    ``min_runs`` when the first run took under a quarter of the budget, a single run otherwise).
    """
    durations = []
    result = None
    while True:
        start = time.perf_counter()
        result = function(argument)
        durations.append(time.perf_counter() - start)
        enough_runs = min_runs if durations[0] < budget_seconds / 4.0 else 1
        if len(durations) >= max_runs or (sum(durations) >= budget_seconds and len(durations) >= enough_runs):
            break
    return result, statistics.median(durations), len(durations)


def measure(tool_name, case, geometry, seconds, runs):
    """Compute every metric of ``geometry`` (a tool's output) on ``case``."""
    measurement = Measurement(tool_name, case.name, seconds, runs)
    parts = line_parts(geometry)
    if not parts:
        measurement.error = "empty output"
        return measurement
    measurement.parts, measurement.branches = topology(geometry)
    measurement.length = float(sum(part.length for part in parts))
    width = case.width
    if case.axis_distance is not None:
        along = case.axis_distance(densified_points(geometry, width / 50.0))
        measurement.mean_dev_rel = float(along.mean()) / width
        measurement.max_dev_rel = float(along.max()) / width
        measurement.max_vertex_dev_rel = float(case.axis_distance(vertices_of(geometry)).max()) / width
    analytic_distance = case.extra.get("analytic_distance")
    if analytic_distance is not None:
        measurement.mean_analytic_dev_rel = (
            float(analytic_distance(densified_points(geometry, width / 50.0)).mean()) / width
        )
    lines = shapely.MultiLineString(parts)
    measurement.end_gap_rel = tuple(float(lines.distance(end)) / width for end in case.ends)
    tolerance = 1e-9 * max(np.ptp(np.asarray(case.polygon.exterior.coords), axis=0))
    outside = lines.difference(case.polygon.buffer(tolerance))
    measurement.outside_rel = float(outside.length) / width
    return measurement
