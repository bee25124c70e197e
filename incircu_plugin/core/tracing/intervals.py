"""The open intervals of the spans between two solved samples, and how they are cut at new samples."""

from dataclasses import dataclass, replace

import numpy as np

from .._arrays import ArrayRecord


@dataclass
class Intervals(ArrayRecord):
    """Intervals ``[u0, u1]`` of spans between two samples (indices ``left``, ``right``), with the sites first
    touched at each end; ``verified`` once the stations of a parabola have been solved inside it."""

    span: np.ndarray
    u0: np.ndarray
    u1: np.ndarray
    left: np.ndarray
    right: np.ndarray
    site0: np.ndarray
    site1: np.ndarray
    verified: np.ndarray

    def __post_init__(self):
        """The index columns as int32 (see :class:`.contacts.Boundary`)."""
        # Plain assignments (no getattr/setattr loop): the rounds build these records thousands of times.
        index = np.int32
        self.span, self.left = np.asarray(self.span, dtype=index), np.asarray(self.left, dtype=index)
        self.right = np.asarray(self.right, dtype=index)
        self.site0, self.site1 = np.asarray(self.site0, dtype=index), np.asarray(self.site1, dtype=index)


def by_owner_then_u(owner, u):
    """The permutation ``np.lexsort((u, owner))``: by owner, then by ``u``, ties in input order.

    A stable sort of ``owner`` alone that leaves every owner's ``u`` in order is that permutation (the order
    sorted by both keys that keeps ties in input order is unique), and nodes mostly come so; otherwise (or
    with a NaN) ``np.lexsort`` sorts them.
    """
    order = np.argsort(owner, kind="stable")
    sorted_owner, sorted_u = owner[order], u[order]
    if np.any((sorted_owner[1:] == sorted_owner[:-1]) & ~(sorted_u[1:] >= sorted_u[:-1])):
        return np.lexsort((u, owner))
    return order


def split_at_nodes(intervals, owner, u, index, site_before, site_after, verified):
    """Every interval cut at its nodes (samples ``index`` at parameters ``u`` of interval ``owner``).

    A node's ``site_before`` becomes the site at the right end of the piece before it, ``site_after`` the one at
    the left end of the piece after it (an event's two sites, else twice its first contact); the pieces are
    marked ``verified`` (the stations of a parabola) or not.
    """
    if len(owner) == 0:
        return replace(intervals, verified=np.full(len(intervals.span), verified))
    order = by_owner_then_u(owner, u)
    owner, u, index = owner[order], u[order], index[order]
    site_before, site_after = site_before[order], site_after[order]
    # Interval i becomes the pieces first[i] .. first[i] + (its node count): the k-th node (sorted) of all
    # ends piece owner + k and starts the next one; the interval's ends start its first piece and end its last.
    nodes = np.bincount(owner, minlength=len(intervals.span))
    first = np.arange(len(nodes)) + np.cumsum(nodes) - nodes
    last = first + nodes
    inner = owner + np.arange(len(owner))
    total = len(nodes) + len(owner)
    pieces = Intervals(
        np.repeat(intervals.span, nodes + 1),
        *(np.empty(total) for _ in range(2)),
        *(np.empty(total, dtype=np.int32) for _ in range(4)),
        np.full(total, verified),
    )
    pieces.u0[first], pieces.u0[inner + 1] = intervals.u0, u
    pieces.u1[last], pieces.u1[inner] = intervals.u1, u
    pieces.left[first], pieces.left[inner + 1] = intervals.left, index
    pieces.right[last], pieces.right[inner] = intervals.right, index
    pieces.site0[first], pieces.site0[inner + 1] = intervals.site0, site_after
    pieces.site1[last], pieces.site1[inner] = intervals.site1, site_before
    return pieces


def unsettled_pieces(curves, owner, u, index, site):
    """The pieces of the curved intervals cut at their stations (samples ``index`` at parameters ``u`` of curve
    ``owner``, first touching ``site``) that may still hold an event: those whose ends touch different sites.

    The pieces are verified, so one whose ends touch the same site is neither open nor curved: the next round
    would drop it (and keeps the others in this order), so it is dropped here, and a curve whose stations all
    touch its own site is not cut at all.
    """
    if not np.any(site != curves.site0[owner]):
        return curves.subset(np.zeros(len(curves.span), dtype=bool))
    pieces = split_at_nodes(curves, owner, u, index, site, site, True)
    return pieces.subset((pieces.site0 != pieces.site1).nonzero()[0])
