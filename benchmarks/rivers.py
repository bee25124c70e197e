"""A seeded layer of river-like polygons for the layer benchmark (issue 9).

Each river is built around a random-walk axis: its curvature is a smoothed random walk, clipped so that
the banks never fold (radius of curvature above 1.5 half-widths, at most 0.35 rad of turn between two
bank stations). The width varies smoothly by ±25 % around a draw between 5 and 40 m, and each bank
vertex is jittered sideways by up to 4 % of the width, as digitised banks are. Both banks have the same
number of vertices, at independently jittered stations; the two ends are flat caps. About one river in
six (the wider ones) gets 1 to 3 elongated islands. Rivers are laid out on a 7 km grid in UTM zone 33N
(EPSG:32633), so they never overlap and every length is in metres.

Everything follows from the seed: river ``i`` draws from ``numpy.random.default_rng([seed, i])``, so the
first ``n`` rivers of a layer do not depend on its size. A draw whose polygon is invalid (the walk came
back onto itself) is replaced by the next draw of the same stream.

Usage: ``python benchmarks/rivers.py [--count 400] [--seed 0]`` prints the layer's statistics.
"""

import argparse
import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Point, Polygon

#: Projected CRS of the layer (UTM zone 33N, metres).
CRS = "EPSG:32633"

#: Grid step between two rivers' starting points (m): longer than any river, so no two rivers meet.
GRID_STEP = 7_000.0

#: Origin of the grid in the CRS (m): inside UTM zone 33N's valid area.
GRID_ORIGIN = (300_000.0, 5_000_000.0)

#: Rivers per grid row.
GRID_COLUMNS = 20


@dataclass
class River:
    """One generated river.

    Attributes
    ----------
    polygon : shapely.geometry.Polygon
        The river, islands as holes, metres (EPSG:32633).
    ends : tuple of two shapely.geometry.Point
        Midpoints of the two end caps: the split points, on the exterior ring.
    axis : shapely.geometry.LineString
        The random-walk axis the banks were offset from (not the exact medial axis: the width varies).
    width : float
        Mean width drawn for this river, metres.
    index : int
        Position in the layer.
    """

    polygon: Polygon
    ends: tuple
    axis: LineString
    width: float
    index: int

    @property
    def vertex_count(self):
        """Distinct boundary vertices (exterior and islands)."""
        rings = [self.polygon.exterior, *self.polygon.interiors]
        return sum(len(ring.coords) - 1 for ring in rings)


def _random_walk_axis(rng, length, width, stations):
    """Axis points (stations, 2) and unit headings of a random walk of ``length`` m, starting at 0."""
    step = length / (stations - 1)
    correlation = math.exp(-step / (3.0 * width))
    noise = rng.normal(0.0, 1.0, stations)
    curvature = np.empty(stations)
    curvature[0] = noise[0]
    for i in range(1, stations):
        curvature[i] = correlation * curvature[i - 1] + math.sqrt(1.0 - correlation**2) * noise[i]
    largest = min(1.0 / (0.75 * width), 0.35 / step)
    curvature = np.clip(curvature * rng.uniform(0.3, 0.8) * largest, -largest, largest)
    heading = rng.uniform(0.0, 2.0 * math.pi) + np.concatenate([[0.0], np.cumsum(curvature[1:] * step)])
    direction = np.column_stack([np.cos(heading), np.sin(heading)])
    points = np.concatenate([[[0.0, 0.0]], np.cumsum(direction[1:] * step, axis=0)])
    return points, direction


def _bank(rng, axis, direction, half_width, side, vertices):
    """One bank: ``vertices`` points offset sideways (``side`` = +1 left, -1 right) at jittered stations."""
    stations = len(axis)
    where = np.linspace(0.0, stations - 1.0, vertices)
    where[1:-1] += rng.uniform(-0.3, 0.3, vertices - 2) * (stations - 1.0) / (vertices - 1.0)
    index = np.clip(where.astype(int), 0, stations - 2)
    fraction = (where - index)[:, None]
    position = axis[index] * (1.0 - fraction) + axis[index + 1] * fraction
    tangent = direction[index] * (1.0 - fraction) + direction[index + 1] * fraction
    tangent /= np.hypot(*tangent.T)[:, None]
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    half = half_width[index] * (1.0 - fraction[:, 0]) + half_width[index + 1] * fraction[:, 0]
    half = half * (1.0 + rng.uniform(-0.08, 0.08, vertices))
    half[[0, -1]] = half_width[[0, -1]]
    return position + side * half[:, None] * normal


def _islands(rng, polygon, axis, direction, half_width):
    """1 to 3 elongated 16-vertex islands well inside ``polygon``, not touching each other."""
    rings = []
    for _ in range(rng.integers(1, 4)):
        station = rng.integers(len(axis) // 8, len(axis) - len(axis) // 8)
        half = half_width[station]
        semi_minor = rng.uniform(0.12, 0.25) * half
        semi_major = rng.uniform(1.5, 4.0) * semi_minor
        centre = axis[station] + rng.uniform(-0.3, 0.3) * half * np.array(
            [-direction[station, 1], direction[station, 0]]
        )
        angle = np.linspace(0.0, 2.0 * math.pi, 16, endpoint=False)
        local = np.column_stack([semi_major * np.cos(angle), semi_minor * np.sin(angle)])
        cosine, sine = direction[station]
        ring = centre + local @ np.array([[cosine, sine], [-sine, cosine]])
        island = Polygon(ring)
        clear = all(island.distance(Polygon(other)) > half for other in rings)
        if clear and polygon.buffer(-0.25 * half).contains(island):
            rings.append(ring)
    return rings


def _draw_river(rng, vertices_per_bank):
    """One river at the origin: (polygon, ends, axis, mean width), or None when the draw is invalid."""
    length = rng.uniform(200.0, 3_000.0)
    width = rng.uniform(5.0, 40.0)
    stations = 4 * vertices_per_bank
    axis, direction = _random_walk_axis(rng, length, width, stations)
    along = np.linspace(0.0, 1.0, stations)
    wavelength = rng.uniform(0.1, 0.5)
    half_width = 0.5 * width * (1.0 + 0.25 * np.sin(2.0 * math.pi * along / wavelength + rng.uniform(0, 2 * math.pi)))
    left = _bank(rng, axis, direction, half_width, 1.0, vertices_per_bank)
    right = _bank(rng, axis, direction, half_width, -1.0, vertices_per_bank)
    exterior = np.concatenate([left, right[::-1]])
    polygon = Polygon(exterior)
    if not polygon.is_valid or polygon.area <= 0.0:
        return None
    if width >= 12.0 and rng.uniform() < 0.2:
        polygon = Polygon(exterior, _islands(rng, polygon, axis, direction, half_width))
    ends = (0.5 * (left[0] + right[0]), 0.5 * (left[-1] + right[-1]))
    return polygon, ends, axis, width


def river_layer(count=400, seed=0, boundary_vertices=290, first=0):
    """The layer: ``count`` rivers from ``seed``, each with about ``boundary_vertices`` exterior vertices.

    Parameters
    ----------
    count : int
        Number of rivers.
    seed : int
        Seed of every draw.
    boundary_vertices : int
        Exterior vertices of each river (both banks together; islands add 16 each).
    first : int
        Index of the first river: the rivers ``first`` to ``first + count - 1`` of a longer layer of ``seed``,
        in their places (each river is drawn from its own index).

    Returns
    -------
    list of River
        In layer order, metres (EPSG:32633).
    """
    vertices_per_bank = boundary_vertices // 2
    rivers = []
    for index in range(first, first + count):
        rng = np.random.default_rng([seed, index])
        drawn = None
        while drawn is None:
            drawn = _draw_river(rng, vertices_per_bank)
        polygon, ends, axis, width = drawn
        offset = np.array(GRID_ORIGIN) + GRID_STEP * np.array([index % GRID_COLUMNS, index // GRID_COLUMNS])
        rivers.append(
            River(
                polygon=shapely.transform(polygon, lambda xy, shift=offset: xy + shift),
                ends=tuple(Point(end + offset) for end in ends),
                axis=LineString(axis + offset),
                width=float(width),
                index=index,
            )
        )
    return rivers


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=400)
    parser.add_argument("--seed", type=int, default=0)
    arguments = parser.parse_args(argv)
    rivers = river_layer(arguments.count, arguments.seed)
    vertices = np.array([river.vertex_count for river in rivers])
    lengths = np.array([river.axis.length for river in rivers])
    widths = np.array([river.width for river in rivers])
    islands = sum(len(river.polygon.interiors) for river in rivers)
    with_islands = sum(1 for river in rivers if river.polygon.interiors)
    print(
        f"{len(rivers)} rivers (seed {arguments.seed}): boundary vertices {vertices.min()}..{vertices.max()} "
        f"(mean {vertices.mean():.0f}, total {vertices.sum():,}); axis {lengths.min():.0f}..{lengths.max():.0f} m; "
        f"width {widths.min():.1f}..{widths.max():.1f} m; {islands} islands in {with_islands} rivers; "
        f"all valid: {all(river.polygon.is_valid for river in rivers)}"
    )


if __name__ == "__main__":
    main()
