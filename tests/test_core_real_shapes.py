"""Valid real-world shapes that once failed: inputs the final guard refused, rings, zero-width spikes and thin
boxes at float64's limit, and chains that cross (issue 40, part A).

Every returned line is checked against independent exact distances (``tests/support/oracle.py``): each
interior vertex is as far from both chains as its radius, its circle is empty, the line is simple and inside.
"""

import json
from pathlib import Path

import numpy as np
import pytest
import shapely
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import substring

from incircu_plugin.core import centerline_from_chains, lines_centerline, multipolygon_centerlines, polygon_centerline
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core.api import _polygon_centerline_steps
from incircu_plugin.core.chains import _spikes_note
from incircu_plugin.core.ends import find_ends, find_ends_together
from incircu_plugin.core.errors import (
    CenterlineError,
    ChainError,
    CrossingLinesError,
    InvalidGeometryError,
    Message,
    OptionError,
)
from incircu_plugin.core.polyline import typical_width
from incircu_plugin.core.rings import RING_NOTE
from incircu_plugin.core.widths import incircle_polygons, transects, vertex_chainages
from tests.support.oracle import check_centerline, segment_distances

DATA = Path(__file__).parent / "data"


def refused_inputs():
    """The two valid inputs of an outside campaign that the final guard refused (``tests/data/valid_refused.json``)."""
    return json.loads((DATA / "valid_refused.json").read_text())


def ring_chains(ring, first, second):
    """The two chains of a closed ring between two of its points (counter-clockwise from ``first``)."""
    line = LineString(shapely.get_coordinates(ring))
    s0, s1 = line.project(Point(first)), line.project(Point(second))
    if s1 > s0:
        chain_a = shapely.get_coordinates(substring(line, s0, s1))
        chain_b = np.concatenate(
            [
                shapely.get_coordinates(substring(line, s1, line.length)),
                shapely.get_coordinates(substring(line, 0.0, s0))[1:],
            ]
        )
    else:
        chain_a = np.concatenate(
            [
                shapely.get_coordinates(substring(line, s0, line.length)),
                shapely.get_coordinates(substring(line, 0.0, s1))[1:],
            ]
        )
        chain_b = shapely.get_coordinates(substring(line, s1, s0))
    return chain_a, chain_b[::-1]


@pytest.mark.parametrize("spacing", [True, False], ids=["fixed", "adaptive"])
def test_spiral_bank_lines_give_their_axis(spacing):
    """Two bank lines winding once around a centre: the end of one lies near the start of the other, across the
    start gap. Disks reaching it through that gap are equidistant from both lines but not on the region's
    axis; they once interleaved with the axis and zigzagged the line, which the final guard refused."""
    case = refused_inputs()["spiral_banks"]
    line_a, line_b = np.array(case["line_a"]), np.array(case["line_b"])
    result = lines_centerline(line_a, line_b, spacing=case["spacing"] if spacing else None)
    region = Polygon(np.concatenate([line_a, line_b[::-1]]))
    ends = [0.5 * (line_a[0] + line_b[0]), 0.5 * (line_a[-1] + line_b[-1])]
    check_centerline(result, line_a, line_b, region, ends)


@pytest.mark.parametrize("spacing", [True, False], ids=["fixed", "adaptive"])
def test_a_split_point_on_a_straight_edge_gives_its_stub_in_order(spacing):
    """A split point in the middle of a straight edge: disks tangent to one chain a hair (1e-7 of 70 units) from
    the split point pass within rounding of the other chain's end, so their feet are one point (the stub
    from the split point). They once were not taken as such and were ordered by their feet, not their radius,
    making a loop at the end that the final guard refused."""
    case = refused_inputs()["multipolygon_split_points"]
    geometry = shapely.from_wkt(case["wkt"])
    outcomes = multipolygon_centerlines(
        geometry, case["split_points"], spacing=case["spacing"] if spacing else None, islands="main_channel"
    )
    assert [outcome.error for outcome in outcomes] == [None, None]
    for part, outcome in zip(geometry.geoms, outcomes):
        ring = shapely.geometry.polygon.orient(part, 1.0).exterior
        near = [q for q in case["split_points"] if ring.distance(Point(q)) < 1e-6]
        chain_a, chain_b = ring_chains(ring, *near)
        check_centerline(outcome.result, chain_a, chain_b, part, near)


def atoll():
    """A ring with seven bumps on its outer bank around an off-centre octagonal lagoon."""
    angles = np.linspace(0.0, 2.0 * np.pi, 200)[:-1]
    radius = 20.0 + 2.0 * np.sin(7.0 * angles)
    return Polygon(np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])).difference(
        Point(0.5, 0.0).buffer(15.0, 8)
    )


RINGS = {
    "roundabout": Point(0, 0).buffer(30).exterior.buffer(4),
    "moat": Point(0, 0).buffer(10).difference(Point(0, 0).buffer(5)),
    "off_centre": Point(0, 0).buffer(10).difference(Point(4, 0).buffer(3)),
    "letter_o": affinity.scale(Point(0, 0).buffer(10), 0.7, 1).difference(
        affinity.scale(Point(0, 0).buffer(7), 0.6, 1)
    ),
    "square_frame": box(0, 0, 10, 10).difference(box(2, 2, 8, 8)),
    "atoll": atoll(),
    # Rotated frames from the fuzz campaign (seed 1, inputs 2585 and 2963): the seam at an inner corner.
    "rotated_frame": shapely.from_wkt(
        "POLYGON ((16952.44815050537 42857.643219670186, 45304.12405747688 6693.516445026472, "
        "-16535.769214839544 -41787.2507833341, -44887.445121811055 -5623.124008690388, "
        "16952.44815050537 42857.643219670186), (-14743.155588914336 -26983.713592062686, "
        "30500.586866205478 8486.130070951684, 15159.83452458016 28054.10602839877, "
        "-30083.90793053965 -7415.737634615601, -14743.155588914336 -26983.713592062686))"
    ),
    "rotated_square_frame": shapely.from_wkt(
        "POLYGON ((-5446.610937172375 584.4126894269826, -139.2064887494219 5477.547583216903, "
        "5448.133525893997 -582.835768610477, 140.72907747104375 -5475.9706624003975, "
        "-5446.610937172375 584.4126894269826), (4172.313127812134 -531.0214938575845, "
        "-191.02076350231548 4201.727185135038, -4170.790539090512 532.5984146740901, "
        "192.54335222393732 -4200.150264318532, 4172.313127812134 -531.0214938575845))"
    ),
    "far_from_origin": affinity.translate(Point(0, 0).buffer(10).difference(Point(2, 1).buffer(6)), 5e5, 5e6),
}


@pytest.mark.parametrize("spacing", [None, pytest.param(0.3, marks=pytest.mark.slow)], ids=["adaptive", "fixed"])
@pytest.mark.parametrize("name", sorted(RINGS))
def test_a_ring_gets_its_closed_loop(name, spacing):
    """A polygon around one hole gets the closed medial loop between its exterior ring and the hole: one closed
    line, every vertex (its start and end too) as far from both rings as its radius, its circle empty."""
    polygon = RINGS[name]
    result = polygon_centerline(polygon, spacing=spacing)
    line = result.line
    assert line.is_closed and line.is_simple and result.notes == (RING_NOTE,)
    outer = shapely.get_coordinates(polygon.exterior)
    hole = shapely.get_coordinates(polygon.interiors[0])
    start = np.asarray(line.coords[0])
    check_centerline(result, outer, hole, polygon, [start, start])
    extent = max(np.ptp(outer, axis=0))
    ulp = float(np.spacing(np.abs(outer).max()))
    assert abs(segment_distances([start], outer)[0] - segment_distances([start], hole)[0]) <= 1e-9 * extent + 16 * ulp
    assert result.radii[0] == pytest.approx(segment_distances([start], outer)[0], abs=1e-9 * extent + 16 * ulp)
    # The loop goes once around the hole: it contains the hole and not the exterior ring's area outside it.
    assert Polygon(line.coords).contains(polygon.interiors[0])


def test_rings_traced_together_are_their_loops_alone():
    """A batch of rings (as a layer is traced) gives each its loop alone, to the default tolerance: the seam's
    feet, a rounding off the rings' ends in the batch's frame, are not across the seam."""
    names = sorted(RINGS)
    together = run_many_steps([_polygon_centerline_steps(RINGS[name]) for name in names * 2])
    for name, result in zip(names * 2, together):
        alone = polygon_centerline(RINGS[name])
        polygon = RINGS[name]
        tolerance = typical_width(polygon.area, 0.5 * polygon.length) / 200.0
        assert result.line.is_closed, name
        assert result.line.hausdorff_distance(alone.line) <= tolerance, name


def test_the_loop_measures_its_widths_and_transects():
    """Widths, chainages, incircles and transects work on the loop: the moat is 5 wide all around, up to the
    sagittas of its polygonised circles (64 chords each)."""
    result = polygon_centerline(RINGS["moat"])
    sagittas = (10.0 + 5.0) * (1.0 - np.cos(np.pi / 64))
    assert np.allclose(result.widths, 5.0, atol=sagittas)
    chainages = vertex_chainages(result)
    assert chainages[-1] == pytest.approx(result.line.length)
    assert len(incircle_polygons(result)) == len(result.radii)
    cuts = transects(result, 5.0)
    assert len(cuts) >= 8
    assert all(cut.width == pytest.approx(5.0, abs=sagittas) for cut in cuts)


def test_a_ring_with_split_points_gives_the_line_between_them():
    """Split points on the exterior ring: the line between them, around the island, as for any polygon."""
    moat = RINGS["moat"]
    result = polygon_centerline(moat, [(-10, 0), (10, 0)])
    assert not result.line.is_closed and result.line.is_simple
    assert result.notes == ()


def test_a_ring_with_one_split_point_gets_its_loop_and_says_the_point_is_not_used():
    result = polygon_centerline(RINGS["moat"], [(-10, 0)])
    assert result.line.is_closed and result.line.is_simple
    assert [note.code for note in result.notes] == ["note_ring_point_unused"]


def test_a_river_with_an_island_keeps_its_ends():
    """One island in a long river: the trunk runs past it, longer than the island's perimeter, so no loop."""
    river = box(0, 0, 100, 10).difference(box(40, 3, 50, 7))
    result = polygon_centerline(river)
    assert not result.line.is_closed
    assert {round(result.line.coords[0][0]), round(result.line.coords[-1][0])} == {0, 100}


def test_a_hole_touching_the_exterior_ring_is_no_loop():
    """A hole touching the exterior ring at a point leaves no loop: the automatic ends are used, no crash."""
    polygon = Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [[(5, 0), (7, 3), (3, 3)]])
    assert polygon.is_valid
    result = polygon_centerline(polygon)
    assert not result.line.is_closed and RING_NOTE not in result.notes


def spiked(ring, after, inserted):
    """``ring`` (closed coordinates) with the vertices ``inserted`` after its vertex ``after`` (not closed)."""
    ring = [tuple(xy) for xy in ring[:-1]]
    return ring[: after + 1] + list(inserted) + ring[after + 1 :]


PARCEL = [(0.0, 0.0), (90.0, 0.0), (90.0, 12.0), (0.0, 12.0), (0.0, 0.0)]

#: Spikes on a 90 x 12 parcel: (the vertex they follow, (base, tip, back)); each comes back a hair (1e-12 to
#: 1e-9 units) beside where it left, a turn sine below 1e-9 at the tip, so GEOS finds the polygon valid.
SPIKES = {
    "2.7 cm out of the east side": (1, [(90.0, 6.0), (90.027, 6.0 + 1e-12), (90.0, 6.0 + 2e-12)]),
    "10.9 m out of the east side": (1, [(90.0, 6.0), (100.9, 6.0 + 1e-9), (90.0, 6.0 + 2e-9)]),
    "10.9 m into the parcel": (2, [(50.0, 12.0), (50.0 - 1e-10, 1.1), (50.0 - 1e-9, 12.0)]),
    "at a corner": (0, [(95.0, -1e-9), (90.0 - 1e-7, 0.0)]),
}


@pytest.mark.parametrize("spacing", [None, 0.5], ids=["adaptive", "fixed"])
@pytest.mark.parametrize("name", sorted(SPIKES))
def test_a_zero_width_spike_is_removed_with_a_note(name, spacing):
    """A valid polygon with a spike going out and back along itself: the spike's tip goes (a note names
    where), no other vertex moves, and the line is that of the polygon without the tip, exact."""
    after, inserted = SPIKES[name]
    tip = inserted[-2]
    ring = spiked(np.array(PARCEL), after, inserted)
    polygon = Polygon(ring)
    assert polygon.is_valid
    ends = [(0.0, 6.0), (90.0, 3.0)]
    result = polygon_centerline(polygon, ends, spacing=spacing)
    assert len(result.notes) == 1 and result.notes[0].startswith("A zero-width spike was removed from the exterior")
    assert f"({tip[0]:.6g}, " in result.notes[0]
    # Without the tip, nor the vertex the spike comes back to when it is within 1e-9 of the extent of where it
    # left (a repeated vertex, which the cleaning drops as well).
    back, base = inserted[-1], inserted[0]
    repeated = back if np.hypot(back[0] - base[0], back[1] - base[1]) <= 1e-9 * 90.0 else None
    without = Polygon([xy for xy in ring if xy not in (tip, repeated)])
    expected = polygon_centerline(without, ends, spacing=spacing)
    assert np.array_equal(np.asarray(result.line.coords), np.asarray(expected.line.coords))
    chain_a, chain_b = ring_chains(without.exterior, *ends)
    check_centerline(result, chain_a, chain_b, without, ends)


def test_spikes_on_an_island_and_with_automatic_ends():
    """Spikes on an island's ring and on the exterior ring of a long river, automatic ends: both named."""
    river = np.array([(0.0, 0.0), (200.0, 0.0), (200.0, 10.0), (0.0, 10.0), (0.0, 0.0)])
    island = [(90.0, 4.0), (110.0, 4.0), (110.0, 6.0), (90.0, 6.0)]
    island = island[:2] + [(110.0, 5.0), (115.0, 5.0 + 1e-10), (110.0, 5.0 + 2e-10)] + island[2:]
    polygon = Polygon(spiked(river, 2, [(150.0, 10.0), (150.0 + 1e-9, 6.0), (150.0 - 1e-9, 10.0)]), [island])
    assert polygon.is_valid
    result = polygon_centerline(polygon)
    assert result.notes[0].startswith("2 zero-width spikes were removed from the exterior ring at (150, 6)")
    assert "island 1 at (115, 5)" in result.notes[0]
    # A Message whose places are Messages too, so the plugin words every part in the user's language.
    note = result.notes[0]
    assert note.code == "note_spikes" and note.values["places"].code == "places_two"
    places = note.values["places"].values
    assert {places["first"].code, places["second"].code} == {"spike_exterior", "spike_island"}
    assert result.line.is_simple and {round(result.line.coords[0][0]), round(result.line.coords[-1][0])} == {0, 200}


@pytest.mark.parametrize("where", ["middle", "end", "start"])
def test_a_bank_line_doubling_back_loses_its_fold(where):
    """A bank line with a zero-width spike, or whose end segment comes back over the one before: the fold goes
    (the line keeps its reach), with a note; the centerline is that of the clean lines."""
    clean = [(0.0, 0.0), (50.0, 0.0), (100.0, 0.0)]
    line = {
        "middle": [(0.0, 0.0), (50.0, 0.0), (60.0, 1e-12), (50.0, 2e-12), (100.0, 0.0)],
        "end": clean + [(90.0, 1e-9)],
        "start": [(10.0, 1e-9)] + clean,
    }[where]
    other = [(0.0, 8.0), (100.0, 8.0)]
    result = lines_centerline(line, other)
    assert len(result.notes) == 1 and "zero-width spike was removed from the first line" in result.notes[0]
    expected = lines_centerline(clean, other)
    assert np.array_equal(np.asarray(result.line.coords), np.asarray(expected.line.coords))


def test_a_thin_box_gets_the_finest_tolerance_float64_allows_with_a_note():
    """A box 3.2e-8 wide and 2 long: its automatic tolerance (width / 200) is finer than float64 can place
    vertices (1e-9 of the extent); the finest possible is used, a note says so, and the line is on the axis."""
    height = 3.2e-8
    result = polygon_centerline(box(0, 0, 2, height))
    assert len(result.notes) == 1 and "finer than float64 can place vertices" in result.notes[0]
    coords = np.asarray(result.line.coords)
    assert np.allclose(coords[:, 1], height / 2, rtol=0, atol=1e-9 * 2)
    assert {round(coords[0, 0], 6), round(coords[-1, 0], 6)} == {0.0, 2.0}


@pytest.mark.parametrize("length", [2.0, pytest.param(1e6, marks=pytest.mark.slow)])
@pytest.mark.parametrize("relative", np.geomspace(1e-6, 1e-16, 21).tolist())
@pytest.mark.parametrize(
    "options", [{}, {"tolerance": 1e-8}, {"spacing": 0.05}], ids=["automatic", "tolerance", "fixed"]
)
@pytest.mark.parametrize("given", [True, False], ids=["split_points", "automatic_ends"])
def test_thin_boxes_down_to_float64_give_their_line_or_name_their_width(length, relative, options, given):
    """Boxes ``relative`` of their length wide, down to float64's resolution: either the line along the middle
    from end to end, or a typed error naming the shape's width (never another error, never a wrong line)."""
    height = relative * length
    options = {name: value * length for name, value in options.items()}
    ends = [(0.0, height / 2), (length, height / 2)] if given else None
    try:
        result = polygon_centerline(box(0, 0, length, height), ends, **options)
    except (InvalidGeometryError, ChainError) as error:
        assert " wide " in str(error) and "float64" in str(error)
        return
    coords = np.asarray(result.line.coords)
    assert result.line.is_simple
    assert np.allclose(coords[:, 1], height / 2, rtol=0, atol=height / 2 + 1e-15 * length)
    assert sorted([coords[0, 0], coords[-1, 0]]) == pytest.approx([0.0, length], abs=1e-9 * length)


def test_a_tolerance_the_user_set_too_fine_is_named_and_its_advice_works():
    """A tolerance below float64's limit names the option the user set; the value it advises works."""
    polygon = box(0, 0, 2.0000000001, 1e-3)
    with pytest.raises(OptionError, match=r"The tolerance 1e-12 \(CRS units\) you set") as caught:
        polygon_centerline(polygon, tolerance=1e-12)
    advised = float(str(caught.value).split("Use at least ")[1].split()[0])
    assert polygon_centerline(polygon, tolerance=advised).line.is_simple


def test_identical_chains_are_refused_as_crossing():
    chain = np.array([(0.0, 0.0), (5.0, 1.0), (10.0, 0.0)])
    for spacing in (None, 0.2):
        with pytest.raises(CrossingLinesError, match=r"cross or touch at \(0, 0\)|cross or touch at \(5, 1\)"):
            centerline_from_chains(chain, chain.copy(), spacing)


def test_chains_sharing_one_end_give_a_simple_line():
    result = centerline_from_chains(np.array([(0.0, 0.0), (10.0, 0.0)]), np.array([(0.0, 0.0), (10.0, 3.0)]))
    assert result.line.is_simple
    assert result.line.coords[0] == (0.0, 0.0) and result.line.coords[-1] == (10.0, 1.5)


def test_a_chain_crossing_itself_is_named():
    walk = np.array([(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.0, -1.0)])
    with pytest.raises(ChainError, match=r"The first chain crosses itself at \(2\.6666666(67)?, 0\)"):
        centerline_from_chains(walk, np.array([(0.0, 5.0), (4.0, 5.0)]))


@pytest.mark.parametrize("seed", range(40))
def test_random_walk_chains_give_a_simple_line_or_a_typed_error(seed):
    """Random walks (an outside campaign's 17 self-crossing lines came from such inputs): a simple line, or
    the typed error of what is wrong (a walk crossing itself or the other, or the last guard)."""
    rng = np.random.default_rng(seed)
    chains = [np.cumsum(rng.normal(size=(8, 2)), axis=0) + [offset, 0.0] for offset in (0.0, 1.0)]
    for spacing in (None, 0.2):
        try:
            result = centerline_from_chains(*chains, spacing)
        except (ChainError, CrossingLinesError, CenterlineError):
            continue
        assert result.line.is_simple


def test_find_ends_of_a_ring_without_a_trunk_line_does_not_crash():
    """A smooth ring's skeleton is a cycle without leaves: a one-point trunk, which once crashed GEOS (a line of
    one point) for the whole batch. Its ends are arbitrary (not elongated) and it has no trunk line; the other
    polygons of the batch get theirs."""
    moat = RINGS["moat"]
    alone = find_ends(moat)
    assert alone.trunk is None and not alone.elongated
    river, ring, other = find_ends_together([box(0, 0, 100, 10), moat, box(0, 20, 50, 25)])
    assert ring.trunk is None
    assert river.trunk.length == pytest.approx(100.0, rel=0.05) and other.trunk.length == pytest.approx(50.0, rel=0.05)


def test_a_spikes_note_names_three_places_and_counts_the_rest():
    """Past three spikes the note names the first three and how many more were removed."""
    places = [Message("spike_first_line", point=f"({x}, 0)", length=0.5) for x in range(5)]
    note = _spikes_note(places)
    assert note == (
        "5 zero-width spikes were removed from the first line at (0, 0) (0.5 CRS units long); the first line at "
        "(1, 0) (0.5 CRS units long); the first line at (2, 0) (0.5 CRS units long); and 2 more before the "
        "centerline was computed."
    )
    assert _spikes_note(places[:1]) == (
        "A zero-width spike was removed from the first line at (0, 0) (0.5 CRS units long) before the centerline "
        "was computed."
    )
