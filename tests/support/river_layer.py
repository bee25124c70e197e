"""A generated layer of river reaches: meandering rivers with tributaries, each cut across at random gates.

Each river is a meandering main stem (a sine-wave polyline) with a few tributaries leaving it at random
places, all buffered with flat ends and joined into one polygon. Every river polygon is then cut by short
straight segments across the main stem at random positions, kept away from the tributaries' mouths, into
reaches. The true topology is known: the reaches of one river form one connected network, and each cut is a
gate shared by the two reaches on either side of it.
"""

import math

import numpy as np
import shapely
from shapely.geometry import LineString
from shapely.ops import split, unary_union


def river(rng, origin, length=2000.0, half_width=20.0, tributaries=2):
    """One river polygon (main stem and tributaries) and its main stem line."""
    x = np.linspace(0.0, length, 200)
    amplitude, wavelength = rng.uniform(50.0, 150.0), rng.uniform(400.0, 800.0)
    y = amplitude * np.sin(2.0 * math.pi * x / wavelength)
    main = LineString(np.column_stack([x, y]) + origin)
    pieces = [main.buffer(half_width, cap_style="flat")]
    mouths = []
    for _ in range(tributaries):
        at = rng.uniform(0.25, 0.75) * main.length
        base = np.asarray(main.interpolate(at).coords[0])
        ahead = np.asarray(main.interpolate(at + 1.0).coords[0]) - base
        side = rng.choice([-1.0, 1.0])
        normal = side * np.array([-ahead[1], ahead[0]]) / np.hypot(*ahead)
        tip = base + normal * rng.uniform(300.0, 500.0) + ahead / np.hypot(*ahead) * rng.uniform(-150.0, 150.0)
        pieces.append(LineString([base, tip]).buffer(half_width * rng.uniform(0.4, 0.7), cap_style="flat"))
        mouths.append(at)
    polygon = shapely.set_precision(unary_union(pieces), 1e-6)
    return polygon, main, mouths


def river_reaches(rivers=10, cuts_per_river=10, seed=20261207):
    """Reach polygons of generated rivers cut at random gates.

    Returns
    -------
    reaches : list of Polygon
    river_of : list of int
        The river each reach belongs to.
    """
    rng = np.random.default_rng(seed)
    reaches, river_of = [], []
    for number in range(rivers):
        origin = np.array([0.0, 3000.0 * number])
        polygon, main, mouths = river(rng, origin)
        positions = []
        while len(positions) < cuts_per_river:
            at = rng.uniform(0.03, 0.97) * main.length
            if all(abs(at - mouth) > 120.0 for mouth in mouths) and all(abs(at - p) > 60.0 for p in positions):
                positions.append(at)
        cutters = []
        for at in sorted(positions):
            base = np.asarray(main.interpolate(at).coords[0])
            ahead = np.asarray(main.interpolate(at + 1.0).coords[0]) - base
            normal = np.array([-ahead[1], ahead[0]]) / np.hypot(*ahead)
            cutters.append(LineString([base - 30.0 * normal, base + 30.0 * normal]))
        pieces = split(polygon, shapely.MultiLineString(cutters))
        for piece in shapely.get_parts(pieces):
            reaches.append(shapely.set_precision(piece, 1e-6).normalize())
            river_of.append(number)
    return reaches, river_of
