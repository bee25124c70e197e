"""Generated inputs of the public core API: valid channels and shapes, and hostile input.

Each input is a :class:`Case`, a pure function of ``(seed, index)``: the category is drawn from
:data:`CATEGORIES` by weight, then the category's generator draws the geometry from a numpy generator seeded
with both numbers. Lengths are in arbitrary CRS units.
"""

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np
import shapely
import shapely.affinity
from shapely.geometry import LineString, MultiPoint, MultiPolygon, Point, Polygon

from incircu_plugin import core
from incircu_plugin.core.polyline import typical_width
from tests.support import compact_shapes


@dataclass
class Case:
    """One call of a public core function and what a correct result must satisfy.

    Attributes
    ----------
    category : str
        Generator name (a row of the outcome table).
    function : str
        Name of the function in ``incircu_plugin.core``.
    args, kwargs : tuple, dict
        The call's arguments.
    polygon : shapely.Geometry or None
        The region the line must stay in (the polygon, or the area between two bank lines).
    split_points : ndarray of shape (2 * parts, 2) or None
        The given ends, to check the line's ends (None: automatic ends, checked to lie on the boundary).
    snap : float
        Largest distance, CRS units, between a given split point and the line's end.
    centre : tuple or None
        A centre of symmetry the automatic ends must lie across (the segment between them passes it).
    tips : ndarray of shape (k, 2) or None
        The points (a star's tips) the two automatic ends must be two of.
    closed : bool
        The line must be a closed loop (a ring's, with automatic ends).
    """

    category: str
    function: str
    args: tuple
    kwargs: dict = field(default_factory=dict)
    polygon: Optional[object] = None
    split_points: Optional[np.ndarray] = None
    snap: float = 0.0
    centre: Optional[tuple] = None
    tips: Optional[np.ndarray] = None
    closed: bool = False

    def describe(self, limit=600):
        """The call as Python-like text (geometries as WKT, cut to ``limit`` characters each)."""

        def text(value):
            if isinstance(value, shapely.Geometry):
                return f"wkt({shapely.to_wkt(value, rounding_precision=17)!r})"[:limit]
            if isinstance(value, np.ndarray):
                return f"array({value.tolist()!r})"[:limit]
            if isinstance(value, (list, tuple)):
                return "[" + ", ".join(text(v) for v in value) + "]"
            return repr(value)[:limit]

        arguments = [text(a) for a in self.args] + [f"{k}={text(v)}" for k, v in self.kwargs.items()]
        return f"{self.function}({', '.join(arguments)})"


# Valid geometry ------------------------------------------------------------------------------------------------


def channel_axis(rng, small):
    """A smooth random axis and its half-widths: ``(axis (n, 2), half_widths (n,))``, bends wider than the width."""
    count = int(rng.integers(6, 12 if small else 120))
    half_width = float(rng.uniform(0.5, 5.0))
    step = half_width * float(rng.uniform(0.5, 3.0))
    # Heading changes keep every bend's radius above three half-widths, so the banks never fold.
    turn = rng.normal(0.0, 1.0, count - 1).cumsum() * 0.15
    turn = np.clip(np.diff(np.concatenate([[0.0], turn])), -step / (3 * half_width), step / (3 * half_width))
    heading = float(rng.uniform(0, 2 * math.pi)) + np.concatenate([[0.0], np.cumsum(turn)])[:-1]
    axis = np.concatenate([[[0.0, 0.0]], np.cumsum(step * np.stack([np.cos(heading), np.sin(heading)], 1), 0)])
    widths = half_width * np.exp(0.3 * np.sin(np.linspace(0, float(rng.uniform(1, 8)), len(axis)) + rng.uniform(0, 6)))
    return axis, widths


def banks_of(axis, half_widths, rng, jitter=0.05):
    """Left and right banks of an axis (offset along the vertex normals, slightly jittered)."""
    tangent = np.gradient(axis, axis=0)
    tangent /= np.hypot(*tangent.T)[:, None]
    normal = np.stack([-tangent[:, 1], tangent[:, 0]], 1)
    noise = 1.0 + jitter * rng.uniform(-1, 1, (2, len(axis)))
    left = axis + normal * (half_widths * noise[0])[:, None]
    right = axis - normal * (half_widths * noise[1])[:, None]
    return left, right


def random_channel(rng, small, islands=0):
    """A valid channel polygon with its two split points (the middles of its end caps), or None."""
    for _ in range(20):
        axis, half_widths = channel_axis(rng, small)
        left, right = banks_of(axis, half_widths, rng)
        polygon = Polygon(np.concatenate([right, left[::-1]]))
        if not polygon.is_valid or polygon.exterior.length > 1.3 * (
            2 * LineString(axis).length + 4 * half_widths.max()
        ):
            continue
        ends = np.array([(left[0] + right[0]) / 2, (left[-1] + right[-1]) / 2])
        holes = []
        for _ in range(islands):
            i = int(rng.integers(1, len(axis) - 1))
            radius = float(half_widths[i] * rng.uniform(0.1, 0.4))
            centre = axis[i] + rng.uniform(-0.3, 0.3, 2) * half_widths[i]
            angles = np.sort(rng.uniform(0, 2 * math.pi, int(rng.integers(3, 12))))
            hole = Polygon(centre + radius * np.stack([np.cos(angles), np.sin(angles)], 1))
            inside = hole.is_valid and polygon.buffer(-0.1 * half_widths.min()).contains(hole)
            if inside and all(hole.distance(other) > 0.05 * radius for other in holes):
                holes.append(hole)
        if holes:
            polygon = Polygon(polygon.exterior, [h.exterior for h in holes])
            if not polygon.is_valid:
                continue
        return polygon, ends, (left, right)
    return None


def _placement(rng):
    """A random centre, turn and size (1e-3 to 1e5) for a compact shape of unit size."""
    size = 10 ** rng.uniform(-3, 5)
    return rng.uniform(-1, 1, 2) * 10 ** rng.uniform(0, 6), rng.uniform(0, 2 * math.pi), size


def _sometimes_segmentized(rng, polygon, size):
    """The polygon, or (half the time) with extra vertices on its edges (the ends must not move)."""
    if rng.random() < 0.5:
        return shapely.segmentize(polygon, size / int(rng.integers(2, 30)))
    return polygon


def random_shape(rng):
    """A random star-shaped polygon (valid) and two random points of its exterior ring."""
    count = int(rng.integers(5, 40))
    angles = np.sort(rng.uniform(0, 2 * math.pi, count))
    radii = rng.uniform(0.3, 1.0, count) * float(rng.uniform(1, 100))
    polygon = Polygon(np.stack([radii * np.cos(angles), radii * np.sin(angles)], 1))
    if not polygon.is_valid:
        polygon = shapely.convex_hull(polygon)
    ring = polygon.exterior
    points = np.array([ring.interpolate(f, normalized=True).coords[0] for f in rng.uniform(0, 1, 2)])
    return polygon, points


# Categories ----------------------------------------------------------------------------------------------------


def valid_split(rng, small):
    """A channel, perhaps with islands, between its two cap middles."""
    polygon, ends, _ = random_channel(rng, small, islands=int(rng.integers(0, 4)))
    islands = "main_channel" if rng.random() < 0.8 else "ignore"
    region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
    return Case("valid split points", "polygon_centerline", (polygon, ends), {"islands": islands}, region, ends)


def valid_parts(rng, small):
    """Two or three channels side by side as one MultiPolygon, with the split points of all of them."""
    parts, points, x = [], [], 0.0
    for _ in range(int(rng.integers(2, 4))):
        polygon, ends, _ = random_channel(rng, small, islands=int(rng.integers(0, 2)))
        west, south, east, _ = polygon.bounds
        shift = np.array([x - west, -south])
        parts.append(shapely.transform(polygon, lambda xy, s=shift: xy + s))
        points.append(ends + shift)
        x += east - west + 1.0
    points = np.concatenate(points)
    order = rng.permutation(len(points))
    return Case(
        "valid several parts", "multipolygon_centerlines", (MultiPolygon(parts), points[order]), {}, None, points
    )


def valid_auto(rng, small):
    """A channel with automatic ends."""
    polygon, _, _ = random_channel(rng, small, islands=int(rng.integers(0, 3)))
    return Case("valid automatic ends", "polygon_centerline", (polygon,), {}, polygon)


def valid_banks(rng, small):
    """The two banks of a channel, one of them perhaps reversed."""
    polygon, _, (left, right) = random_channel(rng, small)
    if rng.random() < 0.5:
        right = right[::-1]
    return Case("valid bank lines", "lines_centerline", (LineString(left), LineString(right)), {}, polygon)


def valid_wide_tolerance(rng, small):
    """A channel with islands, or its two banks, at a tolerance from a third of its typical width to ten widths:
    the simplified line must still stay inside."""
    islands = int(rng.integers(0, 3))
    polygon, ends, (left, right) = random_channel(rng, small, islands=islands)
    width = typical_width(polygon.area, 0.5 * polygon.exterior.length)
    tolerance = {"tolerance": width * 10.0 ** float(rng.uniform(-0.5, 1.0))}
    if islands or rng.random() < 0.6:
        return Case("valid wide tolerance", "polygon_centerline", (polygon, ends), tolerance, polygon, ends)
    banks = (LineString(left), LineString(right))
    return Case("valid wide tolerance", "lines_centerline", banks, tolerance, Polygon(polygon.exterior))


def valid_random_shape(rng, small):
    """A random star-shaped polygon between two random points of its boundary."""
    polygon, points = random_shape(rng)
    return Case("valid random shape, split points", "polygon_centerline", (polygon, points), {}, polygon, points)


def _compact_case(rng, category, polygon, **checks):
    """Automatic ends of a compact or star-like shape: ``find_ends`` or ``polygon_centerline``."""
    function = "find_ends" if rng.random() < 0.3 else "polygon_centerline"
    return Case(category, function, (polygon,), {}, polygon, **checks)


def compact_polygon(rng, small):
    """A square, a compact rectangle (aspect to 1.6) or a regular polygon: ends symmetric across its centre."""
    centre, turn, size = _placement(rng)
    kind = rng.choice(["square", "rectangle", "regular"])
    if kind == "regular":
        polygon = compact_shapes.regular_polygon(int(rng.integers(3, 21)), size, centre, turn)
    else:
        aspect = 1.0 if kind == "square" else rng.uniform(1.0, 1.6)
        polygon = compact_shapes.rectangle(size * aspect, size, centre, turn)
    polygon = _sometimes_segmentized(rng, polygon, size)
    return _compact_case(rng, "compact polygon, automatic ends", polygon, centre=tuple(centre))


def compact_star(rng, small):
    """A star (3 to 12 arms), a hole in the middle of some: ends at the tips of two arms farthest apart; or a
    fat star (not star-like, compact, without a hole): ends symmetric across its centre."""
    centre, turn, size = _placement(rng)
    arms = int(rng.integers(3, 13))
    fat = rng.random() < 0.25
    inner = rng.uniform(0.5, 0.8) if fat else rng.uniform(0.2, 0.4)
    # A fat star with a hole is a ring (its skeleton a loop around the hole), not a compact shape.
    hole = inner * size * rng.uniform(0.2, 0.8) if not fat and rng.random() < 0.3 else 0.0
    polygon = compact_shapes.star(arms, size, inner * size, centre, turn, hole)
    polygon = Polygon(_sometimes_segmentized(rng, Polygon(polygon.exterior), size).exterior, polygon.interiors)
    if fat:
        return _compact_case(rng, "star, automatic ends", polygon, centre=tuple(centre))
    tips = compact_shapes.star_tips(arms, size, centre, turn)
    return _compact_case(rng, "star, automatic ends", polygon, tips=tips)


def compact_ellipse(rng, small):
    """An ellipse (aspect 1.05 to 4) of 8 to 64 vertices, corners on its tips or half a step beside them: ends
    across its centre at its tips."""
    centre, turn, size = _placement(rng)
    vertices = int(rng.choice([8, 10, 12, 16, 24, 32, 64]))
    phase = math.pi / vertices if rng.random() < 0.5 else 0.0
    polygon = compact_shapes.ellipse(vertices, size, size / rng.uniform(1.05, 4.0), centre, turn, phase)
    return _compact_case(rng, "ellipse, automatic ends", polygon, centre=tuple(centre))


def thin_box(rng, small):
    """A box of aspect 1e-1 to 1e-3 (1e-5 in the full campaign), split points or automatic ends."""
    length = 10 ** rng.uniform(-2, 4)
    width = length * 10 ** rng.uniform(-3 if small else -5, -1)
    polygon = shapely.box(0, 0, length, width)
    if rng.random() < 0.5:
        ends = np.array([[0, width / 2], [length, width / 2]])
        return Case("thin box", "polygon_centerline", (polygon, ends), {}, polygon, ends)
    return Case("thin box", "polygon_centerline", (polygon,), {}, polygon)


def ring_shape(rng):
    """A valid ring around one hole: an annulus (off-centre hole), a roundabout (a buffered circle), a
    rectangular frame, an "o" (ellipses) or an atoll (a wavy outer bank); scaled and shifted at random."""
    kind = rng.choice(["annulus", "roundabout", "frame", "o", "atoll"])
    outer = float(rng.uniform(5, 50))
    wall = outer * float(rng.uniform(0.05, 0.35))
    if kind == "annulus":
        offset = rng.uniform(-0.3, 0.3, 2) * wall
        polygon = Point(0, 0).buffer(outer).difference(Point(*offset).buffer(outer - wall))
    elif kind == "roundabout":
        polygon = Point(0, 0).buffer(outer).exterior.buffer(wall / 2)
    elif kind == "frame":
        ratio = float(rng.uniform(0.3, 1.0))
        polygon = shapely.box(-outer, -outer * ratio, outer, outer * ratio).difference(
            shapely.box(-outer + wall, -outer * ratio + wall, outer - wall, outer * ratio - wall)
        )
    elif kind == "o":
        ratio = float(rng.uniform(0.5, 0.9))
        ellipse = shapely.affinity.scale(Point(0, 0).buffer(outer), ratio, 1.0)
        polygon = ellipse.difference(shapely.affinity.scale(Point(0, 0).buffer(outer - wall), ratio, 1.0))
    else:
        angles = np.linspace(0, 2 * math.pi, int(rng.integers(40, 300)), endpoint=False)
        bumps = int(rng.integers(3, 12))
        radius = outer + 0.3 * wall * np.sin(bumps * angles + rng.uniform(0, 2 * math.pi))
        polygon = Polygon(np.stack([radius * np.cos(angles), radius * np.sin(angles)], 1)).difference(
            Point(0, 0).buffer(outer - wall, int(rng.integers(2, 16)))
        )
    polygon = shapely.affinity.rotate(polygon, float(rng.uniform(0, 360)), origin=(0, 0))
    scale, shift = 10 ** rng.uniform(-3, 4), rng.uniform(-1, 1, 2) * 10 ** rng.uniform(0, 6)
    return shapely.transform(polygon, lambda xy: xy * scale + shift)


def ring_auto(rng, small):
    """Rings around one hole with automatic ends: the closed medial loop (``Case.closed``); with split points on
    the outer ring, the line between them."""
    polygon = ring_shape(rng)
    if rng.random() < 0.8:
        return Case("ring, automatic ends", "polygon_centerline", (polygon,), {}, polygon, closed=True)
    ring = polygon.exterior
    points = np.array([ring.interpolate(f, normalized=True).coords[0] for f in (0.1, 0.6)])
    return Case("ring, split points", "polygon_centerline", (polygon, points), {}, polygon, points)


def spiky_channel(rng, small):
    """A valid channel, or its banks, with a zero-width spike: out along the normal of an edge's middle, from a
    millionth to half its width, and back a hair (1e-13 to 1e-10 of the extent) beside where it left."""
    for _ in range(20):
        polygon, ends, (left, right) = random_channel(rng, small)
        width = typical_width(polygon.area, 0.5 * polygon.exterior.length)
        bank = left if rng.random() < 0.5 else right
        i = int(rng.integers(1, len(bank) - 2))
        along = bank[i + 1] - bank[i]
        along = along / np.hypot(*along)
        normal = np.array([-along[1], along[0]]) * rng.choice([-1.0, 1.0])
        base = bank[i] + 0.5 * (bank[i + 1] - bank[i])
        extent = float(np.hypot(*np.ptp(np.concatenate([left, right]), axis=0)))
        tip = base + normal * width * 10 ** rng.uniform(-6, math.log10(0.5))
        back = base + along * extent * 10 ** rng.uniform(-13, -10)
        spiked = np.concatenate([bank[: i + 1], [base, tip, back], bank[i + 1 :]])
        left, right = (spiked, right) if bank is left else (left, spiked)
        if rng.random() < 0.3:
            banks = (LineString(left), LineString(right))
            return Case("spiky bank lines", "lines_centerline", banks, {}, Polygon(polygon.exterior))
        spiky = Polygon(np.concatenate([right, left[::-1]]))
        if spiky.is_valid:
            call = (spiky, ends) if rng.random() < 0.6 else (spiky,)
            return Case("spiky polygon", "polygon_centerline", call, {}, spiky, ends if len(call) == 2 else None)
    return valid_split(rng, small)


def float64_thin_box(rng, small):
    """A box 1e-6 to 1e-16 of its length wide (float64's limit), split points or automatic ends, automatic or
    given tolerance: a line along its middle or a typed error naming its width."""
    length = 10 ** rng.uniform(-2, 6)
    width = length * 10 ** rng.uniform(-16, -6)
    polygon = shapely.box(0, 0, length, width)
    kwargs = {"tolerance": length * 10 ** rng.uniform(-9, -6)} if rng.random() < 0.3 else {}
    if rng.random() < 0.5:
        ends = np.array([[0, width / 2], [length, width / 2]])
        return Case("thin box at float64's limit", "polygon_centerline", (polygon, ends), kwargs, polygon, ends)
    return Case("thin box at float64's limit", "polygon_centerline", (polygon,), kwargs, polygon)


def scaled_channel(rng, small):
    """A valid channel scaled by 10**k, k in [-320, 320] (float64's range and beyond) or in [-45, 45]."""
    polygon, ends, _ = random_channel(rng, small)
    exponent = rng.uniform(-320, 320) if rng.random() < 0.5 else rng.uniform(-45, 45)
    with np.errstate(all="ignore"):
        factor = float(np.power(10.0, exponent))
        shift = float(np.power(10.0, rng.uniform(-5, 16))) * float(rng.choice([0.0, 1.0]))
        polygon = shapely.transform(polygon, lambda xy: xy * factor + shift)
        ends = ends * factor + shift
    return Case("huge or tiny coordinates", "polygon_centerline", (polygon, ends), {}, polygon, ends, snap=0.0)


def non_finite(rng, small):
    """NaN or inf in a polygon, a bank line or a split point."""
    polygon, ends, (left, right) = random_channel(rng, small)
    bad = float(rng.choice([math.nan, math.inf, -math.inf]))
    where = rng.choice(["polygon", "bank", "split"])
    if where == "polygon":
        ring = np.asarray(polygon.exterior.coords)[:-1]
        # Not the first vertex: shapely could not close a ring starting with NaN.
        ring[int(rng.integers(1, len(ring))), int(rng.integers(0, 2))] = bad
        return Case("NaN or inf", "polygon_centerline", (Polygon(ring), ends))
    if where == "bank":
        left = left.copy()
        left[int(rng.integers(0, len(left))), int(rng.integers(0, 2))] = bad
        return Case("NaN or inf", "lines_centerline", (left, LineString(right)))
    ends = ends.copy()
    ends[int(rng.integers(0, 2)), int(rng.integers(0, 2))] = bad
    return Case("NaN or inf", "multipolygon_centerlines", (polygon, ends))


def empty_or_none(rng, small):
    """None and empty geometries to every entry point."""
    empty = [None, Polygon(), MultiPolygon(), LineString(), Point()][int(rng.integers(0, 5))]
    function = ["polygon_centerline", "multipolygon_centerlines", "find_ends", "lines_centerline", "split_polygon"][
        int(rng.integers(0, 5))
    ]
    if function == "lines_centerline":
        return Case("empty or None", function, (empty, [(0, 1), (10, 1)]))
    if function == "split_polygon":
        return Case("empty or None", function, (empty, [(0, 0), (1, 1)]))
    return Case("empty or None", function, (empty,))


def invalid_polygon(rng, small):
    """Bow-ties, spikes and bad holes, with split points or automatic ends."""
    polygon, ends, _ = random_channel(rng, small)
    ring = np.asarray(polygon.exterior.coords)[:-1]
    kind = rng.choice(["bow-tie", "spike", "bad hole"])
    if kind == "bow-tie":
        a, b = rng.uniform(1, 100, 2)
        bad = Polygon([(0, 0), (a, b), (a, 0), (0, b)])
        ends = np.array([(0, b / 2), (a, b / 2)])
    elif kind == "spike":
        i = int(rng.integers(1, len(ring) - 1))
        tip = ring[i] + (ring[i] - ring[i - 1]) * rng.uniform(0.5, 3)
        bad = Polygon(np.concatenate([ring[: i + 1], [tip], ring[i:]]))
    else:
        west, south, east, north = polygon.bounds
        centre = rng.uniform([west, south], [east, north])
        hole = shapely.box(*(centre - 0.5 * (north - south)), *(centre + 0.5 * (north - south)))
        bad = Polygon(polygon.exterior, [hole.exterior])
    call = (bad, ends) if rng.random() < 0.6 else (bad,)
    return Case(f"invalid polygon ({kind})", "polygon_centerline", call)


def crossing_banks(rng, small):
    """Bank lines that cross or touch."""
    _, _, (left, right) = random_channel(rng, small)
    i = int(rng.integers(1, len(left) - 1))
    right = right.copy()
    right[i] = left[i] + (left[i] - right[i]) * rng.uniform(0, 0.5)
    return Case("crossing banks", "lines_centerline", (left, right))


def bad_options(rng, small):
    """Bad numbers and split points of the wrong kind or count."""
    polygon, ends, (left, right) = random_channel(rng, small)
    bad_number = [math.nan, math.inf, -math.inf, -1.0, "1", 0.0, 1e-300, 1e300, 2.5][int(rng.integers(0, 9))]
    choice = int(rng.integers(0, 8))
    if choice == 0:
        kwargs = {str(rng.choice(["spacing", "tolerance"])): bad_number}
        return Case("bad options", "polygon_centerline", (polygon, ends), kwargs, polygon, ends)
    if choice == 1:
        kwargs = {"samples_per_chain": bad_number}
        return Case("bad options", "lines_centerline", (left, right), kwargs, polygon)
    if choice == 2:
        far = np.array([ends[0], ends[1] + 1e3])
        return Case("bad options", "polygon_centerline", (polygon, far), {"snap_tolerance": bad_number})
    points = [
        MultiPoint(ends),
        [Point(), Point()],
        [Point(ends[0])],
        [Point(ends[0]), Point(ends[1]), Point(ends[0])],
        [LineString(ends), Point(ends[1])],
    ][choice - 3]
    function = ["polygon_centerline", "multipolygon_centerlines", "split_polygon"][int(rng.integers(0, 3))]
    expected = ends if isinstance(points, MultiPoint) and function == "polygon_centerline" else None
    return Case(
        "bad split points", function, (polygon, points), {}, polygon if expected is not None else None, expected
    )


#: (generator, weight): about 54 % valid channels and shapes, 17 % compact shapes, 20 % hostile input, 9 %
#: rings, spiky channels and boxes at float64's limit.
CATEGORIES = (
    (valid_split, 22),
    (valid_parts, 8),
    (valid_auto, 10),
    (valid_banks, 10),
    (valid_wide_tolerance, 6),
    (valid_random_shape, 5),
    (compact_polygon, 8),
    (compact_star, 7),
    (compact_ellipse, 5),
    (thin_box, 4),
    (scaled_channel, 4),
    (non_finite, 4),
    (empty_or_none, 2),
    (invalid_polygon, 4),
    (crossing_banks, 2),
    (bad_options, 5),
    (ring_auto, 4),
    (spiky_channel, 4),
    (float64_thin_box, 3),
)


def make_case(seed, index, small=False):
    """Input number ``index`` of the campaign ``seed``; ``small`` keeps channels short (the test sample)."""
    rng = np.random.default_rng([seed, index])
    weights = np.array([weight for _, weight in CATEGORIES], dtype=float)
    generator = CATEGORIES[int(rng.choice(len(CATEGORIES), p=weights / weights.sum()))][0]
    return generator(rng, small)


def call(case):
    """Run the case's function; return what it returns."""
    return getattr(core, case.function)(*case.args, **case.kwargs)


#: The step-generator form (private, :mod:`incircu_plugin.core._steps`) of each public function that computes
#: arrays of geometries in batches traced together: what an array, or a layer, runs.
STEPS = {
    "polygon_centerline": "_polygon_centerline_steps",
    "multipolygon_centerlines": "_multipolygon_centerline_steps",
    "lines_centerline": "_lines_centerline_steps",
}


def steps(case):
    """The case's call as a step generator for :func:`incircu_plugin.core._many.run_many_steps` (arguments are
    bound here, so a misused keyword raises here as the plain call does), or None when its function has none."""
    name = STEPS.get(case.function)
    return None if name is None else getattr(core.api, name)(*case.args, **case.kwargs)
