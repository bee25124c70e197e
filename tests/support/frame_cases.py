"""Generated layers for the data-frame API: many small channels in longitude/latitude, some of them bad.

Shared by ``tests/test_core_frames.py`` and ``benchmarks/bench_frames.py``; numpy and shapely only.
"""

import numpy as np
import shapely

#: Metres per degree of latitude, and of longitude at the equator (enough for placing test shapes).
METRES_PER_DEGREE = (110_540.0, 111_320.0)
#: Every how many rows a bad row of each kind occurs (a self-crossing outline, three split points, no geometry).
BOWTIE_EVERY, THREE_POINTS_EVERY, NULL_EVERY = 997, 1009, 1013
#: Every how many rows the channel has no split points and finds its ends itself.
AUTOMATIC_EVERY = 50
#: Every how many rows the channel bends (a straight one costs the core about half as much).
BENT_EVERY = 5


def channels_lonlat(count, seed=0):
    """Small channels, 150 to 400 m long and 8 to 30 m wide, anywhere between 60° S and 60° N.

    Each channel is a hexagon with split points at the middle of its two short sides; in every
    :data:`BENT_EVERY`-th row its two long sides bend at their middle, elsewhere they are straight. Rows that
    are multiples of :data:`BOWTIE_EVERY` cross themselves, of :data:`THREE_POINTS_EVERY` get a third split point
    (a vertex of a long side), of :data:`NULL_EVERY` have no geometry; rows that are multiples of :data:`AUTOMATIC_EVERY` (and none
    of those) have no split points.

    Parameters
    ----------
    count : int
    seed : int

    Returns
    -------
    channels : list of shapely.Polygon or None
        Longitude/latitude, degrees (EPSG:4326).
    split_points : list of shapely.Point
        Longitude/latitude, degrees.
    bad_rows : set of int
        The rows that must report an error.
    """
    rng = np.random.default_rng(seed)
    longitude, latitude = rng.uniform(-170.0, 170.0, count), rng.uniform(-60.0, 60.0, count)
    half_length, half_width = rng.uniform(75.0, 200.0, count), rng.uniform(4.0, 15.0, count)
    bend, angle = rng.uniform(-1.0, 1.0, count) * half_width, rng.uniform(0.0, np.pi, count)
    rows = np.arange(count)
    bend[rows % BENT_EVERY != 0] = 0.0
    zero = np.zeros(count)
    outline = np.stack(
        [
            [-half_length, -half_width],
            [zero, bend - half_width],
            [half_length, -half_width],
            [half_length, half_width],
            [zero, bend + half_width],
            [-half_length, half_width],
        ]
    ).transpose(2, 0, 1)  # (count, 6, 2) metres
    ends = np.stack([[-half_length, zero], [half_length, zero]]).transpose(2, 0, 1)
    bowtie = rows % BOWTIE_EVERY == BOWTIE_EVERY - 1
    outline[bowtie] = outline[bowtie][:, [0, 1, 3, 2, 4, 5]]
    to_degrees = _metres_to_degrees(longitude, latitude, angle)
    channels = list(shapely.polygons(to_degrees(outline)))
    null = rows % NULL_EVERY == NULL_EVERY - 1
    for row in np.flatnonzero(null):
        channels[row] = None
    three_points = rows % THREE_POINTS_EVERY == THREE_POINTS_EVERY - 1
    automatic = (rows % AUTOMATIC_EVERY == AUTOMATIC_EVERY - 1) & ~(bowtie | three_points | null)
    # The two ends, and for the rows with three split points the middle vertex of the first long side.
    points = shapely.points(to_degrees(np.concatenate([ends, outline[:, 1:2]], axis=1)))  # (count, 3)
    split_points = [
        point for row in np.flatnonzero(~automatic) for point in points[row, : 3 if three_points[row] else 2]
    ]
    return channels, split_points, set(np.flatnonzero(bowtie | three_points | null).tolist())


def _metres_to_degrees(longitude, latitude, angle):
    """A function turning ``(count, n, 2)`` local metres (rotated by ``angle``) into degrees around each centre."""
    cos, sin = np.cos(angle)[:, None], np.sin(angle)[:, None]
    scale_x = METRES_PER_DEGREE[1] * np.cos(np.radians(latitude))[:, None]

    def to_degrees(xy):
        x, y = xy[..., 0] * cos - xy[..., 1] * sin, xy[..., 0] * sin + xy[..., 1] * cos
        return np.stack([longitude[:, None] + x / scale_x, latitude[:, None] + y / METRES_PER_DEGREE[0]], axis=-1)

    return to_degrees
