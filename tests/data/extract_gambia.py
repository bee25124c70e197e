"""Extract the Gambia from Natural Earth 1:10m (npm package ``world-atlas``) into two small GeoJSON files.

Usage::

    npm pack world-atlas@2.0.2 && tar xzf world-atlas-2.0.2.tgz
    python tests/data/extract_gambia.py package/countries-10m.json

Writes ``gambia_ne10m_lonlat.geojson`` (EPSG:4326 degrees, exactly the TopoJSON vertices) and
``gambia_ne10m_utm28n.geojson`` (EPSG:32628 metres, projected with pyproj) next to this script.
"""

import json
import sys
from pathlib import Path

from pyproj import Transformer

HERE = Path(__file__).resolve().parent


def decode_arcs(topology):
    """Return every arc of a quantized TopoJSON topology as a list of [lon, lat] lists (degrees)."""
    (scale_x, scale_y), (translate_x, translate_y) = topology["transform"]["scale"], topology["transform"]["translate"]
    arcs = []
    for arc in topology["arcs"]:
        x = y = 0
        points = []
        for dx, dy in arc:
            x += dx
            y += dy
            points.append([x * scale_x + translate_x, y * scale_y + translate_y])
        arcs.append(points)
    return arcs


def ring_from_arcs(arc_indices, arcs):
    """Join the arcs of one ring (a negative index ``~i`` means arc ``i`` reversed), closed."""
    ring = []
    for index in arc_indices:
        points = arcs[index] if index >= 0 else arcs[~index][::-1]
        ring.extend(points if not ring else points[1:])
    return ring


def feature(rings, crs_note):
    return {
        "type": "Feature",
        "properties": {
            "name": "Gambia",
            "source": "Natural Earth 1:10m Admin 0 via world-atlas 2.0.2",
            "crs": crs_note,
        },
        "geometry": {"type": "Polygon", "coordinates": rings},
    }


def main(path):
    with open(path, encoding="utf-8") as handle:
        topology = json.load(handle)
    arcs = decode_arcs(topology)
    (gambia,) = [g for g in topology["objects"]["countries"]["geometries"] if g["properties"].get("name") == "Gambia"]
    if gambia["type"] != "Polygon":
        raise SystemExit("expected a single polygon, got {}".format(gambia["type"]))
    rings = [ring_from_arcs(ring, arcs) for ring in gambia["arcs"]]
    to_utm = Transformer.from_crs("EPSG:4326", "EPSG:32628", always_xy=True)
    projected = [[list(to_utm.transform(lon, lat)) for lon, lat in ring] for ring in rings]
    for name, data, note in (
        ("gambia_ne10m_lonlat.geojson", rings, "EPSG:4326"),
        ("gambia_ne10m_utm28n.geojson", projected, "EPSG:32628"),
    ):
        with open(HERE / name, "w", encoding="utf-8") as handle:
            json.dump(feature(data, note), handle)
            handle.write("\n")


if __name__ == "__main__":
    main(sys.argv[1])
