"""Joint tracing (``tracing.trace_together``): many features in one vectorised tracing, each still exact.

The features of a joint tracing share one set of rounds, each in its own frame (they are placed side by side
in the spatial index only); contacts are only sought within a feature's own pair of chains. Checked against
the segment-Voronoi oracle and against tracing each feature alone:

- every feature of a mixed batch (closed and open chains, straight and curved axes, islands, extents from
  1 to 1,000) is within its tolerance of its exact medial axis, with its vertices on it;
- each feature's line is the one it gets alone, bit for bit;
- features overlapping in space (the same place in the index before their shift) never see each other;
- features of very different extents are traced in different groups, each group within the documented
  extent ratio and segment budget; groups are traced together (overlapping in the index) within the segment
  budget, each feature's points exactly those its group gets traced alone.
"""

import numpy as np
import pytest
import shapely

from incircu_plugin.core import default_tolerance, split_polygon
from incircu_plugin.core._steps import run_alone, run_together
from incircu_plugin.core.chains import orient_bank_lines
from incircu_plugin.core.engine import centerline_steps
from incircu_plugin.core.tracing.joint import (
    JOINT_BATCH_RATIO,
    JOINT_EXTENT_RATIO,
    JOINT_SEGMENTS,
    joint_batches,
    joint_groups,
    trace_batch,
)
from tests.support import geometry_cases
from tests.support.marks import is_slow_case
from tests.support.oracle import assert_within_tolerance, check_centerline

CLOSED = geometry_cases.analytic_cases() + [
    geometry_cases.wavy_channel(seed=31),
    geometry_cases.wavy_channel(seed=32, n=(25, 80), split_fractions=(0.15, 0.9), teeth=0.05),
]
OPEN = [geometry_cases.wavy_channel(seed=34), geometry_cases.analytic_cases()[0]]


def scaled(case, factor):
    """The case's polygon and split points scaled by ``factor`` about the origin."""
    polygon = shapely.affinity.scale(case.polygon, factor, factor, origin=(0.0, 0.0))
    return polygon, [(factor * x, factor * y) for x, y in case.split_points]


def closed_jobs():
    """(name, chains, region, ends) of every closed case at three scales: 1, 1/30 and 30 times."""
    jobs = []
    for case in CLOSED:
        for factor in (1.0, 1.0 / 30.0, 30.0):
            polygon, ends = scaled(case, factor)
            jobs.append((f"{case.name} x{factor:g}", split_polygon(polygon, ends), polygon, ends, None))
    return jobs


def open_jobs():
    """(name, chains, region, ends, end gap) of the bank pairs of the open cases."""
    jobs = []
    for case in OPEN:
        line_a, line_b = geometry_cases.bank_pair(case, False, True)
        region = geometry_cases.channel_case("region", case.bank_a, case.bank_b, case.width).polygon
        ends = [tuple(0.5 * (case.bank_a[i] + case.bank_b[i])) for i in (0, -1)]
        gap = max(np.hypot(*(case.bank_a[i] - case.bank_b[i])) for i in (0, -1))
        jobs.append((f"{case.name} banks", orient_bank_lines(line_a, line_b), region, ends, gap))
    return jobs


JOBS = closed_jobs() + open_jobs()


def oracle_params():
    """The jobs as parameters of the oracle check; slow: the 1/30 and 30 times scales, and at scale 1 the cases
    :func:`~tests.support.marks.is_slow_case` counts slow in any placement but the unit frame."""
    slow = {f"{case.name} x{factor:g}" for case in CLOSED for factor in (1.0 / 30.0, 30.0)}
    slow |= {f"{case.name} x1" for case in CLOSED if is_slow_case(case, other_placements=True)}
    return [
        pytest.param(i, id=job[0], marks=[pytest.mark.slow] if job[0] in slow else []) for i, job in enumerate(JOBS)
    ]


@pytest.fixture(scope="module")
def joint_results():
    return run_together([centerline_steps(*chains) for _, chains, _, _, _ in JOBS])


@pytest.mark.parametrize("job", oracle_params())
def test_every_feature_of_a_joint_tracing_is_within_its_tolerance_of_its_axis(joint_results, job):
    name, (chain_a, chain_b), region, ends, gap = JOBS[job]
    result = joint_results[job]
    assert not isinstance(result, Exception), f"{name}: {result!r}"
    check_centerline(result, chain_a, chain_b, region, ends)
    near_ends = None if gap is None else ([np.asarray(end) for end in ends], gap)
    assert_within_tolerance(result, chain_a, chain_b, region, default_tolerance(chain_a, chain_b), near_ends=near_ends)


@pytest.mark.parametrize("job", range(len(JOBS)), ids=[job[0] for job in JOBS])
def test_a_joint_tracing_gives_each_feature_the_line_it_gets_alone(joint_results, job):
    _, (chain_a, chain_b), _, _, _ = JOBS[job]
    alone = run_alone(centerline_steps(chain_a, chain_b))
    joint = joint_results[job]
    assert joint.line.wkb == alone.line.wkb
    for name in ("radii", "foot_a", "foot_b"):
        np.testing.assert_array_equal(getattr(joint, name), getattr(alone, name))


def test_features_at_the_same_place_do_not_see_each_other():
    # Two channels on top of each other (their boxes coincide): each alone has its own axis; a joint tracing
    # that let one see the other's banks would give the narrow one the wide one's contacts or vice versa.
    narrow = geometry_cases.rectangle(length=100.0, width=10.0, n=11)
    wide = geometry_cases.rectangle(length=100.0, width=30.0, n=11)
    chains = [split_polygon(case.polygon, case.split_points) for case in (narrow, wide)]
    joint = run_together([centerline_steps(*pair) for pair in chains])
    for case, result in zip((narrow, wide), joint):
        assert result.radii.max() == pytest.approx(case.width / 2.0, rel=1e-12)


def test_joint_groups_keep_extents_within_the_ratio_and_segments_within_the_budget():
    class Request:
        def __init__(self, extent, segments):
            self.extent, self.segment_count = extent, segments

    extents = [1.0, 3.9, 4.1, 1000.0, 2.0, 30.0, 100.0, 1e-3]
    requests = [Request(extent, 10) for extent in extents] + [Request(2.0, JOINT_SEGMENTS - 15)] * 3
    groups = joint_groups(requests)
    assert sorted(index for group in groups for index in group) == list(range(len(requests)))
    for group in groups:
        sizes = [requests[i].extent for i in group]
        assert max(sizes) <= JOINT_EXTENT_RATIO * min(sizes)
        assert sum(requests[i].segment_count for i in group) <= JOINT_SEGMENTS or len(group) == 1


def test_joint_batches_pack_consecutive_groups_within_the_segment_budget_and_extent_ratio():
    class Request:
        def __init__(self, segments, extent=1.0):
            self.segment_count = segments
            self.extent = extent

    sizes = [10, JOINT_SEGMENTS // 2, JOINT_SEGMENTS // 2, 5, JOINT_SEGMENTS + 1, 7, 8]
    requests = [Request(size) for size in sizes]
    groups = [[0, 1], [2], [3], [4], [5], [6]]
    batches = joint_batches(requests, groups)
    assert [group for batch in batches for group in batch] == groups
    assert batches == [[[0, 1]], [[2], [3]], [[4]], [[5], [6]]]
    for batch in batches:
        total = sum(requests[index].segment_count for group in batch for index in group)
        assert total <= JOINT_SEGMENTS or len(batch) == 1
    # Small groups by ascending extent: a batch holds extents up to JOINT_BATCH_RATIO times its first.
    extents = [1.0, 4.0, JOINT_BATCH_RATIO, 1.01 * JOINT_BATCH_RATIO, 10.0 * JOINT_BATCH_RATIO]
    requests = [Request(10, extent) for extent in extents]
    groups = [[index] for index in range(len(extents))]
    assert joint_batches(requests, groups) == [[[0], [1], [2]], [[3], [4]]]


def test_groups_traced_together_give_each_feature_the_points_of_its_group_alone():
    # One shape at scales 1, 1/30 and 30 (each in its local frame about the origin) and a second shape at
    # scale 1: three groups whose frames overlap in the joint tracing (the single features are not shifted,
    # the pair only half a cell). Traced in one batch, every feature's axis points are bit for bit those of
    # its group traced on its own.
    requests = [next(centerline_steps(*chains)) for _, chains, _, _, _ in closed_jobs()[:4]]
    groups = joint_groups(requests)
    assert sorted(len(group) for group in groups) == [1, 1, 2]
    order = [index for group in groups for index in group]
    together = dict(zip(order, trace_batch(requests, groups, lambda fraction: None)))
    for group in groups:
        for index, alone in zip(group, trace_batch(requests, [group], lambda fraction: None)):
            for name in ("centre", "radius", "foot_a", "foot_b", "position_a", "position_b"):
                np.testing.assert_array_equal(getattr(together[index], name), getattr(alone, name))
