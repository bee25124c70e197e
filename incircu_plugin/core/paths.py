"""Heaviest path of a skeleton graph, found in time near-linear in its size.

The skeleton of an elongated polygon is mostly long chains of nodes with two neighbours. The chains are
contracted first, with numpy only (pointer jumping over directed edges: ``log2`` of the longest chain
rounds), into a graph of its *key* nodes (one or three or more neighbours); the double sweep then runs in
Python on that graph only, and the chosen path is expanded back to skeleton nodes.

**Double sweep.** From a start node, the node ``a`` at the largest distance, then from ``a`` the node ``b``
at the largest distance: ``a -> b`` is the heaviest path. Distances are sums of non-negative edge weights
(length, swept area, ...). On a tree (a polygon without holes) each sweep is a plain traversal and the
result is exact; around islands each sweep is a Dijkstra search and the result a close approximation.
"""

import heapq

import numpy as np

from .skeleton import connected_labels

#: Node pops of a sweep between two calls of the cancel check.
CHECK_EVERY = 4096


def heaviest_paths(count, edges, weights, starts, acyclic, check=None):
    """Return the heaviest path of each start's component, found by a double sweep from the start.

    The chains of the whole graph are contracted at once; each sweep then visits only its component's
    contracted nodes, so many small components (the skeletons of a batch of polygons) cost one contraction
    and a few Python operations each.

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
        Per start, whether its component is a tree (each sweep a plain traversal, the double sweep exact).
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
    paths = []
    for start, tree in zip(starts, acyclic):
        first = chains.key_index[_farthest_key(chains, graph, start, tree, check)]
        distance, predecessor = _sweep(graph, first, tree, check)
        last = _farthest(distance)
        key_path = [last]
        while key_path[-1] != first:
            key_path.append(predecessor[key_path[-1]][0])
        via = [predecessor[node][1] for node in key_path[:-1]]
        paths.append(chains.expand(key_path[::-1], via[::-1]))
    return paths


def _farthest(distance):
    """Return the node of largest distance in a ``{node: distance}`` map (the smallest such node on a tie)."""
    return max(distance.items(), key=lambda item: (item[1], -item[0]))[0]


def _farthest_key(chains, graph, start, acyclic, check):
    """Return the key node farthest from ``start`` (a key node of its component)."""
    source = chains.nearest_key(start)
    distance, _ = _sweep(graph, int(chains.key_index[source]), acyclic, check)
    return chains.keys[_farthest(distance)]


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
        key = degree != 2
        # A component made of one cycle has no key node: its smallest node becomes one.
        labels = connected_labels(count, edges[:, 0], edges[:, 1])
        has_key = np.zeros(count, dtype=bool)
        has_key[labels[key]] = True
        key[np.flatnonzero((labels == np.arange(count)) & ~has_key[labels])] = True
        self.key = key
        self.keys = np.flatnonzero(key)
        self.key_index = np.full(count, -1, dtype=np.int64)
        self.key_index[self.keys] = np.arange(len(self.keys))
        self.labels = labels
        order = np.argsort(self.tail, kind="stable")
        first_out = np.concatenate([[0], np.cumsum(degree)])
        through = np.flatnonzero(~key[self.head])
        one = order[first_out[self.head[through]]]
        other = order[first_out[self.head[through]] + 1]
        self.following = np.full(2 * edge_count, -1, dtype=np.int64)
        self.following[through] = np.where(one == twin[through], other, one)
        weights = np.concatenate([weights, weights]).astype(float)
        (self.total, self.steps), self.last = _rank(self.following, (weights, np.ones(len(weights), np.int64)))
        self.first_out = order[np.minimum(first_out[:-1], len(order) - 1)] if len(order) else first_out[:-1]
        # Directed edges grouped by chain, each chain from its first edge to its last: a chain's edges from
        # ``edge`` on are the ``steps[edge]`` entries from ``edge``'s position in ``chain_order``.
        self.chain_order = np.lexsort((-self.steps, self.last))
        self.chain_position = np.empty_like(self.chain_order)
        self.chain_position[self.chain_order] = np.arange(len(self.chain_order))

    def contracted(self):
        """Return the contracted graph in compressed adjacency: ``(start, neighbour, weight, via)`` lists.

        Node ``i`` of the contracted graph is ``keys[i]``; ``via`` is the first directed edge of each chain.
        """
        leaving = np.flatnonzero(self.key[self.tail])
        source = self.key_index[self.tail[leaving]]
        target = self.key_index[self.head[self.last[leaving]]]
        order = np.argsort(source, kind="stable")
        start = np.concatenate([[0], np.cumsum(np.bincount(source, minlength=len(self.keys)))])
        return (
            start.tolist(),
            target[order].tolist(),
            self.total[leaving][order].tolist(),
            leaving[order].tolist(),
        )

    def nearest_key(self, node):
        """Return a key node of ``node``'s component: ``node`` itself or the end of one of its chains."""
        if self.key[node]:
            return int(node)
        return int(self.head[self.last[self.first_out[node]]])

    def expand(self, key_path, via):
        """Return the skeleton nodes of a contracted path (its key nodes and the chains ``via`` between)."""
        pieces = [self.keys[key_path[:1]]]
        for edge in via:
            begin = self.chain_position[edge]
            pieces.append(self.head[self.chain_order[begin : begin + self.steps[edge]]])
        return np.concatenate(pieces).astype(np.int64)


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
    """
    totals = tuple(weight.copy() for weight in weights)
    last = np.arange(len(following))
    successor = following.copy()
    active = np.flatnonzero(successor >= 0)
    while len(active):
        ahead = successor[active]
        for total in totals:
            total[active] += total[ahead]
        last[active] = last[ahead]
        successor[active] = successor[ahead]
        active = active[successor[active] >= 0]
    return totals, last


def _sweep(graph, source, acyclic, check):
    """Return the distance from ``source`` to each contracted node it reaches and each one's ``(predecessor, via)``.

    A plain traversal on a forest (every reachable node has one path from the source), else Dijkstra. Both
    are ``{node: ...}`` maps holding the reached nodes only, so a sweep costs its component's size only.
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
                if acyclic:
                    queue.append((candidate, neighbour))
                else:
                    heapq.heappush(queue, (candidate, neighbour))
    return distance, predecessor
