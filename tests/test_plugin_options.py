"""The algorithms read their parameters once, at the top of a run, into a frozen options object; the working
frame a feature is computed in is a value of its own (issue 39).

Every ``parameterAs...`` call of the plugin's algorithms is counted by parameter name while each algorithm runs
on small layers with every parameter given: each parameter is read exactly once.
"""

import dataclasses
import importlib
from collections import Counter

import processing
import pytest
from qgis.core import QgsCoordinateReferenceSystem, QgsFeature, QgsGeometry, QgsVectorLayer

READERS = (
    "parameterAsSource",
    "parameterAsSink",
    "parameterAsDouble",
    "parameterAsEnum",
    "parameterAsBoolean",
    "parameterAsString",
)


def layer(kind, wkts):
    """A memory layer of EPSG:2180 with one feature per WKT and a ``name`` field."""
    built = QgsVectorLayer(f"{kind}?crs=EPSG:2180&field=name:string", kind, "memory")
    features = []
    for index, wkt in enumerate(wkts):
        feature = QgsFeature(built.fields())
        feature.setAttributes([f"f{index}"])
        feature.setGeometry(QgsGeometry.fromWkt(wkt))
        features.append(feature)
    assert built.dataProvider().addFeatures(features)
    return built


@pytest.fixture
def reads(provider, monkeypatch):
    """Counter of the parameter names read through ``parameterAs...`` by the IncirCu algorithms."""
    base = importlib.import_module("incircu.algorithms.base").IncirCuAlgorithm
    counted = Counter()
    for reader in READERS:
        original = getattr(base, reader)

        def counting(self, parameters, name, context, *rest, _original=original):
            counted[name] += 1
            return _original(self, parameters, name, context, *rest)

        monkeypatch.setattr(base, reader, counting)
    return counted


RIVER = "POLYGON ((0 0, 1000 0, 1000 100, 0 100, 0 0))"
NEIGHBOUR = "POLYGON ((1000 0, 2000 0, 2000 100, 1000 100, 1000 0))"
POLYGON_OUTPUTS = {
    "OUTPUT": "memory:",
    "OUTPUT_VERTICES": "memory:",
    "OUTPUT_CIRCLES": "memory:",
    "OUTPUT_TRANSECTS": "memory:",
}
SAMPLING = {"TOLERANCE": 0.5, "SPACING": 0.0}


def runs():
    """Algorithm id -> its parameters, every one given."""
    polygons = layer("Polygon", [RIVER, NEIGHBOUR])
    points = layer("Point", ["POINT (0 50)", "POINT (2000 50)"])
    guides = layer("LineString", ["LINESTRING (10 50, 990 50)"])
    polygon_inputs = {
        "INPUT": polygons,
        "SPLIT_POINTS": points,
        "SNAP_TOLERANCE": 1.0,
        **SAMPLING,
        "ISLANDS": 0,
        "END_RULE": 0,
        "GUIDE_LINES": guides,
    }
    results = {"ADD_M": True, "TRANSECT_INTERVAL": 100.0, "TRANSECT_STYLE": 0, **POLYGON_OUTPUTS}
    return {
        "incircu:polygoncenterline": {
            **polygon_inputs,
            "END_CAP": 0,
            "SEPARATE_PARTS": False,
            "CONNECT_TOUCHING": True,
            **results,
        },
        "incircu:linescenterline": {
            "LINES_A": layer("LineString", ["LINESTRING (0 0, 1000 0)"]),
            "LINES_B": layer("LineString", ["LINESTRING (0 100, 1000 100)"]),
            "PAIR_FIELD_A": "name",
            "PAIR_FIELD_B": "name",
            **SAMPLING,
            "END_CAP": 0,
            **results,
        },
        "incircu:polygonnetwork": {
            "INPUT": polygons,
            "SPLIT_POINTS": points,
            "SPLIT_ID_FIELD": "name",
            "SNAP_TOLERANCE": 1.0,
            **SAMPLING,
            "ISLANDS": 0,
            "END_CAP": 0,
            "MIN_ARM_RATIO": 1.0,
            "MIN_ARM_LENGTH": 0.0,
            "CONNECT_TOUCHING": True,
            "ADD_M": True,
            "OUTPUT": "memory:",
            "OUTPUT_NODES": "memory:",
        },
        "incircu:labellines": {
            **polygon_inputs,
            "TRIM": 0.5,
            "CLEARANCE": 0.25,
            "BEND": 0.5,
            "MIN_ELONGATION": 3.0,
            "SMOOTHING": 0.5,
            "OUTPUT": "memory:",
            "OUTPUT_POINTS": "memory:",
        },
    }


@pytest.mark.parametrize("algorithm", sorted(runs()))
def test_every_parameter_is_read_exactly_once(reads, algorithm):
    parameters = runs()[algorithm]
    results = processing.run(algorithm, parameters)
    assert results["CENTERLINE_COUNT"] >= 1 and results["SKIPPED_COUNT"] == 0
    assert dict(reads) == {name: 1 for name in parameters}


def test_a_features_frame_is_a_value_and_the_layers_stays_as_it_is(provider):
    WorkingFrame = importlib.import_module("incircu.algorithms.convert").WorkingFrame
    geographic = WorkingFrame.of_layer(QgsCoordinateReferenceSystem("EPSG:4326"))
    first = geographic.around(QgsGeometry.fromWkt("POLYGON ((20 50, 21 50, 21 51, 20 51, 20 50))"))
    second = geographic.around(QgsGeometry.fromWkt("POLYGON ((-70 -30, -69 -30, -69 -29, -70 -29, -70 -30))"))
    assert geographic.projection is None and first.projection is not None and second.projection is not None
    # Each feature's frame brings its own results back, whatever frame came after it; the frames differ.
    corner = first.to_core(QgsGeometry.fromWkt("POINT (20 50)"))
    assert second.to_core(QgsGeometry.fromWkt("POINT (20 50)")).distance(corner) > 1e6
    assert tuple(first.to_layer(corner).coords[0]) == pytest.approx((20.0, 50.0), abs=1e-9)
    with pytest.raises(dataclasses.FrozenInstanceError):
        geographic.projection = first.projection
    projected = WorkingFrame.of_layer(QgsCoordinateReferenceSystem("EPSG:2180"))
    assert projected.around(QgsGeometry.fromWkt("POINT (1 2)")) is projected
