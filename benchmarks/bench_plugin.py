"""Cost per feature of the plugin's feature loop against the core's, on layers of small and of ordinary features;
prints a Markdown table.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_plugin.py [--count 2000] [--repeats 3]``

Layers, both in EPSG:32633 with two split points per polygon:

- ``rectangles``: ``--count`` copies of the 100 x 10 rectangle with 24 boundary vertices
  (``tests/support/geometry_cases.rectangle``), side by side (the issue's small feature);
- ``rivers``: the first ``--count / 5`` polygons of the layer benchmark (``benchmarks/rivers.py``, about 290
  boundary vertices each).

Columns:

- **core**: ``polygon_centerline`` of the array of every feature in this process, how the
  plugin computes a batch; best of ``--repeats``, per feature;
- **plugin**: ``incircu:polygoncenterline`` through ``qgis_process`` (this checkout) from GeoJSON to a
  GeoPackage, net of QGIS's start-up and of reading and writing a small layer: (time on the layer - time on
  its first ``SMALL`` features) / (features - ``SMALL``), best of ``--repeats``; what a feature costs in the
  algorithm's feature loop (reading, conversion, core, attributes, writing);
- **plugin - core**: what the feature loop adds per feature.

Target (issue 9): the 24-vertex rectangle in at most 0.5 ms. The load average is printed: numbers taken while
other processes share the cores are not the machine's.
"""

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import shapely
from peers import QgisProcess
from rivers import river_layer

from incircu_plugin.core import polygon_centerline
from tests.support import geometry_cases

#: Features of the small layer whose qgis_process time is taken as start-up and fixed costs.
SMALL = 10

#: Columns of rectangles in the rectangle layer, and the grid step between them, metres.
COLUMNS = 50
STEP = 200.0


def rectangles(count):
    """``count`` shifted copies of the 24-vertex rectangle: a list of (polygon, (start, end))."""
    case = geometry_cases.rectangle(n=11)
    layer = []
    for index in range(count):
        shift = (STEP * (index % COLUMNS), STEP * (index // COLUMNS))
        polygon = shapely.transform(case.polygon, lambda xy, offset=shift: xy + offset)
        ends = tuple((x + shift[0], y + shift[1]) for x, y in case.split_points)
        layer.append((polygon, ends))
    return layer


def rivers(count):
    """The first ``count`` rivers of the layer benchmark: a list of (polygon, (start, end))."""
    return [(river.polygon, tuple(end.coords[0] for end in river.ends)) for river in river_layer(count=count)]


def core_seconds(layer, repeats):
    """Best time of ``repeats`` joint computations of the layer, per feature (seconds)."""
    best = float("inf")
    for _ in range(repeats):
        started = time.perf_counter()
        outcomes = polygon_centerline([polygon for polygon, _ in layer], [ends for _, ends in layer])
        best = min(best, time.perf_counter() - started)
    failed = [outcome for outcome in outcomes if isinstance(outcome, Exception)]
    if failed:
        raise RuntimeError(f"the core failed on {len(failed)} features: {failed[0]}")
    return best / len(layer)


def _geojson(path, geometries):
    collection = {
        "type": "FeatureCollection",
        "crs": {"type": "name", "properties": {"name": "EPSG:32633"}},
        "features": [
            {"type": "Feature", "properties": {"row": index}, "geometry": shapely.geometry.mapping(geometry)}
            for index, geometry in enumerate(geometries)
        ],
    }
    path.write_text(json.dumps(collection))


def plugin_seconds(qgis, layer, name, repeats):
    """Best net time of ``repeats`` qgis_process runs on the layer, per feature (seconds), see the module."""
    directory = qgis.work_dir / name
    directory.mkdir()
    _geojson(directory / "ends.geojson", [shapely.Point(end) for _, ends in layer for end in ends])
    for stem, rows in (("small", layer[:SMALL]), ("layer", layer)):
        _geojson(directory / f"{stem}.geojson", [polygon for polygon, _ in rows])
    best = {}
    for _ in range(repeats):
        for stem in ("small", "layer"):
            output = directory / f"{stem}-out.gpkg"
            output.unlink(missing_ok=True)
            started = time.perf_counter()
            qgis.call(
                [
                    "run",
                    "incircu:polygoncenterline",
                    "--",
                    f"INPUT={directory / f'{stem}.geojson'}",
                    f"SPLIT_POINTS={directory / 'ends.geojson'}",
                    f"OUTPUT={output}",
                ]
            )
            best[stem] = min(best.get(stem, float("inf")), time.perf_counter() - started)
    return (best["layer"] - best["small"]) / (len(layer) - SMALL)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=2000, help="rectangles (rivers: a fifth of it)")
    parser.add_argument("--repeats", type=int, default=3)
    arguments = parser.parse_args(argv)
    load_before = os.getloadavg()
    layers = {
        "rectangle 100 x 10, 24 v": rectangles(arguments.count),
        "river of the layer benchmark, ~290 v": rivers(arguments.count // 5),
    }
    rows = []
    with tempfile.TemporaryDirectory(prefix="incircu-plugin-") as work_dir:
        qgis = QgisProcess(work_dir, plugins=["incircu"])
        for index, (name, layer) in enumerate(layers.items()):
            core = core_seconds(layer, arguments.repeats)
            plugin = plugin_seconds(qgis, layer, f"layer{index}", arguments.repeats)
            rows.append((name, len(layer), core, plugin))
    print(
        f"Load average (1, 5, 15 min) before: {', '.join(f'{v:.2f}' for v in load_before)}; "
        f"after: {', '.join(f'{v:.2f}' for v in os.getloadavg())}.\n"
    )
    print("| feature | features | core, ms per feature | plugin, ms per feature | plugin - core |")
    print("|---|---:|---:|---:|---:|")
    for name, count, core, plugin in rows:
        print(f"| {name} | {count:,} | {core * 1e3:.2f} | {plugin * 1e3:.2f} | {(plugin - core) * 1e3:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
