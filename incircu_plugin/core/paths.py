"""Heaviest path of a skeleton graph, found in time near-linear in its size.

The skeleton of an elongated polygon is mostly long chains of nodes with two neighbours. The chains are
contracted first, with numpy only (pointer jumping over directed edges: ``log2`` of the longest chain
rounds), into a graph of its *key* nodes (one or three or more neighbours); the double sweeps then run on
that graph only, all components at once, and the chosen paths are expanded back to skeleton nodes.

The components that are trees (all of them for polygons without holes) are swept level by level: one numpy
step per level of their contracted graphs while many nodes are on the front; the last, thin levels of the
deepest components go on in Python. The components with cycles (around islands) are swept by rounds of
Bellman-Ford: each round relaxes, in numpy, the edges out of the nodes whose distance fell in the round
before. Either way a node's distance is the sum of the weights along its path from the source, edge by edge.

**Double sweep.** From a start node, the node ``a`` at the largest distance, then from ``a`` the node ``b``
at the largest distance: ``a -> b`` is the heaviest path. Distances are sums of non-negative edge weights
(length, swept area, ...). On a tree (a polygon without holes) each sweep is a plain traversal and the
result is exact; around islands each sweep finds the shortest distances and the result is a close
approximation.
"""

import functools

import numpy as np

from ._arrays import ranges, stable_order
from .skeleton import connected_labels

#: Nodes or edges a sweep handles between two calls of the cancel check.
CHECK_EVERY = 4096

#: Fewest nodes on the front of the trees' joint sweep for a numpy step; a thinner front goes on in Python.
FRONT_IN_NUMPY = 16


def heaviest_paths(count, edges, weights, starts, acyclic, check=None):
    """Return the heaviest path of each start's component, found by a double sweep from the start.

    The chains of the whole graph are contracted at once; the components that are trees are then swept
    together (see :func:`_forest_sweep`), and so are those with cycles (see :func:`_shortest_sweep`), so many
    small components (the skeletons of a batch of polygons) cost one contraction and a few numpy calls per
    level.

    Parameters
    ----------
    count : int
        Number of nodes.
    edges : ndarray of shape (e, 2) of int
        Node indices of each edge.
    weights : ndarray of shape (e,)
        Non-negative weight of each edge.
    starts : sequence of int
        One node per path, each in a different component: the node its first sweep starts from.
    acyclic : sequence of bool
        Per start, whether its component should be a tree. A component found to be a tree is swept as one
        whatever this says; one with cycles is swept for shortest distances, unless it should be a tree (the
        skeleton of a polygon without holes): then each sweep is a plain traversal in Python that reaches
        each node once, by the first way it finds (depth first), as on a tree.
    check : callable, optional
        Called with no argument now and then; may raise to stop.

    Returns
    -------
    list of ndarray of int
        Per start, the node indices of its path from one end to the other (one node when the start has no
        edge).

    Examples
    --------
    A path of three edges with a twig at its second node, and a lone node:

    >>> import numpy as np
    >>> edges = np.array([[0, 1], [1, 2], [2, 3], [1, 4]])
    >>> weights = np.array([1.0, 1.0, 1.0, 0.5])
    >>> [path.tolist() for path in heaviest_paths(6, edges, weights, [2, 5], [True, True])]
    [[0, 1, 2, 3], [5]]
    """
    chains = _Chains(count, edges, weights)
    graph = chains.contracted()
    starts = np.asarray(starts, dtype=np.int64)
    in_tree = chains.in_tree(starts)
    should_be_tree = np.asarray(acyclic, dtype=bool)
    paths = [None] * len(starts)
    cyclic = np.flatnonzero(~in_tree & ~should_be_tree)
    for group, sweep in ((np.flatnonzero(in_tree), _forest_sweep), (cyclic, _shortest_sweep)):
        if len(group):
            sources = chains.key_index[chains.nearest_keys(starts[group])]
            for index, path in zip(group.tolist(), _double_sweeps(graph, sources, sweep, check)):
                paths[index] = path
    for index in np.flatnonzero(~in_tree & should_be_tree).tolist():
        paths[index] = _traversed_path(chains, graph.lists, int(starts[index]), check)
    return chains.expand_all(paths)


def _double_sweeps(graph, sources, sweep, check):
    """Return the contracted path ``(key_path, via)`` of the double sweep from each source, by ``sweep``
    (:func:`_forest_sweep` or :func:`_shortest_sweep`, all sources at once)."""
    firsts = _farthest_of_sources(sweep(graph, sources, check), len(sources))
    second = sweep(graph, firsts, check)
    lasts = _farthest_of_sources(second, len(firsts))
    parent, parent_via = second[1].tolist(), second[2].tolist()
    paths = []
    for first, last in zip(firsts.tolist(), lasts.tolist()):
        key_path, via = [last], []
        while key_path[-1] != first:
            via.append(parent_via[key_path[-1]])
            key_path.append(parent[key_path[-1]])
        paths.append((key_path[::-1], via[::-1]))
    return paths


def _traversed_path(chains, graph, start, check):
    """Return the contracted path ``(key_path, via)`` of a double sweep by :func:`_traversal` from ``start``."""
    source = int(chains.key_index[chains.nearest_keys(np.array([start]))[0]])
    first = _farthest(_traversal(graph, source, check)[0])
    distance, predecessor = _traversal(graph, first, check)
    key_path = [_farthest(distance)]
    while key_path[-1] != first:
        key_path.append(predecessor[key_path[-1]][0])
    via = [predecessor[node][1] for node in key_path[:-1]]
    return key_path[::-1], via[::-1]


def _farthest(distance):
    """Return the node of largest distance in a ``{node: distance}`` map (the smallest such node on a tie)."""
    largest = max(distance.values())
    return min(node for node, reached in distance.items() if reached == largest)


def _traversal(graph, source, check):
    """Return the distance from ``source`` to each contracted node it reaches and each one's ``(predecessor, via)``,
    by a depth-first traversal that reaches each node once (the first way it finds, as on a tree).

    Both are ``{node: ...}`` maps holding the reached nodes only. ``graph`` is :attr:`_Contracted.lists`.
    """
    start, neighbours, lengths, vias = graph
    distance = {source: 0.0}
    predecessor = {}
    stack = [(0.0, source)]
    pops = 0
    while stack:
        reached, node = stack.pop()
        pops += 1
        if check is not None and pops % CHECK_EVERY == 0:
            check()
        for k in range(start[node], start[node + 1]):
            neighbour = neighbours[k]
            if neighbour in distance:
                continue
            distance[neighbour] = reached + lengths[k]
            predecessor[neighbour] = (node, vias[k])
            if start[neighbour + 1] - start[neighbour] > 1:
                stack.append((distance[neighbour], neighbour))
    return distance, predecessor


class _Contracted:
    """A contracted graph in compressed adjacency: node ``i``'s edges are ``start[i]`` to ``start[i + 1]``.

    ``neighbours``, ``lengths`` and ``vias`` give each edge's other node, weight and first directed edge of
    its chain (see :meth:`_Chains.contracted`).
    """

    def __init__(self, start, neighbours, lengths, vias):
        self.arrays = (start, neighbours, lengths, vias)

    @functools.cached_property
    def lists(self):
        """``(start, neighbours, lengths, vias)`` as lists (faster to read one item at a time in Python)."""
        return tuple(part.tolist() for part in self.arrays)


class _Chains:
    """A graph's chains of two-neighbour nodes, contracted into weighted edges between key nodes.

    Every directed edge ``h`` (``tail[h] -> head[h]``) whose head is not a key node continues with the other
    edge out of its head, ``following[h]``; ``total[h]`` is the weight from ``h`` to the end of its chain,
    ``steps[h]`` the number of edges, and ``last[h]`` the chain's last directed edge, whose head is a key
    node.
    """

    def __init__(self, count, edges, weights):
        edge_count = len(edges)
        self.tail = np.concatenate([edges[:, 0], edges[:, 1]]).astype(np.int64)
        self.head = np.concatenate([edges[:, 1], edges[:, 0]]).astype(np.int64)
        twin = np.concatenate([np.arange(edge_count, 2 * edge_count), np.arange(edge_count)])
        degree = np.bincount(self.tail, minlength=count)
        self.key = degree != 2
        order = stable_order(self.tail, count)
        first_out = np.concatenate([[0], np.cumsum(degree)])
        self.first_out = order[np.minimum(first_out[:-1], len(order) - 1)] if len(order) else first_out[:-1]
        weights = np.concatenate([weights, weights]).astype(float)
        unit = np.ones(len(weights), np.int64)
        self.following = _following_edges(self.key, self.head, twin, order, first_out)
        (self.total, self.steps), self.last, cycling = _rank(self.following, (weights, unit))
        if len(cycling):
            # A component made of one cycle has no key node: its smallest node becomes one.
            labels = connected_labels(count, self.tail[cycling], self.head[cycling])
            self.key[labels[self.tail[cycling]]] = True
            self.following = _following_edges(self.key, self.head, twin, order, first_out)
            (self.total, self.steps), self.last, _ = _rank(self.following, (weights, unit))
        self.keys = np.flatnonzero(self.key)
        self.key_index = np.full(count, -1, dtype=np.int64)
        self.key_index[self.keys] = np.arange(len(self.keys))
        # Directed edges grouped by chain (chains in the order of their last edges), each chain from its first
        # edge to its last: a chain's edges from ``edge`` on are the ``steps[edge]`` entries from ``edge``'s
        # position in ``chain_order``.
        chain_size = np.bincount(self.last, minlength=len(self.last))
        chain_start = np.cumsum(chain_size) - chain_size
        self.chain_position = chain_start[self.last] + chain_size[self.last] - self.steps
        self.chain_order = np.empty_like(self.chain_position)
        self.chain_order[self.chain_position] = np.arange(len(self.chain_position))
        # A chain of k edges has k - 1 inner nodes: a component is a tree when its contracted graph is one.
        self.leaving = np.flatnonzero(self.key[self.tail])
        self.source = self.key_index[self.tail[self.leaving]]
        self.target = self.key_index[self.head[self.last[self.leaving]]]
        self.labels = connected_labels(len(self.keys), self.source, self.target)
        nodes = np.bincount(self.labels, minlength=len(self.keys))
        self.tree = np.bincount(self.labels[self.source], minlength=len(self.keys)) == 2 * (nodes - 1)

    def contracted(self):
        """Return the contracted graph in compressed adjacency: ``(start, neighbour, weight, via)`` arrays.

        Node ``i`` of the contracted graph is ``keys[i]``; ``via`` is the first directed edge of each chain.
        """
        leaving, source = self.leaving, self.source
        order = stable_order(source, len(self.keys))
        start = np.concatenate([[0], np.cumsum(np.bincount(source, minlength=len(self.keys)))])
        return _Contracted(start, self.target[order], self.total[leaving][order], leaving[order])

    def in_tree(self, nodes):
        """Return whether each node's component is a tree (as many edges as nodes less one)."""
        return self.tree[self.labels[self.key_index[self.nearest_keys(nodes)]]]

    def nearest_keys(self, nodes):
        """Return a key node of each node's component: the node itself or the end of one of its chains."""
        nodes = np.array(nodes, dtype=np.int64)
        through = ~self.key[nodes]
        nodes[through] = self.head[self.last[self.first_out[nodes[through]]]]
        return nodes

    def expand_all(self, contracted_paths):
        """Return the skeleton nodes of contracted paths ``(key_path, via)``: their first key node, then the
        chains ``via`` (each up to the next key node)."""
        if not contracted_paths:
            return []
        vias = np.array([edge for _, via in contracted_paths for edge in via], dtype=np.int64)
        lengths = np.array([len(via) for _, via in contracted_paths], dtype=np.int64)
        pieces = self.steps[vias]
        owner, rank = ranges(pieces)
        chain_nodes = self.head[self.chain_order[self.chain_position[vias][owner] + rank]]
        sizes = 1 + np.bincount(np.repeat(np.arange(len(lengths)), lengths), weights=pieces, minlength=len(lengths))
        sizes = sizes.astype(np.int64)
        nodes = np.empty(int(sizes.sum()), dtype=np.int64)
        heads = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
        nodes[heads] = self.keys[[key_path[0] for key_path, _ in contracted_paths]]
        filled = np.ones(len(nodes), dtype=bool)
        filled[heads] = False
        nodes[filled] = chain_nodes
        return np.split(nodes, heads[1:])


def _following_edges(key, head, twin, order, first_out):
    """Return the next directed edge of each one's chain: the other edge out of its head, ``-1`` at a key node.

    Parameters
    ----------
    key : ndarray of bool
        Whether each node is a key node (every other node has two edges).
    head, twin : ndarray of int
        Head node and reverse edge of each directed edge.
    order, first_out : ndarray of int
        The directed edges by tail node, and where each node's edges begin in ``order``.
    """
    through = np.flatnonzero(~key[head])
    one = order[first_out[head[through]]]
    other = order[first_out[head[through]] + 1]
    following = np.full(len(head), -1, dtype=np.int64)
    following[through] = np.where(one == twin[through], other, one)
    return following


def _rank(following, weights):
    """Pointer jumping: the sums of weights from each directed edge to the end of its chain, and that end.

    Parameters
    ----------
    following : ndarray of int
        Next directed edge of each one's chain, ``-1`` at a chain's end.
    weights : tuple of ndarray
        Weights of each directed edge, one array per kind.

    Returns
    -------
    totals : tuple of ndarray
        One per kind of weight.
    last : ndarray of int
    cycling : ndarray of int
        The directed edges on cycles without an end (their totals and ``last`` mean nothing).
    """
    totals = tuple(weight.copy() for weight in weights)
    last = np.arange(len(following))
    successor = following.copy()
    active = np.flatnonzero(successor >= 0)
    # After k rounds every chain of up to 2**k edges has ended: what still runs lies on a cycle.
    for _ in range(len(following).bit_length() + 1):
        if not len(active):
            break
        ahead = successor[active]
        for total in totals:
            total[active] += total[ahead]
        last[active] = last[ahead]
        successor[active] = successor[ahead]
        active = active[successor[active] >= 0]
    return totals, last, active


def _forest_sweep(graph, sources, check):
    """Return the distance from its source, predecessor, chain and source number of each contracted node.

    ``sources`` lie in different components, each a tree; nodes they do not reach get distance ``-inf``,
    predecessor and chain ``-1``. The distance of a node is summed from its source edge by edge, as
    :func:`_traversal` sums it.
    """
    start, neighbours, lengths, vias = graph.arrays
    distance, parent, parent_via, origin, front = _sweep_start(len(start) - 1, sources, -np.inf)
    reached = len(front)
    while len(front) >= FRONT_IN_NUMPY:
        owner, rank = ranges(start[front + 1] - start[front])
        edge = start[front][owner] + rank
        node = front[owner]
        neighbour = neighbours[edge]
        new = neighbour != parent[node]
        edge, node, neighbour = edge[new], node[new], neighbour[new]
        distance[neighbour] = distance[node] + lengths[edge]
        parent[neighbour] = node
        parent_via[neighbour] = vias[edge]
        origin[neighbour] = origin[node]
        front = neighbour
        if check is not None and (reached + len(front)) // CHECK_EVERY > reached // CHECK_EVERY:
            check()
        reached += len(front)
    if len(front):
        _finish_forest_sweep(graph.lists, front.tolist(), (distance, parent, parent_via, origin), check)
    return distance, parent, parent_via, origin


def _finish_forest_sweep(graph, front, sweep, check):
    """Go on with :func:`_forest_sweep` in Python from the nodes ``front``, filling the arrays ``sweep``.

    ``graph`` is the contracted graph's :attr:`_Contracted.lists`.
    """
    start, neighbours, lengths, vias = graph
    distance, parent, parent_via, origin = sweep
    stack = [(node, float(distance[node]), int(parent[node]), int(origin[node])) for node in front]
    found = []
    pops = 0
    while stack:
        node, reached, came_from, source = stack.pop()
        pops += 1
        if check is not None and pops % CHECK_EVERY == 0:
            check()
        for edge in range(start[node], start[node + 1]):
            neighbour = neighbours[edge]
            if neighbour != came_from:
                found.append((neighbour, reached + lengths[edge], node, vias[edge], source))
                stack.append((neighbour, reached + lengths[edge], node, source))
    if found:
        nodes, distances, parents, chains, sources = zip(*found)
        nodes = np.array(nodes, dtype=np.int64)
        distance[nodes], parent[nodes], parent_via[nodes], origin[nodes] = distances, parents, chains, sources


def _sweep_start(size, sources, unreached):
    """Return a sweep's arrays over ``size`` contracted nodes before its first step: distance (0 at the
    ``sources``, ``unreached`` elsewhere), predecessor, chain and source number (``-1`` where not reached), and
    its first front, the sources."""
    distance = np.full(size, unreached)
    parent = np.full(size, -1, dtype=np.int64)
    parent_via = np.full(size, -1, dtype=np.int64)
    origin = np.full(size, -1, dtype=np.int64)
    front = np.asarray(sources, dtype=np.int64)
    distance[front] = 0.0
    origin[front] = np.arange(len(front))
    return distance, parent, parent_via, origin, front


def _farthest_of_sources(sweep, count):
    """Return, per source of a sweep (:func:`_forest_sweep` or :func:`_shortest_sweep`), the node of largest
    distance (the smallest on a tie)."""
    distance, _, _, origin = sweep
    reached = np.flatnonzero(origin >= 0)
    largest = np.full(count, -np.inf)
    np.maximum.at(largest, origin[reached], distance[reached])
    farthest = np.full(count, len(distance), dtype=np.int64)
    at_largest = reached[distance[reached] == largest[origin[reached]]]
    np.minimum.at(farthest, origin[at_largest], at_largest)
    return farthest


def _shortest_sweep(graph, sources, check):
    """Return what :func:`_forest_sweep` returns, for components that may have cycles: shortest distances.

    Rounds of Bellman-Ford, all components at once: each round relaxes the edges out of the nodes whose
    distance fell in the round before (a leaf's only edge leads back, so leaves are not relaxed from). A node
    takes the shortest of its round's candidates; of equally short ways it keeps the one found first (the
    earlier round, then the earlier edge). A node's distance is its predecessor's plus the edge's weight, as
    a Dijkstra search sums it.
    """
    start, neighbours, lengths, vias = graph.arrays
    degree = np.diff(start)
    distance, parent, parent_via, origin, front = _sweep_start(len(start) - 1, sources, np.inf)
    relaxed = 0
    while len(front):
        owner, rank = ranges(degree[front])
        edge = start[front][owner] + rank
        node = front[owner]
        neighbour = neighbours[edge]
        candidate = distance[node] + lengths[edge]
        shorter = np.flatnonzero(candidate < distance[neighbour])
        edge, node, neighbour, candidate = edge[shorter], node[shorter], neighbour[shorter], candidate[shorter]
        order = np.lexsort((candidate, neighbour))
        best = order[np.append(True, neighbour[order][1:] != neighbour[order][:-1])] if len(order) else order
        reached = neighbour[best]
        distance[reached] = candidate[best]
        parent[reached] = node[best]
        parent_via[reached] = vias[edge[best]]
        origin[reached] = origin[node[best]]
        front = reached[degree[reached] > 1]
        if check is not None and (relaxed + len(edge)) // CHECK_EVERY > relaxed // CHECK_EVERY:
            check()
        relaxed += len(edge)
    distance[origin < 0] = -np.inf
    return distance, parent, parent_via, origin
