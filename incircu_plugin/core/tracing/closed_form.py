"""Closed forms on a span: where two sites' radii are equal (an event), and the stations of a parabola of
the axis whose chords stay within the tolerance (docs/tracing.md)."""

import numpy as np

from .._arrays import left_normal, ranges, rows
from .sites import by_kind
from .spans import EDGE, FAN

#: Relative slack under which a slightly negative discriminant is a double root (a contact sliding off a
#: segment's end onto its vertex).
DOUBLE_ROOT = 1e-8


def crossing(spans, intervals, terms0, terms1, counted=False):
    """Parameter inside ``(u0, u1)`` where both sites' radii are equal (else the middle), whether there is
    one, and which end (0, 1; else -1) the crossing lies at when it lies at one; if ``counted``, also how many
    of the equation's two roots lie in ``[u0, u1]``."""
    u0, u1 = intervals.u0, intervals.u1
    d0, d1, d2 = (x - y for x, y in zip(terms0, terms1))
    middle = 0.5 * (u0 + u1)

    def roots_of(kind, row):
        terms = d0[row], d1[row], d2[row]
        return edge_roots(*terms) if kind == EDGE else fan_roots(*terms, middle[row])

    # The two candidate roots of each row, from its edge's or its fan's equation.
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        roots = by_kind(spans.kind[intervals.span], (EDGE, FAN), roots_of, 2)
    slack = 1e-9 * (u1 - u0)
    chosen, found = np.full(len(u0), np.nan), np.zeros(len(u0), dtype=bool)
    count = np.zeros(len(u0), dtype=int)
    for candidate in roots:
        inside = np.isfinite(candidate) & (candidate >= u0 - slack) & (candidate <= u1 + slack)
        # A double root (a segment's line and its end vertex) split by rounding counts once.
        count += inside & ~(found & (np.abs(candidate - chosen) <= DOUBLE_ROOT * (u1 - u0)))
        inside &= ~found
        chosen[inside], found[inside] = candidate[inside], True
    at_end = np.where(found & (chosen <= u0 + slack), 0, np.where(found & (chosen >= u1 - slack), 1, -1))
    found &= at_end < 0
    crossing = np.where(found, chosen, middle), found, at_end
    return crossing + (count,) if counted else crossing


def edge_roots(d0, d1, d2):
    """Roots of d2 u^2 + d1 u + d0 = 0 (on an edge), the stable pair.

    A vertex at the end of a segment's line touches it: their radii meet in a double root, which rounding may
    push to a slightly negative discriminant."""
    discriminant = d1 * d1 - 4.0 * d2 * d0
    root = np.sqrt(np.where(discriminant > -DOUBLE_ROOT * d1 * d1, np.maximum(discriminant, 0.0), discriminant))
    q = -0.5 * (d1 + np.where(d1 < 0, -root, root))
    return q / d2, d0 / q


def fan_roots(d0, d1, d2, middle):
    """Roots of d0 + d1 cos(u) + d2 sin(u) = 0 (on a fan), i.e. R cos(u - psi) = -d0, each the one within pi
    of ``middle``; a cosine that rounding pushed slightly beyond 1 is a double root."""
    psi = np.arctan2(d2, d1)
    cosine = -d0 / np.hypot(d1, d2)
    swing = np.arccos(np.where(np.abs(cosine) < 1.0 + DOUBLE_ROOT, np.clip(cosine, -1.0, 1.0), cosine))
    return tuple(middle + np.remainder(psi + sign * swing - middle + np.pi, 2.0 * np.pi) - np.pi for sign in (1, -1))


def parabola_stations(focus, anchor, unit, ends, tolerance):
    """Points of parabolas (focus, directrix) between two of their points, chords within ``tolerance``.

    In the directrix's frame the parabola is ``r(s) = (s**2 + h**2) / (2 h)`` (``s`` along the directrix
    from the focus's foot, ``h`` the focus's height): the chord over ``[s, s + ds]`` deviates from it by
    ``ds**2 / (8 sqrt(h**2 + m**2))``, ``m`` the chord's middle. Stations uniform in ``z = sqrt(|s| + h)``
    on each side of the apex, ``dz = (sqrt(2) tolerance) ** 0.5`` apart, keep that below ``dz**2 /
    sqrt(2) = tolerance`` (``ds = dz (z0 + z1)`` and ``sqrt(h**2 + m**2) >= (h + |m|) / sqrt(2)``); the
    apex is a station when it lies between the ends.

    Parameters
    ----------
    focus, anchor, unit : ndarray of shape (n, 2)
        Each parabola's focus, a point of its directrix and the directrix's unit direction.
    ends : ndarray of shape (n, 2, 2)
        Two points of each parabola.
    tolerance : float or ndarray of shape (n,)
        Largest distance between a chord and its arc, CRS units (per parabola).

    Returns
    -------
    owner : ndarray of shape (m,)
        The parabola of each station.
    centre, radius : ndarray of shape (m, 2), (m,)
        The stations and their distance to the focus (and the directrix), CRS units.
    """
    relative = focus - anchor
    apex_along = np.einsum("ij,ij->i", relative, unit)
    across = left_normal(unit)
    height = np.einsum("ij,ij->i", relative, across)
    towards_focus = np.where(height < 0, -1.0, 1.0)[:, None] * across
    height = np.abs(height)
    s = np.einsum("ijk,ik->ij", ends - anchor[:, None, :], unit) - apex_along[:, None]
    low, high = np.minimum(s[:, 0], s[:, 1]), np.maximum(s[:, 0], s[:, 1])
    step_z = np.sqrt(np.sqrt(2.0) * tolerance)
    owners, offsets = [], []
    for sign, near, far in (
        (1.0, np.maximum(low, 0.0), np.maximum(high, 0.0)),
        (-1.0, -np.minimum(high, 0.0), -np.minimum(low, 0.0)),
    ):
        z_near, z_far = np.sqrt(near + height), np.sqrt(far + height)
        count = np.where(far > near, np.ceil((z_far - z_near) / step_z), 0).astype(int)
        owner, rank = ranges(np.maximum(count - 1, 0))
        z = z_near[owner] + (rank + 1) * ((z_far - z_near) / np.maximum(count, 1))[owner]
        owners.append(owner)
        offsets.append(sign * (z * z - height[owner]))
    apex = np.flatnonzero((low < 0.0) & (high > 0.0))
    owner = np.concatenate(owners + [apex])
    s = np.concatenate(offsets + [np.zeros(len(apex))])
    radius = (s * s + height[owner] ** 2) / (2.0 * height[owner])
    centre = rows(anchor, owner) + (apex_along[owner] + s)[:, None] * rows(unit, owner)
    centre += radius[:, None] * rows(towards_focus, owner)
    return owner, centre, radius
