"""The real reservoirs of ``tests/data/real_rivers_ne_lonlat.geojson`` and the main-stem score.

Each water body is a Natural Earth 1:10m lake polygon with its main stem from the independent Natural
Earth 1:50m river centerlines (see ``tests/data/README.md``), projected to local metres with
:class:`LocalProjection`.

Score of a line: the share of its length lying within ``TOLERANCE_WIDTHS`` local widths of the main stem,
the local width at a point being twice its distance to the polygon's boundary; the tolerance never drops
below ``MIN_TOLERANCE`` metres, the 1:50m line's quantisation and generalisation (about 1 km).
"""

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import MultiLineString, Polygon

from incircu_plugin.core.geodesy import LocalProjection

DATA = Path(__file__).resolve().parents[1] / "data" / "real_rivers_ne_lonlat.geojson"
TOLERANCE_WIDTHS = 3.0
MIN_TOLERANCE = 2000.0


@dataclass(frozen=True)
class RealRiver:
    """One water body in local metres: its polygon and its main stem (MultiLineString)."""

    name: str
    polygon: Polygon
    main_stem: MultiLineString


def real_rivers():
    """Return the water bodies of the data set as :class:`RealRiver` items, in file order."""
    features = json.loads(DATA.read_text(encoding="utf-8"))["features"]
    polygons = {
        f["properties"]["name"]: shapely.geometry.shape(f["geometry"])
        for f in features
        if f["properties"]["role"] == "polygon"
    }
    rivers = []
    for feature in features:
        if feature["properties"]["role"] != "main_stem":
            continue
        name = feature["properties"]["name"]
        projection = LocalProjection.around(polygons[name])
        stem = shapely.geometry.shape(feature["geometry"])
        rivers.append(RealRiver(name, projection.to_local(polygons[name]), projection.to_local(stem)))
    return rivers


def sample_points(lines, step):
    """Return points every ``step`` metres along every part of ``lines`` (an ``(n, 2)`` array)."""
    parts = [part for part in shapely.get_parts(lines) if part.length > 0]
    points = [
        shapely.get_coordinates(shapely.line_interpolate_point(part, np.arange(0.0, part.length, step)))
        for part in parts
    ]
    return np.concatenate(points) if points else np.empty((0, 2))


def tolerances(polygon, points):
    """Return the allowed distance (m) at each point: ``TOLERANCE_WIDTHS`` local widths, >= ``MIN_TOLERANCE``."""
    widths = 2.0 * shapely.distance(polygon.boundary, shapely.points(points))
    return np.maximum(TOLERANCE_WIDTHS * widths, MIN_TOLERANCE)


def main_stem_share(river, lines):
    """Share (0..1) of the length of ``lines`` within the tolerance of the river's main stem; 0 for no line."""
    points = sample_points(lines, step=river.polygon.length / 20000.0)
    if len(points) == 0:
        return 0.0
    near = shapely.distance(river.main_stem, shapely.points(points)) <= tolerances(river.polygon, points)
    return float(np.mean(near))


def main_stem_cover(river, lines):
    """Share (0..1) of the main stem's length inside the polygon within the tolerance of ``lines``."""
    inside = river.main_stem.intersection(river.polygon)
    points = sample_points(inside, step=river.polygon.length / 20000.0)
    if len(points) == 0 or lines is None or lines.is_empty:
        return 0.0
    return float(np.mean(shapely.distance(lines, shapely.points(points)) <= tolerances(river.polygon, points)))
