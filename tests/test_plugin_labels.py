"""``incircu:labellines``, the expression functions and the shipped lake-label style, in QGIS (offscreen).

The reservoirs are the Natural Earth lakes of ``tests/data/real_rivers_ne_lonlat.geojson`` (lon/lat). The
rendered check draws them with ``styles/lake_labels.qml`` and reads where QGIS placed each label
(``QgsLabelingResults``): every label placed along a label line lies inside its lake.
"""

import importlib.util

import processing
import pytest
import shapely
import shapely.affinity
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsExpression,
    QgsExpressionContext,
    QgsExpressionContextUtils,
    QgsGeometry,
)
from shapely.geometry import Point, box

from incircu_plugin.core import LocalProjection, feature_label, label_lines
from tests.support.project import REPOSITORY

SPEC = importlib.util.spec_from_file_location("label_style", REPOSITORY / "scripts" / "make_label_style.py")
label_style = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(label_style)

FIELDS = ["source_fid", "part", "length", "width_min", "elongation", "kind"]


def as_shapely(geometry):
    return shapely.from_wkb(bytes(geometry.asWkb()))


def run_labels(layer, **parameters):
    return processing.run(
        "incircu:labellines", {"INPUT": layer, "OUTPUT": "memory:", "OUTPUT_POINTS": "memory:", **parameters}
    )


def projected_layer(shapes):
    """A memory polygon layer (EPSG:2180) of Shapely shapes with a ``name``."""
    return label_style.polygon_layer(shapes, [f"Lake number {index}" for index in range(len(shapes))], "EPSG:2180")


def evaluate(layer, feature, text):
    """Evaluate an expression for ``feature`` of ``layer`` (with the layer's scope, as a renderer does)."""
    context = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(layer))
    context.setFeature(feature)
    expression = QgsExpression(text)
    value = expression.evaluate(context)
    assert not expression.hasEvalError(), expression.evalErrorString()
    return value


@pytest.fixture(scope="module")
def reservoirs(qgis_app):
    return label_style.lakes_layer()


@pytest.fixture(autouse=True)
def expression_functions(provider):
    """The plugin's expression functions, as its ``initGui`` registers them: a test that unloaded the plugin
    before (tests/test_plugin_loading.py) removed them."""
    from incircu.algorithms.expressions import register_functions

    register_functions()


def test_label_lines_of_lon_lat_reservoirs(provider, reservoirs):
    results = run_labels(reservoirs)
    lines = results["OUTPUT"]
    assert results["SKIPPED_COUNT"] == 0
    assert results["CENTERLINE_COUNT"] == lines.featureCount() == reservoirs.featureCount()
    assert results["OUTPUT_POINTS"].featureCount() == 0
    assert [field.name() for field in lines.fields()] == ["name", *FIELDS]
    lakes = {feature.id(): feature for feature in reservoirs.getFeatures()}
    polygons = {fid: as_shapely(feature.geometry()) for fid, feature in lakes.items()}
    projections = {fid: LocalProjection.around(polygon) for fid, polygon in polygons.items()}
    # The core on the same polygons in the same local projections, computed together as the algorithm does.
    together = label_lines([projections[fid].to_local(polygon) for fid, polygon in polygons.items()])
    expected = {fid: outcomes[0].result for fid, outcomes in zip(polygons, together)}
    for feature in lines.getFeatures():
        fid = feature["source_fid"]
        line = as_shapely(feature.geometry())
        assert feature["name"] == lakes[fid]["name"]
        assert feature["kind"] == "line" and feature["part"] == 0
        assert polygons[fid].contains(line)
        assert feature["length"] == pytest.approx(expected[fid].length, rel=1e-6)
        assert feature["width_min"] == pytest.approx(expected[fid].width_min, rel=1e-6)
        assert feature["elongation"] == pytest.approx(expected[fid].elongation, rel=1e-6)
        assert line.hausdorff_distance(projections[fid].to_geographic(expected[fid].geometry)) < 1e-9


def test_compact_lakes_get_label_points(provider):
    lakes = projected_layer([Point(500, 500).buffer(300, quad_segs=64), box(2000, 0, 6000, 500)])
    results = run_labels(lakes)
    points, lines = results["OUTPUT_POINTS"], results["OUTPUT"]
    assert points.featureCount() == 1 and lines.featureCount() == 1
    point = next(points.getFeatures())
    assert point["kind"] == "point" and point["length"] == 0
    assert as_shapely(point.geometry()).distance(Point(500, 500)) < 1e-6 * 300
    assert point["width_min"] == pytest.approx(600, rel=1e-3)
    assert next(lines.getFeatures())["kind"] == "line"


def test_expression_gives_the_algorithms_line_to_the_last_bit_on_a_projected_layer(provider, reservoirs):
    # The reservoirs, projected: the algorithm (its features in batches) and the expression (one feature alone)
    # give the core the same coordinates, so the same label bytes (issue 39: no result depends on its batch).
    projected = projected_layer(
        [shapely.affinity.scale(as_shapely(f.geometry()), 9e4, 1.1e5, origin=(0, 0)) for f in reservoirs.getFeatures()]
    )
    results = run_labels(projected)
    written = {feature["source_fid"]: feature for feature in results["OUTPUT"].getFeatures()}
    assert len(written) == projected.featureCount()
    for feature in projected.getFeatures():
        value = evaluate(projected, feature, "incircu_label_line($geometry)")
        assert as_shapely(value).wkb == as_shapely(written[feature.id()].geometry()).wkb, feature.id()
        assert evaluate(projected, feature, "incircu_label_line($geometry)").equals(value)


def test_expression_in_degrees_is_the_cores_label_in_its_local_frame(provider, reservoirs):
    # In degrees the expression projects with QGIS's own transformations (it runs in render threads, where pyproj
    # is unsafe), the algorithm with the core's LocalProjection: the frames agree to about 1e-9 of the lake's
    # size, and a label's trimmed ends may move a lot for that (the width profile crossing the trim share); so
    # the expression is checked against the core's label of its own frame's coordinates, bit for bit.
    from incircu.algorithms.expressions import ThreadFrame

    for feature in reservoirs.getFeatures():
        value = evaluate(reservoirs, feature, "incircu_label_line($geometry)")
        frame = ThreadFrame(feature.geometry(), reservoirs.crs())
        shape = frame.to_core(feature.geometry())
        expected = frame.to_layer(feature_label(label_lines(shape), shape).geometry)
        assert as_shapely(value).wkb == as_shapely(expected).wkb, feature.id()


def test_expression_options_and_points(provider):
    lakes = projected_layer([Point(500, 500).buffer(300, quad_segs=64), box(2000, 0, 6000, 500)])
    round_lake, long_lake = list(lakes.getFeatures())
    assert evaluate(lakes, round_lake, "incircu_label_line($geometry, points:=false)") is None
    point = evaluate(lakes, round_lake, "incircu_label_line($geometry)")
    assert as_shapely(point).distance(Point(500, 500)) < 1e-3
    narrow = as_shapely(evaluate(lakes, long_lake, "incircu_label_line($geometry, clearance:=0.45, trim:=0.9)"))
    [outcome] = label_lines(as_shapely(long_lake.geometry()), clearance=0.45, trim=0.9)
    assert narrow.equals_exact(outcome.result.geometry, 1e-6)
    centerline = as_shapely(evaluate(lakes, long_lake, "incircu_centerline($geometry)"))
    assert centerline.geom_type == "MultiLineString" and centerline.length == pytest.approx(4000, rel=1e-6)
    context = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(lakes))
    context.setFeature(long_lake)
    bad = QgsExpression("incircu_label_line($geometry, clearance:=0.7)")
    assert bad.evaluate(context) is None


def test_an_invalid_option_is_the_expressions_error_every_time(provider):
    """An option out of its range is reported through QGIS's evaluation error (the core's message, worded by
    ``messages.core_text``), on every evaluation: it is not cached as a NULL result."""
    lakes = projected_layer([box(2000, 0, 6000, 500)])
    context = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(lakes))
    context.setFeature(next(lakes.getFeatures()))
    for _ in range(2):
        bad = QgsExpression("incircu_label_line($geometry, clearance:=0.7)")
        assert bad.evaluate(context) is None
        assert bad.hasEvalError()
        assert "clearance" in bad.evalErrorString() and "0.7" in bad.evalErrorString()


def test_arguments_are_converted_once_and_cached_labels_equal_computed_ones(provider):
    """A redraw evaluates the function for every feature with the same arguments: they are converted once per
    distinct tuple (a bad one every time, giving its error), and the cached label equals a fresh computation."""
    from incircu.algorithms import expressions

    [function] = [f for f in expressions.REGISTERED if f.name() == "incircu_label_line"]
    lakes = projected_layer([box(2000, 0, 6000, 500), box(0, 1000, 3000, 1400)])
    converted = []
    convert = function.convert
    function.convert = lambda values: converted.append(tuple(values)) or convert(values)
    try:
        text = "incircu_label_line($geometry, trim:=0.8)"
        for feature in lakes.getFeatures():
            for _ in range(3):
                value = evaluate(lakes, feature, text)
                fresh = expressions.compute_label(
                    feature.geometry(), lakes.crs(), {"trim": 0.8, "end_rule": "main_stem"}
                )
                assert as_shapely(value).equals_exact(as_shapely(fresh), 0.0)
        assert len(converted) == 1
        evaluate(lakes, feature, "incircu_label_line($geometry, trim:=0.7)")
        assert len(converted) == 2
        context = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(lakes))
        context.setFeature(feature)
        for _ in range(2):
            bad = QgsExpression("incircu_label_line($geometry, trim:='wide')")
            assert bad.evaluate(context) is None and "trim must be a number" in bad.evalErrorString()
        assert len(converted) == 4
    finally:
        function.convert = convert


def test_functions_are_in_the_incircu_group_and_removed_on_unload(provider):
    from incircu.algorithms.expressions import register_functions, unregister_functions

    for name in ("incircu_centerline", "incircu_label_line"):
        index = QgsExpression.functionIndex(name)
        assert index >= 0
        function = QgsExpression.Functions()[index]
        assert function.group() == "IncirCu" and name in function.helpText()
    unregister_functions()
    try:
        assert not QgsExpression.isFunctionName("incircu_label_line")
    finally:
        register_functions()
    assert QgsExpression.isFunctionName("incircu_label_line")


def test_rendered_labels_lie_inside_their_lakes(provider, reservoirs):
    """Draw each reservoir with the shipped style; every character QGIS placed along a label line lies inside
    its lake (its box's centre: the box itself pokes out where the lake is narrower than the lettering at the
    map's scale, which is the style's choice of size, not the line's)."""
    reservoirs.loadNamedStyle(str(REPOSITORY / "styles" / "lake_labels.qml"))
    crs = QgsCoordinateReferenceSystem("EPSG:3857")
    lakes = {}
    for lake in reservoirs.getFeatures():
        geometry = QgsGeometry(lake.geometry())
        geometry.transform(label_style.to_map(reservoirs, crs))
        lakes[lake.id()] = as_shapely(geometry)
    labelled, names = set(), lakes_names(reservoirs)
    for feature in reservoirs.getFeatures():
        extent = label_style.lake_extent(reservoirs, feature["name"], crs)
        _, results = label_style.render(reservoirs, extent, label_style.PANEL, crs)
        for label in results.allLabels():
            if label.isUnplaced:
                continue
            assert label.labelText == names[label.featureId]
            character = as_shapely(label.labelGeometry)
            assert lakes[label.featureId].contains(character.centroid), (feature["name"], label.labelText)
            labelled.add(label.featureId)
    # Not a vacuous check: at this size (11 pt) about half the reservoirs get their name (the others are too
    # narrow at the scale of their whole extent, or their label line is shorter than the name).
    assert len(labelled) >= 6


def lakes_names(layer):
    return {feature.id(): feature["name"] for feature in layer.getFeatures()}
