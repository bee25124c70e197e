"""Real outlines for the benchmark: Natural Earth countries from the npm ``world-atlas`` package.

``benchmarks/run.sh`` unpacks the package into ``benchmarks/.cache/world-atlas`` (never committed).
This module decodes its TopoJSON (quantised, delta-encoded arcs), keeps the largest polygon of a
country and projects it to a local azimuthal equidistant CRS centred on it, so every length in the
benchmark is in metres.
"""

import json
from pathlib import Path

import numpy as np
import pyproj
import shapely
from shapely.geometry import Polygon

CACHE_DIR = Path(__file__).resolve().parent / ".cache"
WORLD_ATLAS_DIR = CACHE_DIR / "world-atlas" / "package"
COUNTRIES = ("Gambia", "Chile", "Malawi", "Norway")


def _decode_arcs(topology):
    """Return the arcs of a quantised TopoJSON topology as lon/lat arrays (degrees)."""
    scale = np.asarray(topology["transform"]["scale"], dtype=float)
    translate = np.asarray(topology["transform"]["translate"], dtype=float)
    return [np.cumsum(np.asarray(arc, dtype=float), axis=0) * scale + translate for arc in topology["arcs"]]


def _ring(arc_indices, arcs):
    """Stitch arcs into one closed ring (lon/lat degrees); a negative index ``~i`` means arc ``i`` reversed."""
    pieces = []
    for index in arc_indices:
        coords = arcs[~index][::-1] if index < 0 else arcs[index]
        pieces.append(coords if not pieces else coords[1:])
    return np.concatenate(pieces)


def country_polygon(name, resolution="10m"):
    """Largest polygon (no holes) of a Natural Earth country, in a local AEQD projection (metres).

    Parameters
    ----------
    name : str
        Country name as spelled in ``world-atlas`` (e.g. ``"Gambia"``).
    resolution : {"10m", "50m", "110m"}
        Natural Earth scale of the file to read.

    Returns
    -------
    shapely.geometry.Polygon
        Exterior ring only, coordinates in metres around the polygon's centroid.
    """
    path = WORLD_ATLAS_DIR / f"countries-{resolution}.json"
    topology = json.loads(path.read_text())
    arcs = _decode_arcs(topology)
    for geometry in topology["objects"]["countries"]["geometries"]:
        if geometry.get("properties", {}).get("name") != name:
            continue
        polygons = geometry["arcs"] if geometry["type"] == "MultiPolygon" else [geometry["arcs"]]
        lonlat_polygons = [Polygon(_ring(rings[0], arcs)) for rings in polygons]
        largest = max(lonlat_polygons, key=lambda polygon: polygon.area)
        lon0, lat0 = largest.centroid.x, largest.centroid.y
        transformer = pyproj.Transformer.from_crs(
            "EPSG:4326", f"+proj=aeqd +lat_0={lat0} +lon_0={lon0} +datum=WGS84 +units=m", always_xy=True
        )
        lon, lat = np.asarray(largest.exterior.coords).T
        x, y = transformer.transform(lon, lat)
        repaired = shapely.make_valid(Polygon(np.column_stack([x, y])))
        parts = shapely.get_parts(shapely.get_parts(repaired))
        polygons = parts[shapely.get_type_id(parts) == 3]
        largest_projected = max(polygons, key=lambda part: part.area)
        return Polygon(largest_projected.exterior)
    raise KeyError(f"{name!r} is not a country in {path}")
