"""Analytic test shapes for the IncirCu geometry core, shared by the tests and the benchmarks.

Every builder returns a :class:`Case`: an elongated polygon whose boundary is split into two chains at two
split points, with the exact axis the centerline must follow where one is known analytically. Shapes are
built in a local frame and then placed by a :class:`Placement` (scale, rotation, offset), so the same shape
can be tested at coordinates around 5e6 (a projected CRS) or around 1e-3 (a tiny drawing).

Only numpy and shapely are imported here, so benchmark scripts can use this module without pytest.

Channel construction
--------------------
All channels are built from two *banks* (``(n, 2)`` arrays running from the start end to the far end) joined
by two straight *caps*. The split points are the midpoints of the caps and are vertices of the ring. Chain
``a`` runs split point 0 -> bank ``a`` -> split point 1, chain ``b`` split point 0 -> bank ``b`` -> split
point 1. For open mode (two bank lines) the banks themselves are the lines and the midpoints of the end gaps
are the same split points.

Axis tolerance
--------------
The analytic axis belongs to the smooth shape; the polygon samples it. If every boundary point lies within
``s`` of the smooth boundary (the largest chord sagitta), distances to each chain change by at most ``s``,
and in a channel whose two distances change at rate 1 in opposite directions the equidistant set moves by
at most ``(s_a + s_b) / 2``. ``Case.axis_tolerance`` is that bound plus the rounding of the placed
coordinates (a few units in the last place of the largest coordinate).
"""

import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon
from shapely.geometry import shape as geojson_shape

DATA_FOLDER = Path(__file__).resolve().parents[1] / "data"

#: The Natural Earth 1:10m outline of the Gambia, projected to UTM zone 28N (EPSG:32628), metres.
GAMBIA_UTM_FILE = DATA_FOLDER / "gambia_ne10m_utm28n.geojson"

#: The same outline in longitude/latitude degrees (EPSG:4326).
GAMBIA_LONLAT_FILE = DATA_FOLDER / "gambia_ne10m_lonlat.geojson"


@dataclass(frozen=True)
class Placement:
    """Similarity transform from a shape's local frame to its coordinates: scale, rotate, then offset.

    Attributes
    ----------
    scale : float
        Length of one local unit, CRS units.
    angle : float
        Counter-clockwise rotation, radians.
    offset : tuple of float
        Translation added last, CRS units.
    """

    scale: float = 1.0
    angle: float = 0.0
    offset: tuple[float, float] = (0.0, 0.0)

    def apply(self, local):
        """Map local coordinates (array of shape (..., 2)) to placed coordinates."""
        local = np.asarray(local, dtype=float)
        cos, sin = math.cos(self.angle), math.sin(self.angle)
        x, y = local[..., 0], local[..., 1]
        return np.stack(
            [self.offset[0] + self.scale * (cos * x - sin * y), self.offset[1] + self.scale * (sin * x + cos * y)],
            axis=-1,
        )

    def invert(self, placed):
        """Map placed coordinates (array of shape (..., 2)) back to the local frame."""
        placed = np.asarray(placed, dtype=float)
        cos, sin = math.cos(self.angle), math.sin(self.angle)
        dx, dy = placed[..., 0] - self.offset[0], placed[..., 1] - self.offset[1]
        return np.stack([(cos * dx + sin * dy) / self.scale, (-sin * dx + cos * dy) / self.scale], axis=-1)


#: Placements every analytic case is tested in. ``projected`` puts coordinates around 5e6 (e.g. UTM
#: northings), ``tiny`` shrinks a 100-unit shape to about 1e-3 and moves it to about 1e-3.
PLACEMENTS = {
    "unit": Placement(),
    "projected": Placement(scale=1.0, angle=0.37, offset=(5.0e6, 5.2e6)),
    "tiny": Placement(scale=1e-5, angle=-1.1, offset=(1.0e-3, 2.0e-3)),
}


@dataclass(frozen=True)
class Case:
    """An elongated polygon split into two chains, with its analytic axis when known.

    Attributes
    ----------
    name : str
        Short description with the parameters.
    polygon : Polygon
        The region, CRS units; its exterior ring is chain ``a`` followed by chain ``b`` reversed.
    split_points : tuple of two (x, y) tuples
        Where the boundary is split (the ends of the centerline), CRS units.
    chain_a, chain_b : ndarray of shape (n, 2)
        Both chains, each from ``split_points[0]`` to ``split_points[1]``, CRS units.
    bank_a, bank_b : ndarray of shape (n, 2)
        The chains without the caps: the two lines of open mode, CRS units.
    width : float
        Nominal width of the channel, CRS units.
    axis_line : LineString or None
        The analytic axis between the split points, densely sampled (vertices exactly on it), CRS units.
    axis_distance : callable or None
        ``axis_distance(points)`` -> exact distance, CRS units, from each point of an ``(n, 2)`` array to
        the analytic axis (the whole curve between the split points).
    axis_tolerance : float
        How far the polygon's true medial axis may lie from the analytic one, CRS units (see the module
        docstring); 0 only when the polygon is exact and its coordinates are exactly representable.
    placement : Placement
        How the local frame was placed.
    axis_end_margin : float
        The analytic axis is exact only farther than this from both split points, CRS units: near a cap
        the medial axis between the chains bends to the junction of the cap's corner branches (annulus,
        meander); 0 when it is exact up to the split points (rectangle, tapered channel).
    """

    name: str
    polygon: Polygon
    split_points: tuple[tuple[float, float], tuple[float, float]]
    chain_a: np.ndarray
    chain_b: np.ndarray
    bank_a: np.ndarray
    bank_b: np.ndarray
    width: float
    axis_line: Optional[LineString] = None
    axis_distance: Optional[Callable[[np.ndarray], np.ndarray]] = None
    axis_tolerance: float = 0.0
    placement: Placement = field(default_factory=Placement)
    axis_end_margin: float = 0.0

    def away_from_ends(self, points):
        """Mask of the points farther than ``axis_end_margin`` from both split points."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        ends = np.asarray(self.split_points, dtype=float)
        return (np.hypot(*(points - ends[0]).T) > self.axis_end_margin) & (
            np.hypot(*(points - ends[1]).T) > self.axis_end_margin
        )

    @property
    def extent(self):
        """float: the larger side of the polygon's bounding box, CRS units."""
        x0, y0, x1, y1 = self.polygon.bounds
        return max(x1 - x0, y1 - y0)

    @property
    def coordinate_ulp(self):
        """float: spacing of doubles at the largest coordinate magnitude, CRS units (rounding floor)."""
        return float(np.spacing(np.max(np.abs(shapely.get_coordinates(self.polygon)))))

    @property
    def vertex_count(self):
        """int: number of distinct vertices of the exterior ring."""
        return len(self.polygon.exterior.coords) - 1

    @property
    def ring(self):
        """ndarray of shape (n + 1, 2): the closed exterior ring, chain a then chain b reversed."""
        return np.concatenate([self.chain_a, self.chain_b[-2::-1]])


def _bank_chains(bank_a, bank_b):
    """Return the split points (cap midpoints) and the two chains from two banks (local or placed)."""
    start = 0.5 * (bank_a[0] + bank_b[0])
    end = 0.5 * (bank_a[-1] + bank_b[-1])
    chain_a = np.concatenate([start[None], bank_a, end[None]])
    chain_b = np.concatenate([start[None], bank_b, end[None]])
    return start, end, chain_a, chain_b


def channel_case(
    name,
    bank_a,
    bank_b,
    width,
    placement=None,
    axis_local=None,
    axis_distance_local=None,
    axis_tolerance_local=0.0,
    validate=True,
    axis_end_margin_local=0.0,
):
    """Build a :class:`Case` from two banks given in a local frame.

    Parameters
    ----------
    name : str
        Description.
    bank_a, bank_b : array_like of shape (n, 2)
        The two banks in the local frame, both from the start end to the far end.
    width : float
        Nominal width, local units.
    placement : Placement, optional
        Where to put the shape; default the identity.
    axis_local : ndarray of shape (m, 2), optional
        Dense vertices of the analytic axis, local frame.
    axis_distance_local : callable, optional
        Exact distance from local points to the analytic axis, local units.
    axis_tolerance_local : float
        Polygonisation bound on the axis position, local units.
    validate : bool
        Check that the polygon is valid (skip for very large benchmark rivers).
    axis_end_margin_local : float
        See :attr:`Case.axis_end_margin`, local units.

    Returns
    -------
    Case
    """
    placement = placement or Placement()
    bank_a = placement.apply(np.asarray(bank_a, dtype=float))
    bank_b = placement.apply(np.asarray(bank_b, dtype=float))
    start, end, chain_a, chain_b = _bank_chains(bank_a, bank_b)
    ring = np.concatenate([chain_a, chain_b[-2::-1]])
    polygon = Polygon(ring)
    if validate and not polygon.is_valid:
        raise ValueError(f"{name}: the built polygon is invalid: {shapely.is_valid_reason(polygon)}")
    ulp = float(np.spacing(np.max(np.abs(ring))))
    axis_line = None
    axis_distance = None
    if axis_local is not None:
        axis_line = LineString(placement.apply(axis_local))
    if axis_distance_local is not None:

        def axis_distance(points, _local=axis_distance_local, _placement=placement):
            return placement.scale * _local(_placement.invert(np.asarray(points, dtype=float).reshape(-1, 2)))

    return Case(
        name=name,
        polygon=polygon,
        split_points=(tuple(start.tolist()), tuple(end.tolist())),
        chain_a=chain_a,
        chain_b=chain_b,
        bank_a=bank_a,
        bank_b=bank_b,
        width=width * placement.scale,
        axis_line=axis_line,
        axis_distance=axis_distance,
        axis_tolerance=axis_tolerance_local * placement.scale + 8.0 * ulp,
        placement=placement,
        axis_end_margin=axis_end_margin_local * placement.scale,
    )


def _segment_distance(points, start, end):
    """Exact distance from points (n, 2) to one segment."""
    direction = end - start
    t = np.clip(((points - start) @ direction) / float(direction @ direction), 0.0, 1.0)
    return np.hypot(*(points - start - t[:, None] * direction).T)


def _stations(length, count, jitter, rng):
    """``count`` increasing stations from 0 to ``length`` inclusive, interior ones jittered."""
    stations = np.linspace(0.0, length, count)
    if jitter and count > 2 and rng is not None:
        step = length / (count - 1)
        stations[1:-1] += rng.uniform(-jitter, jitter, count - 2) * step
    return stations


def rectangle(length=100.0, width=10.0, n=11, placement=None, jitter=0.0, seed=0):
    """Rectangle split at the midpoints of its short sides; the axis is the exact centreline.

    Parameters
    ----------
    length, width : float
        Sides, local units.
    n : int or (int, int)
        Vertices on each long side (ends included); collinear interior vertices are part of the test.
    placement : Placement, optional
    jitter : float
        Interior vertices move by up to this fraction of their spacing (needs ``seed``).
    seed : int

    Returns
    -------
    Case
        Axis: the segment from ``(0, width/2)`` to ``(length, width/2)``; ``axis_tolerance`` is rounding only.
    """
    n_a, n_b = (n, n) if np.isscalar(n) else n
    rng = np.random.default_rng(seed)
    xa = _stations(length, n_a, jitter, rng)
    xb = _stations(length, n_b, jitter, rng)
    bank_a = np.stack([xa, np.zeros_like(xa)], axis=1)
    bank_b = np.stack([xb, np.full_like(xb, width)], axis=1)
    axis = np.array([[0.0, width / 2.0], [length, width / 2.0]])
    return channel_case(
        f"rectangle L={length:g} W={width:g} n={n} {_describe(placement)}",
        bank_a,
        bank_b,
        width,
        placement,
        axis_local=axis,
        axis_distance_local=lambda p: _segment_distance(p, axis[0], axis[1]),
    )


def tapered_channel(length=100.0, width_start=20.0, width_end=5.0, n=11, placement=None, jitter=0.0, seed=0):
    """Trapezoid narrowing from ``width_start`` to ``width_end``; the axis is the bisector of the long sides.

    Parameters
    ----------
    length : float
        Distance between the two short sides, local units.
    width_start, width_end : float
        Widths of the short sides, local units.
    n : int or (int, int)
        Vertices on each long side.
    placement : Placement, optional
    jitter : float
        Interior vertices move along the side by up to this fraction of their spacing.
    seed : int

    Returns
    -------
    Case
        Axis: the x-axis of the local frame from 0 to ``length``.
    """
    n_a, n_b = (n, n) if np.isscalar(n) else n
    rng = np.random.default_rng(seed)

    def half_width(x):
        return 0.5 * (width_start + (width_end - width_start) * x / length)

    xa = _stations(length, n_a, jitter, rng)
    xb = _stations(length, n_b, jitter, rng)
    bank_a = np.stack([xa, -half_width(xa)], axis=1)
    bank_b = np.stack([xb, half_width(xb)], axis=1)
    axis = np.array([[0.0, 0.0], [length, 0.0]])
    return channel_case(
        f"tapered L={length:g} W={width_start:g}->{width_end:g} n={n} {_describe(placement)}",
        bank_a,
        bank_b,
        0.5 * (width_start + width_end),
        placement,
        axis_local=axis,
        axis_distance_local=lambda p: _segment_distance(p, axis[0], axis[1]),
    )


def annulus_sector(r_inner=40.0, r_outer=60.0, angle_start=0.0, angle_end=math.pi, n=61, placement=None):
    """Sector of an annulus; the axis is the circular arc of the mean radius.

    Parameters
    ----------
    r_inner, r_outer : float
        Radii, local units.
    angle_start, angle_end : float
        Angular range, radians, ``angle_end - angle_start`` in (0, 2*pi).
    n : int
        Vertices on each arc (equal angular steps).
    placement : Placement, optional

    Returns
    -------
    Case
        ``axis_tolerance`` is half the sum of the chord sagittas of the two arcs (module docstring).
    """
    span = angle_end - angle_start
    if not 0.0 < span < 2.0 * math.pi:
        raise ValueError("the sector must span between 0 and 2*pi")
    angles = np.linspace(angle_start, angle_end, n)
    unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    r_mean = 0.5 * (r_inner + r_outer)
    half_step = 0.5 * span / (n - 1)
    sagitta = 0.5 * (r_inner + r_outer) * (1.0 - math.cos(half_step))
    axis_angles = np.linspace(angle_start, angle_end, max(16 * n, 256))
    axis = r_mean * np.stack([np.cos(axis_angles), np.sin(axis_angles)], axis=1)
    ends = r_mean * np.array(
        [[math.cos(angle_start), math.sin(angle_start)], [math.cos(angle_end), math.sin(angle_end)]]
    )

    def distance(points):
        radius = np.hypot(points[:, 0], points[:, 1])
        theta = np.mod(np.arctan2(points[:, 1], points[:, 0]) - angle_start, 2.0 * math.pi)
        to_ends = np.minimum(np.hypot(*(points - ends[0]).T), np.hypot(*(points - ends[1]).T))
        return np.where(theta <= span, np.abs(radius - r_mean), to_ends)

    return channel_case(
        f"annulus sector r={r_inner:g}..{r_outer:g} span={span:.4g} n={n} {_describe(placement)}",
        r_inner * unit,
        r_outer * unit,
        r_outer - r_inner,
        placement,
        axis_local=axis,
        axis_distance_local=distance,
        axis_tolerance_local=sagitta,
        axis_end_margin_local=r_outer - r_inner,
    )


def _sine(x, amplitude, wavelength):
    k = 2.0 * math.pi / wavelength
    return amplitude * np.sin(k * x), amplitude * k * np.cos(k * x), -amplitude * k * k * np.sin(k * x)


def meander(length=2000.0, width=20.0, amplitude=60.0, wavelength=400.0, n=1166, placement=None):
    """Constant-width meander: the exact flat-capped buffer of a sine curve, banks sampled at ``n`` points.

    The banks are the exact offsets ``s(x) +- (width / 2) * normal(x)`` of ``y = amplitude *
    sin(2 pi x / wavelength)`` for ``0 <= x <= length`` (the buffer of the curve with flat caps, as long as
    the curve's radius of curvature exceeds ``width / 2``), sampled at equal steps of ``x``. The medial axis
    between the banks is the sine curve itself. The ring has ``n_a + n_b + 2`` vertices (the two split
    points are the cap midpoints), so ``n=(1166, 1165)`` gives 2,333.

    Parameters
    ----------
    length : float
        Extent of the sine along x, local units.
    width : float
        Constant width, local units.
    amplitude, wavelength : float
        Of the sine, local units.
    n : int or (int, int)
        Vertices on each bank.
    placement : Placement, optional

    Returns
    -------
    Case
        ``axis_distance`` is exact (Newton projection onto the sine); ``axis_tolerance`` bounds the bank
        chords' sagitta.
    """
    k = 2.0 * math.pi / wavelength
    min_radius = 1.0 / (amplitude * k * k) if amplitude else math.inf
    if min_radius <= width / 2.0:
        raise ValueError("the sine bends tighter than half the width; its buffer would fold")
    n_a, n_b = (n, n) if np.isscalar(n) else n

    def bank(x, side):
        y, dy, _ = _sine(x, amplitude, wavelength)
        norm = np.hypot(1.0, dy)
        return np.stack([x - side * 0.5 * width * dy / norm, y + side * 0.5 * width / norm], axis=1)

    banks, sagittas = [], []
    for count, side in ((n_a, -1.0), (n_b, 1.0)):
        x = np.linspace(0.0, length, count)
        points = bank(x, side)
        fractions = np.linspace(0.0, 1.0, 9)[1:-1]
        mid = bank((x[:-1, None] + np.diff(x)[:, None] * fractions[None, :]).ravel(), side).reshape(
            -1, len(fractions), 2
        )
        chord = np.diff(points, axis=0)
        chord_length = np.hypot(*chord.T)
        offset = mid - points[:-1, None, :]
        cross = np.abs(offset[..., 0] * chord[:, None, 1] - offset[..., 1] * chord[:, None, 0]) / chord_length[:, None]
        banks.append(points)
        # The sampled maximum of a smooth sagitta profile over 7 interior stations, with a 5 % margin.
        sagittas.append(1.05 * float(cross.max()))
    dense_x = np.linspace(0.0, length, max(20 * max(n_a, n_b), 2000))
    axis = np.stack([dense_x, _sine(dense_x, amplitude, wavelength)[0]], axis=1)

    def distance(points):
        return _distance_to_sine(points, amplitude, wavelength, length, axis)

    return channel_case(
        f"meander L={length:g} W={width:g} A={amplitude:g} lambda={wavelength:g} n={n} {_describe(placement)}",
        banks[0],
        banks[1],
        width,
        placement,
        axis_local=axis,
        axis_distance_local=distance,
        axis_tolerance_local=0.5 * (sagittas[0] + sagittas[1]),
        axis_end_margin_local=width,
    )


def meander_with_vertex_count(vertex_count=2333, **kwargs):
    """:func:`meander` whose ring has exactly ``vertex_count`` distinct vertices (at least 6)."""
    banks = vertex_count - 2
    return meander(n=((banks + 1) // 2, banks // 2), **kwargs)


def _distance_to_sine(points, amplitude, wavelength, length, dense):
    """Exact distance from points to the sine arc ``0 <= x <= length`` (nearest dense vertex + Newton)."""
    points = np.asarray(points, dtype=float)
    tree = shapely.STRtree(shapely.points(dense))
    nearest = tree.query_nearest(shapely.points(points), all_matches=False)[1]
    x = dense[nearest, 0]
    step = dense[1, 0] - dense[0, 0]
    for _ in range(30):
        y, dy, ddy = _sine(x, amplitude, wavelength)
        gradient = (x - points[:, 0]) + (y - points[:, 1]) * dy
        curvature = 1.0 + dy * dy + (y - points[:, 1]) * ddy
        update = np.where(curvature > 0, gradient / np.where(curvature > 0, curvature, 1.0), 0.0)
        x = np.clip(x - np.clip(update, -step, step), 0.0, length)
    y = _sine(x, amplitude, wavelength)[0]
    return np.hypot(points[:, 0] - x, points[:, 1] - y)


def wavy_channel(
    length=100.0,
    mean_width=10.0,
    n=(40, 50),
    harmonics=((6.0, 80.0, 0.3),),
    width_variation=0.3,
    width_wavelength=55.0,
    jitter=0.4,
    seed=0,
    placement=None,
    split_fractions=(0.5, 0.5),
    teeth=0.0,
):
    """Random x-monotone channel: a smooth wavy centreline with a varying width and jittered vertices.

    Bank ``a`` is ``f(x) - w(x) / 2`` and bank ``b`` is ``f(x) + w(x) / 2``, sampled at independent
    jittered stations, with ``f`` a sum of sines and ``w`` a width varying by up to ``width_variation``. No
    analytic axis: these shapes feed the invariant, oracle and property-based tests.

    Parameters
    ----------
    length, mean_width : float
        Local units.
    n : (int, int)
        Vertices of each bank.
    harmonics : sequence of (amplitude, wavelength, phase)
        Terms of the centreline ``f``, local units and radians.
    width_variation : float
        Relative amplitude of the width's variation (below 1).
    width_wavelength : float
        Wavelength of the width's variation, local units.
    jitter : float
        Fraction of the station spacing by which interior vertices move.
    seed : int
    placement : Placement, optional
    split_fractions : (float, float)
        Where each split point sits on its cap, 0 = on bank ``a``, 1 = on bank ``b`` (0.5 = midpoint).
    teeth : float
        Interior vertices move alternately into and out of the channel by this fraction of the mean width
        (a saw-toothed bank: many reflex vertices facing the other bank); keep below 0.25.

    Returns
    -------
    Case
        With no axis; ``split_points`` are vertices of the ring.
    """
    rng = np.random.default_rng(seed)

    def centre(x):
        return sum(a * np.sin(2.0 * math.pi * x / lam + phase) for a, lam, phase in harmonics) + 0.0 * x

    def half_width(x):
        return 0.5 * mean_width * (1.0 + width_variation * np.sin(2.0 * math.pi * x / width_wavelength + 1.0))

    xa = _stations(length, n[0], jitter, rng)
    xb = _stations(length, n[1], jitter, rng)
    bank_a = np.stack([xa, centre(xa) - half_width(xa)], axis=1)
    bank_b = np.stack([xb, centre(xb) + half_width(xb)], axis=1)
    if teeth:
        for bank in (bank_a, bank_b):
            saw = teeth * mean_width * (np.arange(len(bank)) % 2 - 0.5) * 2.0
            saw[[0, -1]] = 0.0
            bank[:, 1] += saw
    placement = placement or Placement()
    case = channel_case(
        f"wavy L={length:g} W={mean_width:g} n={n} seed={seed} teeth={teeth:g} {_describe(placement)}",
        bank_a,
        bank_b,
        mean_width,
        placement,
    )
    if tuple(split_fractions) == (0.5, 0.5):
        return case
    return resplit(case, split_fractions)


def resplit(case, split_fractions):
    """Move the split points of a channel case along its caps (0 = bank ``a`` end, 1 = bank ``b`` end).

    Parameters
    ----------
    case : Case
    split_fractions : (float, float)
        Position of each split point on its cap, strictly between 0 and 1.

    Returns
    -------
    Case
        Same polygon shape (the split points are new ring vertices on the caps), same banks, no axis.
    """
    bank_a, bank_b = case.bank_a, case.bank_b
    start = bank_a[0] + split_fractions[0] * (bank_b[0] - bank_a[0])
    end = bank_a[-1] + split_fractions[1] * (bank_b[-1] - bank_a[-1])
    chain_a = np.concatenate([start[None], bank_a, end[None]])
    chain_b = np.concatenate([start[None], bank_b, end[None]])
    polygon = Polygon(np.concatenate([chain_a, chain_b[-2::-1]]))
    return Case(
        name=f"{case.name} split={tuple(split_fractions)}",
        polygon=polygon,
        split_points=(tuple(start.tolist()), tuple(end.tolist())),
        chain_a=chain_a,
        chain_b=chain_b,
        bank_a=bank_a,
        bank_b=bank_b,
        width=case.width,
        placement=case.placement,
    )


def bank_pair(case, reverse_a=False, reverse_b=False):
    """The two bank lines of a channel case, for open mode.

    Parameters
    ----------
    case : Case
    reverse_a, reverse_b : bool
        Give a line in the opposite direction (the engine must orient them itself).

    Returns
    -------
    line_a, line_b : LineString
        CRS units. The expected ends of the centerline are the midpoints of the end gaps, which for a
        channel built by :func:`channel_case` are ``case.split_points``.
    """
    a = case.bank_a[::-1] if reverse_a else case.bank_a
    b = case.bank_b[::-1] if reverse_b else case.bank_b
    return LineString(a), LineString(b)


def synthetic_river(n_samples, seed=0, width=20.0, vertex_spacing=None, validate=False):
    """A long meandering river for benchmarks: about ``n_samples`` boundary vertices in total.

    The centreline is ``y = f(x)`` with ``f`` a sum of three random sines whose curvature stays below
    ``1 / (3 * width)`` (so the banks never fold), the width varies smoothly by +-25 %, and the banks are
    the normal offsets of the centreline sampled at jittered stations. With ``spacing >= vertex_spacing``
    the engine therefore sees about ``n_samples`` samples (every vertex is a sample).

    Parameters
    ----------
    n_samples : int
        Total number of bank vertices (split between the two banks), at least 8.
    seed : int
    width : float
        Mean width, CRS units (metres).
    vertex_spacing : float, optional
        Mean distance between bank vertices along x, CRS units; default ``width / 4``.
    validate : bool
        Check polygon validity with GEOS (slow above 10^5 vertices).

    Returns
    -------
    Case
        Without axis; ``Case.width`` is the mean width.
    """
    if n_samples < 8:
        raise ValueError("n_samples must be at least 8")
    rng = np.random.default_rng(seed)
    vertex_spacing = vertex_spacing or width / 4.0
    n_a = n_samples // 2
    n_b = n_samples - n_a
    length = vertex_spacing * (max(n_a, n_b) - 1)
    wavelengths = rng.uniform(15.0, 60.0, 3) * width
    curvature_budget = 1.0 / (3.0 * width)
    weights = rng.uniform(0.5, 1.0, 3)
    # Each term's curvature is amplitude * (2 pi / wavelength)^2; share the budget between the terms.
    amplitudes = weights / weights.sum() * curvature_budget / (2.0 * math.pi / wavelengths) ** 2
    phases = rng.uniform(0.0, 2.0 * math.pi, 3)

    def centre(x):
        y = np.zeros_like(x)
        dy = np.zeros_like(x)
        for amplitude, wavelength, phase in zip(amplitudes, wavelengths, phases):
            k = 2.0 * math.pi / wavelength
            y += amplitude * np.sin(k * x + phase)
            dy += amplitude * k * np.cos(k * x + phase)
        return y, dy

    width_wavelength = rng.uniform(20.0, 40.0) * width

    def bank(x, side):
        y, dy = centre(x)
        half = 0.5 * width * (1.0 + 0.25 * np.sin(2.0 * math.pi * x / width_wavelength))
        norm = np.hypot(1.0, dy)
        return np.stack([x - side * half * dy / norm, y + side * half / norm], axis=1)

    xa = _stations(length, n_a, 0.3, rng)
    xb = _stations(length, n_b, 0.3, rng)
    return channel_case(
        f"synthetic river n={n_samples} seed={seed} W={width:g}",
        bank(xa, -1.0),
        bank(xb, 1.0),
        width,
        validate=validate,
    )


def load_gambia(projected=True):
    """The Natural Earth 1:10m outline of the Gambia (public domain), a real elongated polygon.

    Parameters
    ----------
    projected : bool
        True: UTM zone 28N metres (EPSG:32628); False: longitude/latitude degrees (EPSG:4326).

    Returns
    -------
    Polygon
    """
    path = GAMBIA_UTM_FILE if projected else GAMBIA_LONLAT_FILE
    with open(path, encoding="utf-8") as handle:
        feature = json.load(handle)
    return geojson_shape(feature["geometry"])


def gambia(projected=True):
    """The Gambia as a :class:`Case`, split at its westernmost and easternmost ring vertices.

    The west end is the Atlantic coast, the east end the eastern border; the chains are the northern
    (``a``) and southern (``b``) borders. There is no analytic axis: the tests use the oracle.

    Parameters
    ----------
    projected : bool
        See :func:`load_gambia`.

    Returns
    -------
    Case
    """
    polygon = shapely.geometry.polygon.orient(load_gambia(projected), 1.0)
    ring = np.asarray(polygon.exterior.coords)[:-1]
    west, east = int(np.argmin(ring[:, 0])), int(np.argmax(ring[:, 0]))
    loop = np.roll(ring, -west, axis=0)
    east = (east - west) % len(ring)
    # Counter-clockwise from the west end the ring runs along the south border to the east end.
    south = loop[: east + 1]
    north = np.concatenate([loop[:1], loop[: east - 1 : -1]])
    x0, y0, x1, y1 = polygon.bounds
    return Case(
        name="Gambia (Natural Earth 1:10m, {})".format("UTM 28N" if projected else "lon/lat"),
        polygon=polygon,
        split_points=(tuple(loop[0].tolist()), tuple(loop[east].tolist())),
        chain_a=north,
        chain_b=south,
        bank_a=north[1:-1],
        bank_b=south[1:-1],
        width=polygon.area / max(x1 - x0, y1 - y0),
    )


def _describe(placement):
    if placement is None:
        return "unit"
    for name, known in PLACEMENTS.items():
        if known == placement:
            return name
    return f"scale={placement.scale:g} angle={placement.angle:g} offset={placement.offset}"


def analytic_cases(placement_names: Sequence[str] = tuple(PLACEMENTS)):
    """The standard analytic cases in every named placement, as a list of :class:`Case`.

    Parameters
    ----------
    placement_names : sequence of str
        Keys of :data:`PLACEMENTS`.

    Returns
    -------
    list of Case
    """
    cases = []
    for name in placement_names:
        placement = PLACEMENTS[name]
        cases += [
            rectangle(placement=placement),
            rectangle(n=(7, 13), jitter=0.4, seed=3, placement=placement),
            tapered_channel(placement=placement),
            tapered_channel(width_start=4.0, width_end=16.0, n=(9, 17), jitter=0.4, seed=5, placement=placement),
            annulus_sector(placement=placement),
            annulus_sector(r_inner=30.0, r_outer=36.0, angle_start=0.5, angle_end=5.5, n=181, placement=placement),
            meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, n=(301, 287), placement=placement),
        ]
    return cases
