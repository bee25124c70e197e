"""The data-frame API: ``centerlines`` and ``frame_labels`` on GeoPandas frames equal the core feature by
feature, and on dask-geopandas (a LocalCluster of two worker processes, GeoParquet in and out) the serial run.

Expected values come from the core called directly on each feature (every split point offered, so the
core's own distance rule picks them, not the API's bounding-box search), never from a previous run. The
fixtures are read with the standard library (no GDAL driver in the test process, which also holds QGIS).
"""

import json
import os

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, MultiLineString, MultiPolygon, Point, Polygon, box

from incircu_plugin.core import (
    IncirCuError,
    LocalProjection,
    centerlines,
    feature_label,
    frame_labels,
    label_lines,
    multipolygon_centerlines,
    width_statistics,
)
from incircu_plugin.core.api import _multipolygon_centerline_steps
from tests.support.frame_cases import channels_lonlat
from tests.support.project import DATA, REPOSITORY
from tests.support.real_rivers import DATA as RESERVOIRS

geopandas = pytest.importorskip("geopandas")
pandas = pytest.importorskip("pandas")

STATISTICS = ("length", "width_min", "width_mean", "width_max")

#: Rows are traced together in batches: equal to the core feature by feature up to float64 rounding, which the
#: joint tracing's shared coordinates may move by this fraction of the shape's extent (or of a statistic).
ROUNDING = 1e-9


def rounding_of(shape):
    """The coordinate tolerance of a shape's row: :data:`ROUNDING` of its extent, CRS units."""
    west, south, east, north = shape.bounds
    return ROUNDING * max(east - west, north - south)


def same_value(one, other):
    """Equal within :data:`ROUNDING` (relative), NaN equal to NaN."""
    return bool(np.isclose(one, other, rtol=ROUNDING, atol=0.0, equal_nan=True))


def read_geojson(name, crs):
    """A GeoDataFrame of a fixture (its attributes and geometries), in ``crs``."""
    with open(DATA / name, encoding="utf-8") as stream:
        document = json.load(stream)
    features = document["features"] if document["type"] == "FeatureCollection" else [document]
    rows = [feature["properties"] or {} for feature in features]
    geometries = [shapely.geometry.shape(f["geometry"]) if f["geometry"] else None for f in features]
    return geopandas.GeoDataFrame(rows, geometry=geometries, crs=crs)


def expected_row(shape, points, crs=None, snap_tolerance=1.0, **options):
    """The core on one feature, as the plugin calls it (with the run-out at the ends, the plugin's default):
    ``(line or None, statistics, error or None)``."""
    options.setdefault("end_cap", "runout")
    projection = None
    if crs is not None and crs.is_geographic and shape is not None:
        projection = LocalProjection.around(shape, crs.srs)
    try:
        local = shape if projection is None else projection.to_local(shape)
        offered = [p if projection is None else projection.to_local(p) for p in points] or None
        outcomes = multipolygon_centerlines(local, offered, snap_tolerance=snap_tolerance, **options)
    except IncirCuError as error:
        return None, None, str(error)
    results = [outcome.result for outcome in outcomes if outcome.error is None]
    prefix = "part {}: " if isinstance(shape, MultiPolygon) else ""
    errors = [prefix.format(o.part_index) + str(o.error) for o in outcomes if o.error is not None]
    if not results:
        return None, None, "; ".join(errors)
    lines = [r.line if projection is None else projection.to_geographic(r.line) for r in results]
    line = MultiLineString(lines) if isinstance(shape, MultiPolygon) else lines[0]
    return line, width_statistics(results), "; ".join(errors) or None


def assert_rows_equal_core(result, data, points, **options):
    assert list(result.index) == list(data.index)
    assert result.crs == data.crs
    geometries = np.asarray(points.geometry.values) if hasattr(points, "geometry") else points
    coordinates = [Point(xy) for xy in shapely.get_coordinates(geometries)]
    for label, shape in data.geometry.items():
        line, statistics, error = expected_row(shape, coordinates, data.crs, **options)
        row = result.loc[label]
        assert (None if pandas.isna(row["error"]) else row["error"]) == error, label
        if line is None:
            assert row.geometry is None and np.isnan(row["length"]) and pandas.isna(row["ends_found"]), label
            continue
        assert row.geometry.geom_type == line.geom_type, label
        assert row.geometry.equals_exact(line, rounding_of(shape)), label
        for name in STATISTICS:  # no positive width on the line: None from the core, NaN in the frame
            expected = np.nan if statistics[name] is None else statistics[name]
            assert same_value(row[name], expected), (label, name, row[name], expected)
        assert bool(row["ends_found"]) == statistics["ends_found"], label
        assert row["ends_from"] == statistics["ends_from"], label


def test_rivers_with_split_points_equal_the_core_feature_by_feature():
    rivers = read_geojson("river_2180.geojson", "EPSG:2180")
    points = read_geojson("split_points_2180.geojson", "EPSG:2180")
    rivers.index = [17, 3]  # any index is kept
    result = centerlines(rivers, points)
    assert_rows_equal_core(result, rivers, points)
    assert result["error"].isna().all() and result.geometry.notna().all()


def test_multipart_rows_get_one_multilinestring_of_their_parts():
    parts = read_geojson("multipart_2180.geojson", "EPSG:2180")
    result = centerlines(parts.geometry)  # a GeoSeries, ends found automatically
    assert_rows_equal_core(result, parts, [])
    line = result.geometry.iloc[0]
    assert isinstance(line, MultiLineString)
    assert len(line.geoms) == len(parts.geometry.iloc[0].geoms)
    assert bool(result["ends_found"].iloc[0])


def test_bad_rows_report_the_core_error_and_never_stop_the_frame():
    bad = read_geojson("bad_polygons_2180.geojson", "EPSG:2180")
    points = read_geojson("bad_split_points_2180.geojson", "EPSG:2180")
    good = read_geojson("river_2180.geojson", "EPSG:2180")
    frame = geopandas.GeoDataFrame(
        geometry=[*bad.geometry, None, Polygon(), LineString([(0, 0), (1, 1)]), good.geometry.iloc[0]],
        crs="EPSG:2180",
    )
    result = centerlines(frame, points)
    assert_rows_equal_core(result, frame, points)
    good_rows = [i for i, name in enumerate(bad["name"]) if name == "good"] + [len(frame) - 1]
    assert np.flatnonzero(result["error"].isna().to_numpy()).tolist() == good_rows
    assert result.geometry.iloc[good_rows].notna().all()
    assert result["error"].iloc[len(bad)] == "The polygon is null (no geometry)."


def test_rings_spikes_and_thin_boxes_give_lines_or_their_error_in_a_frame():
    """Valid shapes that once crashed (issue 40): a ring gets its closed loop, a parcel with a zero-width spike
    its line, a box too thin for float64 the error naming its width; as the core, row by row."""
    moat = Point(0, 0).buffer(10).difference(Point(0, 0).buffer(5))
    spiky = Polygon([(0, 0), (90, 0), (90, 6), (90.027, 6 + 1e-12), (90, 6 + 2e-12), (90, 12), (0, 12)])
    frame = geopandas.GeoDataFrame(geometry=[moat, spiky, box(0, 0, 2, 3.2e-8), box(0, 0, 2, 1e-13)], crs="EPSG:2180")
    result = centerlines(frame)
    assert_rows_equal_core(result, frame, [])
    assert result.geometry.iloc[0].is_closed and not result.geometry.iloc[1].is_closed
    assert result["error"].iloc[:3].isna().all()
    assert " wide " in result["error"].iloc[3]


def test_geographic_frames_are_computed_in_metres():
    lonlat = read_geojson("gambia_ne10m_lonlat.geojson", "EPSG:4326")
    utm = read_geojson("gambia_ne10m_utm28n.geojson", "EPSG:32628")
    in_degrees = centerlines(lonlat, spacing=2000.0)
    assert_rows_equal_core(in_degrees, lonlat, [], spacing=2000.0)
    in_metres = centerlines(utm, spacing=2000.0)
    # UTM's scale factor within the Gambia (about 150 km from the central meridian) is within 1e-3 of 1.
    for name in STATISTICS:
        assert in_degrees[name].iloc[0] == pytest.approx(in_metres[name].iloc[0], rel=2e-3), name
    assert in_degrees.crs == lonlat.crs
    # Back in degrees; straight in metres is not quite straight in degrees, hence the slack.
    line, country = in_degrees.geometry.iloc[0], lonlat.geometry.iloc[0]
    assert line.difference(country).length < 1e-5 * line.length


def test_split_points_in_another_crs_are_reprojected():
    rivers = read_geojson("river_2180.geojson", "EPSG:2180")
    points = read_geojson("split_points_2180.geojson", "EPSG:2180")
    direct = centerlines(rivers, points)
    reprojected = centerlines(rivers, points.to_crs("EPSG:4326"), snap_tolerance=0.01)
    for one, other in zip(direct.geometry, reprojected.geometry):
        assert one.hausdorff_distance(other) < 1e-3 * one.length


def test_core_keywords_are_forwarded_only_when_given(monkeypatch):
    from incircu_plugin.core import api

    seen = []

    def record(shape, split_points=None, **options):
        seen.append(options)
        return (yield from _multipolygon_centerline_steps(shape, split_points, **options))

    monkeypatch.setattr(api, "_multipolygon_centerline_steps", record)
    frame = geopandas.GeoSeries([box(0, 0, 100, 10)], crs="EPSG:2180")
    centerlines(frame, guide=geopandas.GeoSeries([LineString([(0, 5), (100, 5)])], crs="EPSG:2180"))
    assert "tolerance" not in seen[-1] and "end_rule" not in seen[-1]
    assert seen[-1]["guide"].equals(MultiLineString([[(0, 5), (100, 5)]]))
    # As in the plugin, a guide is near when its box meets the feature's grown by a quarter of its larger side.
    centerlines(frame, guide=geopandas.GeoSeries([LineString([(120, 5), (200, 5)])], crs="EPSG:2180"))
    assert seen[-1]["guide"].equals(MultiLineString([[(120, 5), (200, 5)]]))
    centerlines(frame, guide=geopandas.GeoSeries([LineString([(130, 5), (200, 5)])], crs="EPSG:2180"))
    assert seen[-1]["guide"] is None
    result = centerlines(frame, tolerance=0.5, end_rule="longest_path")  # a core without them: an error per row
    assert seen[-1]["tolerance"] == 0.5 and seen[-1]["end_rule"] == "longest_path"
    assert len(result) == 1


def test_guide_lines_choose_the_ends_in_any_crs():
    # A channel with a side arm: the guide runs along the main channel, so the line must follow it.
    channel = shapely.union_all([box(0, 0, 300, 20), box(140, 20, 160, 400)])
    guide = geopandas.GeoSeries([LineString([(0, 10), (300, 10)]), Point(0, 0)], crs="EPSG:2180")
    result = centerlines(geopandas.GeoSeries([channel], crs="EPSG:2180"), guide=guide.to_crs("EPSG:4326"))
    assert result["ends_from"].iloc[0] == "guide" and pandas.isna(result["error"].iloc[0])
    line = result.geometry.iloc[0]
    assert line.length == pytest.approx(300.0, rel=0.1) and line.bounds[3] < 20.0


def test_an_unexpected_exception_in_one_row_is_reported_there(monkeypatch):
    from incircu_plugin.core import api

    def fail_on_the_wide_one(shape, split_points=None, **options):
        if shape.bounds[3] > 10:
            raise RuntimeError("boom")
        return (yield from _multipolygon_centerline_steps(shape, split_points, **options))

    monkeypatch.setattr(api, "_multipolygon_centerline_steps", fail_on_the_wide_one)
    result = centerlines(geopandas.GeoSeries([box(0, 0, 100, 10), box(0, 0, 100, 20)], crs="EPSG:2180"))
    assert pandas.isna(result["error"].iloc[0]) and result["length"].iloc[0] > 0
    assert result["error"].iloc[1] == "unexpected RuntimeError: boom" and result.geometry.iloc[1] is None


def test_empty_frame_gives_an_empty_result_with_the_columns():
    result = centerlines(geopandas.GeoDataFrame(geometry=[], crs="EPSG:4326"))
    assert len(result) == 0 and result.crs == "EPSG:4326"
    assert {"length", "width_min", "width_mean", "width_max", "ends_found", "ends_from", "error"} <= set(result.columns)


def test_dask_frame_gives_a_lazy_frame_with_the_right_meta():
    dask_geopandas = pytest.importorskip("dask_geopandas")
    rivers = read_geojson("river_2180.geojson", "EPSG:2180")
    points = read_geojson("split_points_2180.geojson", "EPSG:2180")
    frame = geopandas.GeoDataFrame(
        geometry=[*rivers.geometry, None, box(0, 0, 40, 4), *rivers.geometry], crs="EPSG:2180", index=[5, 6, 7, 8, 9, 1]
    )
    lazy = centerlines(dask_geopandas.from_geopandas(frame, npartitions=3, sort=False), points)
    assert isinstance(lazy, dask_geopandas.GeoDataFrame)
    computed = lazy.compute(scheduler="synchronous")
    assert dict(lazy._meta.dtypes) == dict(computed.dtypes) and lazy.crs == computed.crs
    assert_frames_identical(computed, centerlines(frame, points))


def assert_frames_identical(one, other):
    """Same index, CRS, columns and values (geometries vertex for vertex within :data:`ROUNDING` of their
    extent, since other partitions trace other batches; NaN equal to NaN)."""
    assert list(one.index) == list(other.index) and one.crs == other.crs
    assert list(one.columns) == list(other.columns)
    same_geometry = [
        (a is None and b is None) or (a is not None and b is not None and a.equals_exact(b, rounding_of(b)))
        for a, b in zip(one.geometry, other.geometry)
    ]
    assert all(same_geometry)
    for name in STATISTICS:
        assert all(map(same_value, one[name].to_numpy(), other[name].to_numpy())), name
    assert (
        one["ends_found"].astype(object).fillna("na").tolist()
        == other["ends_found"].astype(object).fillna("na").tolist()
    )
    assert one["error"].fillna("").tolist() == other["error"].fillna("").tolist()
    assert one["error"].isna().tolist() == other["error"].isna().tolist()


@pytest.mark.slow
def test_dask_cluster_on_geoparquet_equals_the_serial_run(tmp_path, monkeypatch):
    dask_geopandas = pytest.importorskip("dask_geopandas")
    distributed = pytest.importorskip("distributed")
    pytest.importorskip("pyarrow")
    count = 10_000
    channels, split_points, bad_rows = channels_lonlat(count, seed=12)
    layer = geopandas.GeoDataFrame({"row": np.arange(count)}, geometry=channels, crs="EPSG:4326")
    layer.index = 3 * layer.index + 7  # not a RangeIndex: the index must come back as it was
    dask_geopandas.from_geopandas(layer, npartitions=8, sort=False).to_parquet(tmp_path / "channels")
    geopandas.GeoDataFrame(geometry=split_points, crs="EPSG:4326").to_parquet(tmp_path / "ends.parquet")
    ends = geopandas.read_parquet(tmp_path / "ends.parquet")
    # Spawned workers import the core from the repository, as an installed package would be imported.
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(filter(None, [str(REPOSITORY), os.environ.get("PYTHONPATH")])))
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster),
    ):
        lazy_layer = dask_geopandas.read_parquet(tmp_path / "channels")
        assert lazy_layer.npartitions > 1 and lazy_layer.crs == "EPSG:4326"
        lazy = centerlines(lazy_layer, ends, spacing=20.0)
        lazy.to_parquet(tmp_path / "centerlines")
        read_layer = lazy_layer.compute()
    distributed_result = geopandas.read_parquet(tmp_path / "centerlines")
    serial = centerlines(read_layer, ends, spacing=20.0)
    assert len(serial) == count
    assert_frames_identical(distributed_result, serial)
    errors = set(np.flatnonzero(serial["error"].notna().to_numpy()).tolist())
    assert errors == bad_rows
    assert serial.geometry.iloc[sorted(set(range(count)) - bad_rows)].notna().all()


def reservoirs_lonlat():
    """The real reservoirs (Natural Earth polygons, lon/lat) as a frame indexed by name."""
    features = json.loads(RESERVOIRS.read_text(encoding="utf-8"))["features"]
    polygons = [f for f in features if f["properties"]["role"] == "polygon"]
    return geopandas.GeoDataFrame(
        geometry=[shapely.geometry.shape(f["geometry"]) for f in polygons],
        index=[f["properties"]["name"] for f in polygons],
        crs="EPSG:4326",
    )


def expected_labels(data, **options):
    """``label_lines`` on the frame's features as an array (each in a LocalProjection when geographic), and
    each feature's largest part's label: per row ``(label or None, geometry in the layer's CRS or None, error
    or None)``. Computed together as the frame is (the joint tracing's rounding is then the same)."""
    shapes = list(data.geometry.values)
    projections = [
        LocalProjection.around(shape, data.crs.srs)
        if data.crs.is_geographic and shape is not None and not shape.is_empty
        else None
        for shape in shapes
    ]
    local = [
        shape if projection is None else projection.to_local(shape) for shape, projection in zip(shapes, projections)
    ]
    rows = []
    for shape, projection, outcomes in zip(shapes, projections, label_lines(local, **options)):
        if isinstance(outcomes, Exception):
            rows.append((None, None, str(outcomes)))
            continue
        prefix = "part {}: " if isinstance(shape, MultiPolygon) else ""
        error = "; ".join(prefix.format(o.part_index) + str(o.error) for o in outcomes if o.error is not None)
        label = feature_label(outcomes, shape)
        geometry = None if label is None else label.geometry
        if projection is not None and geometry is not None:
            geometry = projection.to_geographic(geometry)
        rows.append((label, geometry, error or None))
    return rows


def assert_labels_equal_core(result, data, **options):
    assert list(result.index) == list(data.index) and result.crs == data.crs
    assert list(result.columns) == ["kind", "length", "width_min", "elongation", "error", "geometry"]
    for (name, row), line, (label, geometry, error) in zip(
        result.iterrows(), result.geometry, expected_labels(data, **options)
    ):
        assert (None if pandas.isna(row["error"]) else row["error"]) == error, name
        if label is None:
            assert line is None and pandas.isna(row["kind"]) and np.isnan(row["length"]), name
            continue
        assert row["kind"] == label.kind and line.wkb == geometry.wkb, name
        for column in ("length", "width_min", "elongation"):
            assert row[column] == getattr(label, column), (name, column)


@pytest.mark.slow
def test_labels_of_real_reservoirs_in_lon_lat_equal_label_lines_row_by_row():
    lakes = reservoirs_lonlat()
    result = frame_labels(lakes)
    assert_labels_equal_core(result, lakes)
    assert result["error"].isna().all() and (result["kind"] == "line").all()
    # In metres although the layer is in degrees: each lake's label stays inside it, its length is a length on
    # the ground (a Natural Earth reservoir is kilometres long, not a fraction of a degree).
    assert all(lake.contains(line) for lake, line in zip(lakes.geometry, result.geometry))
    assert (result["length"] > 1000.0).all() and (result["width_min"] < result["length"]).all()


def test_labels_in_a_projected_crs_with_options_a_round_lake_and_a_multipolygon():
    lakes = reservoirs_lonlat().to_crs("EPSG:3857")
    round_lake = Point(0, 0).buffer(5000.0)
    two_lakes = MultiPolygon([box(0, 0, 100, 100), box(200, 0, 1200, 100)])
    frame = geopandas.GeoDataFrame(geometry=[*lakes.geometry[:4], round_lake, two_lakes], crs="EPSG:3857")
    result = frame_labels(frame, trim=0.7, clearance=0.3, min_elongation=4.0)
    assert_labels_equal_core(result, frame, trim=0.7, clearance=0.3, min_elongation=4.0)
    assert result["kind"].tolist() == ["line"] * 4 + ["point", "line"]
    assert result.geometry.iloc[4].distance(Point(0, 0)) < 1e-6 * 5000.0
    # The larger part (the 1000 x 100 box) gives the multipolygon's label.
    assert result.geometry.iloc[5].within(box(200, 0, 1200, 100))


def test_a_bad_label_row_reports_its_error_and_the_others_are_labelled():
    good = reservoirs_lonlat().to_crs("EPSG:3857").geometry.iloc[0]
    frame = geopandas.GeoDataFrame(
        geometry=[good, None, Polygon(), LineString([(0, 0), (1, 1)]), box(0, 0, 100, 10)], crs="EPSG:3857"
    )
    result = frame_labels(frame)
    assert_labels_equal_core(result, frame)
    assert result["error"].isna().tolist() == [True, False, False, False, True]
    assert result["error"].iloc[1] == "The polygon is null (no geometry)."
    with pytest.raises(IncirCuError):  # a bad option is one error for every row, as the core raises it
        label_lines(box(0, 0, 100, 10), clearance=0.6)
    assert_labels_equal_core(frame_labels(frame, clearance=0.6), frame, clearance=0.6)
    assert frame_labels(frame, clearance=0.6)["error"].notna().all()


@pytest.mark.slow
def test_dask_labels_are_lazy_and_equal_the_eager_run_of_each_partition_byte_for_byte():
    """Each partition is computed as the eager API computes that frame. (Rows traced in other batches may
    differ a little: the joint tracing's rounding moves the main stem by ~1e-9 of its extent, which can move
    where the label's smoothing and trimming settle.)"""
    dask_geopandas = pytest.importorskip("dask_geopandas")
    lakes = reservoirs_lonlat()
    frame = geopandas.GeoDataFrame(geometry=[*lakes.geometry, None], index=[*lakes.index, "none"], crs="EPSG:4326")
    lazy_frame = dask_geopandas.from_geopandas(frame, npartitions=3, sort=False)
    lazy = frame_labels(lazy_frame)
    assert isinstance(lazy, dask_geopandas.GeoDataFrame)
    computed = lazy.compute(scheduler="synchronous")
    assert dict(lazy._meta.dtypes) == dict(computed.dtypes) and lazy.crs == computed.crs
    eager = pandas.concat([frame_labels(part.compute()) for part in lazy_frame.partitions])
    assert list(computed.index) == list(frame.index) == list(eager.index)
    assert computed.geometry.to_wkb().tolist() == eager.geometry.to_wkb().tolist()
    pandas.testing.assert_frame_equal(
        pandas.DataFrame(computed.drop(columns="geometry")), pandas.DataFrame(eager.drop(columns="geometry"))
    )
    serial = frame_labels(frame)
    assert computed["kind"].equals(serial["kind"]) and computed["error"].equals(serial["error"])
