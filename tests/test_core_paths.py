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


def shortest_distances(edges, weights, first, size):
    """All pairs' shortest distances in the graph of nodes ``first`` to ``first + size - 1`` (Floyd-Warshall)."""
    own = (edges[:, 0] >= first) & (edges[:, 0] < first + size)
    local = edges[own] - first
    distance = np.full((size, size), np.inf)
    np.fill_diagonal(distance, 0.0)
    distance[local[:, 0], local[:, 1]] = distance[local[:, 1], local[:, 0]] = weights[own]
    for middle in range(size):
        distance = np.minimum(distance, distance[:, middle, None] + distance[None, middle, :])
    return distance


def heaviest_by_brute_force(edges, weights, first, size):
    """The weight of the heaviest path in the tree of nodes ``first`` to ``first + size - 1``, from all pairs'
    distances."""
    return shortest_distances(edges, weights, first, size).max()


def path_weight(path, edges, weights):
    """Sum of the weights of the edges joining consecutive nodes of ``path``."""
    lookup = {frozenset(pair): weight for pair, weight in zip(edges.tolist(), weights.tolist())}
    return sum(lookup[frozenset(pair)] for pair in zip(path[:-1].tolist(), path[1:].tolist()))


@pytest.mark.parametrize("equal_weights", [False, True])
@pytest.mark.parametrize("front", [1, 16, 10**9])
def test_trees_swept_together_get_their_heaviest_paths(monkeypatch, front, equal_weights):
    """Forty random trees (one a single node), swept together in numpy, in Python, or first one then the
    other: each gets a heaviest path of its own tree, and the same nodes as when swept alone in Python (also
    when every weight is 1, so that many paths tie)."""
    monkeypatch.setattr(paths_module, "FRONT_IN_NUMPY", front)
    rng = np.random.default_rng(11)
    sizes = [1] + rng.integers(2, 40, 39).tolist()
    count, edges, weights = random_forest(rng, sizes)
    if equal_weights:
        weights = np.ones(len(edges))
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


def test_a_cycle_is_swept_for_shortest_distances_next_to_trees():
    """A square with two tails next to a tree: the square's component is no tree, so it is swept for shortest
    distances (the shorter way around the square), the tree with the others; both paths are right."""
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [2, 5], [6, 7], [7, 8]])
    weights = np.array([1.0, 1.0, 2.0, 2.0, 5.0, 5.0, 2.0, 3.0])
    square, chain = heaviest_paths(9, edges, weights, [1, 7], [False, True])
    assert square.tolist() in ([4, 0, 1, 2, 5], [5, 2, 1, 0, 4])
    assert chain.tolist() in ([6, 7, 8], [8, 7, 6])


def test_no_start_gives_no_path():
    assert heaviest_paths(3, np.array([[0, 1], [1, 2]]), np.array([1.0, 1.0]), [], []) == []


def test_a_long_tree_finished_in_python_can_be_cancelled(monkeypatch):
    """A caterpillar (a trunk of 5,000 nodes, each with a twig) swept in Python after the numpy start: the
    cancel check is called every ``CHECK_EVERY`` nodes, and what it raises stops the sweep."""
    monkeypatch.setattr(paths_module, "FRONT_IN_NUMPY", 10**9)
    monkeypatch.setattr(paths_module, "CHECK_EVERY", 64)
    trunk = np.arange(5000)
    edges = np.concatenate([np.stack([trunk[:-1], trunk[1:]], axis=1), np.stack([trunk, trunk + 5000], axis=1)])
    weights = np.ones(len(edges))
    calls = []
    paths = heaviest_paths(10000, edges, weights, [0], [True], check=lambda: calls.append(1))
    assert len(paths[0]) == 5002 and len(calls) >= 10000 // 64 - 1

    class Stop(Exception):
        pass

    def stop():
        raise Stop

    with pytest.raises(Stop):
        heaviest_paths(10000, edges, weights, [0], [True], check=stop)


@pytest.mark.parametrize("front", [1, 16, 10**9])
def test_equally_far_nodes_go_to_the_smallest_node(monkeypatch, front):
    """Two stars of five unit arms, listed out of order, one of them with a small cycle at its centre (swept for
    shortest distances): every leaf is equally far, so each sweep takes the smallest node, and each path runs
    from the smallest leaf through the centre to the next smallest, the tree's in numpy, in Python, or both."""
    monkeypatch.setattr(paths_module, "FRONT_IN_NUMPY", front)
    star = [[0, 5], [0, 3], [0, 1], [0, 4], [0, 2]]
    cyclic = [[10, 14], [10, 12], [10, 15], [10, 11], [10, 13], [10, 16], [16, 17], [17, 10]]
    edges = np.array(star + cyclic)
    weights = np.array([1.0] * 10 + [0.1] * 3)
    tree_path, cyclic_path = heaviest_paths(18, edges, weights, [0, 10], [True, False])
    assert tree_path.tolist() == [1, 0, 2]
    assert cyclic_path.tolist() == [11, 10, 12]


@pytest.mark.parametrize("size", [5, 1000])
def test_a_component_that_is_one_cycle_starts_from_its_smallest_node(size):
    """A ring of ``size`` nodes has no node without two neighbours: its smallest node becomes the key node, so
    its path is that node alone, whatever node it starts from; the chain next to it is a tree and keeps its
    heaviest path."""
    ring = np.arange(3, 3 + size)
    edges = np.concatenate([[[0, 1], [1, 2]], np.stack([ring, np.roll(ring, -1)], axis=1)])
    weights = np.ones(len(edges))
    chain, cycle = heaviest_paths(3 + size, edges, weights, [1, 3 + size // 2], [True, False])
    assert chain.tolist() in ([0, 1, 2], [2, 1, 0])
    assert cycle.tolist() == [3]


def random_graph_with_cycles(rng, sizes):
    """Random connected graphs of ``sizes`` nodes (numbered one after another): a random tree, its chains of
    two-neighbour nodes lengthened, plus a few extra edges closing cycles; random positive weights."""
    count, edges, _ = random_forest(rng, sizes)
    extra, first = [], 0
    for size in sizes:
        for _ in range(int(rng.integers(1, 4))):
            low, high = sorted(rng.choice(size, 2, replace=False).tolist())
            extra.append((first + low, first + high))
        first += size
    edges = np.unique(np.sort(np.concatenate([edges, np.array(extra)]), axis=1), axis=0)
    return count, edges, rng.random(len(edges)) + 0.01


def test_components_with_cycles_get_the_double_sweep_of_shortest_distances(monkeypatch):
    """Thirty random graphs with cycles swept together (cancel checks on the way): each path is a shortest
    path, from the key node (one without two neighbours) farthest from the start to the key node farthest from
    that one, as a Dijkstra search over the contracted graph finds them (the weights are random, so no two
    ways tie)."""
    monkeypatch.setattr(paths_module, "CHECK_EVERY", 16)
    rng = np.random.default_rng(12)
    sizes = rng.integers(4, 60, 30).tolist()
    count, edges, weights = random_graph_with_cycles(rng, sizes)
    firsts = np.cumsum([0] + sizes[:-1])
    key = np.bincount(edges.ravel(), minlength=count) != 2
    starts = np.array([first + np.flatnonzero(key[first : first + size])[0] for first, size in zip(firsts, sizes)])
    calls = []
    found = heaviest_paths(count, edges, weights, starts.tolist(), [False] * len(starts), check=lambda: calls.append(1))
    assert len(calls) >= 2
    for first, size, start, path in zip(firsts.tolist(), sizes, starts.tolist(), found):
        distance = shortest_distances(edges, weights, first, size)
        own_keys = np.flatnonzero(key[first : first + size])
        head, tail = path[0] - first, path[-1] - first
        assert distance[start - first, head] == distance[start - first, own_keys].max()
        assert distance[head, tail] == distance[head, own_keys].max()
        assert path_weight(path, edges, weights) == pytest.approx(distance[head, tail], rel=1e-12)
