"""The layer benchmark's generator (``benchmarks/rivers.py``) gives the layer issue 9 describes, from its seed."""

import numpy as np
import shapely

from benchmarks.rivers import river_layer

COUNT = 30


def test_same_seed_same_layer_and_prefix_independent_of_size():
    first, again, shorter = river_layer(COUNT, seed=3), river_layer(COUNT, seed=3), river_layer(10, seed=3)
    assert all(a.polygon.equals_exact(b.polygon, 0.0) for a, b in zip(first, again))
    assert all(a.polygon.equals_exact(b.polygon, 0.0) for a, b in zip(first, shorter))
    assert not first[0].polygon.equals(river_layer(1, seed=4)[0].polygon)


def test_rivers_are_valid_elongated_and_within_the_issue_ranges():
    rivers = river_layer(COUNT, seed=0)
    for river in rivers:
        assert river.polygon.is_valid
        assert 200.0 <= river.axis.length <= 3_000.0
        assert 5.0 <= river.width <= 40.0
        assert len(river.polygon.exterior.coords) - 1 == 290
        assert river.polygon.area > 0.5 * river.width * river.axis.length
        for end in river.ends:
            assert river.polygon.exterior.distance(end) <= 1e-9 * river.axis.length
    assert any(river.polygon.interiors for river in rivers)
    assert 0.5 * COUNT * 290 < sum(river.vertex_count for river in rivers) < 1.2 * COUNT * 290


def test_rivers_never_meet():
    polygons = np.array([river.polygon for river in river_layer(COUNT, seed=0)])
    pairs = shapely.STRtree(polygons).query(polygons, predicate="intersects")
    assert np.all(pairs[0] == pairs[1])
