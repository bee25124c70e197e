"""A fixed-seed sample of the fuzz campaign (``fuzz/``): no untyped exception, hang, invalid result, crash or
batch that differs.

About 2,000 small generated inputs (valid channels with islands and several parts, bank lines, compact shapes
with automatic ends, thin boxes, and hostile input), in batches of ``SAMPLE_BATCH`` in one of two worker
processes with a 10 s limit per input: each input alone, then every batch traced together as a layer is, each
outcome in the batch compared with the one alone. The runner runs in its own interpreter (no QGIS in the
workers). ``make fuzz N=100000`` runs the full campaign.
"""

import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest
from shapely.geometry import LineString, Polygon, box

from fuzz.checks import ends_in_concave_corner, together_problems
from fuzz.inputs import Case
from incircu_plugin.core import CenterlineError, SplitPointError, polygon_centerline
from tests.support.project import REPOSITORY

SAMPLE_SIZE = 2000
SAMPLE_SEED = 20261201
SAMPLE_BATCH = 8


@pytest.mark.slow
def test_fixed_sample_has_no_untyped_error_hang_or_invalid_result():
    done = subprocess.run(
        [
            *(sys.executable, "-m", "fuzz", "--small", "--count", str(SAMPLE_SIZE), "--seed", str(SAMPLE_SEED)),
            *("--together", str(SAMPLE_BATCH)),
        ],
        cwd=REPOSITORY,
        capture_output=True,
        text=True,
        timeout=1200,
        check=False,
    )
    print(done.stdout)
    assert done.returncode == 0, done.stdout + done.stderr
    assert f"**{SAMPLE_SIZE}**" in done.stdout


# The batch comparison itself (fuzz.checks.together_problems), on a 100 x 10 rectangle: a feature's outcome in a
# batch must be the same bytes as alone.

RECTANGLE = box(0.0, 0.0, 100.0, 10.0)
ENDS = np.array([[0.0, 5.0], [100.0, 5.0]])
CASE = Case("valid split points", "polygon_centerline", (RECTANGLE, ENDS), {}, RECTANGLE, ENDS)


def shifted(result, offset):
    """The result with every vertex but the two ends, and their feet, moved ``offset`` along the channel's
    width (each foot stays on its vertex's disk)."""
    moved = [np.array(values) for values in (result.line.coords, result.foot_a, result.foot_b)]
    for values in moved:
        values[1:-1, 1] += offset
    return replace(result, line=LineString(moved[0]), foot_a=moved[1], foot_b=moved[2])


def test_the_same_outcome_together_and_alone_is_no_problem():
    alone = polygon_centerline(RECTANGLE, ENDS)
    assert together_problems(CASE, polygon_centerline(RECTANGLE, ENDS), alone) == []
    error = SplitPointError("no")
    assert together_problems(CASE, SplitPointError("no"), error) == []


@pytest.mark.parametrize(
    ("together", "expected"),
    [
        (lambda alone: SplitPointError("no"), "together SplitPointError"),
        (lambda alone: shifted(alone, 1e-12), "line differ"),
        (lambda alone: replace(alone, radii=np.nextafter(alone.radii, np.inf)), "radii and feet differ"),
        (lambda alone: replace(alone, notes=("a note",)), "notes and ends differ"),
    ],
    ids=["an error instead of a line", "a line a hair off", "radii a bit off", "another note"],
)
def test_an_outcome_that_differs_together_is_a_problem(together, expected):
    alone = polygon_centerline(RECTANGLE, ENDS)
    assert expected in "; ".join(together_problems(CASE, together(alone), alone))


@pytest.mark.parametrize(
    ("end", "concave"),
    [((10.0, 10.0), True), ((20.0, 0.0), False), ((12.0, 10.0), False), ((14.0, 4.0), True), ((15.0, 4.0), False)],
    ids=["the L's inner corner", "an outer corner", "mid-edge", "a hole's corner", "mid-side of a hole"],
)
def test_a_line_ending_in_a_concave_corner_is_recognised(end, concave):
    # An L (inner corner at (10, 10)) with a square hole: the hole's corners are concave for the region.
    hole = [(14.0, 2.0), (16.0, 2.0), (16.0, 4.0), (14.0, 4.0)]
    region = Polygon([(0, 0), (20, 0), (20, 10), (10, 10), (10, 20), (0, 20)], [hole])
    line = LineString([(2.0, 2.0), end])
    assert ends_in_concave_corner(region, line, 1e-9) is concave
    assert ends_in_concave_corner(region, LineString([end, (2.0, 2.0)]), 1e-9) is concave


def test_errors_that_differ_only_in_their_numbers_together_are_a_problem():
    # Where a line leaves its polygon is computed in the feature's own frame, whatever its batch: same numbers.
    alone = CenterlineError("The computed centerline leaves the polygon at (-105839.7246, 21492.98771)")
    together = CenterlineError("The computed centerline leaves the polygon at (-105901.4311, 21429.91438)")
    assert together_problems(CASE, together, alone)
