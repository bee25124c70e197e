"""Benchmark inputs: analytic shapes with a known axis (from ``tests/geometry_cases.py``) and real outlines.

The analytic shapes are the core tests' own builders (imported, never copied), so the benchmark and the
tests agree on what the exact axis is. Real outlines come from :mod:`outlines`; their reference axis is
the medial-axis target set of the segment-Voronoi oracle ``tests/oracle.py`` (Boost.Polygon through
pyvoronoi, no code shared with the engine), between the two chains cut at the automatically found ends.
"""

import sys

import shapely

from outlines import COUNTRIES, country_polygon
from peers import REPO_ROOT, Case, mean_width

TESTS_DIR = REPO_ROOT / "tests"
if str(TESTS_DIR) not in sys.path:
    sys.path.insert(0, str(TESTS_DIR))

import geometry_cases  # noqa: E402  (tests/ is put on the path just above)
import oracle  # noqa: E402

#: The constant-width meander of issue 2's speed target: 2 km long, 20 wide, 2,333 boundary vertices.
MEANDER_VERTICES = 2333


def from_geometry_case(analytic, name=None):
    """Wrap one :class:`geometry_cases.Case` as a benchmark :class:`~peers.Case` (exact axis)."""
    return Case(
        name=name or analytic.name,
        polygon=analytic.polygon,
        ends=tuple(shapely.Point(point) for point in analytic.split_points),
        width=float(analytic.width),
        axis_distance=analytic.axis_distance,
        axis_kind="exact" if analytic.axis_distance is not None else "none",
        extra={"axis_line": analytic.axis_line},
    )


def analytic_cases():
    """Rectangle, tapered channel, annulus sector and meander, each small and large (boundary vertices)."""
    builders = [
        ("rectangle 100×10", geometry_cases.rectangle(n=11)),
        ("rectangle 100×10, 1k v", geometry_cases.rectangle(n=500)),
        ("tapered 20→5", geometry_cases.tapered_channel(n=11)),
        ("tapered 20→5, 1k v", geometry_cases.tapered_channel(n=500)),
        ("annulus sector", geometry_cases.annulus_sector(n=61)),
        ("annulus sector, 1k v", geometry_cases.annulus_sector(n=500)),
        ("meander 2 km×20, 2,333 v", geometry_cases.meander_with_vertex_count(MEANDER_VERTICES)),
        ("meander 2 km×20, 10k v", geometry_cases.meander_with_vertex_count(10_000)),
    ]
    return [from_geometry_case(analytic, name) for name, analytic in builders]


def meander_case():
    """The issue's meander (2 km long, width 20, 2,333 boundary vertices)."""
    return from_geometry_case(geometry_cases.meander_with_vertex_count(MEANDER_VERTICES),
                              "meander 2 km×20, 2,333 v")


def river_case(boundary_vertices):
    """A long synthetic river (vertex every quarter width) with ``boundary_vertices`` bank vertices."""
    river = geometry_cases.synthetic_river(boundary_vertices)
    return from_geometry_case(river, f"river {boundary_vertices:,} v")


def outline_cases(with_oracle=True):
    """Natural Earth countries, projected to metres, split at the core's automatically found ends."""
    from incircu_plugin.core import find_ends, split_polygon

    cases = []
    for country in COUNTRIES:
        polygon = country_polygon(country)
        found = find_ends(polygon)
        ends = (found.start, found.end)
        case = Case(name=country, polygon=polygon, ends=ends, width=mean_width(polygon))
        if with_oracle:
            chain_a, chain_b = split_polygon(polygon, ends)
            medial = oracle.MedialOracle(chain_a, chain_b, region=polygon)
            case.axis_distance, case.axis_kind = medial.distance, "oracle"
            case.extra["target_length"] = medial.length
        cases.append(case)
    return cases
