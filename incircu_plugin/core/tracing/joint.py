"""Joint tracing: many features' pairs of chains in one vectorised tracing, each feature's points the very
ones it gets traced alone (docs/tracing.md, *Joint tracing*)."""

import numpy as np

from ..contacts import Boundary
from .options import TraceOptions
from .tracer import adaptive_axis_points, trace_one

#: A joint group places its features, in the spatial index only, on a grid of cells this many times their
#: largest extent, and holds features whose extents differ at most by ``JOINT_EXTENT_RATIO`` (a cell's
#: candidate boxes then list few segments of its neighbours). The groups of one tracing overlap in the index;
#: their extents differ at most by ``JOINT_BATCH_RATIO``. Every value is computed in the feature's own frame.
JOINT_CELL = 1.25
JOINT_EXTENT_RATIO = 4.0
JOINT_BATCH_RATIO = JOINT_EXTENT_RATIO**2

#: Most segments in one joint tracing (bounds its memory).
JOINT_SEGMENTS = 1 << 17


def trace_together(requests, report):
    """:func:`.tracer.adaptive_axis_points` of many :class:`.._steps.TraceRequest` objects, traced jointly.

    Requests of similar extent are placed side by side in one frame (a group, :func:`joint_groups`); groups
    are traced together in one set of vectorised rounds up to ``JOINT_SEGMENTS`` (:func:`joint_batches`: their
    frames overlap, which changes nothing since contacts are only ever sought within a feature's own pair of
    chains); each feature is computed in its own frame. ``report(fraction)`` is called as the batches are done.
    Returns a list of :class:`.contacts.AxisPoints` in the requests' order.
    """
    results = [None] * len(requests)
    batches = joint_batches(requests, joint_groups(requests))
    for done, batch in enumerate(batches):
        part = lambda fraction, begin=done: report((begin + fraction) / len(batches))
        if len(batch) == 1 and len(batch[0]) == 1:
            results[batch[0][0]] = trace_one(requests[batch[0][0]], part)
        else:
            indices = [index for group in batch for index in group]
            for index, points in zip(indices, trace_batch(requests, batch, part)):
                results[index] = points
    return results


def joint_groups(requests):
    """Indices of the requests in groups placed on one grid (several groups share a tracing,
    :func:`joint_batches`): extents at most ``JOINT_EXTENT_RATIO`` apart, at most ``JOINT_SEGMENTS``
    segments; by ascending extent."""
    extents = np.array([request.extent for request in requests])
    sizes = np.array([request.segment_count for request in requests])
    order = np.argsort(extents, kind="stable")
    return consecutive_bins(order.tolist(), extents[order], sizes[order], JOINT_EXTENT_RATIO)


def joint_batches(requests, groups):
    """Consecutive ``groups`` (lists of request indices, by ascending extent) packed into batches traced in one
    tracing: extents at most ``JOINT_BATCH_RATIO`` apart (the groups' grids overlap, so a large feature's
    candidate boxes would list the segments of every much smaller feature under them, dropped only after the
    search), at most ``JOINT_SEGMENTS`` segments."""
    extents = [requests[group[0]].extent for group in groups]
    sizes = [sum(requests[index].segment_count for index in group) for group in groups]
    return consecutive_bins(groups, extents, sizes, JOINT_BATCH_RATIO)


def consecutive_bins(items, extents, sizes, ratio):
    """``items`` (by ascending ``extents``, CRS units) cut into runs whose extents differ at most by ``ratio``
    and whose ``sizes`` (segments) add up to at most ``JOINT_SEGMENTS`` (an item of more is a run of its own)."""
    bins, current, smallest, segments = [], [], 0.0, 0
    for item, extent, size in zip(items, extents, sizes):
        if current and (extent > ratio * smallest or segments + size > JOINT_SEGMENTS):
            bins.append(current)
            current = []
        if not current:
            smallest, segments = extent, 0
        current.append(item)
        segments += size
    return bins + [current] if current else bins


def group_offsets(requests):
    """Shift of each of ``requests`` (one group) to its cell of a square grid centred on the origin, CRS units."""
    columns = int(np.ceil(np.sqrt(len(requests))))
    cell = JOINT_CELL * max(request.extent for request in requests)
    rank = np.arange(len(requests))
    return cell * (np.stack([rank % columns, rank // columns], axis=1) - 0.5 * (columns - 1))


def trace_batch(requests, batch, report):
    """Trace the groups of ``batch`` in one tracing, each feature in its own frame: its chains are placed on
    its group's grid in the spatial index only (:func:`group_offsets`, ``index_shift`` of
    :class:`.contacts.Boundary`), so its points are those it gets traced alone; returns them in the order of
    the batch's requests."""
    offsets = np.concatenate([group_offsets([requests[index] for index in group]) for group in batch])
    requests = [requests[index] for group in batch for index in group]
    chains = [chain for request in requests for chain in request.chains]
    rounding = np.repeat([request.rounding for request in requests], 2)
    boundary = Boundary(chains, rounding, index_shift=np.repeat(offsets, 2, axis=0))
    points, chain = adaptive_axis_points(boundary, TraceOptions.from_requests(requests), report)
    feature = chain >> 1
    order = np.argsort(feature, kind="stable")
    points = points.subset(order)
    bounds = np.searchsorted(feature[order], np.arange(len(requests) + 1)).tolist()
    return [points.subset(slice(begin, end)) for begin, end in zip(bounds[:-1], bounds[1:])]
