"""The centerline algorithms compute their features in batches traced together (``FeatureRun.run_batches``).

With the batch size made small, a layer spans several batches: every feature's output must equal the core
on that feature alone (within ``ROUNDING`` of its extent: the joint tracing may round differently), in input
order; bad features first, in the middle or last in a batch are skipped with their own id; a cancel stops
the run with complete batches written.
"""

import importlib
import re

import numpy as np
import processing
import pytest
import shapely
from qgis.core import QgsFeature, QgsGeometry, QgsProcessingFeedback, QgsVectorLayer
from shapely.geometry import LineString, MultiPolygon, Polygon, box

from incircu_plugin.core import LocalProjection, lines_centerline, multipolygon_centerlines

#: Largest difference allowed between a feature computed in a batch and alone, as a fraction of its extent.
ROUNDING = 1e-9

#: Features per batch in these tests.
BATCH = 3

BOW_TIE = Polygon([(0, 0), (10, 10), (10, 0), (0, 10)])


class RecordingFeedback(QgsProcessingFeedback):
    """Keeps warnings and progress; cancels once progress passes ``cancel_at`` percent (never when None)."""

    def __init__(self, cancel_at=None):
        super().__init__()
        self.warnings, self.steps, self.cancel_at = [], [], cancel_at

    def pushWarning(self, message):
        self.warnings.append(message)

    def setProgress(self, progress):
        super().setProgress(progress)
        self.steps.append(progress)
        if self.cancel_at is not None and progress > self.cancel_at:
            self.cancel()


@pytest.fixture
def small_batches(provider, monkeypatch):
    """The plugin's batches made ``BATCH`` features long."""
    _many = importlib.import_module("incircu.incircu_plugin.core._many")
    monkeypatch.setattr(_many, "BATCH_FEATURES", BATCH)


def memory_layer(kind, crs, geometries, numbers=None):
    """A memory layer with one feature per geometry (None: no geometry) and an ``n`` field (default: its position)."""
    layer = QgsVectorLayer(f"{kind}?crs={crs}&field=n:integer", "input", "memory")
    features = []
    for n, geometry in zip(numbers or range(len(geometries)), geometries):
        feature = QgsFeature(layer.fields())
        feature.setAttributes([n])
        if geometry is not None:
            feature.setGeometry(QgsGeometry.fromWkt(geometry.wkt))
        features.append(feature)
    assert layer.dataProvider().addFeatures(features)
    return layer


def channel(index, bad):
    """Channel ``index``: a gently bent box, or a bow-tie (invalid) where ``bad``; a row of them side by side."""
    x0 = 300.0 * index
    if bad:
        return shapely.affinity.translate(BOW_TIE, x0)
    return Polygon([(x0, 0), (x0 + 100, 8 + index), (x0 + 200, 0), (x0 + 200, 12), (x0 + 100, 20 + index), (x0, 12)])


def output_by_n(layer):
    """The output features keyed by the input's ``n``, in the order written."""
    return {feature["n"]: feature for feature in layer.getFeatures()}


def as_shapely(geometry):
    flat = QgsGeometry(geometry)
    flat.get().dropMValue()
    return shapely.from_wkb(bytes(flat.asWkb()))


def axis_tolerance(shape):
    """The core's default tolerance for a polygon without holes: its typical width (area over half its
    perimeter, the mean length of its two chains) / 200, CRS units."""
    return max(2.0 * part.area / part.length / 200.0 for part in shapely.get_parts(shape))


def assert_close(line, expected, tolerance, label):
    """A line computed in a batch against the core alone: the shared frame's rounding may tip the final
    simplification between equally good vertices, so the lines agree within the axis ``tolerance`` and their
    ends within ``ROUNDING`` of the extent."""
    coordinates = shapely.get_coordinates(expected)
    extent = np.max(np.ptp(coordinates, axis=0))
    rounding = ROUNDING * extent + 16 * np.spacing(np.max(np.abs(coordinates)))
    assert line.hausdorff_distance(expected) <= tolerance + rounding, label
    for one, other in zip(shapely.get_parts(line), shapely.get_parts(expected), strict=True):
        for index in (0, -1):
            assert np.hypot(*np.subtract(one.coords[index], other.coords[index])) <= rounding, label


def skipped_ids(feedback):
    """What the "Feature ... skipped" warnings name (``"7"`` or ``"7 (part 2)"`` for its second part), in order."""
    return [found.group(1) for found in map(re.compile("Feature (.+?) skipped: ").match, feedback.warnings) if found]


def test_polygons_over_several_batches_equal_the_core_per_feature(small_batches):
    # Bad features first (0), in the middle (4) and last (8) of a batch of 3; a missing geometry (10); a
    # multipart feature (12) whose second part is bad.
    bad = {0, 4, 8}
    shapes = [None if n == 10 else channel(n, n in bad) for n in range(14)]
    shapes[12] = MultiPolygon([channel(12, False), shapely.affinity.translate(BOW_TIE, 3600, 100)])
    source = memory_layer("MultiPolygon", "EPSG:2180", shapes)
    ids = [feature.id() for feature in source.getFeatures()]
    feedback = RecordingFeedback()
    results = processing.run("incircu:polygoncenterline", {"INPUT": source, "OUTPUT": "memory:"}, feedback=feedback)
    expected_skips = [str(ids[n]) for n in (0, 4, 8, 10)] + [f"{ids[12]} (part 2)"]
    assert skipped_ids(feedback) == expected_skips
    assert results["SKIPPED_COUNT"] == len(expected_skips)
    written = output_by_n(results["OUTPUT"])
    good = [n for n in range(14) if n not in bad and n != 10]
    assert list(written) == good  # in input order
    for n in good:
        outcomes = multipolygon_centerlines(shapes[n], end_cap="runout")  # the plugin's default
        lines = [outcome.result.line for outcome in outcomes if outcome.error is None]
        assert_close(as_shapely(written[n].geometry()), shapely.MultiLineString(lines), axis_tolerance(shapes[n]), n)
    assert feedback.steps == sorted(feedback.steps) and feedback.steps[-1] == 100.0


def test_geographic_features_in_one_batch_are_written_in_their_own_frame(small_batches):
    # Far-apart features in degrees: each is computed in a projection centred on it and must come back there.
    centres = [(-170.0, 60.0), (20.0, 0.0), (100.0, -45.0), (175.0, 10.0)]
    shapes = [shapely.affinity.translate(box(0, 0, 0.02, 0.002), x, y) for x, y in centres]
    source = memory_layer("Polygon", "EPSG:4326", shapes)
    results = processing.run("incircu:polygoncenterline", {"INPUT": source, "OUTPUT": "memory:"})
    written = output_by_n(results["OUTPUT"])
    assert list(written) == list(range(len(shapes)))
    for n, shape in enumerate(shapes):
        projection = LocalProjection.around(shape, "EPSG:4326")
        (outcome,) = multipolygon_centerlines(projection.to_local(shape), end_cap="runout")
        # Compared in metres, in the feature's own projection: a line written through another feature's
        # projection would land kilometres away.
        line = projection.to_local(as_shapely(written[n].geometry()))
        assert_close(line, outcome.result.line, axis_tolerance(projection.to_local(shape)), n)


def test_cancel_mid_layer_writes_whole_batches_only(small_batches):
    shapes = [channel(n, False) for n in range(12)]
    source = memory_layer("Polygon", "EPSG:2180", shapes)
    feedback = RecordingFeedback(cancel_at=40.0)
    results = processing.run("incircu:polygoncenterline", {"INPUT": source, "OUTPUT": "memory:"}, feedback=feedback)
    assert feedback.isCanceled()
    written = list(output_by_n(results["OUTPUT"]))
    # The batch running when the user cancelled is dropped: what is written is whole batches from the start.
    assert len(written) % BATCH == 0 and 0 < len(written) < len(shapes)
    assert written == list(range(len(written)))


def test_lines_over_several_batches_equal_the_core_per_pair(small_batches):
    # Pair 4 crosses its other bank (skipped, middle of the second batch); pair 6 has no line in LINES_B.
    banks_a = [LineString([(0, 100 * n), (200, 100 * n + 5)]) for n in range(8)]
    banks_b = [LineString([(200, 100 * n + 12), (0, 100 * n + 10)]) for n in range(8)]
    banks_b[4] = LineString([(0, 400 + 20), (200, 400 - 20)])
    layer_a = memory_layer("LineString", "EPSG:2180", banks_a)
    paired = [n for n in range(8) if n != 6]
    layer_b = memory_layer("LineString", "EPSG:2180", [banks_b[n] for n in paired], paired)
    feedback = RecordingFeedback()
    results = processing.run(
        "incircu:linescenterline",
        {"LINES_A": layer_a, "LINES_B": layer_b, "PAIR_FIELD_A": "n", "PAIR_FIELD_B": "n", "OUTPUT": "memory:"},
        feedback=feedback,
    )
    ids = [feature.id() for feature in layer_a.getFeatures()]
    assert skipped_ids(feedback) == [str(ids[4]), str(ids[6])]
    written = output_by_n(results["OUTPUT"])
    assert list(written) == [0, 1, 2, 3, 5, 7]
    for n in written:
        expected = lines_centerline(banks_a[n], banks_b[n], end_cap="runout").line
        # The default tolerance between two lines: the area between them over their mean length, / 200.
        between = Polygon([*banks_a[n].coords, *banks_b[n].coords])  # the banks face each other
        tolerance = between.area / (0.5 * (banks_a[n].length + banks_b[n].length)) / 200.0
        assert_close(as_shapely(written[n].geometry()), expected, tolerance, n)
