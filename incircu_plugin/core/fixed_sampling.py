"""The paper's fixed sampling: equidistant stations along both chains (``spacing``, ``samples_per_chain``).

Each chain is sampled at every vertex (a fan of normals at a reflex vertex, the bisector at a convex one)
and at equidistant stations, which also halve the spacing towards both ends. Every sample whose first
contact lies on the other chain gives a point of the medial axis. Where the samples of an edge switch
between skipped and accepted, or their contacts jump along the other chain, the branch point between them
is located by bisection (to 1/4096 of the spacing) and added.
"""

import numpy as np

from ._arrays import left_normal, rotate
from .chains import COINCIDENCE_TOLERANCE
from .contacts import CLEAR, SKIPPED, AxisPoints, Samples, solve, solve_in_chunks
from .polyline import turns_between

#: Default spacing as a fraction of the typical width (see :func:`default_spacing`).
DEFAULT_SPACING_PER_WIDTH = 1.0 / 20.0

#: Largest angle, radians, between two normals of the fan at a reflex vertex.
MAX_FAN_STEP = np.radians(5.0)

#: Probes per round and rounds locating where the samples of an edge switch between accepted and skipped,
#: or where their contacts jump along the other chain.
TRANSITION_PROBES = 15
TRANSITION_ROUNDS = 3

#: Contacts of two neighbouring samples farther apart along the other chain than this many times the samples'
#: own distance mark a side branch leaving the axis between them.
JUMP_RATIO = 8.0

#: Stations at spacing/2, spacing/4, ... spacing/2**END_REFINEMENT from both ends of each chain.
END_REFINEMENT = 16

#: Most directions in the fan of one reflex vertex.
MAX_FAN_DIRECTIONS = 256

#: Stations closer than this share of the chain's length to a vertex are dropped (the vertex has its own
#: samples): a disk tangent to an edge that close to a convex corner meets the corner's other edge within the
#: smallest contact parameter the solver counts (``min_t``), so it would miss that edge and find a contact
#: beyond it (a station 4.5e-10 past a 112 degree corner did, in a hypothesis example).
VERTEX_MARGIN = 1e-9

#: Most samples one call accepts (measured: about 600 bytes of memory per sample, so about 6 GB).
MAX_SAMPLES = 10_000_000


def _sample_chain(chain_id, chain, positions, side, spacing, offset, fan_step):
    """Sample one chain: equidistant edge points plus every interior vertex (a fan at reflex ones).

    ``side`` is +1 when the region lies left of the chain, -1 when right; ``offset`` is the global index of
    the chain's first segment.
    """
    n_segments = len(chain) - 1
    unit = np.diff(chain, axis=0) / np.diff(positions)[:, None]
    normal = side * left_normal(unit)
    total = positions[-1]
    coincidence = COINCIDENCE_TOLERANCE * max(total, 1.0)
    margin = VERTEX_MARGIN * max(total, 1.0)

    # Near each end the part of the axis whose disks touch both chains can be much shorter than the spacing
    # (a split point on a straight cap); stations halving the spacing towards the ends trace it too.
    towards_ends = spacing * 0.5 ** np.arange(1, END_REFINEMENT + 1)
    stations = np.unique(
        np.concatenate([np.arange(1, int(np.ceil(total / spacing))) * spacing, towards_ends, total - towards_ends])
    )
    stations = stations[(stations > coincidence) & (stations < total - coincidence)]
    segment = np.clip(np.searchsorted(positions, stations, side="right") - 1, 0, n_segments - 1)
    off_vertex = (stations - positions[segment] > margin) & (positions[segment + 1] - stations > margin)
    stations, segment = stations[off_vertex], segment[off_vertex]
    edge_point = chain[segment] + (stations - positions[segment])[:, None] * unit[segment]

    inner = np.arange(1, n_segments)
    incoming, outgoing = unit[inner - 1], unit[inner]
    turn = turns_between(incoming, outgoing)
    convex = side * turn > 0
    bisector = normal[inner - 1] + normal[inner]
    bisector /= np.linalg.norm(bisector, axis=1, keepdims=True)
    interior_angle = np.pi - side * turn

    fan_vertex = inner[~convex]
    fan_turn = turn[~convex]
    fan_count = np.where(
        np.abs(fan_turn) >= fan_step,
        np.minimum(np.ceil(np.abs(fan_turn) / fan_step), MAX_FAN_DIRECTIONS - 1).astype(int) + 1,
        1,
    )
    fan_owner = np.repeat(np.arange(len(fan_vertex)), fan_count)
    first_of_fan = np.repeat(np.cumsum(fan_count) - fan_count, fan_count)
    fan_index = np.arange(len(fan_owner)) - first_of_fan
    fraction = np.where(fan_count[fan_owner] > 1, fan_index / np.maximum(fan_count[fan_owner] - 1, 1), 0.5)
    fan_direction = rotate(normal[fan_vertex - 1][fan_owner], fan_turn[fan_owner] * fraction)
    fan_vertex = fan_vertex[fan_owner]

    convex_vertex = inner[convex]
    half_angle = interior_angle[convex] / 2.0

    position = np.concatenate([stations, positions[fan_vertex], positions[convex_vertex]])
    order = np.argsort(position, kind="stable")
    return Samples(
        chain=np.full(len(order), chain_id, dtype=np.int8),
        point=np.concatenate([edge_point, chain[fan_vertex], chain[convex_vertex]])[order],
        direction=np.concatenate([normal[segment], fan_direction, bisector[convex]])[order],
        scale=np.concatenate([np.ones(len(segment) + len(fan_vertex)), np.sin(half_angle)])[order],
        position=position[order],
        slide=np.concatenate([np.zeros(len(segment) + len(fan_vertex)), np.cos(half_angle)])[order],
        first_own=offset + np.concatenate([segment, fan_vertex - 1, convex_vertex - 1])[order],
        last_own=offset + np.concatenate([segment, fan_vertex, convex_vertex])[order],
    )


def _edge_probes(samples, template, positions, boundary):
    """Samples at arc-length ``positions`` on the edges of the edge samples ``template``."""
    segment = samples.first_own[template]
    along = positions - boundary.segment_position[segment]
    return Samples(
        chain=samples.chain[template],
        point=boundary.start[segment] + along[:, None] * boundary.unit[segment],
        direction=samples.direction[template],
        scale=np.ones(len(template)),
        position=positions,
        slide=np.zeros(len(template)),
        first_own=segment,
        last_own=segment,
    )


def _bisect(samples, left, contact_t, boundary, max_t, min_t, on_low_side):
    """Shrink, on the edge of each pair of samples ``left, left + 1``, the bracket of a switch.

    ``TRANSITION_ROUNDS`` rounds of ``TRANSITION_PROBES`` probes shrink each bracket to
    ``(TRANSITION_PROBES + 1) ** -TRANSITION_ROUNDS`` of it (1/4096). ``on_low_side(solution, pair)`` tells,
    for the probes of pair ``pair``, which behave like the pair's left sample.

    Returns the last round's probes and solution (as :func:`solve`) and, per pair, the index of the last
    probe on the low side (-1: none) among that pair's ``TRANSITION_PROBES`` probes.
    """
    low, high = samples.position[left], samples.position[left + 1]
    trial = np.repeat(1.25 * np.maximum(contact_t[left], contact_t[left + 1]), TRANSITION_PROBES)
    steps = np.arange(1, TRANSITION_PROBES + 1) / (TRANSITION_PROBES + 1)
    template = np.repeat(left, TRANSITION_PROBES)
    pair = np.repeat(np.arange(len(left)), TRANSITION_PROBES)
    rows = np.arange(len(left))
    for _ in range(TRANSITION_ROUNDS):
        where = (low[:, None] + (high - low)[:, None] * steps).ravel()
        probes = _edge_probes(samples, template, where, boundary)
        solution = solve(probes, np.arange(len(where)), boundary, trial, max_t, min_t, points=True)
        same = on_low_side(solution, pair).reshape(-1, TRANSITION_PROBES)
        last_same = np.where(same.any(axis=1), TRANSITION_PROBES - 1 - np.argmax(same[:, ::-1], axis=1), -1)
        grid = np.column_stack([low, where.reshape(-1, TRANSITION_PROBES), high])
        low, high = grid[rows, last_same + 1], grid[rows, last_same + 2]
    return probes, solution, last_same


def _refine_switches(samples, contact_t, status, contact_position, boundary, max_t, min_t):
    """Add the branch points of the medial axis that lie between two samples of an edge.

    Two kinds of switch between neighbours on one edge mark such a point, and a chord between the
    neighbours would cut the axis's corner there by up to the spacing:

    - one is skipped and the other clearly accepted: the incircle touches both chains and the sample's own
      chain elsewhere (e.g. where the axis meets the part of an end that touches both chains); the clearly
      accepted end of the final bracket is added. (Ties are left alone: a switch inside a tie's tolerance is
      no branch point; neither is a skipped sample next to an accepted convex vertex, which lies in that
      corner's own branch meeting the axis at the vertex sample's point.)
    - both are accepted but their contacts on the other chain are far apart along it (more than
      ``JUMP_RATIO`` times the samples' distance): the incircle touches the other chain at two places, where a
      side branch into a bay of that chain leaves the axis; both ends of the final bracket are added.

    Returns the probe samples and their solution (as :func:`solve`), with ties counted as skipped.
    """
    edge = samples.first_own == samples.last_own
    pair = edge[:-1] & edge[1:] & (samples.first_own[:-1] == samples.first_own[1:])
    pair &= np.isfinite(contact_t[:-1]) & np.isfinite(contact_t[1:])
    switch = np.flatnonzero(
        pair & (np.minimum(status[:-1], status[1:]) == SKIPPED) & (np.maximum(status[:-1], status[1:]) == CLEAR)
    )
    accepted_convex = (samples.slide > 0) & (status != SKIPPED)
    # The skipped sample's neighbour on the far side from the accepted one.
    beyond_skipped = np.where(status[switch] == SKIPPED, switch - 1, switch + 2)
    exists = (beyond_skipped >= 0) & (beyond_skipped < len(status))
    corner = exists & accepted_convex[np.clip(beyond_skipped, 0, len(status) - 1)]
    switch = switch[~corner]
    jump = np.flatnonzero(
        pair
        & (status[:-1] == CLEAR)
        & (status[1:] == CLEAR)
        & (np.abs(np.diff(contact_position)) > JUMP_RATIO * np.diff(samples.position))
    )
    found = []
    if len(switch):
        low_accepted = status[switch] == CLEAR
        probes, solution, last_same = _bisect(
            samples,
            switch,
            contact_t,
            boundary,
            max_t,
            min_t,
            lambda solution, pair: (solution[1] == CLEAR) == low_accepted[pair],
        )
        found.append((probes, solution, np.where(low_accepted, last_same, last_same + 1)))
    if len(jump):
        low_contact, high_contact = contact_position[jump], contact_position[jump + 1]
        probes, solution, last_same = _bisect(
            samples,
            jump,
            contact_t,
            boundary,
            max_t,
            min_t,
            lambda solution, pair: np.abs(solution[3] - low_contact[pair]) < np.abs(solution[3] - high_contact[pair]),
        )
        found += [(probes, solution, last_same), (probes, solution, last_same + 1)]
    chosen_probes, chosen_solutions = [], []
    for probes, solution, index in found:
        keep = (index >= 0) & (index < TRANSITION_PROBES)
        chosen = np.flatnonzero(keep) * TRANSITION_PROBES + index[keep]
        chosen_probes.append(probes.subset(chosen))
        chosen_solutions.append([part[chosen] for part in solution])
    if not found:
        return samples.subset(slice(0, 0)), np.empty(0), np.empty(0, dtype=np.int8), np.empty((0, 2)), np.empty(0)
    contact_t_kept, status_kept, contact, position, _ = (np.concatenate(parts) for parts in zip(*chosen_solutions))
    return (
        Samples.concatenate(chosen_probes),
        contact_t_kept,
        np.where(status_kept == CLEAR, CLEAR, SKIPPED),
        contact,
        position,
    )


def _medial_points(samples, sample, t, boundary):
    """Centre, radius, touching point and its arc length on the sampled chain, for settled samples.

    Returns those arrays and a mask of the samples to keep: at a convex vertex the disk touches the
    incident edges ``slide*t`` from the vertex, on the incoming edge if it is that long, else on the
    outgoing one; a disk that reaches past both edges touches its own chain nowhere and is dropped.
    """
    point = samples.point[sample]
    centre = point + t[:, None] * samples.direction[sample]
    radius = samples.scale[sample] * t
    slide = samples.slide[sample] * t
    incoming, outgoing = samples.first_own[sample], samples.last_own[sample]
    on_incoming = slide <= boundary.length[incoming]
    on_outgoing = ~on_incoming & (slide <= boundary.length[outgoing])
    foot = np.where(
        on_incoming[:, None],
        point - slide[:, None] * boundary.unit[incoming],
        point + slide[:, None] * boundary.unit[outgoing],
    )
    position = samples.position[sample] + np.where(on_incoming, -slide, slide)
    return centre, radius, foot, position, on_incoming | on_outgoing


def fixed_axis_points(chains, boundary, side, spacings, width, max_t, min_t, report):
    """Points of the medial axis between the chains from the paper's fixed sampling.

    Parameters
    ----------
    chains : sequence of two ndarray of shape (n, 2)
        The chains in the engine's local frame, CRS units.
    boundary : Boundary
    side : float
        +1 when the region lies left of the first chain, -1 when right.
    spacings : sequence of two float
        Distance between equidistant stations on each chain, CRS units.
    width : float
        Typical width, CRS units (sets the trial radius and the fan's angular step).
    max_t, min_t : float
        Largest disk parameter searched, and the smallest one that counts as a contact, CRS units.
    report : callable
        ``report(done_fraction)``; raises to cancel.

    Returns
    -------
    AxisPoints
    """
    fan_step = min(MAX_FAN_STEP, 2.0 * min(spacings) / width)
    samples = Samples.concatenate(
        [
            _sample_chain(
                i, chains[i], boundary.position[i], side if i == 0 else -side, spacings[i], boundary.offset[i], fan_step
            )
            for i in (0, 1)
        ]
    )
    contact_t, status, contact, position, _ = solve_in_chunks(
        samples, np.arange(len(samples.point)), boundary, 0.625 * width, max_t, min_t, report, points=True
    )
    pieces = []
    for probes, probe_t, probe_status, probe_contact, probe_position in (
        (samples, contact_t, status, contact, position),
        _refine_switches(samples, contact_t, status, position, boundary, max_t, min_t),
    ):
        chosen = np.flatnonzero(probe_status != SKIPPED)
        *medial, keep = _medial_points(probes, chosen, probe_t[chosen], boundary)
        centre, radius, own_foot, own_position = (array[keep] for array in medial)
        pieces.append(
            AxisPoints.from_chain_feet(
                probes.chain[chosen][keep],
                centre,
                radius,
                own_foot,
                own_position,
                probe_contact[chosen][keep],
                probe_position[chosen][keep],
            )
        )
    return AxisPoints.concatenate(pieces)
