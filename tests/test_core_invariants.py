"""Invariants of every IncirCu result, checked against exact distances computed independently of the engine.

On every interior vertex ``v`` with radius ``r``: ``|dist(v, c1) - r|`` and ``|dist(v, c2) - r|`` are at most
``1e-9`` of the extent; the circle is empty (no boundary point closer than ``r * (1 - 1e-9)``); its feet lie on
their chains at distance ``r`` and advance monotonically along them. The line is simple, in the region and
runs between the split points (closed mode) or the midpoints of the end gaps (open mode). See
:func:`oracle.check_centerline`; the chains it uses are the builders' own, not the engine's.

The only tolerance beyond the relative ``1e-9`` is the double rounding at the coordinates' magnitude (16
units in the last place), which dominates only when the coordinates are huge compared with the extent.
"""

import numpy as np
import pytest

from incircu_plugin.core import lines_centerline, polygon_centerline
from tests.support import geometry_cases
from tests.support.marks import case_params
from tests.support.oracle import MedialOracle, check_centerline

ANALYTIC = geometry_cases.analytic_cases()

#: Extra shapes: randomised channels with the split points off the cap midpoints, and a real outline.
WAVY = [
    geometry_cases.wavy_channel(seed=1),
    geometry_cases.wavy_channel(seed=2, n=(23, 61), split_fractions=(0.2, 0.85)),
    geometry_cases.wavy_channel(
        seed=3,
        length=300.0,
        mean_width=12.0,
        n=(150, 140),
        harmonics=((20.0, 150.0, 1.0), (4.0, 37.0, 0.0)),
        placement=geometry_cases.PLACEMENTS["projected"],
    ),
    geometry_cases.wavy_channel(seed=4, split_fractions=(0.7, 0.3), placement=geometry_cases.PLACEMENTS["tiny"]),
]
CLOSED = ANALYTIC + WAVY + [geometry_cases.gambia()]


#: Spacings as fractions of each case's width: coarse (fewer samples than vertices on some cases), the
#: issue's benchmark setting, and the default rule.
SPACING_FRACTIONS = [0.5, 0.1, None]


def spacing_for(case, fraction):
    return None if fraction is None else fraction * case.width


@pytest.mark.parametrize("fraction", SPACING_FRACTIONS, ids=["w/2", "w/10", "default"])
@pytest.mark.parametrize("case", case_params(CLOSED))
def test_closed_mode_invariants(case, fraction):
    result = polygon_centerline(case.polygon, case.split_points, spacing=spacing_for(case, fraction))
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)


@pytest.mark.parametrize("case", CLOSED, ids=[c.name for c in CLOSED])
def test_closed_mode_starts_at_the_first_split_point(case):
    result = polygon_centerline(case.polygon, case.split_points, spacing=0.2 * case.width)
    coords = np.asarray(result.line.coords)
    tolerance = 1e-9 * case.extent + 16.0 * case.coordinate_ulp
    assert np.hypot(*(coords[0] - case.split_points[0])) <= tolerance
    assert np.hypot(*(coords[-1] - case.split_points[1])) <= tolerance
    assert result.radii[0] == 0.0 and result.radii[-1] == 0.0


@pytest.mark.parametrize("samples", [5, 40])
@pytest.mark.parametrize("case", ANALYTIC[:7], ids=[c.name for c in ANALYTIC[:7]])
def test_closed_mode_invariants_with_a_sample_count(case, samples):
    result = polygon_centerline(case.polygon, case.split_points, samples_per_chain=samples)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)


OPEN = [c for c in ANALYTIC if not c.name.startswith("annulus sector r=30")] + WAVY[:3]


@pytest.mark.parametrize("reverse", [(False, False), (False, True), (True, False), (True, True)], ids=str)
@pytest.mark.parametrize("case", case_params(OPEN))
def test_open_mode_invariants(case, reverse):
    line_a, line_b = geometry_cases.bank_pair(case, *reverse)
    result = lines_centerline(line_a, line_b, spacing=0.1 * case.width)
    check_centerline(result, case.bank_a, case.bank_b, open_region(case), gap_midpoints(case))


def gap_midpoints(case):
    """The ends of an open-mode centerline: midpoints of the gaps between the banks' ends."""
    return tuple(tuple(0.5 * (case.bank_a[i] + case.bank_b[i])) for i in (0, -1))


def open_region(case):
    """The region between two banks, closed by the straight end gaps."""
    return geometry_cases.channel_case("region", case.bank_a, case.bank_b, case.width).polygon


@pytest.mark.parametrize("case", OPEN[:3], ids=[c.name for c in OPEN[:3]])
def test_open_mode_end_radii_are_half_the_end_gaps(case):
    line_a, line_b = geometry_cases.bank_pair(case)
    result = lines_centerline(line_a, line_b, spacing=0.1 * case.width)
    gaps = [np.hypot(*(case.bank_a[i] - case.bank_b[i])) / 2.0 for i in (0, -1)]
    ends = sorted([result.radii[0], result.radii[-1]])
    assert ends == pytest.approx(sorted(gaps), rel=1e-9)


def test_open_mode_staggered_banks_stay_between_the_ends():
    # Bank b starts a quarter width before bank a: the end gap is slanted. The centerline must still run
    # from one gap midpoint to the other without vertices beyond them.
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=21)
    bank_a = case.bank_a
    bank_b = case.bank_b.copy()
    bank_b[0, 0] -= 2.5
    region = geometry_cases.channel_case("staggered", bank_a, bank_b, 10.0).polygon
    result = lines_centerline(bank_a, bank_b, spacing=0.5)
    ends = (tuple(0.5 * (bank_a[0] + bank_b[0])), tuple(0.5 * (bank_a[-1] + bank_b[-1])))
    check_centerline(result, bank_a, bank_b, region, ends)


@pytest.mark.slow
def test_long_river_beyond_one_chunk_of_samples():
    # About 20,000 samples per chain, more than the engine's internal block of samples, so the invariants
    # are checked across block boundaries too. Every vertex is also checked against the oracle.
    case = geometry_cases.synthetic_river(40_000, seed=5)
    spacing = 1.25 * case.width / 4.0
    result = polygon_centerline(case.polygon, case.split_points, spacing=spacing)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    oracle = MedialOracle(case.chain_a, case.chain_b, region=case.polygon)
    distance = oracle.distance(np.asarray(result.line.coords)[1:-1])
    assert distance.max() <= 1e-7 * case.extent + 4.0 * oracle.error_bound


#: A one-metre ditch in a projected CRS: extent about 1 while the coordinates are about 5e6, so the input's
#: own rounding (half an ulp of 5e6, 5e-10 of the extent) is the floor every check has to live with.
DITCH = geometry_cases.Placement(scale=0.01, angle=0.9, offset=(5.3e6, 4.9e6))
DITCH_CASES = [
    geometry_cases.rectangle(placement=DITCH),
    geometry_cases.tapered_channel(placement=DITCH),
    geometry_cases.annulus_sector(placement=DITCH),
    geometry_cases.wavy_channel(seed=3, placement=DITCH, teeth=0.1),
]


@pytest.mark.parametrize("case", DITCH_CASES, ids=[c.name for c in DITCH_CASES])
def test_small_extent_at_large_coordinates(case):
    result = polygon_centerline(case.polygon, case.split_points, spacing=0.1 * case.width)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    oracle = MedialOracle(case.chain_a, case.chain_b, region=case.polygon)
    distance = oracle.distance(np.asarray(result.line.coords)[1:-1])
    assert distance.max() <= 1e-7 * case.extent + 4.0 * oracle.error_bound
