"""Analytic network shapes for the network tests: road junctions and confluences with their exact junctions.

Each builder returns the polygon, its split points (on the exterior ring, at the arms' ends) and the
expected junction centres, derived from the geometry (see each docstring). Numpy and shapely only.
"""

import math

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon, box
from shapely.ops import unary_union


def arm(angle, length, half_width, start=0.0):
    """A rectangular arm from ``start`` to ``length`` along direction ``angle`` (radians), centred on it."""
    direction = np.array([math.cos(angle), math.sin(angle)])
    normal = np.array([-direction[1], direction[0]])
    corners = [
        start * direction - half_width * normal,
        length * direction - half_width * normal,
        length * direction + half_width * normal,
        start * direction + half_width * normal,
    ]
    return Polygon(corners)


def circumcentre(a, b, c):
    """Centre of the circle through three points."""
    a, b, c = (np.asarray(p, dtype=float) for p in (a, b, c))
    d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    squares = [p @ p for p in (a, b, c)]
    x = squares[0] * (b[1] - c[1]) + squares[1] * (c[1] - a[1]) + squares[2] * (a[1] - b[1])
    y = squares[0] * (c[0] - b[0]) + squares[1] * (a[0] - c[0]) + squares[2] * (b[0] - a[0])
    return np.array([x / d, y / d])


def reflex_corners(polygon):
    """Vertices of the exterior ring where the interior angle exceeds 180 degrees."""
    ring = shapely.get_coordinates(shapely.geometry.polygon.orient(polygon, 1.0).exterior)[:-1]
    before, after = ring - np.roll(ring, 1, axis=0), np.roll(ring, -1, axis=0) - ring
    cross = before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0]
    return ring[cross < -1e-9 * float(np.max(np.abs(ring)))]


def star(angles, half_widths, length=60.0):
    """Arms from the origin in the given directions (a Y for three, an X for four); split points at the caps.

    The arms start at the origin; the convex hull of their inner ends fills the centre (no notch).
    """
    arms = [arm(a, length, h) for a, h in zip(angles, half_widths)]
    hub = shapely.convex_hull(
        shapely.MultiPoint([xy for a in arms for xy in (a.exterior.coords[0], a.exterior.coords[3])])
    )
    polygon = unary_union([*arms, hub])
    polygon = shapely.set_precision(polygon, 0.0).normalize()
    caps = [length * np.array([math.cos(a), math.sin(a)]) for a in angles]
    return polygon, caps


def symmetric_y(half_width=5.0, length=60.0):
    """Three equal arms at 120 degrees: one junction at the origin, the centre of the three reflex corners.

    The corners lie at ``half_width / sin(60 deg)`` from the origin, so that is the junction's radius.
    """
    polygon, caps = star([math.radians(a) for a in (90.0, 210.0, 330.0)], [half_width] * 3, length)
    return polygon, caps, [np.zeros(2)], half_width / math.sin(math.radians(60.0))


def skewed_y():
    """Three arms of different widths at 80, 200 and 310 degrees.

    The junction's circle touches the three reflex corners (the arms' edges run away from it), so the
    junction is their circumcentre.
    """
    polygon, caps = star([math.radians(a) for a in (80.0, 200.0, 310.0)], [6.0, 4.0, 5.0], 60.0)
    corners = reflex_corners(polygon)
    return polygon, caps, [circumcentre(*corners)]


def t_junction(half_width=5.0, side_half_width=3.0, length=50.0):
    """A straight road ``|y| <= a`` for ``|x| <= L`` with a side road ``|x| <= b``, ``y >= 0`` up to ``L``.

    The junction's circle touches the bottom edge ``y = -a`` and the corners ``(+-b, a)``: centre ``(0, y0)``
    with ``y0 + a = sqrt(b**2 + (a - y0)**2)``, so ``y0 = b**2 / (4 a)`` and radius ``a + y0`` (needs
    ``b < 2 a``).
    """
    a, b = half_width, side_half_width
    polygon = unary_union(
        [
            Polygon([(-length, -a), (length, -a), (length, a), (-length, a)]),
            Polygon([(-b, 0.0), (b, 0.0), (b, length), (-b, length)]),
        ]
    )
    y0 = b * b / (4.0 * a)
    return polygon, [(-length, 0.0), (length, 0.0), (0.0, length)], [np.array([0.0, y0])], a + y0


def crossing(angle_degrees, half_width_a=5.0, half_width_b=3.0, length=50.0):
    """Road A (``|y| <= a``) crossed by road B (half width ``b``) at ``angle_degrees`` (theta); junctions.

    B's edges meet ``y = a`` at ``x = (a cos(theta) -+ b) / sin(theta)`` and ``y = -a`` at the opposite
    points. A circle touching the two upper corners and the lower edge ``y = -a`` has its centre on their
    perpendicular bisector, ``x0 = a cot(theta)``, with ``y0 + a = sqrt(h**2 + (a - y0)**2)`` for the corners'
    half distance ``h = b / sin(theta)``: ``y0 = h**2 / (4 a)``. Its foot ``(x0, -a)`` lies on the lower
    edge when ``x0 >= (b - a cos(theta)) / sin(theta)``, i.e. ``2 a cos(theta) >= b``: then there are two
    junctions, ``(x0, y0)`` and its mirror through the centre ``(-x0, -y0)``, joined by a short branch.
    Otherwise (a right angle) the circles touch only the four corners, which lie on one circle about the
    centre: one junction of degree 4 at the centre.
    """
    theta = math.radians(angle_degrees)
    a, b = half_width_a, half_width_b
    polygon, caps = star([0.0, theta, math.pi, math.pi + theta], [a, b, a, b], length)
    if 2.0 * a * math.cos(theta) >= b:
        x0, y0 = a / math.tan(theta), (b / math.sin(theta)) ** 2 / (4.0 * a)
        return polygon, caps, [np.array([x0, y0]), np.array([-x0, -y0])]
    return polygon, caps, [np.zeros(2)]


def reservoir():
    """A three-arm reservoir: winding arms of widths 16, 10 and 6 meeting in a basin, flat ends.

    No closed form: the oracle alone checks it.
    """
    arms = [
        (LineString([(0, 0), (40, -10), (90, -5), (140, -25)]), 8.0),
        (LineString([(0, 0), (-30, 35), (-45, 80), (-80, 110)]), 5.0),
        (LineString([(0, 0), (-40, -20), (-70, -60)]), 3.0),
    ]
    basin = LineString([(0, 0), (1, 0)]).buffer(14.0, quad_segs=8)
    shapes = [line.buffer(width, cap_style="flat", join_style="round", quad_segs=8) for line, width in arms]
    polygon = shapely.set_precision(unary_union([basin, *shapes]), 0.0).normalize()
    caps = [np.asarray(line.coords[-1], dtype=float) for line, _ in arms]
    return polygon, caps


def delta():
    """Six straight arms of half widths 4 to 9 fanning out from a round basin of radius 9; flat ends.

    No closed form: the oracle alone checks it (four junctions).
    """
    angles = np.radians([0.0, 40.0, 80.0, 120.0, 160.0, 250.0])
    lines = [
        LineString([(0.0, 0.0), (50.0 * math.cos(a), 50.0 * math.sin(a) + (10.0 if i % 2 else 0.0))])
        for i, a in enumerate(angles)
    ]
    arms = [line.buffer(4.0 + i, cap_style="flat") for i, line in enumerate(lines)]
    basin = LineString([(0.0, 0.0), (1.0, 0.0)]).buffer(9.0)
    polygon = shapely.set_precision(unary_union([*arms, basin]), 0.0).normalize()
    return polygon, [np.asarray(line.coords[-1], dtype=float) for line in lines]


def fishbone(sides=5, spacing=40.0, half_width=5.0, side_half_width=3.0, side_length=45.0):
    """A main road with ``sides`` side roads on each side (alternating, flat ends): ``2 sides + 2`` arms."""
    length = spacing * (sides + 1)
    pieces = [box(0.0, -half_width, length, half_width)]
    caps = [(0.0, 0.0), (length, 0.0)]
    for index in range(2 * sides):
        x = spacing * (index // 2 + 1) + (spacing / 2.0 if index % 2 else 0.0) - spacing / 4.0
        sign = 1.0 if index % 2 == 0 else -1.0
        pieces.append(box(x - side_half_width, 0.0, x + side_half_width, sign * side_length).normalize())
        caps.append((x, sign * side_length))
    return unary_union(pieces), caps


def noisy(polygon, width, seed):
    """The polygon with bank noise: the outline sampled every 0.3 ``width`` and each sample moved along the
    outward normal by up to 5 % of ``width`` (steps of random sign every few samples: bumps, notches and
    digitising steps), except within one ``width`` of a corner, so the outline stays simple."""
    rng = np.random.default_rng(seed)
    ring = shapely.geometry.polygon.orient(polygon, 1.0).exterior
    corners = shapely.get_coordinates(ring)[:-1]
    before, after = corners - np.roll(corners, 1, axis=0), np.roll(corners, -1, axis=0) - corners
    turn = np.abs(
        np.arctan2(before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0], np.einsum("ij,ij->i", before, after))
    )
    sharp = shapely.multipoints(corners[turn > np.radians(20.0)])
    samples = shapely.get_coordinates(shapely.segmentize(ring, 0.3 * width))[:-1]
    tangent = np.roll(samples, -1, axis=0) - np.roll(samples, 1, axis=0)
    normal = np.stack([tangent[:, 1], -tangent[:, 0]], axis=1) / np.hypot(*tangent.T)[:, None]
    blocks = np.repeat(rng.choice([-1.0, 0.0, 1.0], size=len(samples) // 3 + 1), 3)[: len(samples)]
    amplitude = 0.05 * width * blocks * rng.uniform(0.5, 1.0, len(samples))
    far = shapely.distance(shapely.points(samples), sharp) > width
    moved = samples + (amplitude * far)[:, None] * normal
    return Polygon(moved)


def road_grid(columns=2, rows=2, block=40.0, street=10.0, stub=30.0):
    """A road area: a grid of ``columns x rows`` square city blocks (holes) with streets ``street`` wide
    between and around them, every street leaving the grid by a stub ``stub`` long (flat ends).

    Street centre lines run at ``x = street / 2 + m (block + street)`` (and the same in ``y``); they cross at
    the junctions, whose circles touch the four block (or outline) corners around them: radius
    ``street / sqrt(2)``. The network has one branch per street segment between two crossings and one per stub.

    Returns
    -------
    polygon : Polygon
    caps : list of (x, y)
        The stubs' cut-off ends' middles.
    junctions : list of ndarray of shape (2,)
    radius : float
    """
    pitch = block + street
    width, height = columns * pitch + street, rows * pitch + street
    lines_x = [street / 2.0 + m * pitch for m in range(columns + 1)]
    lines_y = [street / 2.0 + m * pitch for m in range(rows + 1)]
    half = street / 2.0
    pieces = [box(0.0, 0.0, width, height)]
    caps = []
    for x in lines_x:
        pieces += [box(x - half, -stub, x + half, 0.0), box(x - half, height, x + half, height + stub)]
        caps += [(x, -stub), (x, height + stub)]
    for y in lines_y:
        pieces += [box(-stub, y - half, 0.0, y + half), box(width, y - half, width + stub, y + half)]
        caps += [(-stub, y), (width + stub, y)]
    outline = shapely.set_precision(unary_union(pieces), 0.0)
    blocks = [
        box(street + i * pitch, street + j * pitch, street + i * pitch + block, street + j * pitch + block)
        for i in range(columns)
        for j in range(rows)
    ]
    polygon = Polygon(outline.exterior.coords, [b.exterior.coords for b in blocks])
    junctions = [np.array([x, y]) for x in lines_x for y in lines_y]
    return polygon, caps, junctions, street / math.sqrt(2.0)
