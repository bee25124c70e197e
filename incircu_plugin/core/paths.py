"""Heaviest path of a skeleton graph, found in time near-linear in its size.

The skeleton of an elongated polygon is mostly long chains of nodes with two neighbours. The chains are
contracted first, with numpy only (pointer jumping over directed edges: ``log2`` of the longest chain
rounds), into a graph of its *key* nodes (one or three or more neighbours); the double sweep then runs in
Python on that graph only, and the chosen path is expanded back to skeleton nodes.

The components that are trees (all of them for polygons without holes) are swept together instead: one
numpy step per level of their contracted graphs, all components at once, while many nodes are on the
front; the last, thin levels of the deepest components go on in Python. The distances are the same sums
in the same order, so the paths are the same as one component's sweep in Python gives.

**Double sweep.** From a start node, the node ``a`` at the largest distance, then from ``a`` the node ``b``
at the largest distance: ``a -> b`` is the heaviest path. Distances are sums of non-negative edge weights
(length, swept area, ...). On a tree (a polygon without holes) each sweep is a plain traversal and the
result is exact; around islands each sweep is a Dijkstra search and the result a close approximation.
"""

import functools
import heapq

import numpy as np

from .contacts import ranges, stable_order
from .skeleton import connected_labels

#: Node pops of a sweep between two calls of the cancel check.
CHECK_EVERY = 4096

#: Fewest nodes on the front of the trees' joint sweep for a numpy step; a thinner front goes on in Python.
FRONT_IN_NUMPY = 16


def heaviest_paths(count, edges, weights, starts, acyclic, check=None):
    """Return the heaviest path of each start's component, found by a double sweep from the start.

    The chains of the whole graph are contracted at once; the components that are trees are then swept
    together (see :func:`_forest_sweep`), each other one in Python over its contracted nodes only, so many
    small components (the skeletons of a batch of polygons) cost one contraction and a few numpy calls.

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
        Per start, whether its component is a tree (each sweep a plain traversal, the double sweep exact);
        a component found to be a tree is swept as one whatever this says (a tree's Dijkstra gives the same).
    check : callable, optional
        Called with no argument now and then; may raise to stop.

    Returns
    -------
    list of ndarray of int
        Per start, the node indices of its path from one end to the other (one node when the start has no
        edge).
    """
    chains = _Chains(count, edges, weights)
    graph = chains.contracted()
    starts = np.asarray(starts, dtype=np.int64)
    in_tree = chains.in_tree(starts)
    paths = [None] * len(starts)
    together = np.flatnonzero(in_tree)
    if len(together):
        sources = chains.key_index[chains.nearest_keys(starts[together])]
        firsts = _farthest_of_sources(_forest_sweep(graph, sources, check), len(sources))
        sweep = _forest_sweep(graph, firsts, check)
        lasts = _farthest_of_sources(sweep, len(firsts))
        parent, parent_via = sweep[1].tolist(), sweep[2].tolist()
        for index, first, last in zip(together.tolist(), firsts.tolist(), lasts.tolist()):
            key_path, via = [last], []
            while key_path[-1] != first:
                via.append(parent_via[key_path[-1]])
                key_path.append(parent[key_path[-1]])
            paths[index] = (key_path[::-1], via[::-1])
    for index in np.flatnonzero(~in_tree).tolist():
        paths[index] = _swept_path(chains, graph.lists, int(starts[index]), acyclic[index], check)
    return chains.expand_all(paths)


def _swept_path(chains, graph, start, acyclic, check):
    """Return the contracted path ``(key_path, via)`` of a double sweep in Python from ``start``."""
    first = chains.key_index[_farthest_key(chains, graph, start, acyclic, check)]
    distance, predecessor = _sweep(graph, first, acyclic, check)
    last = _farthest(distance)
    key_path = [last]
    while key_path[-1] != first:
        key_path.append(predecessor[key_path[-1]][0])
    via = [predecessor[node][1] for node in key_path[:-1]]
    return key_path[::-1], via[::-1]


def _farthest(distance):
    """Return the node of largest distance in a ``{node: distance}`` map (the smallest such node on a tie)."""
    largest = max(distance.values())
    return min(node for node, reached in distance.items() if reached == largest)


def _farthest_key(chains, graph, start, acyclic, check):
    """Return the key node farthest from ``start`` (a key node of its component)."""
    source = chains.nearest_key(start)
    distance, _ = _sweep(graph, int(chains.key_index[source]), acyclic, check)
    return chains.keys[_farthest(distance)]


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

    def nearest_key(self, node):
        """Return a key node of ``node``'s component: ``node`` itself or the end of one of its chains."""
        return int(self.nearest_keys(np.array([node]))[0])

    def nearest_keys(self, nodes):
        """Return :meth:`nearest_key` of each of the ``nodes`` (an int array)."""
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
    :func:`_sweep` sums it.
    """
    start, neighbours, lengths, vias = graph.arrays
    size = len(start) - 1
    distance = np.full(size, -np.inf)
    parent = np.full(size, -1, dtype=np.int64)
    parent_via = np.full(size, -1, dtype=np.int64)
    origin = np.full(size, -1, dtype=np.int64)
    distance[sources] = 0.0
    origin[sources] = np.arange(len(sources))
    front = np.asarray(sources, dtype=np.int64)
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


def _farthest_of_sources(sweep, count):
    """Return, per source of a :func:`_forest_sweep`, the node of largest distance (the smallest on a tie)."""
    distance, _, _, origin = sweep
    reached = np.flatnonzero(origin >= 0)
    largest = np.full(count, -np.inf)
    np.maximum.at(largest, origin[reached], distance[reached])
    farthest = np.full(count, len(distance), dtype=np.int64)
    at_largest = reached[distance[reached] == largest[origin[reached]]]
    np.minimum.at(farthest, origin[at_largest], at_largest)
    return farthest


def _sweep(graph, source, acyclic, check):
    """Return the distance from ``source`` to each contracted node it reaches and each one's ``(predecessor, via)``.

    A plain traversal on a forest (every reachable node has one path from the source), else Dijkstra. Both
    are ``{node: ...}`` maps holding the reached nodes only, so a sweep costs its component's size only. A
    leaf is not queued: from it the only way leads back (no shorter, the weights being non-negative).
    """
    start, neighbours, lengths, vias = graph
    distance = {source: 0.0}
    predecessor = {}
    queue = [(0.0, source)]
    pops = 0
    while queue:
        reached, node = queue.pop() if acyclic else heapq.heappop(queue)
        pops += 1
        if check is not None and pops % CHECK_EVERY == 0:
            check()
        if reached > distance[node]:
            continue
        for k in range(start[node], start[node + 1]):
            neighbour = neighbours[k]
            candidate = reached + lengths[k]
            if acyclic and (neighbour in predecessor or neighbour == source):
                continue
            if candidate < distance.get(neighbour, float("inf")):
                distance[neighbour] = candidate
                predecessor[neighbour] = (node, vias[k])
                if start[neighbour + 1] - start[neighbour] == 1:
                    continue
                if acyclic:
                    queue.append((candidate, neighbour))
                else:
                    heapq.heappush(queue, (candidate, neighbour))
    return distance, predecessor
