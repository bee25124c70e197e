"""pytest parameters shared by the tests: which geometry cases are ``slow`` (left out of ``make test-core``)."""

import pytest

from . import geometry_cases

#: Cases with more boundary vertices than this take a second or more of oracle work each.
LARGE_CASE = 300


def is_slow_case(case, other_placements=False):
    """Whether ``case`` is large, or (with ``other_placements``) placed elsewhere than in the unit frame: the
    same check of a shape again, in another frame."""
    moved = other_placements and case.placement != geometry_cases.PLACEMENTS["unit"]
    return case.vertex_count > LARGE_CASE or moved


def case_params(cases, other_placements=False):
    """The cases as pytest parameters named after them, those :func:`is_slow_case` marked ``slow``."""
    return [
        pytest.param(case, id=case.name, marks=[pytest.mark.slow] if is_slow_case(case, other_placements) else [])
        for case in cases
    ]
