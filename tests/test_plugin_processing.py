"""In-process runs of both algorithms through ``processing.run`` on the committed fixtures.

Expected values come from the analytic shapes the fixtures are made of (``scripts/make_sample_data.py``):
constant-width meanders around a known axis, straight channels, offset bank lines.
"""

import importlib
import importlib.util
import sys
import types

import numpy as np
import processing
import pytest
import shapely
import shapely.affinity
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsFeature,
    QgsGeometry,
    QgsProcessingException,
    QgsProcessingFeedback,
    QgsProject,
    QgsVectorLayer,
    QgsWkbTypes,
)

from tests.support.project import DATA, REPOSITORY

SPEC = importlib.util.spec_from_file_location("sample_data", REPOSITORY / "scripts" / "make_sample_data.py")
sample_data = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(sample_data)

RIVER_WIDTH = 2.0 * sample_data.RIVER_HALF_WIDTH
#: What the output attributes resolve, metres (the fixtures are in metres).
MILLIMETRE = 0.001
SNAP_TOLERANCE = 1.0


class RecordingFeedback(QgsProcessingFeedback):
    """Feedback that keeps the warnings and messages an algorithm pushes."""

    def __init__(self):
        super().__init__()
        self.warnings = []
        self.infos = []

    def pushWarning(self, message):
        self.warnings.append(message)

    def reportError(self, message, fatalError=False):
        self.warnings.append(message)

    def pushInfo(self, message):
        self.infos.append(message)


def run(algorithm, parameters, feedback=None):
    """Run an IncirCu algorithm with memory outputs; return (results, feedback)."""
    feedback = feedback or RecordingFeedback()
    parameters = {"OUTPUT": "memory:", **parameters}
    results = processing.run("incircu:" + algorithm, parameters, feedback=feedback)
    return results, feedback


def features_by(layer, field):
    """Map the value of ``field`` to the feature of ``layer``."""
    return {feature[field]: feature for feature in layer.getFeatures()}


def as_shapely(geometry):
    """2-D Shapely copy of a QGIS geometry."""
    flat = QgsGeometry(geometry)
    flat.get().dropMValue()
    flat.get().dropZValue()
    return shapely.from_wkb(bytes(flat.asWkb()))


def shifted_axis(axis, dy=0.0):
    """The analytic axis of a fixture in EPSG:2180."""
    return sample_data.shifted(axis, dy=dy)


def layer(name):
    """Open a fixture layer."""
    opened = QgsVectorLayer(str(DATA / name), name, "ogr")
    assert opened.isValid(), name
    return opened


def fixture_polygon(name, file_name="river_2180.geojson"):
    return as_shapely(features_by(layer(file_name), "name")[name].geometry())


def m_values(geometry):
    return [vertex.m() for vertex in geometry.vertices()]


def test_committed_fixtures_match_their_generator(tmp_path):
    samples, fixtures = tmp_path / "samples", tmp_path / "fixtures"
    sample_data.write_layers(samples, fixtures)
    for folder, committed in ((samples, sample_data.SAMPLE_FOLDER), (fixtures, sample_data.FIXTURE_FOLDER)):
        written = sorted(path.name for path in folder.iterdir())
        assert written
        for name in written:
            assert (folder / name).read_text() == (committed / name).read_text(), name


def test_polygon_centerline_in_projected_crs(provider):
    results, feedback = run(
        "polygoncenterline",
        {
            "INPUT": str(DATA / "river_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
            "SNAP_TOLERANCE": SNAP_TOLERANCE,
        },
    )
    output = results["OUTPUT"]
    assert output.crs().authid() == "EPSG:2180"
    assert QgsWkbTypes.hasM(output.wkbType())
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    assert results["CENTERLINE_COUNT"] == 2
    meander = features_by(output, "name")["Meander"]
    assert meander["kind"] == "river"
    assert not meander["ends_found"]
    line = as_shapely(meander.geometry())
    axis = shifted_axis(sample_data.meander_axis())
    start, end = (sample_data.shifted(p) for p in sample_data.end_points(sample_data.meander_axis(), 0.0))
    assert line.boundary.geoms[0].distance(start) <= SNAP_TOLERANCE
    assert line.boundary.geoms[1].distance(end) <= SNAP_TOLERANCE
    assert line.hausdorff_distance(axis) < 0.05 * RIVER_WIDTH
    assert meander["length"] == pytest.approx(axis.length, rel=0.01)
    assert meander["length"] == pytest.approx(line.length, abs=MILLIMETRE / 2.0 + 1e-9)
    assert meander["width_mean"] == pytest.approx(RIVER_WIDTH, rel=0.02)
    assert meander["width_min"] <= meander["width_mean"] <= meander["width_max"]
    assert meander["width_max"] == pytest.approx(RIVER_WIDTH, rel=0.02)
    assert meander["n_vertices"] == len(line.coords)
    polygon = fixture_polygon("Meander")
    assert polygon.buffer(1e-6 * RIVER_WIDTH).contains(line)
    interior_m = m_values(meander.geometry())[1:-1]
    assert min(interior_m) > 0.9 * RIVER_WIDTH
    assert max(interior_m) < 1.1 * RIVER_WIDTH


def test_island_channel_goes_round_the_island_on_the_wide_side(provider):
    results, _feedback = run("polygoncenterline", {"INPUT": str(DATA / "river_2180.geojson")})
    channel = features_by(results["OUTPUT"], "name")["Island channel"]
    assert channel["ends_found"]
    line = as_shapely(channel.geometry())
    polygon = fixture_polygon("Island channel")
    island = shapely.Polygon(polygon.interiors[0])
    assert not line.intersects(island)
    island_bottom = island.bounds[1]
    channel_bottom = polygon.bounds[1]
    crossing = line.intersection(
        shapely.LineString([(island.centroid.x, channel_bottom), (island.centroid.x, island_bottom + 1)])
    )
    assert not crossing.is_empty, "the line must pass below the island, in the wider channel"
    wide_middle = 0.5 * (island_bottom + channel_bottom)
    assert abs(crossing.centroid.y - wide_middle) < 0.1 * (island_bottom - channel_bottom)


def test_ignored_island_lets_the_line_run_down_the_middle(provider):
    results, _ = run("polygoncenterline", {"INPUT": str(DATA / "river_2180.geojson"), "ISLANDS": 1})
    channel = features_by(results["OUTPUT"], "name")["Island channel"]
    line = as_shapely(channel.geometry())
    outline = shapely.Polygon(fixture_polygon("Island channel").exterior)
    middle_y = 0.5 * (outline.bounds[1] + outline.bounds[3])
    width = outline.bounds[3] - outline.bounds[1]
    assert max(abs(y - middle_y) for _, y in line.coords) < 0.05 * width
    assert channel["width_max"] == pytest.approx(width, rel=0.02)


def test_geographic_layer_is_computed_in_metres(provider):
    projected, _ = run(
        "polygoncenterline",
        {"INPUT": str(DATA / "river_2180.geojson"), "SPLIT_POINTS": str(DATA / "split_points_2180.geojson")},
    )
    geographic, _feedback = run(
        "polygoncenterline",
        {"INPUT": str(DATA / "river_4326.geojson"), "SPLIT_POINTS": str(DATA / "split_points_4326.geojson")},
    )
    output = geographic["OUTPUT"]
    assert output.crs().authid() == "EPSG:4326"
    meander = features_by(output, "name")["Meander"]
    reference = features_by(projected["OUTPUT"], "name")["Meander"]
    assert meander["width_mean"] == pytest.approx(RIVER_WIDTH, rel=0.02)
    assert meander["length"] == pytest.approx(reference["length"], rel=0.005)
    box = output.extent()
    assert -180 <= box.xMinimum() <= box.xMaximum() <= 180
    assert -90 <= box.yMinimum() <= box.yMaximum() <= 90
    back = QgsGeometry(meander.geometry())
    back.transform(
        QgsCoordinateTransform(
            QgsCoordinateReferenceSystem("EPSG:4326"), QgsCoordinateReferenceSystem("EPSG:2180"), QgsProject.instance()
        )
    )
    assert as_shapely(back).hausdorff_distance(as_shapely(reference.geometry())) < 0.05 * RIVER_WIDTH


def test_split_points_in_another_crs_are_reprojected(provider):
    results, _feedback = run(
        "polygoncenterline",
        {
            "INPUT": str(DATA / "river_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "split_points_4326.geojson"),
            "SNAP_TOLERANCE": SNAP_TOLERANCE,
        },
    )
    assert results["OUTPUT"].crs().authid() == "EPSG:2180"
    meander = features_by(results["OUTPUT"], "name")["Meander"]
    assert not meander["ends_found"]
    line = as_shapely(meander.geometry())
    start, _ = (sample_data.shifted(p) for p in sample_data.end_points(sample_data.meander_axis(), 0.0))
    assert line.boundary.geoms[0].distance(start) <= SNAP_TOLERANCE


def bank_axes():
    return {
        "R1": (shifted_axis(sample_data.meander_axis(900.0, 80.0, 450.0, 73), dy=-600.0), 50.0),
        "R2": (shifted_axis(shapely.LineString([(0, 0), (600, 40)]), dy=-1000.0), 30.0),
    }


@pytest.mark.parametrize("banks_b", ["banks_b_2180.geojson", "banks_b_4326.geojson"])
def test_lines_centerline_pairs_by_field(provider, banks_b):
    results, feedback = run(
        "linescenterline",
        {
            "LINES_A": str(DATA / "banks_a_2180.geojson"),
            "LINES_B": str(DATA / banks_b),
            "PAIR_FIELD_A": "reach",
            "PAIR_FIELD_B": "reach",
        },
    )
    assert results["CENTERLINE_COUNT"] == 2
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    output = results["OUTPUT"]
    assert output.crs().authid() == "EPSG:2180"
    first_lines = features_by(layer("banks_a_2180.geojson"), "reach")
    for reach, feature in features_by(output, "reach").items():
        axis, width = bank_axes()[reach]
        assert feature["side"] == "left"
        assert feature["source_fid"] == first_lines[reach].id()
        line = as_shapely(feature.geometry())
        assert line.hausdorff_distance(axis) < 0.1 * width
        assert feature["width_mean"] == pytest.approx(width, rel=0.02)


def test_lines_without_pair_fields_use_one_line_per_layer(provider):
    line_a, line_b = layer("banks_a_2180.geojson"), layer("banks_b_2180.geojson")
    line_a.setSubsetString("\"reach\" = 'R2'")
    line_b.setSubsetString("\"reach\" = 'R2'")
    results, _feedback = run("linescenterline", {"LINES_A": line_a, "LINES_B": line_b, "ADD_M": False})
    assert results["CENTERLINE_COUNT"] == 1
    feature = next(results["OUTPUT"].getFeatures())
    assert not QgsWkbTypes.hasM(results["OUTPUT"].wkbType())
    axis, width = bank_axes()["R2"]
    assert as_shapely(feature.geometry()).hausdorff_distance(axis) < 0.1 * width


@pytest.mark.parametrize("folder", [DATA, REPOSITORY / "scripts" / "data"])
def test_bank_lines_sharing_a_field_are_paired_by_it_with_the_defaults(provider, folder):
    suffix = "_2180" if folder == DATA else ""
    results, feedback = run(
        "linescenterline",
        {"LINES_A": str(folder / f"banks_a{suffix}.geojson"), "LINES_B": str(folder / f"banks_b{suffix}.geojson")},
    )
    assert results["CENTERLINE_COUNT"] == 2
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    assert any("'reach'" in info for info in feedback.infos), feedback.infos
    for reach, feature in features_by(results["OUTPUT"], "reach").items():
        axis, width = bank_axes()[reach]
        assert as_shapely(feature.geometry()).hausdorff_distance(axis) < 0.1 * width


@pytest.mark.parametrize("folder", [DATA, REPOSITORY / "scripts" / "data"])
def test_the_polygon_sample_runs_with_the_defaults(provider, folder):
    path = folder / ("river_2180.geojson" if folder == DATA else "river.geojson")
    results, feedback = run("polygoncenterline", {"INPUT": str(path)})
    assert results["SKIPPED_COUNT"] == 0, feedback.warnings
    assert results["CENTERLINE_COUNT"] == layer_from(path).featureCount()
    assert not feedback.warnings


def layer_from(path):
    opened = QgsVectorLayer(str(path), path.name, "ogr")
    assert opened.isValid(), path
    return opened


def test_a_shared_field_without_a_common_value_pairs_nothing(provider):
    # 'side' is in both layers but 'left' is never 'right': no guess, one line per layer is asked for.
    line_a, line_b = layer("banks_a_2180.geojson"), layer("banks_b_2180.geojson")
    for opened in (line_a, line_b):
        opened.setSubsetString("\"reach\" = 'R2'")
        opened.startEditing()
        opened.deleteAttribute(opened.fields().lookupField("reach"))
    results, feedback = run("linescenterline", {"LINES_A": line_a, "LINES_B": line_b})
    assert results["CENTERLINE_COUNT"] == 1
    assert not any("pair" in info for info in feedback.infos), feedback.infos


def test_bad_features_are_skipped_with_their_id(provider):
    results, feedback = run(
        "polygoncenterline",
        {
            "INPUT": str(DATA / "bad_polygons_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "bad_split_points_2180.geojson"),
        },
    )
    assert results["CENTERLINE_COUNT"] == 1
    assert results["SKIPPED_COUNT"] == 2
    assert [feature["name"] for feature in results["OUTPUT"].getFeatures()] == ["good"]
    bowtie = [message for message in feedback.warnings if message.startswith("Feature 1 ")]
    three = [message for message in feedback.warnings if message.startswith("Feature 2 ")]
    assert len(bowtie) == 1 and len(three) == 1, feedback.warnings
    assert "3 split points" in three[0]


def test_feature_without_geometry_is_skipped(provider):
    memory = QgsVectorLayer("Polygon?crs=EPSG:2180&field=name:string", "polygons", "memory")
    empty = QgsFeature(memory.fields())
    empty.setAttributes(["nothing"])
    good = QgsFeature(memory.fields())
    good.setAttributes(["good"])
    good.setGeometry(QgsGeometry.fromWkt("POLYGON((0 0, 300 0, 300 40, 0 40, 0 0))"))
    memory.dataProvider().addFeatures([empty, good])
    results, feedback = run("polygoncenterline", {"INPUT": memory})
    assert results["CENTERLINE_COUNT"] == 1
    assert results["SKIPPED_COUNT"] == 1
    assert any("no geometry" in message for message in feedback.warnings)


def test_crossing_banks_are_skipped(provider):
    results, feedback = run(
        "linescenterline",
        {"LINES_A": str(DATA / "crossing_a_2180.geojson"), "LINES_B": str(DATA / "crossing_b_2180.geojson")},
    )
    assert results["CENTERLINE_COUNT"] == 0
    assert results["SKIPPED_COUNT"] == 1
    assert any(message.startswith("Feature 1 ") for message in feedback.warnings), feedback.warnings


def test_unpaired_line_is_skipped(provider):
    line_b = layer("banks_b_2180.geojson")
    line_b.setSubsetString("\"reach\" = 'R1'")
    results, feedback = run(
        "linescenterline",
        {
            "LINES_A": str(DATA / "banks_a_2180.geojson"),
            "LINES_B": line_b,
            "PAIR_FIELD_A": "reach",
            "PAIR_FIELD_B": "reach",
        },
    )
    assert results["CENTERLINE_COUNT"] == 1
    assert results["SKIPPED_COUNT"] == 1
    assert any("'R2'" in message for message in feedback.warnings), feedback.warnings


@pytest.mark.parametrize(
    "algorithm, parameters, message",
    [
        ("polygoncenterline", {"INPUT": str(DATA / "split_points_2180.geojson")}, "polygon"),
        ("polygoncenterline", {"INPUT": str(DATA / "does_not_exist.geojson")}, "does_not_exist.geojson not found"),
        (
            "polygoncenterline",
            {"INPUT": str(DATA / "river_2180.geojson"), "SPLIT_POINTS": str(DATA / "banks_a_2180.geojson")},
            "point",
        ),
        (
            "linescenterline",
            {"LINES_A": str(DATA / "river_2180.geojson"), "LINES_B": str(DATA / "banks_b_2180.geojson")},
            "line",
        ),
        (
            "linescenterline",
            {
                "LINES_A": str(DATA / "banks_a_2180.geojson"),
                "LINES_B": str(DATA / "banks_b_2180.geojson"),
                "PAIR_FIELD_A": "reach",
            },
            "PAIR_FIELD_B",
        ),
        (
            "linescenterline",
            {"LINES_A": str(DATA / "banks_a_2180.geojson"), "LINES_B": str(DATA / "crossing_b_2180.geojson")},
            "separate lines",
        ),
    ],
)
def test_layer_level_problems_raise(provider, algorithm, parameters, message):
    with pytest.raises(QgsProcessingException) as raised:
        run(algorithm, parameters)
    assert message in str(raised.value)


def test_multipart_polygon_gets_one_line_per_part(provider):
    together, _ = run("polygoncenterline", {"INPUT": str(DATA / "multipart_2180.geojson")})
    assert together["CENTERLINE_COUNT"] == 1
    assert QgsWkbTypes.isMultiType(together["OUTPUT"].wkbType())
    multi = as_shapely(next(together["OUTPUT"].getFeatures()).geometry())
    assert len(multi.geoms) == 2
    separate, _ = run("polygoncenterline", {"INPUT": str(DATA / "multipart_2180.geojson"), "SEPARATE_PARTS": True})
    assert separate["CENTERLINE_COUNT"] == 2
    assert not QgsWkbTypes.isMultiType(separate["OUTPUT"].wkbType())
    polygon = as_shapely(next(layer("multipart_2180.geojson").getFeatures()).geometry())
    for feature, part in zip(separate["OUTPUT"].getFeatures(), polygon.geoms):
        width = part.bounds[3] - part.bounds[1]
        length = part.bounds[2] - part.bounds[0]
        assert feature["ends_found"]
        assert length - width <= feature["length"] <= length + 0.01 * width
        assert feature["width_max"] == pytest.approx(width, rel=0.02)


def test_optional_outputs_describe_the_centerline(provider):
    results, _feedback = run(
        "polygoncenterline",
        {
            "INPUT": str(DATA / "river_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
            "OUTPUT_VERTICES": "memory:",
            "OUTPUT_CIRCLES": "memory:",
            "OUTPUT_TRANSECTS": "memory:",
            "TRANSECT_INTERVAL": 100.0,
        },
    )
    meander = features_by(results["OUTPUT"], "name")["Meander"]
    polygon = fixture_polygon("Meander")
    vertices = [f for f in results["OUTPUT_VERTICES"].getFeatures() if f["source_fid"] == meander.id()]
    assert len(vertices) == meander["n_vertices"]
    chainage = np.array([f["chainage"] for f in vertices])
    assert np.all(np.diff(chainage) >= 0)
    assert chainage[-1] == pytest.approx(meander["length"], rel=1e-9)
    for vertex in vertices:
        # Each rounded to the millimetre: 2 radius by up to one, the width by half of one.
        assert vertex["width"] == pytest.approx(2 * vertex["radius"], abs=1.5 * MILLIMETRE + 1e-9)
        point = as_shapely(vertex.geometry())
        assert point.distance(polygon.exterior) == pytest.approx(vertex["radius"], abs=0.01 * RIVER_WIDTH)
    circles = [f for f in results["OUTPUT_CIRCLES"].getFeatures() if f["source_fid"] == meander.id()]
    assert 0 < len(circles) <= len(vertices)
    grown = polygon.buffer(0.01 * RIVER_WIDTH)
    assert all(grown.contains(as_shapely(circle.geometry())) for circle in circles)
    transects = [f for f in results["OUTPUT_TRANSECTS"].getFeatures() if f["source_fid"] == meander.id()]
    assert len(transects) == pytest.approx(meander["length"] / 100.0, abs=1.5)
    for transect in transects:
        section = as_shapely(transect.geometry())
        assert section.length == pytest.approx(transect["width"], rel=0.01)
        assert transect["width"] == pytest.approx(RIVER_WIDTH, rel=0.05)
        for end in section.boundary.geoms:
            assert end.distance(polygon.exterior) < 0.01 * RIVER_WIDTH


@pytest.mark.parametrize("suffix", ["2180", "4326"])
def test_lengths_in_the_attributes_are_rounded_to_the_millimetre(provider, suffix):
    results, _feedback = run(
        "polygoncenterline",
        {
            "INPUT": str(DATA / f"river_{suffix}.geojson"),
            "SPLIT_POINTS": str(DATA / f"split_points_{suffix}.geojson"),
            "OUTPUT_VERTICES": "memory:",
            "OUTPUT_CIRCLES": "memory:",
            "OUTPUT_TRANSECTS": "memory:",
        },
    )
    lengths = {
        "OUTPUT": ("length", "width_min", "width_mean", "width_max"),
        "OUTPUT_VERTICES": ("chainage", "radius", "width"),
        "OUTPUT_CIRCLES": ("chainage", "radius"),
        "OUTPUT_TRANSECTS": ("chainage", "width"),
    }
    for output, names in lengths.items():
        features = list(results[output].getFeatures())
        assert features, output
        for feature in features:
            for name in names:
                value = feature[name]
                # A whole number of millimetres, up to the float's own rounding.
                assert abs(value * 1000.0 - round(value * 1000.0)) < 1e-6, (output, name, value)
    if suffix == "2180":
        for feature in results["OUTPUT"].getFeatures():
            assert feature["length"] == pytest.approx(feature.geometry().length(), abs=MILLIMETRE / 2.0 + 1e-9)


@pytest.mark.parametrize(
    "crs, decimals",
    [
        ("EPSG:2180", 3),  # metres
        ("EPSG:4326", 3),  # degrees: lengths are metres
        ("EPSG:2263", 3),  # feet: a millimetre is 0.0033 ft
        ("PROJ:+proj=merc +ellps=WGS84 +units=km +no_defs +type=crs", 6),
        ("", None),
    ],
)
def test_attribute_decimals_resolve_a_millimetre_in_the_layers_unit(provider, crs, decimals):
    from incircu.algorithms.units import length_decimals

    if crs.startswith("PROJ:"):
        reference = QgsCoordinateReferenceSystem.fromProj(crs[len("PROJ:") :])
    else:
        reference = QgsCoordinateReferenceSystem(crs)
    assert length_decimals(reference) == decimals


def test_parts_are_numbered_from_one_in_fields_and_messages(provider):
    results, feedback = run(
        "polygoncenterline",
        {"INPUT": str(DATA / "multipart_2180.geojson"), "SEPARATE_PARTS": True, "OUTPUT_VERTICES": "memory:"},
    )
    assert {feature["part"] for feature in results["OUTPUT_VERTICES"].getFeatures()} == {1, 2}
    polygon = next(layer("multipart_2180.geojson").getFeatures())
    # Three split points on the first part: it is skipped, and the warning names it as the fields do.
    three_points = QgsVectorLayer("Point?crs=EPSG:2180", "three split points", "memory")
    ring = polygon.geometry().constGet().geometryN(0).exteriorRing()
    points = []
    for index in range(3):
        point = QgsFeature()
        point.setGeometry(QgsGeometry(ring.pointN(index).clone()))
        points.append(point)
    three_points.dataProvider().addFeatures(points)
    _results, feedback = run(
        "polygoncenterline", {"INPUT": str(DATA / "multipart_2180.geojson"), "SPLIT_POINTS": three_points}
    )
    assert any(f"Feature {polygon.id()} (part 1) skipped" in warning for warning in feedback.warnings), (
        feedback.warnings
    )


def test_lengths_take_a_value_per_feature_where_data_defined(provider):
    from qgis.core import QgsProperty

    def per_river(meander, island_channel):
        return QgsProperty.fromExpression(f"CASE WHEN \"name\" = 'Meander' THEN {meander} ELSE {island_channel} END")

    common = {
        "INPUT": str(DATA / "river_2180.geojson"),
        "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
        "OUTPUT_TRANSECTS": "memory:",
    }
    fixed, _ = run("polygoncenterline", common)
    varied, _ = run(
        "polygoncenterline",
        {
            **common,
            "TRANSECT_INTERVAL": per_river(100.0, 50.0),
            "TOLERANCE": per_river(0.0, RIVER_WIDTH / 4.0),
        },
    )
    fixed_lines, varied_lines = features_by(fixed["OUTPUT"], "name"), features_by(varied["OUTPUT"], "name")
    for name, interval in (("Meander", 100.0), ("Island channel", 50.0)):
        feature = varied_lines[name]
        count = sum(1 for t in varied["OUTPUT_TRANSECTS"].getFeatures() if t["source_fid"] == feature["source_fid"])
        # Every interval along the line but the end caps (each at most a width long).
        span = (feature["length"] - 2.0 * feature["width_max"], feature["length"])
        assert span[0] / interval - 1.0 <= count <= span[1] / interval + 1.0, name
    # A coarser tolerance on one river only: fewer vertices there, the same line on the other.
    assert varied_lines["Island channel"]["n_vertices"] < fixed_lines["Island channel"]["n_vertices"]
    assert varied_lines["Meander"]["n_vertices"] == fixed_lines["Meander"]["n_vertices"]
    # The meander's split points lie 0.4 m outside it: beyond a snap tolerance of a millimetre, its ends are
    # found automatically, and the warning says so.
    snapped, feedback = run("polygoncenterline", {**common, "SNAP_TOLERANCE": per_river(0.001, SNAP_TOLERANCE)})
    assert not fixed_lines["Meander"]["ends_found"] and features_by(snapped["OUTPUT"], "name")["Meander"]["ends_found"]
    assert any("found automatically" in warning for warning in feedback.warnings), feedback.warnings


def test_progress_rises_to_100_percent(provider):
    class ProgressRecorder(RecordingFeedback):
        def __init__(self):
            super().__init__()
            self.steps = []

        def setProgress(self, progress):
            super().setProgress(progress)
            self.steps.append(progress)

    results, feedback = run(
        "polygoncenterline",
        {"INPUT": str(DATA / "river_2180.geojson"), "SPLIT_POINTS": str(DATA / "split_points_2180.geojson")},
        ProgressRecorder(),
    )
    assert results["CENTERLINE_COUNT"] == 2
    assert feedback.steps[-1] == 100.0
    assert all(0.0 <= step <= 100.0 for step in feedback.steps)
    assert feedback.steps == sorted(feedback.steps)
    assert len(set(feedback.steps)) > 3, "progress is reported inside features, not only at the end"


def test_cancel_stops_the_run(provider):
    class CancelOnProgress(RecordingFeedback):
        def setProgress(self, progress):
            super().setProgress(progress)
            if progress > 0:
                self.cancel()

    results, feedback = run(
        "polygoncenterline",
        {"INPUT": str(DATA / "river_2180.geojson"), "SPLIT_POINTS": str(DATA / "split_points_2180.geojson")},
        CancelOnProgress(),
    )
    assert feedback.isCanceled()
    assert results["CENTERLINE_COUNT"] == 0


def test_missing_or_old_shapely_gives_an_install_message(provider, monkeypatch):
    monkeypatch.setitem(sys.modules, "shapely", None)
    with pytest.raises(QgsProcessingException) as raised:
        run("polygoncenterline", {"INPUT": str(DATA / "river_2180.geojson")})
    hint = importlib.import_module("incircu.algorithms.dependencies").install_hint()
    assert "not installed" in str(raised.value) and str(raised.value).endswith(hint)
    # Shapely 1.8: the geometry classes in shapely.geometry, none of Shapely 2's module-level functions.
    old_shapely = types.ModuleType("shapely")
    old_shapely.__version__, old_shapely.geometry = "1.8.5", shapely.geometry
    monkeypatch.setitem(sys.modules, "shapely", old_shapely)
    with pytest.raises(QgsProcessingException) as raised:
        run(
            "linescenterline",
            {"LINES_A": str(DATA / "crossing_a_2180.geojson"), "LINES_B": str(DATA / "crossing_b_2180.geojson")},
        )
    assert "1.8.5" in str(raised.value) and str(raised.value).endswith(hint)


def polygon_layer(rows, fields="name:string"):
    """A memory layer of EPSG:2180 polygons; ``rows`` holds (shapely geometry, attribute values) pairs."""
    memory = QgsVectorLayer(
        "MultiPolygon?crs=EPSG:2180&" + "&".join(f"field={f}" for f in fields.split(",")), "in", "memory"
    )
    features = []
    for geometry, values in rows:
        feature = QgsFeature(memory.fields())
        feature.setGeometry(QgsGeometry.fromWkt(geometry.wkt))
        feature.setAttributes(values)
        features.append(feature)
    assert memory.dataProvider().addFeatures(features)
    return memory


def geopackage(source, path):
    """Write ``source`` to the GeoPackage ``path`` and return it as an input."""
    return processing.run("native:reprojectlayer", {"INPUT": source, "TARGET_CRS": "EPSG:2180", "OUTPUT": str(path)})[
        "OUTPUT"
    ]


def assert_each_centerline_has_its_source(source, output_path, expected):
    """Every input feature of ``source`` got ``expected[name]`` centerlines in the GeoPackage ``output_path``.

    Each centerline carries its input's ``name`` and its input's id in ``source_fid``; the fids are unique.
    """
    names = {feature.id(): feature["name"] for feature in source.getFeatures()}
    centerlines = list(QgsVectorLayer(str(output_path), "centerlines", "ogr").getFeatures())
    assert sorted(feature["name"] for feature in centerlines) == sorted(
        name for name, count in expected.items() for _ in range(count)
    )
    assert len({feature.id() for feature in centerlines}) == len(centerlines)
    for feature in centerlines:
        assert names[feature["source_fid"]] == feature["name"]


def test_separate_parts_from_a_geopackage_keep_every_part(provider, tmp_path):
    # A GeoPackage's fid is unique: the second part of the first feature must not take the second's fid.
    multipart = as_shapely(next(layer("multipart_2180.geojson").getFeatures()).geometry())
    second = shapely.affinity.translate(multipart, yoff=1000.0)
    written = geopackage(polygon_layer([(multipart, ["first"]), (second, ["second"])]), tmp_path / "in.gpkg")
    target = tmp_path / "parts.gpkg"
    results, feedback = run("polygoncenterline", {"INPUT": written, "SEPARATE_PARTS": True, "OUTPUT": str(target)})
    assert results["CENTERLINE_COUNT"] == 4, feedback.warnings
    assert_each_centerline_has_its_source(QgsVectorLayer(written, "in", "ogr"), target, {"first": 2, "second": 2})


def test_an_attribute_named_fid_with_repeated_values_loses_no_feature(provider, tmp_path):
    # A GeoPackage takes a field named fid as its primary key: repeated values must not stop the writing.
    rectangle = shapely.box(0.0, 0.0, 400.0, 40.0)
    rows = [(rectangle, [7, "a"]), (shapely.affinity.translate(rectangle, yoff=100.0), [7, "b"])]
    source = polygon_layer(rows, "fid:integer,name:string")
    target = tmp_path / "centerlines.gpkg"
    results, feedback = run("polygoncenterline", {"INPUT": source, "OUTPUT": str(target)})
    assert results["CENTERLINE_COUNT"] == 2, feedback.warnings
    assert_each_centerline_has_its_source(source, target, {"a": 1, "b": 1})


def test_feature_ids_beyond_32_bits_reach_source_fid(provider, tmp_path):
    """A GeoPackage feature whose fid needs more than 32 bits: the centerline and its vertices carry it whole."""
    from osgeo import ogr, osr

    path = tmp_path / "big_ids.gpkg"
    dataset = ogr.GetDriverByName("GPKG").CreateDataSource(str(path))
    crs = osr.SpatialReference()
    crs.ImportFromEPSG(2180)
    ogr_layer = dataset.CreateLayer("rivers", crs, ogr.wkbPolygon)
    feature = ogr.Feature(ogr_layer.GetLayerDefn())
    feature.SetFID(5_000_000_000)
    feature.SetGeometry(ogr.CreateGeometryFromWkt("POLYGON((0 0, 400 0, 400 40, 0 40, 0 0))"))
    assert ogr_layer.CreateFeature(feature) == 0
    dataset = None
    results, feedback = run("polygoncenterline", {"INPUT": str(path), "OUTPUT_VERTICES": "memory:"})
    assert results["CENTERLINE_COUNT"] == 1, feedback.warnings
    assert [line["source_fid"] for line in results["OUTPUT"].getFeatures()] == [5_000_000_000]
    assert {vertex["source_fid"] for vertex in results["OUTPUT_VERTICES"].getFeatures()} == {5_000_000_000}


def test_curved_polygons_are_linearised(provider):
    straight = QgsGeometry.fromWkt("Polygon ((0 0, 100 0, 100 10, 0 10, 0 0))")
    curved = QgsGeometry.fromWkt(
        "CurvePolygon (CompoundCurve ((0 0, 100 0), CircularString (100 0, 105 5, 100 10), (100 10, 0 10, 0 0)))"
    )
    source = QgsVectorLayer("CurvePolygon?crs=EPSG:2180", "curved", "memory")
    feature = QgsFeature()
    feature.setGeometry(curved)
    source.dataProvider().addFeatures([feature])
    results, feedback = run("polygoncenterline", {"INPUT": source})
    assert results["CENTERLINE_COUNT"] == 1, feedback.warnings
    line = as_shapely(next(results["OUTPUT"].getFeatures()).geometry())
    # The ends were found on the linearised outline: the line runs along y = 5 over the straight part.
    assert line.length >= straight.boundingBox().width() - 10.0
    assert abs(line.interpolate(0.5, normalized=True).y - 5.0) <= 1e-6


def test_tolerance_reaches_the_core(provider):
    """``TOLERANCE`` is the core's ``tolerance`` (its bound is proven against the oracle in the core tests)."""
    from incircu_plugin.core import polygon_centerline

    polygon = fixture_polygon("Meander")
    ends = [as_shapely(f.geometry()) for f in layer("split_points_2180.geojson").getFeatures()]
    ends = [point for point in ends if point.distance(polygon.exterior) <= SNAP_TOLERANCE]
    counts = []
    for tolerance in (0.002 * RIVER_WIDTH, 0.02 * RIVER_WIDTH):
        parameters = {
            "INPUT": str(DATA / "river_2180.geojson"),
            "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
            "SNAP_TOLERANCE": SNAP_TOLERANCE,
            "TOLERANCE": tolerance,
        }
        results, feedback = run("polygoncenterline", parameters)
        assert results["SKIPPED_COUNT"] == 0, feedback.warnings
        line = as_shapely(features_by(results["OUTPUT"], "name")["Meander"].geometry())
        expected = polygon_centerline(
            polygon, ends, snap_tolerance=SNAP_TOLERANCE, tolerance=tolerance, end_cap="runout"
        ).line
        assert line.hausdorff_distance(expected) <= 1e-6 * RIVER_WIDTH
        counts.append(len(line.coords))
    assert counts[1] < counts[0] <= 1.5 * len(polygon.exterior.coords)


def test_tolerance_and_fixed_spacing_together_stop_the_run(provider):
    parameters = {"INPUT": str(DATA / "river_2180.geojson"), "TOLERANCE": 0.1, "SPACING": 0.5}
    with pytest.raises(QgsProcessingException, match="not both"):
        run("polygoncenterline", parameters)


@pytest.mark.parametrize("interval, count", [(0.0, 24), (100.0, 9)])
def test_transects_cover_a_long_rectangle(provider, interval, count):
    """A 1000 x 40 channel: its adaptive line has four vertices, yet transects span all but the end caps."""
    length, width = 1000.0, 40.0
    source = QgsVectorLayer("Polygon?crs=EPSG:2180", "channel", "memory")
    channel = QgsFeature()
    channel.setGeometry(QgsGeometry.fromWkt(f"POLYGON((0 0, {length} 0, {length} {width}, 0 {width}, 0 0))"))
    source.dataProvider().addFeatures([channel])
    ends = QgsVectorLayer("Point?crs=EPSG:2180", "ends", "memory")
    points = [QgsFeature(), QgsFeature()]
    for point, x in zip(points, (0.0, length)):
        point.setGeometry(QgsGeometry.fromWkt(f"POINT({x} {width / 2})"))
    ends.dataProvider().addFeatures(points)
    results, feedback = run(
        "polygoncenterline",
        {"INPUT": source, "SPLIT_POINTS": ends, "OUTPUT_TRANSECTS": "memory:", "TRANSECT_INTERVAL": interval},
    )
    assert results["CENTERLINE_COUNT"] == 1, feedback.warnings
    # The default tolerance is width / 200: the line, and so each foot, is within it of the exact position.
    tolerance = width / 200.0
    step = interval or width
    transects = list(results["OUTPUT_TRANSECTS"].getFeatures())
    # Stations are the multiples of the interval from half a width in to half a width before the far end.
    expected = [station for station in step * np.arange(1, length / step) if width / 2 <= station <= length - width / 2]
    assert len(expected) == count
    assert [transect["chainage"] for transect in transects] == pytest.approx(expected, abs=tolerance)
    for transect in transects:
        section = as_shapely(transect.geometry())
        assert transect["width"] == pytest.approx(width, abs=2.0 * tolerance)
        start, end = section.boundary.geoms
        assert sorted([start.y, end.y]) == pytest.approx([0.0, width], abs=2.0 * tolerance)
        assert start.x == pytest.approx(transect["chainage"], abs=2.0 * tolerance)
        assert end.x == pytest.approx(transect["chainage"], abs=2.0 * tolerance)


def memory_layer(kind, rows, fields="field=name:string"):
    """A memory layer in EPSG:2180 of ``kind`` ("Polygon", "PointZ"...) with one feature per (name, WKT) row."""
    memory = QgsVectorLayer(f"{kind}?crs=EPSG:2180&{fields}", kind, "memory")
    features = []
    for name, wkt in rows:
        feature = QgsFeature(memory.fields())
        feature.setAttributes([name])
        feature.setGeometry(QgsGeometry.fromWkt(wkt))
        features.append(feature)
    assert memory.dataProvider().addFeatures(features)
    return memory


CHANNEL = "POLYGON((0 0, 300 0, 300 40, 0 40, 0 0))"


def test_split_points_beyond_the_snap_tolerance_are_warned_about(provider):
    # The two split points lie 100 m beyond the channel's ends: ends are found automatically, with a warning
    # saying how far the nearest point is and what the tolerance is.
    polygons = memory_layer("Polygon", [("channel", CHANNEL)])
    points = memory_layer("Point", [("west", "POINT(-100 20)"), ("east", "POINT(400 20)")])
    results, feedback = run(
        "polygoncenterline", {"INPUT": polygons, "SPLIT_POINTS": points, "SNAP_TOLERANCE": SNAP_TOLERANCE}
    )
    assert results["CENTERLINE_COUNT"] == 1 and results["SKIPPED_COUNT"] == 0
    (warning,) = [message for message in feedback.warnings if message.startswith("Feature 1:")]
    assert f"within {SNAP_TOLERANCE:g} m of its outline, the 'Split point snapping tolerance'" in warning, warning
    assert "the nearest is 100 m away" in warning and "found automatically" in warning, warning


def test_core_lengths_in_a_skip_are_named_in_the_layers_unit(provider):
    """A polygon with three split points is skipped with the core's reason, its lengths named in metres for a
    layer in degrees (the core says "CRS units": those of the frame it computed in)."""
    polygon = "POLYGON((10 50, 10.01 50, 10.01 50.001, 10 50.001, 10 50))"
    polygons = QgsVectorLayer("Polygon?crs=EPSG:4326", "degrees", "memory")
    points = QgsVectorLayer("Point?crs=EPSG:4326", "one end", "memory")
    for layer_, wkt in (
        (polygons, polygon),
        (points, "POINT(10 50.0005)"),
        (points, "POINT(10.01 50.0005)"),
        (points, "POINT(10.005 50)"),
    ):
        feature = QgsFeature()
        feature.setGeometry(QgsGeometry.fromWkt(wkt))
        layer_.dataProvider().addFeatures([feature])
    results, feedback = run("polygoncenterline", {"INPUT": polygons, "SPLIT_POINTS": points, "SNAP_TOLERANCE": 1.0})
    assert results["SKIPPED_COUNT"] == 1
    (warning,) = feedback.warnings
    assert "3 split points within the snap tolerance (1 m) of its exterior ring" in warning, warning
    assert "CRS units" not in warning


def test_an_empty_split_point_layer_is_warned_about(provider):
    polygons = memory_layer("Polygon", [("channel", CHANNEL)])
    results, feedback = run("polygoncenterline", {"INPUT": polygons, "SPLIT_POINTS": memory_layer("Point", [])})
    assert results["CENTERLINE_COUNT"] == 1 and results["SKIPPED_COUNT"] == 0
    assert feedback.warnings == [
        "Feature 1: 'Split points' (SPLIT_POINTS) holds no point. Its ends were found automatically."
    ], feedback.warnings


def test_split_points_within_the_snap_tolerance_bring_no_warning(provider):
    polygons = memory_layer("Polygon", [("channel", CHANNEL)])
    points = memory_layer("Point", [("west", "POINT(0 20)"), ("east", "POINT(300 20)")])
    results, feedback = run("polygoncenterline", {"INPUT": polygons, "SPLIT_POINTS": points})
    assert results["CENTERLINE_COUNT"] == 1 and feedback.warnings == []


@pytest.mark.parametrize(
    "algorithm, parameters, words",
    [
        (
            "linescenterline",
            {
                "LINES_A": str(DATA / "banks_a_2180.geojson"),
                "LINES_B": str(DATA / "banks_b_2180.geojson"),
                "PAIR_FIELD_A": "reach",
                "PAIR_FIELD_B": "rech",
            },
            "'Second lines (bank B)' (LINES_B) has no field 'rech'; its fields are: ",
        ),
        (
            "linescenterline",
            {
                "LINES_A": str(DATA / "banks_a_2180.geojson"),
                "LINES_B": str(DATA / "banks_b_2180.geojson"),
                "PAIR_FIELD_A": "rech",
                "PAIR_FIELD_B": "reach",
            },
            "'First lines (bank A)' (LINES_A) has no field 'rech'; its fields are: ",
        ),
        (
            "polygonnetwork",
            {
                "INPUT": str(DATA / "river_2180.geojson"),
                "SPLIT_POINTS": str(DATA / "split_points_2180.geojson"),
                "SPLIT_ID_FIELD": "arms",
            },
            "'Split points' (SPLIT_POINTS) has no field 'arms'; its fields are: ",
        ),
    ],
    ids=["pair-field-b", "pair-field-a", "split-id-field"],
)
def test_a_field_the_layer_does_not_have_stops_the_run(provider, algorithm, parameters, words):
    with pytest.raises(QgsProcessingException) as raised:
        run(algorithm, parameters)
    assert words in str(raised.value)


def test_z_values_are_warned_about_once(provider):
    rows = [
        (name, f"POLYGON Z(({x} 0 5, {x + 300} 0 5, {x + 300} 40 6, {x} 40 6, {x} 0 5))")
        for name, x in [("a", 0), ("b", 500)]
    ]
    results, feedback = run("polygoncenterline", {"INPUT": memory_layer("PolygonZ", rows)})
    assert results["CENTERLINE_COUNT"] == 2
    assert [message for message in feedback.warnings if "Z values are ignored" in message] == feedback.warnings
    assert len(feedback.warnings) == 1


def test_messages_name_the_dialog_labels_and_count_branches(provider):
    with pytest.raises(QgsProcessingException) as raised:
        run(
            "linescenterline",
            {
                "LINES_A": str(DATA / "banks_a_2180.geojson"),
                "LINES_B": str(DATA / "banks_b_2180.geojson"),
                "PAIR_FIELD_A": "reach",
            },
        )
    assert "'Pairing field of the second lines' (PAIR_FIELD_B)" in str(raised.value)
    points = memory_layer("Point", [("west", "POINT(0 20)"), ("east", "POINT(300 20)")])
    results, feedback = run(
        "polygonnetwork", {"INPUT": memory_layer("Polygon", [("channel", CHANNEL)]), "SPLIT_POINTS": points}
    )
    assert results["CENTERLINE_COUNT"] == 1
    assert "Number of branches: 1; Number of skipped features: 0" in feedback.infos, feedback.infos


def test_a_wrong_split_point_count_names_no_part_of_a_single_polygon(provider):
    points = memory_layer("Point", [("west", "POINT(0 20)"), ("east", "POINT(300 20)"), ("south", "POINT(150 0)")])
    results, feedback = run(
        "polygoncenterline", {"INPUT": memory_layer("Polygon", [("channel", CHANNEL)]), "SPLIT_POINTS": points}
    )
    assert results["SKIPPED_COUNT"] == 1
    (warning,) = feedback.warnings
    assert warning.startswith("Feature 1 skipped: The polygon has 3 split points within the snap tolerance"), warning


def test_one_split_point_is_the_start_and_the_far_end_is_found(provider):
    points = memory_layer("Point", [("west", "POINT(0 10)")])
    results, _ = run(
        "polygoncenterline", {"INPUT": memory_layer("Polygon", [("channel", CHANNEL)]), "SPLIT_POINTS": points}
    )
    (feature,) = results["OUTPUT"].getFeatures()
    line = feature.geometry().constGet()
    assert (line.startPoint().x(), line.startPoint().y()) == (0.0, 10.0)
    assert abs(line.endPoint().x() - 300.0) < 1e-9 and abs(line.endPoint().y() - 20.0) < 1e-9


def test_banks_of_very_different_lengths_are_warned_about(provider):
    # Bank A 1000 m, bank B 100 m, 40 m apart: beyond bank B the line follows the closing chord.
    bank_a = memory_layer("LineString", [("a", "LINESTRING(0 0, 1000 0)")])
    bank_b = memory_layer("LineString", [("b", "LINESTRING(0 40, 100 40)")])
    results, feedback = run("linescenterline", {"LINES_A": bank_a, "LINES_B": bank_b})
    assert results["CENTERLINE_COUNT"] == 1
    (warning,) = feedback.warnings
    assert warning.startswith("Feature 1: The first line is 1000 long, 10 times the second one (100 m): "), warning
