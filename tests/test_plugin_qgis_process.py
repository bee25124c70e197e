"""The plugin driven by ``qgis_process`` as a subprocess: exit codes, GeoPackage outputs read back."""

from qgis.core import QgsVectorLayer, QgsWkbTypes
from test_plugin_processing import RIVER_WIDTH, as_shapely, bank_axes, features_by

from tests.support.project import DATA


def read_layer(path, layer_name=None):
    uri = str(path) if layer_name is None else f"{path}|layername={layer_name}"
    layer = QgsVectorLayer(uri, "output", "ogr")
    assert layer.isValid(), uri
    return layer


def test_algorithms_are_listed(qgis_process):
    listed = qgis_process("list")
    assert listed.returncode == 0, listed.stderr
    assert "incircu:polygoncenterline" in listed.stdout
    assert "incircu:linescenterline" in listed.stdout


def test_help_names_every_parameter(qgis_process):
    shown = qgis_process("help", "incircu:polygoncenterline")
    assert shown.returncode == 0, shown.stderr
    for name in ("INPUT", "SPLIT_POINTS", "SNAP_TOLERANCE", "SPACING", "ISLANDS", "SEPARATE_PARTS", "ADD_M"):
        assert name in shown.stdout


def test_polygon_centerline_to_geopackage(qgis_process, tmp_path):
    output = tmp_path / "centerlines.gpkg"
    vertices = tmp_path / "vertices.gpkg"
    done = qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(DATA / "river_2180.geojson"),
        "SPLIT_POINTS={}".format(DATA / "split_points_2180.geojson"),
        "SNAP_TOLERANCE=1",
        f"OUTPUT={output}",
        f"OUTPUT_VERTICES={vertices}",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "CENTERLINE_COUNT:\t2" in done.stdout
    assert "SKIPPED_COUNT:\t0" in done.stdout
    layer = read_layer(output)
    assert layer.crs().authid() == "EPSG:2180"
    assert QgsWkbTypes.hasM(layer.wkbType())
    meander = features_by(layer, "name")["Meander"]
    assert abs(meander["width_mean"] - RIVER_WIDTH) < 0.02 * RIVER_WIDTH
    line = as_shapely(meander.geometry())
    assert abs(line.length - meander["length"]) < 1e-6 * line.length
    assert read_layer(vertices).featureCount() == sum(f["n_vertices"] for f in layer.getFeatures())


def test_lines_centerline_with_reprojected_second_layer(qgis_process, tmp_path):
    output = tmp_path / "between.gpkg"
    done = qgis_process(
        "run",
        "incircu:linescenterline",
        "--",
        "LINES_A={}".format(DATA / "banks_a_2180.geojson"),
        "LINES_B={}".format(DATA / "banks_b_4326.geojson"),
        "PAIR_FIELD_A=reach",
        "PAIR_FIELD_B=reach",
        f"OUTPUT={output}",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    layer = read_layer(output)
    assert layer.crs().authid() == "EPSG:2180"
    for reach, feature in features_by(layer, "reach").items():
        axis, width = bank_axes()[reach]
        assert as_shapely(feature.geometry()).hausdorff_distance(axis) < 0.1 * width


def test_geographic_polygons_keep_their_crs(qgis_process, tmp_path):
    output = tmp_path / "geographic.gpkg"
    done = qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(DATA / "river_4326.geojson"),
        "SPLIT_POINTS={}".format(DATA / "split_points_4326.geojson"),
        f"OUTPUT={output}",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    layer = read_layer(output)
    assert layer.crs().authid() == "EPSG:4326"
    meander = features_by(layer, "name")["Meander"]
    assert abs(meander["width_mean"] - RIVER_WIDTH) < 0.02 * RIVER_WIDTH
    polygon = as_shapely(features_by(read_layer(DATA / "river_4326.geojson"), "name")["Meander"].geometry())
    assert polygon.buffer(1e-6).contains(as_shapely(meander.geometry()))


def test_per_feature_problems_do_not_fail_the_run(qgis_process, tmp_path):
    done = qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(DATA / "bad_polygons_2180.geojson"),
        "SPLIT_POINTS={}".format(DATA / "bad_split_points_2180.geojson"),
        "OUTPUT={}".format(tmp_path / "some.gpkg"),
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "SKIPPED_COUNT:\t2" in done.stdout
    assert "Feature 1 skipped" in done.stdout + done.stderr


def test_layer_level_problem_exits_non_zero(qgis_process, tmp_path):
    done = qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(DATA / "split_points_2180.geojson"),
        "OUTPUT={}".format(tmp_path / "none.gpkg"),
    )
    assert done.returncode != 0
    assert "polygon" in done.stdout + done.stderr


def test_output_geometry_matches_in_process_run(qgis_process, tmp_path, provider):
    import processing

    output = tmp_path / "multipart.gpkg"
    done = qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(DATA / "multipart_2180.geojson"),
        "SEPARATE_PARTS=true",
        f"OUTPUT={output}",
    )
    assert done.returncode == 0, done.stdout + done.stderr
    in_process = processing.run(
        "incircu:polygoncenterline",
        {"INPUT": str(DATA / "multipart_2180.geojson"), "SEPARATE_PARTS": True, "OUTPUT": "memory:"},
    )["OUTPUT"]
    subprocess_lines = [as_shapely(f.geometry()) for f in read_layer(output).getFeatures()]
    in_process_lines = [as_shapely(f.geometry()) for f in in_process.getFeatures()]
    assert len(subprocess_lines) == len(in_process_lines) == 2
    polygon = as_shapely(next(read_layer(DATA / "multipart_2180.geojson").getFeatures()).geometry())
    narrowest = min(part.bounds[3] - part.bounds[1] for part in polygon.geoms)
    for a, b in zip(subprocess_lines, in_process_lines):
        assert a.hausdorff_distance(b) < 0.01 * narrowest
