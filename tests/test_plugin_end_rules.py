"""``END_RULE`` and ``GUIDE_LINES`` of ``incircu:polygoncenterline``, on a synthetic river with a long side arm.

The river is 1000 long and 40 wide with a 900 x 6 arm (``tests/support/reservoirs.py``): the main stem ends at
the middles of the river's flat caps, the longest path at the arm's tip.
"""

import processing
import shapely
from qgis.core import QgsFeature, QgsGeometry, QgsVectorLayer

from tests.support.reservoirs import straight_river_with_long_arm

RIVER_WIDTH = 40.0

#: Fraction of the river's width within which an end must match a flat cap's middle (as in test_core_ends).
FLAT_CAP_TOLERANCE = 0.01


def memory_layer(kind, geometries, crs="EPSG:2180"):
    """A memory layer of ``kind`` ("Polygon", "LineString", ...) holding the Shapely geometries."""
    layer = QgsVectorLayer(f"{kind}?crs={crs}", kind, "memory")
    features = []
    for geometry in geometries:
        feature = QgsFeature()
        feature.setGeometry(QgsGeometry.fromWkt(geometry.wkt))
        features.append(feature)
    layer.dataProvider().addFeatures(features)
    return layer


def river_line(parameters):
    """Run the algorithm on the river; return the one output feature and its line as Shapely."""
    polygon, _, _, _ = straight_river_with_long_arm()
    results = processing.run(
        "incircu:polygoncenterline", {"INPUT": memory_layer("Polygon", [polygon]), "OUTPUT": "memory:", **parameters}
    )
    feature = next(results["OUTPUT"].getFeatures())
    geometry = QgsGeometry(feature.geometry())
    geometry.get().dropMValue()
    return feature, shapely.from_wkb(bytes(geometry.asWkb()))


def ends_near(line, points, tolerance):
    """True when the line's two ends are the two points (either order) within ``tolerance``."""
    first, last = (shapely.Point(line.coords[0]), shapely.Point(line.coords[-1]))
    a, b = (shapely.Point(point) for point in points)
    return (
        max(first.distance(a), last.distance(b)) <= tolerance or max(first.distance(b), last.distance(a)) <= tolerance
    )


def test_main_stem_is_the_default(provider):
    feature, line = river_line({})
    _, expected, _, _ = straight_river_with_long_arm()
    assert feature["ends_found"]
    assert ends_near(line, expected, FLAT_CAP_TOLERANCE * RIVER_WIDTH)


def test_longest_path_takes_the_arm(provider):
    _, line = river_line({"END_RULE": 1})
    _, _, _, arm_tip = straight_river_with_long_arm()
    assert min(shapely.Point(arm_tip).distance(shapely.Point(line.coords[i])) for i in (0, -1)) <= 10.0


def test_guide_lines_in_another_crs_choose_the_ends(provider):
    _, expected, _, arm_tip = straight_river_with_long_arm()
    guide = shapely.LineString([(arm_tip[0] + 3.0, arm_tip[1] + 80.0), (603.0, 20.0), (1100.0, 20.0)])
    guide_layer = memory_layer("LineString", [guide])
    reprojected = processing.run(
        "native:reprojectlayer", {"INPUT": guide_layer, "TARGET_CRS": "EPSG:4326", "OUTPUT": "memory:"}
    )["OUTPUT"]
    feature, line = river_line({"GUIDE_LINES": reprojected})
    assert feature["ends_from"] == "guide"
    assert ends_near(line, [arm_tip, expected[1]], FLAT_CAP_TOLERANCE * RIVER_WIDTH)


def test_ends_from_says_where_the_ends_came_from(provider):
    feature, _ = river_line({})
    assert feature["ends_from"] == "automatic"
    _, expected, _, _ = straight_river_with_long_arm()
    points = memory_layer("Point", [shapely.Point(point) for point in expected])
    feature, line = river_line(
        {
            "SPLIT_POINTS": points,
            "GUIDE_LINES": memory_layer("LineString", [shapely.LineString([(600.0, 900.0), (600.0, 0.0)])]),
        }
    )
    assert feature["ends_from"] == "split_points"
    assert ends_near(line, expected, 1e-6 * RIVER_WIDTH)
