"""Lines made together (``lines.lines_together``) are the lines each request makes alone, byte for byte.

A batch orders, de-duplicates and simplifies the axis points of many features at once; every step treats a
feature's points with its own only, and each feature's values (tolerances, lengths, direction of travel) go
with its points. Checked on the line requests of a mix of features (the analytic shapes, rivers with and
without islands, bank lines whose points are first cut to the region between them, the fixed sampling, which
is not simplified, a feature whose simplified chords leave its polygon, a feature without axis points, a
feature twice), with lines simplified in pieces, in groups smaller than the batch, and when the sort keys cannot
be offset exactly; the simplification's fallback for a line it would make cross itself, and the batch's fallback
when the joint pass fails.
"""

import dataclasses

import numpy as np
import pytest
import shapely

from benchmarks.rivers import river_layer
from incircu_plugin.core import _steps as steps_module
from incircu_plugin.core import lines, polygon_centerline
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core._steps import answer_alone
from incircu_plugin.core.api import _lines_centerline_steps, _polygon_centerline_steps
from incircu_plugin.core.lines import LineRequest, _Blocks, _fewest_of_features, _fewest_vertices, lines_together
from tests.support import geometry_cases

#: A line (integer coordinates) that the plain Douglas-Peucker simplification at ``CROSSING_TOLERANCE`` makes
#: cross itself, though it does not.
CROSSING_LINE = np.array([[8, 7], [7, 5], [5, 4], [6, 2], [4, 2], [5, 6], [7, 6]], dtype=float)
CROSSING_TOLERANCE = 1.5


def line_request(steps):
    """The :class:`LineRequest` a step generator makes once its earlier requests are answered alone."""
    request = next(steps)
    while not isinstance(request, LineRequest):
        request = steps.send(answer_alone(request))
    return request


def wavy_banks(seed):
    """Two bank lines 12 to 16 apart along a sine, CRS units."""
    x = np.linspace(0.0, 600.0, 40 + seed)
    bank = np.c_[x, 20.0 * np.sin(x / 90.0 + seed)]
    return bank, bank + [3.0, 12.0 + seed % 5]


@pytest.fixture(scope="module")
def requests():
    """The line requests of the mix, and the index of the one whose simplified chords leave its polygon."""
    steps = [_polygon_centerline_steps(case.polygon, case.split_points) for case in geometry_cases.analytic_cases()]
    # The first 40 rivers of the layer, and river 292 (each river is drawn from its own index).
    rivers = river_layer(count=40)
    steps += [_polygon_centerline_steps(river.polygon, list(river.ends)) for river in rivers]
    steps += [_lines_centerline_steps(*wavy_banks(seed)) for seed in range(4)]
    case = geometry_cases.meander()
    steps.append(_polygon_centerline_steps(case.polygon, case.split_points, spacing=case.width / 10.0))
    # River 292 at a tolerance of 2 m: a chord of its simplified line cuts a bend (found by a search of the
    # layer at that tolerance; asserted below).
    river = river_layer(count=1, first=292)[0]
    steps.append(_polygon_centerline_steps(river.polygon, list(river.ends), tolerance=2.0))
    made = [line_request(step) for step in steps]
    empty = dataclasses.replace(made[0], points=made[0].points.subset(np.zeros(len(made[0].points.radius), bool)))
    # The first request again at the end: its centres are those of the first, in the same local frame.
    return made[:3] + [empty] + made[3:] + [made[0]]


def assert_same_lines(together, alone):
    assert len(together) == len(alone)
    for number, (line, single) in enumerate(zip(together, alone)):
        assert len(line) == 4, number
        for values, expected in zip(line, single):
            assert values.shape == expected.shape and values.tobytes() == expected.tobytes(), number


@pytest.mark.slow
def test_lines_made_together_are_those_made_alone(requests, monkeypatch):
    restored = []
    restore = lines._restore_leaving_chords
    monkeypatch.setattr(lines, "_restore_leaving_chords", lambda *args: restored.append(1) or restore(*args))
    alone = [lines_together([request])[0] for request in requests]
    assert restored, "no request of the mix had a chord leaving its polygon"
    assert_same_lines(lines_together(requests), alone)
    # The request without axis points: its two split points.
    assert len(alone[3][0]) == 2 and alone[3][1].tolist() == [0.0, 0.0]
    # The open bank lines' points were cut to the region between them: some lay outside.
    banks = [request for request in requests if not request.frame.closed]
    assert banks and any(len(line[0]) < len(request.points.radius) for request, line in zip(requests, alone))


@pytest.mark.parametrize("setting", [("SIMPLIFY_PIECE", 16), ("LINE_GROUP", 3)])
def test_lines_in_pieces_or_in_small_groups_are_those_made_alone(requests, monkeypatch, setting):
    monkeypatch.setattr(lines, *setting)
    assert_same_lines(lines_together(requests), [lines_together([request])[0] for request in requests])


def test_sort_keys_that_cannot_be_offset_exactly_make_each_line_alone(requests, monkeypatch):
    by_feature = lines._by_feature
    refused = []

    def inexact(key, blocks):
        if blocks.count > 1:
            refused.append(blocks.count)
            raise lines._NotExact()
        return by_feature(key, blocks)

    expected = [lines_together([request])[0] for request in requests]
    monkeypatch.setattr(lines, "_by_feature", inexact)
    assert_same_lines(lines_together(requests), expected)
    assert refused == [len(requests)]


def test_a_key_too_large_to_offset_is_refused():
    blocks = _Blocks([2, 1])
    assert lines._by_feature(np.array([3.0, -1.0, 2.0]), blocks).tolist() == [3.0, -1.0, 10.0]
    with pytest.raises(lines._NotExact):
        lines._by_feature(np.array([2.0**52, 0.0, 1.0]), blocks)
    with pytest.raises(lines._NotExact):
        lines._by_feature(np.array([np.nan, 0.0, 1.0]), blocks)


def test_a_simplification_that_would_cross_itself_falls_back_feature_by_feature():
    plain = shapely.simplify(shapely.LineString(CROSSING_LINE), CROSSING_TOLERANCE, preserve_topology=False)
    assert shapely.LineString(CROSSING_LINE).is_simple and not plain.is_simple
    straight = np.c_[np.arange(10.0), 0.01 * np.arange(10.0) ** 2]
    features = [straight, CROSSING_LINE, straight + 100.0]
    centre = np.concatenate(features)
    tolerances = np.array([0.05, CROSSING_TOLERANCE, 0.5])
    seen = np.arange(len(centre))
    simplified = _fewest_of_features(centre, seen, _Blocks([len(f) for f in features]), tolerances)
    expected = np.concatenate([_fewest_vertices(f, t) for f, t in zip(features, tolerances)])
    assert simplified.tolist() == expected.tolist()
    # The crossing line's own fallback (GEOS's topology-preserving simplification), not the plain one.
    kept = CROSSING_LINE[simplified[len(straight) : -len(straight)]]
    assert shapely.LineString(kept).is_simple and len(kept) > len(plain.coords)


def test_a_batch_whose_lines_fail_together_makes_each_alone(monkeypatch):
    # run_together's fallback: an unexpected failure of the joint pass costs the batch its speed, not its lines.
    cases = [geometry_cases.rectangle(), geometry_cases.tapered_channel(), geometry_cases.meander()]
    joint = steps_module.lines_together
    calls = []

    def failing_together(requests):
        calls.append(len(requests))
        if len(requests) > 1:
            raise RuntimeError("the joint pass failed")
        return joint(requests)

    monkeypatch.setattr(steps_module, "lines_together", failing_together)
    outcomes = run_many_steps([_polygon_centerline_steps(case.polygon, case.split_points) for case in cases])
    assert calls == [3, 1, 1, 1]
    for case, outcome in zip(cases, outcomes):
        alone = polygon_centerline(case.polygon, case.split_points)
        assert outcome.line.equals_exact(alone.line, 1e-9 * case.width)
