"""Benchmark inputs: analytic shapes with a known axis (from ``tests/support/geometry_cases.py``) and real outlines.

The analytic shapes are the core tests' own builders (imported, never copied). The reference axis of
every input is the medial-axis target set of the segment-Voronoi oracle ``tests/support/oracle.py``
(Boost.Polygon through pyvoronoi, no code shared with the engine) between the two chains; for analytic
shapes the distance to the smooth analytic axis is measured as well. Real outlines come from
:mod:`outlines`, cut into two chains at the automatically found ends.
"""

import shapely
from outlines import COUNTRIES, country_polygon
from peers import Case, mean_width  # peers puts the repository root on sys.path

from tests.support import geometry_cases, oracle

#: The constant-width meander of issue 2's speed target: 2 km long, 20 wide, 2,333 boundary vertices.
MEANDER_VERTICES = 2333


def from_geometry_case(analytic, name=None, with_oracle=True):
    """Wrap one :class:`geometry_cases.Case` as a benchmark :class:`~peers.Case`.

    The reference axis is the polygon's own medial axis between the two chains (the oracle's target set),
    which is what "on the axis" means for a polygon; the smooth shape's analytic axis, which differs from
    it by the polygonisation (``axis_tolerance``) and near curved ends (where the target set follows the
    split point's Voronoi cell), is kept as ``extra["analytic_distance"]`` for a second deviation column.
    """
    case = Case(
        name=name or analytic.name,
        polygon=analytic.polygon,
        ends=tuple(shapely.Point(point) for point in analytic.split_points),
        width=float(analytic.width),
        extra={"analytic_distance": analytic.axis_distance},
    )
    if with_oracle:
        medial = oracle.MedialOracle(analytic.chain_a, analytic.chain_b, region=analytic.polygon)
        case.axis_distance, case.axis_kind = medial.distance, "oracle"
    return case


def analytic_cases():
    """Rectangle, tapered channel, annulus sector and the issue's meander; two sizes of rectangle and sector.

    Larger inputs are covered by the scaling run; a tapered channel with 1,000 (nearly collinear) bank
    vertices is left out because SFCGAL's straight skeleton spends minutes on it, beyond the time budget.
    """
    builders = [
        ("rectangle 100×10", geometry_cases.rectangle(n=11)),
        ("rectangle 100×10, 1k v", geometry_cases.rectangle(n=500)),
        ("tapered 20→5", geometry_cases.tapered_channel(n=11)),
        ("annulus sector", geometry_cases.annulus_sector(n=61)),
        ("annulus sector, 1k v", geometry_cases.annulus_sector(n=500)),
        ("meander 2 km×20, 2,333 v", geometry_cases.meander_with_vertex_count(MEANDER_VERTICES)),
    ]
    return [from_geometry_case(analytic, name) for name, analytic in builders]


def meander_case():
    """The issue's meander (2 km long, width 20, 2,333 boundary vertices)."""
    return from_geometry_case(geometry_cases.meander_with_vertex_count(MEANDER_VERTICES), "meander 2 km×20, 2,333 v")


def river_case(boundary_vertices):
    """A long synthetic river (vertex every quarter width) with ``boundary_vertices`` bank vertices."""
    river = geometry_cases.synthetic_river(boundary_vertices)
    return from_geometry_case(river, f"river {boundary_vertices:,} v", with_oracle=False)


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


def _fine_incircu_reference(polygon, ends, width):
    """Distance to IncirCu's line within width/2000 of the exact axis (adaptive sampling, every vertex on the
    axis): the reference where the oracle cannot run."""
    from metrics import NearestDistance

    from incircu_plugin.core import polygon_centerline

    return NearestDistance(polygon_centerline(polygon, ends, tolerance=width / 2000.0).line)


def river_cases(count, seed, with_reference=True):
    """The layer of :mod:`rivers` as benchmark cases, split at the caps' midpoints.

    The reference axis is the oracle's target set between the two chains (islands spliced in as IncirCu
    does); where the oracle rejects the chains (the slits of zero width to islands touch), it is IncirCu's
    own line within width/2000 of the exact axis (``axis_kind`` ``"IncirCu w/2000"``).
    """
    from rivers import river_layer

    from incircu_plugin.core import split_polygon
    from incircu_plugin.core.islands import bridge_islands

    cases = []
    for river in river_layer(count, seed):
        case = Case(name=f"river {river.index}", polygon=river.polygon, ends=river.ends, width=river.width)
        if with_reference:
            chain_a, chain_b = split_polygon(river.polygon, river.ends)
            holes = [shapely.get_coordinates(ring) for ring in river.polygon.interiors]
            if holes:
                chain_a, chain_b = bridge_islands(chain_a, chain_b, holes)
            try:
                case.axis_distance = oracle.MedialOracle(chain_a, chain_b, region=river.polygon).distance
                case.axis_kind = "oracle"
            except ValueError:
                case.axis_distance = _fine_incircu_reference(river.polygon, river.ends, river.width)
                case.axis_kind = "IncirCu w/2000"
        cases.append(case)
    return cases
