"""A geographic layer across the antimeridian, through ``processing.run``: the line does not wrap round the globe.

The channel of ``test_core_antimeridian`` (0.14 degrees of longitude on the equator, centred on 180) stored
unwrapped (179.93 to 180.07) and wrapped (179.93 to 180, then -180 to -179.93), with split points at its
short sides.
"""

import json

import numpy as np
import processing
import pyproj
import pytest
from test_core_antimeridian import EAST, WEST, channel, wrap
from test_plugin_processing import as_shapely

GEOD = pyproj.Geod(ellps="WGS84")


def write_layer(path, geometries):
    features = [{"type": "Feature", "properties": {}, "geometry": g} for g in geometries]
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    return str(path)


@pytest.mark.parametrize("wrapped", [False, True], ids=["unwrapped", "wrapped"])
def test_line_across_the_antimeridian_is_continuous_and_true_to_length(provider, tmp_path, wrapped):
    polygon = channel(wrapped)
    ring = [list(map(float, xy)) for xy in polygon.exterior.coords]
    east = float(wrap(EAST)) if wrapped else EAST
    results = processing.run(
        "incircu:polygoncenterline",
        {
            "INPUT": write_layer(tmp_path / "channel.geojson", [{"type": "Polygon", "coordinates": [ring]}]),
            "SPLIT_POINTS": write_layer(
                tmp_path / "ends.geojson", [{"type": "Point", "coordinates": [x, 0.0]} for x in (WEST, east)]
            ),
            "OUTPUT": "memory:",
        },
    )
    assert results["CENTERLINE_COUNT"] == 1
    (feature,) = results["OUTPUT"].getFeatures()
    line = np.asarray(as_shapely(feature.geometry()).coords)
    assert np.ptp(line[:, 0]) == pytest.approx(EAST - WEST, abs=1e-9)
    assert np.abs(wrap(line[[0, -1], 0]) - wrap([WEST, east])).max() < 1e-9
    _, _, ground = GEOD.inv(WEST, 0.0, EAST, 0.0)
    assert feature["length"] == pytest.approx(ground, rel=1e-3)
