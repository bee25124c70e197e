"""Heaviest skeleton paths (``incircu_plugin.core.paths``): the trees' joint sweep against the exact answer."""

import numpy as np
import pytest

from incircu_plugin.core import paths as paths_module
from incircu_plugin.core.paths import heaviest_paths


def random_forest(rng, sizes):
    """Random trees of ``sizes`` nodes (numbered one tree after another) with random positive weights."""
    edges, first = [], 0
    for size in sizes:
        for node in range(1, size):
            edges.append((first + int(rng.integers(0, node)), first + node))
        first += size
    edges = np.array(edges, dtype=np.int64).reshape(-1, 2)
    return sum(sizes), edges, rng.random(len(edges)) + 0.01


def heaviest_by_brute_force(edges, weights, first, size):
    """The weight of the heaviest path in the tree of nodes ``first`` to ``first + size - 1``, from all pairs'
    distances."""
    own = (edges[:, 0] >= first) & (edges[:, 0] < first + size)
    local = edges[own] - first
    distance = np.full((size, size), np.inf)
    np.fill_diagonal(distance, 0.0)
    distance[local[:, 0], local[:, 1]] = distance[local[:, 1], local[:, 0]] = weights[own]
    for middle in range(size):
        distance = np.minimum(distance, distance[:, middle, None] + distance[None, middle, :])
    return distance.max()


def path_weight(path, edges, weights):
    """Sum of the weights of the edges joining consecutive nodes of ``path``."""
    lookup = {frozenset(pair): weight for pair, weight in zip(edges.tolist(), weights.tolist())}
    return sum(lookup[frozenset(pair)] for pair in zip(path[:-1].tolist(), path[1:].tolist()))


@pytest.mark.parametrize("front", [1, 16, 10**9])
def test_trees_swept_together_get_their_heaviest_paths(monkeypatch, front):
    """Forty random trees (one a single node), swept together in numpy, in Python, or first one then the
    other: each gets a heaviest path of its own tree, and the same nodes as when swept alone in Python."""
    monkeypatch.setattr(paths_module, "FRONT_IN_NUMPY", front)
    rng = np.random.default_rng(11)
    sizes = [1] + rng.integers(2, 40, 39).tolist()
    count, edges, weights = random_forest(rng, sizes)
    firsts = np.cumsum([0] + sizes[:-1])
    starts = firsts + rng.integers(0, sizes)
    found = heaviest_paths(count, edges, weights, starts.tolist(), [True] * len(starts))
    for first, size, path in zip(firsts.tolist(), sizes, found):
        assert np.all((path >= first) & (path < first + size))
        assert len(set(path.tolist())) == len(path)
        expected = heaviest_by_brute_force(edges, weights, first, size)
        assert path_weight(path, edges, weights) == pytest.approx(expected, rel=1e-12)
    monkeypatch.setattr(paths_module, "FRONT_IN_NUMPY", 10**9)
    alone = [heaviest_paths(count, edges, weights, [start], [False])[0] for start in starts.tolist()]
    assert all(np.array_equal(a, b) for a, b in zip(alone, found))


def test_a_cycle_is_swept_by_dijkstra_next_to_trees():
    """A square with two tails next to a tree: the square's component is no tree, so it is swept in Python
    (Dijkstra: the shorter way around the square), the tree with the others; both paths are right."""
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [2, 5], [6, 7], [7, 8]])
    weights = np.array([1.0, 1.0, 2.0, 2.0, 5.0, 5.0, 2.0, 3.0])
    square, chain = heaviest_paths(9, edges, weights, [1, 7], [False, True])
    assert square.tolist() in ([4, 0, 1, 2, 5], [5, 2, 1, 0, 4])
    assert chain.tolist() in ([6, 7, 8], [8, 7, 6])


def test_no_start_gives_no_path():
    assert heaviest_paths(3, np.array([[0, 1], [1, 2]]), np.array([1.0, 1.0]), [], []) == []
