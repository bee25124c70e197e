"""Many features traced together (``centerlines_together`` over the ``*_steps`` generators) equal each one alone.

Each feature is computed in its own frame whatever its batch (the joint tracing places features side by side
in its spatial index only), so a feature's outcome is the same bytes alone, in any batch, in any order:
errors agree in type and message, results in every float64 of their lines, radii and feet
(:func:`fuzz.checks.outcome_key`).
"""

import gc
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, MultiPolygon, Polygon, box

from benchmarks.rivers import river_layer
from fuzz.checks import outcome_key
from fuzz.inputs import STEPS, call, make_case, steps
from incircu_plugin.core import (
    Cancelled,
    CenterlineError,
    CenterlineResult,
    InvalidGeometryError,
    OptionError,
    SplitPointError,
    _many,
    contacts,
    polygon_centerline,
)
from incircu_plugin.core import _steps as steps_module
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core._steps import (
    _huge_page_advice_setter,
    answer_alone,
    run_alone,
    run_settings_paused,
    trace_alone,
)
from incircu_plugin.core.api import _lines_centerline_steps, _multipolygon_centerline_steps, _polygon_centerline_steps
from incircu_plugin.core.lines import LineRequest
from incircu_plugin.core.tracing import joint
from tests.support import geometry_cases

#: A self-crossing ring: an invalid polygon.
BOW_TIE = Polygon([(0, 0), (10, 10), (10, 0), (0, 10)])


@dataclass
class Feature:
    """One input of the mix: ``make()`` returns a fresh step generator."""

    name: str
    make: Callable


def mixed_features():
    """A mix of inputs, good and bad, as :class:`Feature` objects."""
    features = [
        Feature(case.name, lambda c=case: _polygon_centerline_steps(c.polygon, c.split_points))
        for case in geometry_cases.analytic_cases(("unit", "projected"))
    ]
    rectangle = geometry_cases.rectangle(length=300.0, width=12.0, n=9)
    tapered = geometry_cases.tapered_channel()
    meander = geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, n=(301, 287))
    two_parts = MultiPolygon([rectangle.polygon, shapely.affinity.translate(tapered.polygon, 0, 200)])
    islands = box(0, 0, 200, 20).difference(box(80, 11, 120, 15))
    island_ends = [(0, 10), (200, 10)]
    far = (rectangle.split_points[0], (1e3, 1e3))
    features += [
        Feature(
            "automatic ends",
            lambda: _polygon_centerline_steps(meander.polygon),
        ),
        Feature("multipart, automatic ends", lambda: _multipolygon_centerline_steps(two_parts)),
        Feature(
            "multipart, one part with split points",
            lambda: _multipolygon_centerline_steps(two_parts, list(rectangle.split_points)),
        ),
        Feature(
            "multipart, bad part",
            lambda: _multipolygon_centerline_steps(MultiPolygon([BOW_TIE, box(20, 0, 80, 6)])),
        ),
        Feature("islands", lambda: _polygon_centerline_steps(islands, island_ends)),
        Feature(
            "islands ignored",
            lambda: _polygon_centerline_steps(islands, island_ends, islands="ignore"),
        ),
        Feature(
            "lines",
            lambda: _lines_centerline_steps(*geometry_cases.bank_pair(meander, reverse_b=True)),
        ),
        Feature(
            "fixed spacing",
            lambda: _polygon_centerline_steps(rectangle.polygon, rectangle.split_points, spacing=2.0),
        ),
        Feature("invalid polygon", lambda: _polygon_centerline_steps(BOW_TIE, [(0, 5), (10, 5)])),
        Feature("split point off the ring", lambda: _polygon_centerline_steps(rectangle.polygon, far)),
        Feature(
            "negative tolerance",
            lambda: _polygon_centerline_steps(rectangle.polygon, rectangle.split_points, tolerance=-1.0),
        ),
        Feature("bad island mode", lambda: _multipolygon_centerline_steps(two_parts, islands="swim")),
    ]
    return features


def alone(make_steps):
    """What the plain function returns or raises for one feature."""
    try:
        return run_alone(make_steps())
    except Exception as error:  # noqa: BLE001 - the error is the expected outcome
        return error


def assert_identical(together, expected, name):
    """``together`` and ``expected`` are the same outcome, to the last bit; a kept error has no traceback."""
    assert outcome_key(together) == outcome_key(expected), name
    if isinstance(together, Exception):
        assert together.__traceback__ is None, name


def test_a_mix_of_features_traced_together_equals_each_alone():
    features = mixed_features()
    expected = [alone(feature.make) for feature in features]
    # Each kind of input and outcome is in the mix, so the comparison below covers them all.
    kinds = {type(outcome) for outcome in expected}
    assert {InvalidGeometryError, SplitPointError, OptionError, list} <= kinds
    assert any(isinstance(outcome, CenterlineResult) and not hasattr(outcome, "ends_from") for outcome in expected)
    assert any(isinstance(o, list) and any(p.error for p in o) and any(p.result for p in o) for o in expected)
    # In input order and reversed: a feature's outcome does not depend on its neighbours.
    for order in (list(range(len(features))), list(range(len(features)))[::-1]):
        together = run_many_steps([features[i].make() for i in order])
        assert len(together) == len(order)
        for i, outcome in zip(order, together):
            assert_identical(outcome, expected[i], features[i].name)


def test_features_of_different_sizes_and_places_together_equal_each_alone():
    small = geometry_cases.rectangle(length=20.0, width=2.0, n=5)
    far = geometry_cases.tapered_channel(placement=geometry_cases.PLACEMENTS["projected"])
    tiny = geometry_cases.rectangle(n=(7, 13), jitter=0.4, seed=3, placement=geometry_cases.PLACEMENTS["tiny"])
    cases = [small, far, tiny]
    together = run_many_steps([_polygon_centerline_steps(c.polygon, c.split_points) for c in cases])
    for case, outcome in zip(cases, together):
        expected = polygon_centerline(case.polygon, case.split_points)
        assert_identical(outcome, expected, case.name)


@pytest.mark.slow
def test_a_batch_of_rivers_with_automatic_ends_equals_each_alone():
    # Rivers 19,712 to 19,967 of the seeded layer (seed 7): one batch of a 50,000-river run through qgis_process
    # (automatic ends), which skipped river 19,890 as crossing itself. Its automatic start lies on a zigzag cap,
    # events are sought a hair from it, and in the batch's shared frame the other chain's copy of the start was
    # touched through rounding at radii along the stub, out of order. Every river must come out as it does alone.
    rivers = river_layer(256, seed=7, first=19_712)
    together = run_many_steps([_polygon_centerline_steps(river.polygon) for river in rivers])
    for river, outcome in zip(rivers, together, strict=True):
        assert_identical(outcome, polygon_centerline(river.polygon), river.index)


def test_an_error_thrown_at_a_parts_request_fails_that_part_only():
    # What run_together does when a part's tracing fails: the part gets the error, the next part goes on.
    # Split points given, so the first request is the first part's tracing (not its automatic ends).
    generator = _multipolygon_centerline_steps(
        MultiPolygon([box(0, 0, 50, 4), box(0, 10, 50, 14)]), [(0, 2), (50, 2), (0, 12), (50, 12)]
    )
    next(generator)
    request = generator.throw(CenterlineError("the tracing failed"))
    # The second part's axis points, then its line, finish the generator.
    line_request = generator.send(trace_alone(request))
    assert isinstance(line_request, LineRequest)
    with pytest.raises(StopIteration) as stop:
        generator.send(answer_alone(line_request))
    first, second = stop.value.value
    assert (first.result, str(first.error)) == (None, "the tracing failed") and first.error.__traceback__ is None
    assert second.error is None and second.result.line.length == pytest.approx(50.0, rel=1e-9)


def test_a_part_whose_tracing_fails_alone_fails_that_part_only(monkeypatch):
    # run_alone, like run_together, raises a failed tracing inside the generator: the part gets the error.
    from incircu_plugin.core import _steps as steps

    calls = []

    def failing_first(request):
        calls.append(request)
        if len(calls) == 1:
            raise CenterlineError("the tracing failed")
        return trace_alone(request)

    monkeypatch.setattr(steps, "trace_alone", failing_first)
    outcomes = run_alone(_multipolygon_centerline_steps(MultiPolygon([box(0, 0, 50, 4), box(0, 10, 50, 14)])))
    assert len(calls) == 2
    assert (outcomes[0].result, str(outcomes[0].error)) == (None, "the tracing failed")
    assert outcomes[1].error is None and outcomes[1].result.line.length == pytest.approx(50.0, rel=1e-9)


def test_batch_progress_rises_from_0_to_1():
    cases = [geometry_cases.rectangle(), geometry_cases.tapered_channel(), geometry_cases.annulus_sector()]
    fractions = []
    run_many_steps([_polygon_centerline_steps(c.polygon, c.split_points) for c in cases], lambda f: fractions.append(f))
    assert fractions == sorted(fractions) and fractions[-1] == 1.0 and 0.0 <= fractions[0]
    assert len(set(fractions)) > 2


def test_cancel_through_the_batch_progress_raises_cancelled():
    cases = [geometry_cases.rectangle(), geometry_cases.meander()]
    with pytest.raises(Cancelled):
        run_many_steps([_polygon_centerline_steps(c.polygon, c.split_points) for c in cases], lambda f: f < 0.5)


def test_cancel_through_one_features_progress_stops_the_batch():
    # The automatic ends report progress from inside the generator, before the tracing.
    case = geometry_cases.meander()
    steps = [
        _polygon_centerline_steps(case.polygon, case.split_points),
        _polygon_centerline_steps(case.polygon, progress=lambda fraction: False),
    ]
    with pytest.raises(Cancelled):
        run_many_steps(steps)


def test_batches_are_bounded_by_features_and_vertices(monkeypatch):
    monkeypatch.setattr(_many, "BATCH_FEATURES", 3)
    monkeypatch.setattr(_many, "BATCH_VERTICES", 10)
    sizes = [1, 2, 3, 4, 1, 1, 1, 25, 2]
    batches = list(_many.batches(range(len(sizes)), sizes.__getitem__))
    assert [index for batch in batches for index in batch] == list(range(len(sizes)))
    for batch in batches:
        assert len(batch) <= 3 and (len(batch) == 1 or sum(sizes[i] for i in batch) <= 10)
    # Full batches: no two neighbouring batches could have been one.
    for first, second in zip(batches, batches[1:]):
        assert len(first) + len(second) > 3 or sum(sizes[i] for i in first + second) > 10
    assert list(_many.batches([], len)) == []


def test_lines_with_an_error_together_with_good_ones():
    crossing = (LineString([(0, 0), (100, 0)]), LineString([(0, 10), (100, -10)]))
    good = geometry_cases.bank_pair(geometry_cases.rectangle())
    together = run_many_steps([_lines_centerline_steps(*crossing), _lines_centerline_steps(*good)])
    expected = alone(lambda: _lines_centerline_steps(*crossing))
    assert isinstance(expected, Exception)
    assert type(together[0]) is type(expected) and str(together[0]) == str(expected)
    assert_identical(together[1], run_alone(_lines_centerline_steps(*good)), "good")


def test_the_garbage_collector_is_paused_during_a_run_and_restored_after(monkeypatch):
    seen = []
    tracer = steps_module.trace_together
    monkeypatch.setattr(steps_module, "trace_together", lambda *a: seen.append(gc.isenabled()) or tracer(*a))
    monkeypatch.setattr(steps_module, "trace_one", lambda *a: seen.append(gc.isenabled()) or tracer([a[0]], a[1])[0])
    case = geometry_cases.rectangle()
    for enabled in (True, False):
        (gc.enable if enabled else gc.disable)()
        try:
            run_many_steps([_polygon_centerline_steps(case.polygon, case.split_points)])
            polygon_centerline(case.polygon, case.split_points)
            assert gc.isenabled() is enabled
            with pytest.raises(Cancelled):
                run_many_steps([_polygon_centerline_steps(case.polygon, case.split_points)], lambda f: False)
            assert gc.isenabled() is enabled
        finally:
            gc.enable()
    assert seen and not any(seen)


def test_overlapping_pauses_restore_the_collector_and_the_huge_page_advice_when_the_last_ends():
    setter = _huge_page_advice_setter()
    assert setter is not None
    assert gc.isenabled()
    original = setter(True)
    try:
        first, second = run_settings_paused(), run_settings_paused()
        first.__enter__()
        second.__enter__()
        first.__exit__(None, None, None)
        # One run still goes on: both stay paused.
        assert not gc.isenabled()
        assert setter(False) is False
        second.__exit__(None, None, None)
        assert gc.isenabled()
        assert setter(True) is True
    finally:
        setter(original)
        gc.enable()


def tie_cases():
    """(name, polygon, split points or None) of shapes whose disks often touch two sites at exactly the same
    parameter: straight sides cut into collinear segments, rivers at their events."""
    rectangle = geometry_cases.rectangle(length=100.0, width=10.0, n=21)
    collinear = shapely.segmentize(box(0.0, 0.0, 120.0, 10.0), 7.5)
    cases = [
        ("rectangle", rectangle.polygon, rectangle.split_points),
        ("collinear box", collinear, [(0.0, 5.0), (120.0, 5.0)]),
    ]
    for river in river_layer(3, seed=0):
        cases += [
            (f"river {river.index}", river.polygon, river.ends),
            (f"river {river.index} auto", river.polygon, None),
        ]
    return cases


def exactly(result):
    """Every bit of a result's line, radii and feet."""
    return shapely.to_wkb(result.line), result.radii.tobytes(), result.foot_a.tobytes(), result.foot_b.tobytes()


@pytest.mark.slow
def test_ties_are_broken_alike_alone_on_every_candidate_path_and_in_a_shuffled_batch(monkeypatch):
    # Contacts tie exactly at many events; which foot wins must not depend on the order in which the spatial
    # index, the all-pairs test or a batch's larger index list the candidates. The batch is traced in one
    # frame without shifts (features overlap, contacts stay within each feature), so every bit must agree.
    cases = tie_cases()
    expected = [exactly(polygon_centerline(polygon, ends)) for _, polygon, ends in cases]
    for all_pairs, index_run in ((1 << 62, contacts.INDEX_RUN), (0, contacts.INDEX_RUN), (0, 1)):
        monkeypatch.setattr(contacts, "ALL_PAIRS", all_pairs)
        monkeypatch.setattr(contacts, "INDEX_RUN", index_run)
        for (name, polygon, ends), bits in zip(cases, expected, strict=True):
            assert exactly(polygon_centerline(polygon, ends)) == bits, (name, all_pairs, index_run)
    monkeypatch.undo()
    monkeypatch.setattr(joint, "JOINT_CELL", 0.0)
    order = np.random.default_rng(5).permutation(2 * len(cases)) % len(cases)
    together = run_many_steps([_polygon_centerline_steps(*cases[i][1:]) for i in order])
    for i, outcome in zip(order, together, strict=True):
        assert exactly(outcome) == expected[i], cases[i][0]


@pytest.mark.slow
@pytest.mark.parametrize("seed", [3, 29])
def test_fuzzed_inputs_are_the_same_bytes_alone_in_a_batch_reversed_and_in_slices(seed):
    # The fuzz generator's inputs (channels with and without split points, bank lines, islands, rings, spikes,
    # compact shapes, bad inputs) that have a step form: each outcome alone, then in one batch, in the reverse
    # order and in four slices, as a dask frame's partitions or a selection in QGIS would split a layer.
    cases = [make_case(seed, index, small=True) for index in range(120)]
    cases = [case for case in cases if case.function in STEPS]
    expected = []
    for case in cases:
        try:
            expected.append(call(case))
        except Exception as error:  # noqa: BLE001 - the error is the expected outcome
            expected.append(error)
    order = list(range(len(cases)))
    for batch in (order, order[::-1], *np.array_split(order, 4)):
        together = run_many_steps([steps(cases[index]) for index in batch])
        for index, outcome in zip(batch, together, strict=True):
            assert_identical(outcome, expected[index], (seed, index, cases[index].category))
