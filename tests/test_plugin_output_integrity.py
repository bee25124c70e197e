"""Every output is complete and closed when the run ends, whichever features are skipped.

A skipped feature once kept the output sinks alive in a reference cycle (stored error -> traceback -> frames ->
progress callback -> writer -> sinks): ``qgis_process`` then exited with a GeoPackage holding no layer, and an
in-process output stayed unreadable until the garbage collector ran. Inputs: a 100 x 10 box and a chevron with
split points at their short sides, and a bow-tie (invalid, always skipped) first, in the middle or last.
"""

import gc
import json
import sqlite3

import pytest
from qgis.core import QgsProcessingFeedback, QgsVectorLayer

# The 100 x 10 box, and a chevron whose bend gives the optional outputs vertices with a positive width.
GOOD_BOXES = (
    [[0, 0], [100, 0], [100, 10], [0, 10], [0, 0]],
    [[0, 40], [50, 50], [100, 40], [100, 50], [50, 60], [0, 50], [0, 40]],
)
BOW_TIE = [[0, 20], [100, 30], [100, 20], [0, 30], [0, 20]]
SPLIT_POINTS = ([0, 5], [100, 5], [0, 45], [100, 45])
EPSG_2180 = {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2180"}}
OPTIONAL_OUTPUTS = ("OUTPUT_VERTICES", "OUTPUT_CIRCLES", "OUTPUT_TRANSECTS")
ALL_OUTPUTS = ("OUTPUT", *OPTIONAL_OUTPUTS)
FORMATS = ("gpkg", "geojson", "shp")
BAD_POSITIONS = ("first", "middle", "last")


def write_collection(path, geometries):
    features = [{"type": "Feature", "properties": {"n": i}, "geometry": g} for i, g in enumerate(geometries)]
    return write_features(path, features)


def write_features(path, features):
    path.write_text(json.dumps({"type": "FeatureCollection", "crs": EPSG_2180, "features": features}))
    return path


def polygons_with_bad_feature(folder, position):
    """The two boxes and the bow-tie at ``position``; returns the GeoJSON path."""
    rings = list(GOOD_BOXES)
    rings.insert(BAD_POSITIONS.index(position), BOW_TIE)
    return write_collection(
        folder / f"polygons_{position}.geojson", [{"type": "Polygon", "coordinates": [r]} for r in rings]
    )


def split_points(folder):
    return write_collection(
        folder / "split_points.geojson", [{"type": "Point", "coordinates": p} for p in SPLIT_POINTS]
    )


def feature_count(path):
    layer = QgsVectorLayer(str(path), "output", "ogr")
    assert layer.isValid(), f"{path} has no readable layer"
    return layer.featureCount()


def reference_counts(polygons, points):
    """Feature count of every output of an in-process run with memory outputs (the memory case itself)."""
    import processing

    parameters = {"INPUT": str(polygons), "SPLIT_POINTS": str(points), **{name: "memory:" for name in ALL_OUTPUTS}}
    results = processing.run("incircu:polygoncenterline", parameters)
    assert results["SKIPPED_COUNT"] == 1
    counts = {name: results[name].featureCount() for name in ALL_OUTPUTS}
    assert counts["OUTPUT"] == len(GOOD_BOXES)
    assert counts["OUTPUT_VERTICES"] == sum(f["n_vertices"] for f in results["OUTPUT"].getFeatures())
    assert min(counts.values()) > 0
    return counts


@pytest.mark.slow
def test_qgis_process_writes_every_output_whatever_feature_is_skipped(qgis_process, provider, tmp_path):
    points = split_points(tmp_path)
    for shift, position in enumerate(BAD_POSITIONS):
        polygons = polygons_with_bad_feature(tmp_path, position)
        expected = reference_counts(polygons, points)
        # Each output gets another format in each run: over the three runs every output is written in every format.
        paths = {
            name: tmp_path / f"{position}_{name.lower()}.{FORMATS[(shift + i) % len(FORMATS)]}"
            for i, name in enumerate(ALL_OUTPUTS)
        }
        done = qgis_process(
            "run",
            "incircu:polygoncenterline",
            "--",
            f"INPUT={polygons}",
            f"SPLIT_POINTS={points}",
            *(f"{name}={path}" for name, path in paths.items()),
        )
        assert done.returncode == 0, done.stdout + done.stderr
        assert "SKIPPED_COUNT:\t1" in done.stdout
        for name, path in paths.items():
            assert feature_count(path) == expected[name], (position, name, path.suffix)


def test_geopackage_is_readable_right_after_an_in_process_run(provider, tmp_path):
    import processing

    polygons = polygons_with_bad_feature(tmp_path, "middle")
    paths = {name: tmp_path / f"{name.lower()}.gpkg" for name in ALL_OUTPUTS}
    expected = reference_counts(polygons, split_points(tmp_path))
    parameters = {"INPUT": str(polygons), "SPLIT_POINTS": str(tmp_path / "split_points.geojson")}
    # Without the collector, only reference counting can close the outputs: a cycle holding a sink shows.
    gc.disable()
    try:
        processing.run("incircu:polygoncenterline", {**parameters, **{k: str(p) for k, p in paths.items()}})
        counts = {name: feature_count(path) for name, path in paths.items()}
    finally:
        gc.enable()
    assert counts == expected


def test_cancelled_run_leaves_the_geopackage_unlocked(provider, tmp_path):
    import processing

    class CancelAfterFirstFeature(QgsProcessingFeedback):
        def setProgress(self, progress):
            super().setProgress(progress)
            if progress >= 30:
                self.cancel()

    output = tmp_path / "cancelled.gpkg"
    gc.disable()
    try:
        processing.run(
            "incircu:polygoncenterline",
            {
                "INPUT": str(polygons_with_bad_feature(tmp_path, "first")),
                "SPLIT_POINTS": str(split_points(tmp_path)),
                "OUTPUT": str(output),
            },
            feedback=CancelAfterFirstFeature(),
        )
        connection = sqlite3.connect(output, timeout=0)
        try:
            connection.execute("BEGIN EXCLUSIVE")
            connection.rollback()
        finally:
            connection.close()
    finally:
        gc.enable()


def test_lines_centerline_output_is_closed_when_a_pair_is_skipped(provider, tmp_path):
    import processing

    def lines(name, coordinates):
        features = [
            {"type": "Feature", "properties": {"reach": i}, "geometry": {"type": "LineString", "coordinates": c}}
            for i, c in enumerate(coordinates)
        ]
        return write_features(tmp_path / name, features)

    # Reach 1 crosses its other bank: skipped between two good reaches.
    banks_a = lines("a.geojson", [[[0, 0], [100, 0]], [[0, 100], [100, 100]], [[0, 200], [100, 200]]])
    banks_b = lines("b.geojson", [[[100, 8], [0, 8]], [[0, 90], [100, 110]], [[0, 208], [100, 208]]])
    output = tmp_path / "between.gpkg"
    gc.disable()
    try:
        results = processing.run(
            "incircu:linescenterline",
            {
                "LINES_A": str(banks_a),
                "LINES_B": str(banks_b),
                "PAIR_FIELD_A": "reach",
                "PAIR_FIELD_B": "reach",
                "OUTPUT": str(output),
            },
        )
        count = feature_count(output)
    finally:
        gc.enable()
    assert (results["CENTERLINE_COUNT"], results["SKIPPED_COUNT"]) == (2, 1)
    assert count == 2
