"""Compact and star-like shapes with known symmetric ends (shared by the tests and the fuzz campaign).

Each shape is centred on ``centre`` and turned by ``turn`` radians; lengths in CRS units.
"""

import math

import numpy as np
from shapely.geometry import Point, Polygon


def _placed(xy, centre, turn):
    """Return the polygon of the points ``xy`` (about the origin) turned by ``turn`` and moved to ``centre``."""
    cos, sin = math.cos(turn), math.sin(turn)
    x, y = np.asarray(xy, dtype=float).T
    return Polygon(np.c_[cos * x - sin * y, sin * x + cos * y] + np.asarray(centre, dtype=float))


def rectangle(length, width, centre=(0.0, 0.0), turn=0.0):
    """A ``length`` x ``width`` rectangle, its long sides along the turned x axis."""
    x, y = length / 2.0, width / 2.0
    return _placed([(-x, -y), (x, -y), (x, y), (-x, y)], centre, turn)


def rectangle_ends(length, centre=(0.0, 0.0), turn=0.0):
    """The middles of a :func:`rectangle`'s two sides across its length axis, shape (2, 2)."""
    half = length / 2.0 * np.array([math.cos(turn), math.sin(turn)])
    return np.asarray(centre, dtype=float) + np.array([-half, half])


def regular_polygon(sides, radius, centre=(0.0, 0.0), turn=0.0):
    """A regular polygon with ``sides`` corners on a circle of ``radius``, its first corner on the turned x axis."""
    angles = np.arange(sides) * 2.0 * math.pi / sides
    return _placed(radius * np.c_[np.cos(angles), np.sin(angles)], centre, turn)


def star(arms, outer, inner, centre=(0.0, 0.0), turn=0.0, hole=0.0):
    """A star with ``arms`` tips at ``outer`` and notches at ``inner`` from its centre (a round hole of radius
    ``hole`` in the middle when positive), its first tip on the turned x axis."""
    angles = np.arange(2 * arms) * math.pi / arms
    radii = np.where(np.arange(2 * arms) % 2 == 0, outer, inner)
    polygon = _placed(radii[:, None] * np.c_[np.cos(angles), np.sin(angles)], centre, turn)
    if hole > 0.0:
        polygon = Polygon(polygon.exterior, [Point(centre).buffer(hole, quad_segs=16).exterior])
    return polygon


def star_tips(arms, outer, centre=(0.0, 0.0), turn=0.0):
    """The tips of a :func:`star`, shape (arms, 2)."""
    angles = turn + np.arange(arms) * 2.0 * math.pi / arms
    return np.asarray(centre, dtype=float) + outer * np.c_[np.cos(angles), np.sin(angles)]


def ellipse(vertices, major, minor, centre=(0.0, 0.0), turn=0.0, phase=0.0):
    """An ellipse of semi-axes ``major`` (along the turned x axis) and ``minor`` drawn with ``vertices`` corners,
    the first at parameter ``phase`` (radians; 0 puts corners on the tips)."""
    angles = phase + np.arange(vertices) * 2.0 * math.pi / vertices
    return _placed(np.c_[major * np.cos(angles), minor * np.sin(angles)], centre, turn)
