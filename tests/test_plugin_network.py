"""``incircu:polygonnetwork`` through ``processing.run`` on memory layers built from the analytic network shapes.

Expected values come from the shapes (``tests/support/network_cases.py``): the T junction's centre and width
in closed form, the k = 2 case from ``incircu:polygoncenterline`` on the same input.
"""

import math

import numpy as np
import processing
import pytest
import shapely
import shapely.affinity
from qgis.core import (
    QgsFeature,
    QgsGeometry,
    QgsLineString,
    QgsPoint,
    QgsPolygon,
    QgsProcessingFeedback,
    QgsVectorLayer,
    QgsWkbTypes,
)
from shapely.geometry import Point, Polygon, box

from tests.support import network_cases as cases


class RecordingFeedback(QgsProcessingFeedback):
    """Feedback that keeps the warnings an algorithm pushes."""

    def __init__(self):
        super().__init__()
        self.warnings = []

    def pushWarning(self, message):
        self.warnings.append(message)

    def reportError(self, message, fatalError=False):
        self.warnings.append(message)


def memory_layer(kind, crs, rows, fields="name:string"):
    """A memory layer of shapely geometries with one ``name`` attribute each (``rows``: (geometry, name))."""
    layer = QgsVectorLayer(f"{kind}?crs={crs}&field={fields}", kind, "memory")
    features = []
    for geometry, name in rows:
        feature = QgsFeature(layer.fields())
        feature.setGeometry(QgsGeometry.fromWkt(geometry.wkt))
        feature.setAttributes([name])
        features.append(feature)
    assert layer.dataProvider().addFeatures(features)
    return layer


def split_layer(points, crs="EPSG:2180", names=None):
    """A point layer of split points named ``names`` (default A, B, C, ...)."""
    names = names or [chr(ord("A") + i) for i in range(len(points))]
    return memory_layer("Point", crs, [(Point(p), name) for p, name in zip(points, names)])


def run(parameters, algorithm="polygonnetwork"):
    """Run an algorithm with a memory output; return (results, feedback)."""
    feedback = RecordingFeedback()
    results = processing.run("incircu:" + algorithm, {"OUTPUT": "memory:", **parameters}, feedback=feedback)
    return results, feedback


def as_shapely(geometry):
    """2-D Shapely copy of a QGIS geometry."""
    flat = QgsGeometry(geometry)
    flat.get().dropMValue()
    return shapely.from_wkb(bytes(flat.asWkb()))


def test_t_junction_branches_carry_their_ends_chains_and_widths(provider):
    polygon, caps, (junction,), radius = cases.t_junction()
    results, feedback = run(
        {
            "INPUT": memory_layer("Polygon", "EPSG:2180", [(polygon, "T")]),
            "SPLIT_POINTS": split_layer(caps, names=["west", "east", "north"]),
            "SPLIT_ID_FIELD": "name",
            "SPACING": 0.25,
        }
    )
    output = results["OUTPUT"]
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    assert results["CENTERLINE_COUNT"] == 3
    assert QgsWkbTypes.hasM(output.wkbType())
    branches = {feature["from_point"]: feature for feature in output.getFeatures()}
    assert set(branches) == {"west", "east", "north"}
    extent = 100.0
    for name, cap in zip(("west", "east", "north"), caps):
        branch = branches[name]
        assert branch["name"] == "T" and branch["to_point"] == "junction"
        line = as_shapely(branch.geometry())
        assert np.hypot(*(np.asarray(line.coords[0]) - cap)) <= 1e-9 * extent
        assert np.hypot(*(np.asarray(line.coords[-1]) - junction)) <= 1e-9 * extent
        m = [vertex.m() for vertex in branch.geometry().vertices()]
        assert m[0] == 0.0 and m[-1] == pytest.approx(2.0 * radius, abs=1e-9 * extent)
        # The attributes are rounded to the millimetre (the layer is in metres).
        assert branch["length"] == pytest.approx(line.length, abs=0.0005 + 1e-9 * extent)
        assert branch["width_max"] == pytest.approx(2.0 * radius, abs=0.0005 + 1e-9 * extent)
        assert branch["n_vertices"] == len(line.coords)
    # Walking from the west end to the junction, the straight road's bottom is on the right: the chain from
    # the west split point counter-clockwise to the east one.
    assert (branches["west"]["right_chain"], branches["west"]["left_chain"]) == ("west-east", "north-west")
    assert (branches["north"]["right_chain"], branches["north"]["left_chain"]) == ("north-west", "east-north")


def test_two_split_points_give_the_polygon_centerline(provider):
    polygon, caps = cases.reservoir()
    inputs = {
        "INPUT": memory_layer("Polygon", "EPSG:2180", [(polygon, "reservoir")]),
        "SPLIT_POINTS": split_layer(caps[:2]),
    }
    network, _ = run(inputs)
    centerline, _ = run(inputs, "polygoncenterline")
    (branch,) = network["OUTPUT"].getFeatures()
    (line,) = centerline["OUTPUT"].getFeatures()
    assert as_shapely(branch.geometry()).equals_exact(as_shapely(line.geometry()), 0.0)
    for field in ("length", "width_min", "width_mean", "width_max", "n_vertices"):
        assert branch[field] == line[field]


def test_a_part_with_one_split_point_gets_its_other_end_and_islands_are_avoided(provider):
    y_polygon, y_caps, _, _ = cases.symmetric_y(half_width=8.0)
    island = box(-2.0, 30.0, 4.0, 45.0)
    with_island = Polygon(y_polygon.exterior.coords, [island.exterior.coords])
    lonely = box(500.0, 0.0, 600.0, 10.0)
    results, feedback = run(
        {
            "INPUT": memory_layer("Polygon", "EPSG:2180", [(with_island, "Y"), (lonely, "one point")]),
            "SPLIT_POINTS": split_layer([*y_caps, (500.0, 5.0)]),
        }
    )
    assert results["CENTERLINE_COUNT"] == 4 and results["SKIPPED_COUNT"] == 0, feedback.warnings
    features = list(results["OUTPUT"].getFeatures())
    assert {feature["from_point"] for feature in features} | {feature["to_point"] for feature in features} == {
        "1",
        "2",
        "3",
        "4",
        "auto",
        "junction",
    }
    (lonely_line,) = [feature for feature in features if feature["name"] == "one point"]
    line = as_shapely(lonely_line.geometry())
    assert line.coords[0] == (500.0, 5.0) and np.allclose(line.coords[-1], (600.0, 5.0), atol=1e-9)
    assert lonely_line["kind"] == "arm" and lonely_line["right_chain"].startswith("4-auto:")
    for feature in features:
        assert not as_shapely(feature.geometry()).intersects(island)


def test_automatic_network_carries_its_topology_and_nodes(provider):
    polygon, caps, _, radius = cases.symmetric_y()
    results, feedback = run(
        {"INPUT": memory_layer("Polygon", "EPSG:2180", [(polygon, "Y")]), "OUTPUT_NODES": "memory:"}
    )
    assert results["CENTERLINE_COUNT"] == 3 and results["SKIPPED_COUNT"] == 0, feedback.warnings
    branches = list(results["OUTPUT"].getFeatures())
    nodes = {feature["node"]: feature for feature in results["OUTPUT_NODES"].getFeatures()}
    assert len(nodes) == 4
    (junction,) = [node for node in nodes.values() if node["kind"] == "junction"]
    # The radius is written to the millimetre (3 decimals of metres, units.length_decimals).
    assert junction["degree"] == 3 and junction["radius"] == pytest.approx(radius, abs=5e-4)
    assert junction.geometry().asPoint().distance(0.0, 0.0) <= 1e-9 * 120.0
    for branch in branches:
        assert branch["kind"] == "arm" and branch["from_point"] == "auto" and branch["to_point"] == "junction"
        assert branch["to_node"] == junction["node"]
        line = as_shapely(branch.geometry())
        start = nodes[branch["from_node"]]
        assert start["kind"] == "end" and start["degree"] == 1 and start["radius"] == 0.0
        assert (
            Point(line.coords[0]).distance(Point(start.geometry().asPoint().x(), start.geometry().asPoint().y())) == 0.0
        )
        assert min(Point(line.coords[0]).distance(Point(cap)) for cap in caps) <= 1e-9 * 120.0


def test_geographic_layer_is_computed_in_metres(provider):
    polygon, caps, _, radius = cases.symmetric_y()
    # At the equator a degree of longitude is 111,320 m and a degree of latitude 110,574 m (WGS 84): a Y
    # 120 m across around (10 E, 0 N), in degrees; lengths then agree to the ellipsoid's variation, << 0.5 %.
    east, north = 1.0 / 111_320.0, 1.0 / 110_574.0
    in_degrees = shapely.affinity.translate(shapely.affinity.scale(polygon, east, north, origin=(0, 0)), 10.0, 0.0)
    points = [(10.0 + x * east, y * north) for x, y in caps]
    results, feedback = run(
        {
            "INPUT": memory_layer("Polygon", "EPSG:4326", [(in_degrees, "Y")]),
            "SPLIT_POINTS": split_layer(points, crs="EPSG:4326"),
            "SNAP_TOLERANCE": 0.01,
        }
    )
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    for feature in results["OUTPUT"].getFeatures():
        assert feature["length"] == pytest.approx(60.0, rel=5e-3)
        assert feature["width_max"] == pytest.approx(2.0 * radius, rel=5e-3)


def test_branches_of_geopackage_features_get_their_own_fid(provider, tmp_path):
    # A GeoPackage's fid is unique: the branches of the first polygon must not take the fid of the second.
    polygon, caps, _, _ = cases.t_junction()
    offset = 200.0
    shifted = shapely.affinity.translate(polygon, xoff=offset)
    written = processing.run(
        "native:reprojectlayer",
        {
            "INPUT": memory_layer("Polygon", "EPSG:2180", [(polygon, "T1"), (shifted, "T2")]),
            "TARGET_CRS": "EPSG:2180",
            "OUTPUT": str(tmp_path / "in.gpkg"),
        },
    )["OUTPUT"]
    target = tmp_path / "network.gpkg"
    points = [*caps, *((x + offset, y) for x, y in caps)]
    results, feedback = run({"INPUT": written, "SPLIT_POINTS": split_layer(points), "OUTPUT": str(target)})
    assert results["CENTERLINE_COUNT"] == 6, feedback.warnings
    names = {feature.id(): feature["name"] for feature in QgsVectorLayer(written, "in", "ogr").getFeatures()}
    branches = list(QgsVectorLayer(str(target), "network", "ogr").getFeatures())
    assert sorted(branch["name"] for branch in branches) == ["T1"] * 3 + ["T2"] * 3
    assert len({branch.id() for branch in branches}) == len(branches)
    for branch in branches:
        assert names[branch["source_fid"]] == branch["name"]


#: Valid shapes that once crashed or were refused (issue 40): a ring around one island, and a parcel with a
#: zero-width spike (out 2.7 cm and back along itself, a hair beside where it left).
MOAT = Point(0, 0).buffer(10).difference(Point(0, 0).buffer(5))
SPIKY = Polygon([(0, 0), (90, 0), (90, 6), (90.027, 6 + 1e-12), (90, 6 + 2e-12), (90, 12), (0, 12)])


def test_rings_and_spikes_give_lines_with_warnings_in_every_algorithm(provider):
    """The ring gets its closed loop, the spiky parcel its line with a warning naming the spike, in
    ``polygoncenterline`` (automatic ends), ``polygonnetwork`` (split points) and ``linescenterline`` (bank
    lines, one doubling back at its end)."""
    polygons = memory_layer("Polygon", "EPSG:2180", [(MOAT, "moat"), (SPIKY, "spiky")])
    results, feedback = run({"INPUT": polygons}, "polygoncenterline")
    assert (results["CENTERLINE_COUNT"], results["SKIPPED_COUNT"]) == (2, 0), feedback.warnings
    lines = {feature["name"]: as_shapely(feature.geometry()) for feature in results["OUTPUT"].getFeatures()}
    assert lines["moat"].is_closed and lines["moat"].is_simple
    assert lines["moat"].length == pytest.approx(2 * np.pi * 7.5, rel=1e-3)
    assert not lines["spiky"].is_closed
    assert any("ring around one island" in warning for warning in feedback.warnings), feedback.warnings
    assert any("zero-width spike" in warning and "(90.027, 6)" in warning for warning in feedback.warnings)

    network, feedback = run({"INPUT": polygons, "SPLIT_POINTS": split_layer([(-10, 0), (0, 10), (0, 6), (90, 3)])})
    assert network["SKIPPED_COUNT"] == 0, feedback.warnings
    assert {feature["name"] for feature in network["OUTPUT"].getFeatures()} == {"moat", "spiky"}
    assert any("zero-width spike" in warning for warning in feedback.warnings), feedback.warnings

    bank_a = memory_layer("LineString", "EPSG:2180", [(shapely.LineString([(0, 0), (100, 0), (90, 1e-9)]), "a")])
    bank_b = memory_layer("LineString", "EPSG:2180", [(shapely.LineString([(0, 8), (100, 8)]), "b")])
    banks, feedback = run({"LINES_A": bank_a, "LINES_B": bank_b}, "linescenterline")
    assert (banks["CENTERLINE_COUNT"], banks["SKIPPED_COUNT"]) == (1, 0)
    (line,) = banks["OUTPUT"].getFeatures()
    assert as_shapely(line.geometry()).coords[:] == [(0.0, 4.0), (100.0, 4.0)]
    assert any("zero-width spike" in warning for warning in feedback.warnings), feedback.warnings


@pytest.mark.parametrize("crs", ["EPSG:2180", "EPSG:4326"])
def test_touching_reaches_meet_exactly_and_share_their_node(provider, crs):
    # A river cut into three reaches (in degrees: about 70 m by 10 m at 52 N); the cuts are slanted.
    scale = (1.0 / 68_000.0, 1.0 / 111_000.0) if crs == "EPSG:4326" else (1.0, 1.0)
    offset = (19.0, 52.0) if crs == "EPSG:4326" else (0.0, 0.0)
    outline = [
        [(0, 0), (30, 0), (32, 10), (0, 10)],
        [(30, 0), (60, 0), (57, 10), (32, 10)],
        [(60, 0), (90, 0), (90, 10), (57, 10)],
    ]
    reaches = [Polygon([(offset[0] + x * scale[0], offset[1] + y * scale[1]) for x, y in ring]) for ring in outline]
    layer = memory_layer("Polygon", crs, [(reach, f"reach {i}") for i, reach in enumerate(reaches)])
    results, feedback = run({"INPUT": layer, "CONNECT_TOUCHING": True, "OUTPUT_NODES": "memory:"})
    assert results["CENTERLINE_COUNT"] == 3 and results["SKIPPED_COUNT"] == 0, feedback.warnings
    lines = {feature["name"]: feature for feature in results["OUTPUT"].getFeatures()}
    ends = {name: as_shapely(feature.geometry()).coords for name, feature in lines.items()}
    for a, b in (("reach 0", "reach 1"), ("reach 1", "reach 2")):
        shared = {ends[a][0], ends[a][-1]} & {ends[b][0], ends[b][-1]}
        assert len(shared) == 1, (a, b)  # end-to-end distance exactly 0
        nodes_a = {lines[a]["from_node"], lines[a]["to_node"]}
        assert len(nodes_a & {lines[b]["from_node"], lines[b]["to_node"]}) == 1
    degrees = sorted(feature["degree"] for feature in results["OUTPUT_NODES"].getFeatures())
    assert degrees == [1, 1, 2, 2]
    assert {lines["reach 1"]["from_point"], lines["reach 1"]["to_point"]} == {"gate"}
    centerlines, feedback = run({"INPUT": layer, "CONNECT_TOUCHING": True}, algorithm="polygoncenterline")
    assert centerlines["SKIPPED_COUNT"] == 0, feedback.warnings
    cl = [as_shapely(feature.geometry()).coords for feature in centerlines["OUTPUT"].getFeatures()]
    assert len({cl[0][0], cl[0][-1]} & {cl[1][0], cl[1][-1]}) == 1
    assert len({cl[1][0], cl[1][-1]} & {cl[2][0], cl[2][-1]}) == 1


def test_channels_on_both_sides_of_a_large_island_make_a_loop(provider):
    island = box(120.0, 15.0, 180.0, 25.0)
    reach = Polygon(box(0.0, 0.0, 300.0, 40.0).exterior.coords, [island.exterior.coords])
    results, feedback = run(
        {"INPUT": memory_layer("Polygon", "EPSG:2180", [(reach, "braided")]), "ISLANDS": 2, "OUTPUT_NODES": "memory:"}
    )
    assert results["CENTERLINE_COUNT"] == 4 and results["SKIPPED_COUNT"] == 0, feedback.warnings
    branches = list(results["OUTPUT"].getFeatures())
    assert sorted(branch["kind"] for branch in branches) == ["arm", "arm", "loop", "loop"]
    loops = [branch for branch in branches if branch["kind"] == "loop"]
    assert {loops[0]["from_node"], loops[0]["to_node"]} == {loops[1]["from_node"], loops[1]["to_node"]}
    assert {branch["right_chain"] for branch in loops} | {branch["left_chain"] for branch in loops} >= {"island:0"}
    junctions = [node for node in results["OUTPUT_NODES"].getFeatures() if node["kind"] == "junction"]
    assert sorted((node.geometry().asPoint().x(), node["degree"]) for node in junctions) == [(100.0, 3), (200.0, 3)]
    for branch in branches:
        assert not as_shapely(branch.geometry()).intersects(island)


def test_a_confluence_reach_with_three_gates_is_traced_as_a_network(provider):
    # A T of rivers 10 and 6 wide cut into a confluence reach and three arms: the middle reach touches three
    # neighbours, so its three gates are its ends and its lines meet at one junction.
    t = shapely.union(box(-50.0, -5.0, 50.0, 5.0), box(-3.0, 0.0, 3.0, 50.0))
    cuts = {"west": box(-60, -10, -20, 60), "east": box(20, -10, 60, 60), "north": box(-20, 20, 20, 60)}
    middle = t.intersection(box(-20.0, -10.0, 20.0, 20.0))
    rows = [(middle, "confluence")] + [(t.intersection(cut), name) for name, cut in cuts.items()]
    layer = memory_layer("Polygon", "EPSG:2180", rows)
    results, feedback = run({"INPUT": layer, "CONNECT_TOUCHING": True, "OUTPUT_NODES": "memory:"})
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    branches = [feature for feature in results["OUTPUT"].getFeatures() if feature["name"] == "confluence"]
    assert len(branches) == 3 and {feature["from_point"] for feature in branches} == {"gate"}


@pytest.mark.filterwarnings("ignore:invalid value encountered in from_wkb:RuntimeWarning")
def test_a_feature_whose_gates_cannot_be_found_does_not_stop_the_layer(provider):
    # A NaN coordinate made GEOS raise while the layer's gates were found, which stopped the whole run.
    layer = memory_layer("Polygon", "EPSG:2180", [(box(0, 0, 50, 10), "a"), (box(50, 0, 100, 10), "b")])
    bad = QgsFeature(layer.fields())
    ring = QgsLineString([QgsPoint(x, y) for x, y in [(100, 0), (math.nan, 0), (150, 10), (100, 10), (100, 0)]])
    bad.setGeometry(QgsGeometry(QgsPolygon(ring)))
    bad.setAttributes(["nan"])
    assert layer.dataProvider().addFeatures([bad])
    for algorithm in ("polygonnetwork", "polygoncenterline"):
        results, feedback = run({"INPUT": layer, "CONNECT_TOUCHING": True}, algorithm)
        assert (results["CENTERLINE_COUNT"], results["SKIPPED_COUNT"]) == (2, 1), feedback.warnings
        lines = [as_shapely(feature.geometry()) for feature in results["OUTPUT"].getFeatures()]
        assert len({lines[0].coords[0], lines[0].coords[-1]} & {lines[1].coords[0], lines[1].coords[-1]}) == 1


def test_a_road_grid_with_blocks_as_holes_gives_one_branch_per_street_segment(provider):
    # 2 x 2 blocks with streets around and between them, every street leaving by a stub: 12 stubs and 12
    # street segments, 9 crossings of degree four at the streets' crossing points.
    polygon, caps, crossings, radius = cases.road_grid(2, 2)
    tolerance = 1e-9 * 200.0  # of the grid's extent
    layer = memory_layer("Polygon", "EPSG:2180", [(polygon, "roads")])
    results, feedback = run({"INPUT": layer, "ISLANDS": 2, "OUTPUT_NODES": "memory:"})
    assert results["CENTERLINE_COUNT"] == 24 and results["SKIPPED_COUNT"] == 0, feedback.warnings
    nodes = {
        kind: [n for n in results["OUTPUT_NODES"].getFeatures() if n["kind"] == kind] for kind in ("end", "junction")
    }
    assert {n["degree"] for n in nodes["junction"]} == {4}
    assert all(abs(n["radius"] - radius) <= 0.0005 for n in nodes["junction"])  # rounded to the millimetre
    for kind, expected in (("junction", crossings), ("end", caps)):
        found = sorted((n.geometry().asPoint().x(), n.geometry().asPoint().y()) for n in nodes[kind])
        assert np.allclose(found, sorted(map(tuple, expected)), rtol=0.0, atol=tolerance)
