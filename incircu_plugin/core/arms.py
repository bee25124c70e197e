"""Automatic arm ends: the ends of every arm of a network polygon (a confluence, a lake with arms, a road area).

The arms come from the skeleton :func:`.ends.find_ends` builds (:func:`.skeleton.joint_skeletons`, in the
polygon's local frame), pruned so that bank noise never makes an arm:

1. **Branches.** The skeleton is contracted into branches between its nodes of degree other than two
   (leaves and junctions).
2. **Reach.** A *leaf branch* runs from a leaf ``l`` (radius ``r_l``) to a junction ``J`` (radius ``r_J``,
   width ``2 r_J``) over a skeleton length ``s``. The arm's tip lies about ``r_l`` beyond ``l``, so the arm
   reaches ``reach = s + r_l - r_J`` beyond the junction's incircle.
3. **Pruning.** A leaf branch is *short* when ``reach < min_arm_ratio * 2 r_J`` or ``reach <
   min_arm_length``. The short leaf branch reaching the smallest share of its threshold is removed, then the
   next one, until none is short (a priority queue). Removing a branch lowers its junction's degree: at two,
   its other two branches merge into one (which may be a leaf branch reaching farther); at one, the junction
   becomes a leaf (the two corner branches of a flat cut leave their common junction as the arm's leaf). The
   result depends on the geometry only, never on the order in which branches were found. A branch between
   two leaves (the last one of an elongated shape) and a cycle (around an island) are never removed.
4. **Ends.** Each remaining leaf is an arm. Its trunk (the skeleton path from the deepest leaf of what was
   pruned beyond it, through the arm and on along the longest branches, four times as long as the arm) is
   centred in its end
   cap exactly as :func:`.ends.find_ends` centres its two ends (the middle of a cut-off end, the tip of a bay
   or a pointed arm, the apex of a rounded cap). Two ends closer than the narrower arm's width lie on one end
   cap (the acute corner of a dam's end beside its middle): only the farther-reaching one is kept.

Why ``min_arm_ratio = 1`` (see :data:`MIN_ARM_RATIO`): an arm must reach beyond the junction's incircle by at
least the junction's width. A bump of the bank or a digitising step reaches a small fraction of the width (a
5 % bump: 0.05); a bay as deep as it is wide at the mouth of a river twice as wide reaches about 0.5; a
tributary, a drowned valley or a road leaving a junction is several widths long. On the 16 reservoirs of
``tests/data`` it keeps 2 to 30 arms, the main stem's ends among them (``tests/test_core_arms.py``; pictures
in ``docs/images/real_network_vs_sfcgal.png``), and on generated shapes with bank noise at 5 % of the width
it adds no branch (``benchmarks/bench_network.py``).
"""

import heapq
from dataclasses import dataclass

import numpy as np
import shapely

from .ends import PolygonSkeleton
from .errors import InvalidGeometryError, Message, OptionError
from .polyline import typical_width

#: Default ``min_arm_ratio``: an arm is kept when it reaches beyond its junction's incircle by at least this
#: many junction widths (see the module docstring).
MIN_ARM_RATIO = 1.0


@dataclass(frozen=True)
class ArmEnds:
    """The arm ends found automatically on a polygon's exterior ring.

    Attributes
    ----------
    points : ndarray of shape (k, 2)
        One end per arm, on the exterior ring, CRS units (in the order of the pruned skeleton's leaves).
    widths : ndarray of shape (k,)
        Width of each arm near its end (twice the largest clearance along its leaf branch), CRS units.
    reaches : ndarray of shape (k,)
        How far each arm reaches beyond the incircle of the junction it leaves, in widths of that junction
        (``inf`` for the two ends of a shape without junction, and for a main-stem end added by rule 5).
    """

    points: np.ndarray
    widths: np.ndarray
    reaches: np.ndarray


def check_arm_options(min_arm_ratio, min_arm_length):
    """Return ``(min_arm_ratio, min_arm_length)`` as floats (None length: 0); raise :class:`OptionError` when
    one is negative or not finite."""
    ratio = MIN_ARM_RATIO if min_arm_ratio is None else float(min_arm_ratio)
    length = 0.0 if min_arm_length is None else float(min_arm_length)
    if not (np.isfinite(ratio) and ratio >= 0.0):
        raise OptionError(Message("arm_ratio_bad", value=min_arm_ratio))
    if not (np.isfinite(length) and length >= 0.0):
        raise OptionError(Message("arm_length_bad", value=min_arm_length))
    return ratio, length


def find_arm_ends(polygon, *, min_arm_ratio=MIN_ARM_RATIO, min_arm_length=None, every_island=False):
    """Find one end per arm of a polygon: the leaves of its pruned skeleton, centred in their end caps.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, CRS units; holes smaller than the typical width are left out, as for
        :func:`.ends.find_ends`.
    min_arm_ratio : float
        Shortest reach of a kept arm beyond its junction's incircle, in widths of that junction.
    min_arm_length : float, optional
        Shortest reach of a kept arm beyond its junction's incircle, CRS units.
    every_island : bool
        Keep every hole in the skeleton, also those smaller than the typical width (the channel islands of a
        network: a road grid's blocks).

    Returns
    -------
    ArmEnds
        The arms' ends and the main stem's (so at least two, unless the main stem's ends coincide).

    Raises
    ------
    InvalidGeometryError
        As :func:`.ends.find_ends` (an invalid, absurdly scaled or untriangulable polygon).
    OptionError
        A negative or non-finite option.

    Examples
    --------
    A T of two roads 10 and 6 wide: three arms, ends in the middle of the three cut-off ends.

    >>> from shapely.geometry import box
    >>> from shapely.ops import unary_union
    >>> t = unary_union([box(-50, -5, 50, 5), box(-3, 0, 3, 50)])
    >>> ends = find_arm_ends(t)
    >>> sorted((round(float(x), 6) + 0.0, round(float(y), 6) + 0.0) for x, y in ends.points)
    [(-50.0, 0.0), (0.0, 50.0), (50.0, 0.0)]
    """
    ratio, length = check_arm_options(min_arm_ratio, min_arm_length)
    shape = PolygonSkeleton(polygon, every_island=every_island)
    skeleton, scale = shape.skeleton, shape.scale
    if len(skeleton.edges) == 0:
        raise InvalidGeometryError(Message("arms_too_thin"))
    main = shape.main_stem()
    graph = _Graph(skeleton.nodes, skeleton.radii, skeleton.edges)
    graph.prune(ratio, length / scale)
    arms = graph.arms()
    exterior = shape.local.exterior
    step = float(skeleton.steps[0])
    # An arm whose tip lies on an island's shore (a large bump of an island) is not an end of the network.
    arms = [
        arm
        for arm in arms
        if exterior.distance(shapely.Point(graph.nodes[arm.trunk[0]])) <= graph.radii[arm.trunk[0]] + 2.0 * step
    ]
    if not arms:
        return _with_main_stem(polygon, main, ArmEnds(np.empty((0, 2)), np.empty(0), np.empty(0)))
    degree = np.bincount(skeleton.edges.ravel(), minlength=len(skeleton.nodes))
    points = shape.trunk_ends(
        [(graph.nodes[arm.trunk], graph.radii[arm.trunk], degree[arm.trunk] >= 3, step) for arm in arms]
    )
    widths = np.array([arm.width for arm in arms]) * scale
    reaches = np.array([arm.reach for arm in arms])
    keep = _separate(points, widths, reaches)
    return _with_main_stem(polygon, main, ArmEnds(points[keep], widths[keep], reaches[keep]))


def _with_main_stem(polygon, main, arms):
    """Return the arm ends with the two ends of the main stem ``main`` (what :func:`.ends.find_ends` gives)
    added where no arm end lies within that arm's width of them (a main river ending in a basin wider than it
    is long beyond its last junction), so the network always holds the polygon's centerline; their width is
    the polygon's typical width and their reach ``inf``."""
    points, widths, reaches = list(arms.points), list(arms.widths), list(arms.reaches)
    width = typical_width(polygon.area, polygon.length / 2.0)
    for end in (main.start, main.end):
        xy = np.asarray(end.coords[0], dtype=float)
        if all(np.hypot(*(xy - point)) > near for point, near in zip(points, widths)):
            points.append(xy)
            widths.append(width)
            reaches.append(np.inf)
    return ArmEnds(np.array(points, dtype=float).reshape(-1, 2), np.array(widths), np.array(reaches))


def _separate(points, widths, reaches):
    """Return the indices of the ends kept when two ends closer than the narrower arm's width are one end.

    Two such ends lie on one end cap (a pointed corner of a dam's end beside its middle): the one reaching
    farther beyond its junction is kept (the first one on a tie), the farthest-reaching ends first.
    """
    order = sorted(range(len(points)), key=lambda index: (-reaches[index], index))
    apart = np.hypot(*(points[:, None, :] - points[None, :, :]).T).T > np.minimum(widths[:, None], widths[None, :])
    keep = []
    for index in order:
        if np.all(apart[index, keep]):
            keep.append(index)
    return sorted(keep)


@dataclass
class _Arm:
    """A leaf of the pruned skeleton: its trunk (node indices from its deepest pruned leaf inward), the width
    near its end and its reach (local units, junction widths)."""

    trunk: np.ndarray
    width: float
    reach: float


class _Graph:
    """A skeleton contracted into branches between its nodes of degree other than two, pruned in place.

    Attributes
    ----------
    branches : dict
        Branch id to its node indices, from one end to the other.
    incident : dict
        Key node to the set of branch ids ending there (a branch with both ends at one node once).
    """

    def __init__(self, nodes, radii, edges):
        self.nodes, self.radii = nodes, radii
        neighbours = [[] for _ in range(len(nodes))]
        for a, b in edges.tolist():
            neighbours[a].append(b)
            neighbours[b].append(a)
        self.neighbours = neighbours
        self.branches = {}
        self.lengths = {}
        self.incident = {}
        self.tails = {}
        self.next_id = 0
        keys = [node for node, near in enumerate(neighbours) if len(near) not in (0, 2)]
        seen = set()
        paths = []
        for key in keys:
            for first in neighbours[key]:
                if (key, first) in seen:
                    continue
                path = [key, first]
                while len(neighbours[path[-1]]) == 2:
                    a, b = neighbours[path[-1]]
                    path.append(b if a == path[-2] else a)
                seen.add((path[-1], path[-2]))
                paths.append(path)
        if paths:
            # The segments of all branches measured in one pass (summed per branch as :meth:`length` sums them).
            flat = np.concatenate(paths)
            steps = np.hypot(*(nodes[flat[1:]] - nodes[flat[:-1]]).T)
            firsts = np.cumsum([0] + [len(path) for path in paths[:-1]]).tolist()
            lengths = [float(np.sum(steps[first : first + len(path) - 1])) for first, path in zip(firsts, paths)]
            for path, length in zip(paths, lengths):
                self._add(path, length)

    def _add(self, path, length=None):
        """Add a branch along ``path`` (node indices) and of ``length`` (local units; measured when None);
        return its id."""
        branch = self.next_id
        self.next_id += 1
        self.branches[branch] = np.asarray(path, dtype=np.int64)
        self.lengths[branch] = self.length(self.branches[branch]) if length is None else length
        for end in (path[0], path[-1]):
            self.incident.setdefault(end, set()).add(branch)
        return branch

    def _remove(self, branch):
        """Remove a branch; return its node indices."""
        path = self.branches.pop(branch)
        del self.lengths[branch]
        for end in (int(path[0]), int(path[-1])):
            self.incident[end].discard(branch)
        return path

    def degree(self, node):
        """Number of branch ends at a key node (a loop counts twice)."""
        return sum(2 if self.branches[b][0] == self.branches[b][-1] else 1 for b in self.incident.get(node, ()))

    def length(self, path):
        """Skeleton length along a node path, local units."""
        points = self.nodes[path]
        return float(np.sum(np.hypot(*np.diff(points, axis=0).T)))

    def _leaf_of(self, branch):
        """Return ``(leaf, junction)`` of a leaf branch (one end of degree 1, the other of 3 or more), else None."""
        path = self.branches[branch]
        a, b = int(path[0]), int(path[-1])
        if a == b:
            return None
        da, db = self.degree(a), self.degree(b)
        if da == 1 and db >= 3:
            return a, b
        if db == 1 and da >= 3:
            return b, a
        return None

    def _reach(self, branch, leaf, junction):
        """Return the reach of a leaf branch beyond its junction's incircle, local units."""
        tail = self.tails.get(leaf)
        beyond = 0.0 if tail is None else self.length(tail)
        tip = self.radii[leaf] if tail is None else self.radii[tail[0]]
        return self.lengths[branch] + beyond + tip - self.radii[junction]

    def _score(self, branch, ratio, length):
        """Return ``(share of its threshold reached, leaf, junction, reach in junction widths)`` or None."""
        ends = self._leaf_of(branch)
        if ends is None:
            return None
        leaf, junction = ends
        reach = self._reach(branch, leaf, junction)
        width = 2.0 * self.radii[junction]
        shares = [reach / (ratio * width) if ratio > 0.0 and width > 0.0 else np.inf]
        if length > 0.0:
            shares.append(reach / length)
        return min(shares), leaf, junction, reach / width if width > 0.0 else np.inf

    def prune(self, ratio, length):
        """Remove the short leaf branches, the shortest share of its threshold first (see the module docstring).

        Parameters
        ----------
        ratio : float
            ``min_arm_ratio``.
        length : float
            ``min_arm_length``, local units.
        """
        heap = []

        def push(branch):
            scored = self._score(branch, ratio, length)
            if scored is not None and scored[0] < 1.0:
                # Ties are broken by the leaf's position, so the order found never matters.
                leaf = scored[1]
                heapq.heappush(heap, (scored[0], *self.nodes[leaf].tolist(), branch))

        for branch in list(self.branches):
            push(branch)
        while heap:
            *_, branch = heapq.heappop(heap)
            if branch not in self.branches:
                continue
            scored = self._score(branch, ratio, length)
            if scored is None or scored[0] >= 1.0:
                continue
            _, leaf, junction = scored[:3]
            path = self._remove(branch)
            oriented = path if path[0] == leaf else path[::-1]
            tail = self.tails.pop(leaf, None)
            removed = oriented if tail is None else np.concatenate([tail, oriented[1:]])
            best = self.tails.get(junction)
            if best is None or self._tail_reach(removed) > self._tail_reach(best):
                self.tails[junction] = removed
            self._settle(junction, push)

    def _tail_reach(self, tail):
        """Length of a pruned tail plus the clearance at its deepest leaf, local units."""
        return self.length(tail) + self.radii[tail[0]]

    def _settle(self, junction, push):
        """After a removal at ``junction``: merge its two branches at degree two, or re-score its last one."""
        around = list(self.incident.get(junction, ()))
        degree = self.degree(junction)
        if degree == 2 and len(around) == 2:
            self.tails.pop(junction, None)
            first, second = (self._remove(branch) for branch in around)
            first = first if first[-1] == junction else first[::-1]
            second = second if second[0] == junction else second[::-1]
            push(self._add(np.concatenate([first, second[1:]])))
        elif degree == 1:
            push(around[0])

    def arms(self):
        """Return the :class:`_Arm` of each leaf of the pruned skeleton, ordered by their leaves' positions."""
        leaves = sorted(
            (node for node, around in self.incident.items() if around and self.degree(node) == 1),
            key=lambda node: tuple(self.nodes[node]),
        )
        arms = []
        for leaf in leaves:
            (branch,) = self.incident[leaf]
            path = self.branches[branch]
            inward = path if path[0] == leaf else path[::-1]
            tail = self.tails.get(leaf, inward[:1])
            onward = self._onward_path(leaf, 4.0 * (self._tail_reach(tail) + self.lengths[branch]))
            trunk = np.concatenate([tail, onward[1:]])
            inner = inward[:-1] if self.degree(int(inward[-1])) >= 3 else inward
            width = 2.0 * float(np.max(self.radii[np.concatenate([tail, inner])]))
            scored = self._score(branch, 1.0, 0.0)
            reach = np.inf if scored is None else float(scored[3])
            arms.append(_Arm(trunk, width, reach))
        return arms

    def _onward_path(self, start, reach):
        """Return a node path from ``start`` into the pruned skeleton at least ``reach`` long (local units) or
        ending at a leaf: at each junction it takes the longest branch not yet walked."""
        path = [np.array([start], dtype=np.int64)]
        here, walked, length = start, set(), 0.0
        while length < reach:
            choices = [branch for branch in self.incident.get(here, ()) if branch not in walked]
            if not choices:
                break
            branch = max(choices, key=lambda b: (self.lengths[b], -b))
            walked.add(branch)
            nodes = self.branches[branch]
            nodes = nodes if nodes[0] == here else nodes[::-1]
            path.append(nodes[1:])
            length += self.lengths[branch]
            here = int(nodes[-1])
        return np.concatenate(path)
