"""Layer benchmark (issue 9): polygons per second, output vertices and accuracy of every tool on whole layers.

Inputs: the seeded layer of :mod:`rivers` (``--count`` river-like polygons, split points at the caps) and, as
extra rows, each real outline of :mod:`outlines` as a layer of one polygon (split at the ends ``find_ends``
places). Tools:

- in a clean child process, polygon after polygon (:func:`harness.run_layer`, killed past the time limit):
  IncirCu's core with split points, without them (automatic ends) and, when the core has the ``tolerance``
  keyword, at a fine tolerance; and the whole layer as one array (``polygon_centerline`` of the array, traced
  together in batches) (as the plugin runs a layer; each polygon is given an equal share of the time);
  pygeoops, label_centerlines, centerline, SFCGAL (as ``bench_compare.py`` runs them). Time = sum of the
  tool calls.
- one ``qgis_process run`` on the whole layer in a GeoPackage, as a QGIS user would: IncirCu
  (``incircu:polygoncenterline`` with and without a split-point layer) and GRASS ``v.voronoi.skeleton``.
  Time = wall time of the call, QGIS start-up and GeoPackage writing included.

Each polygon's output is measured by :func:`metrics.measure` against the reference axis of
:func:`cases.river_cases` (the oracle's exact medial axis between the two chains, or IncirCu at a fine
spacing where the oracle rejects the chains). Writes ``benchmarks/results/layer.json`` and prints the tables.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_layer.py [--count 400] [--no-qgis] [--no-outlines]``
"""

import argparse
import dataclasses
import json
import os
import sqlite3
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BENCH_DIR = Path(__file__).resolve().parent
if str(BENCH_DIR) not in sys.path:
    sys.path.insert(0, str(BENCH_DIR))

import cases as bench_cases
import numpy as np
import shapely
from bench_compare import incircu_version
from harness import preload, run_layer
from metrics import measure, vertices_of
from peers import (
    FINE_TOLERANCE,
    QgisProcess,
    Tool,
    core_accepts,
    mean_width,
    peer_tools,
    run_incircu,
    run_incircu_automatic_ends,
    run_incircu_fine,
    run_incircu_together,
)
from report import format_layer

RESULTS_DIR = BENCH_DIR / "results"

#: CRS written into the outlines' layers (their local AEQD has no EPSG code; only planar lengths matter).
OUTLINE_CRS = "EPSG:3857"


def core_tools():
    """IncirCu's core rows: with split points (one by one, and the layer together when the core can), automatic
    ends, and a fine tolerance when the core has one."""
    tools = [
        Tool("IncirCu (core)", run_incircu, True, "polygon_centerline(polygon, ends), defaults"),
        Tool("IncirCu (core, automatic ends)", run_incircu_automatic_ends, True, "polygon_centerline(polygon)"),
    ]
    note = "polygon_centerline(array of polygons, ends of each), the layer in batches"
    tools.insert(1, Tool("IncirCu (core, layer together)", run_incircu, True, note, run_all=run_incircu_together))
    if core_accepts("tolerance"):
        note = f"polygon_centerline(polygon, ends, tolerance={FINE_TOLERANCE:g} × width)"
        tools.append(Tool(f"IncirCu (core, tolerance {FINE_TOLERANCE:g} w)", run_incircu_fine, True, note))
    return tools


def _feature_collection(geometries, crs):
    features = [
        {"type": "Feature", "properties": {"polygon": index}, "geometry": shapely.geometry.mapping(geometry)}
        for index, geometry in geometries
    ]
    return {"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": crs}}, "features": features}


class LayerFiles:
    """A layer of cases as GeoPackages (polygons, split points), written through ``qgis_process`` itself."""

    def __init__(self, qgis, case_list, crs, name):
        self.directory = qgis.work_dir / name
        self.directory.mkdir()
        polygons = [(index, case.polygon) for index, case in enumerate(case_list)]
        ends = [(index, end) for index, case in enumerate(case_list) for end in case.ends]
        self.polygons = self._geopackage(qgis, "polygons", _feature_collection(polygons, crs), crs)
        self.ends = self._geopackage(qgis, "ends", _feature_collection(ends, crs), crs)

    def _geopackage(self, qgis, stem, collection, crs):
        source = self.directory / f"{stem}.geojson"
        source.write_text(json.dumps(collection))
        target = self.directory / f"{stem}.gpkg"
        qgis.call(["run", "native:reprojectlayer", "--", f"INPUT={source}", f"TARGET_CRS={crs}", f"OUTPUT={target}"])
        return target


def read_geopackage(path):
    """Every geometry of the (single) feature table of a GeoPackage, 2D, read with sqlite3 (no GDAL needed)."""
    with sqlite3.connect(path) as database:
        table, column = database.execute("SELECT table_name, column_name FROM gpkg_geometry_columns").fetchone()
        blobs = [row[0] for row in database.execute(f'SELECT "{column}" FROM "{table}"')]
    geometries = []
    for blob in blobs:
        if blob is None:
            continue
        envelope_bytes = (0, 32, 48, 48, 64)[(blob[3] >> 1) & 0b111]
        geometries.append(shapely.force_2d(shapely.from_wkb(bytes(blob[8 + envelope_bytes :]))))
    return geometries


def lines_per_case(geometries, case_list):
    """Each output line part assigned to the polygon nearest its midpoint: one geometry (or None) per case."""
    parts = [part for geometry in geometries for part in shapely.get_parts(shapely.get_parts(geometry))]
    parts = [part for part in parts if part.geom_type == "LineString" and not part.is_empty]
    grouped = [[] for _ in case_list]
    if parts:
        tree = shapely.STRtree([case.polygon for case in case_list])
        midpoints = shapely.line_interpolate_point(parts, 0.5, normalized=True)
        nearest = tree.query_nearest(midpoints, all_matches=False)[1]
        for part, index in zip(parts, nearest):
            grouped[index].append(part)
    return [shapely.MultiLineString(lines) if lines else None for lines in grouped]


def qgis_runs(qgis, files, case_list, timeout, grass=True):
    """The whole-layer ``qgis_process`` runs: {tool name: (wall seconds or None, geometry per case, note)}."""
    width = float(np.median([mean_width(case.polygon) for case in case_list]))
    calls = {
        "IncirCu (qgis_process)": [
            "incircu:polygoncenterline",
            f"INPUT={files.polygons}",
            f"SPLIT_POINTS={files.ends}",
        ],
        "IncirCu (qgis_process, automatic ends)": ["incircu:polygoncenterline", f"INPUT={files.polygons}"],
        "GRASS v.voronoi.skeleton (qgis_process)": [
            "grass7:v.voronoi.skeleton",
            f"input={files.polygons}",
            f"smoothness={width / 10.0!r}",
            "thin=-1",
            "-s=true",
        ],
    }
    if not grass:
        del calls["GRASS v.voronoi.skeleton (qgis_process)"]
    runs = {}
    for name, (algorithm, *parameters) in calls.items():
        output = files.directory / f"{name.split()[0]}-{len(runs)}.gpkg"
        key = "output" if algorithm.startswith("grass") else "OUTPUT"
        started = time.perf_counter()
        try:
            qgis.call(["run", algorithm, "--", *parameters, f"{key}={output}"], timeout=timeout)
        except subprocess.TimeoutExpired:
            runs[name] = (None, [None] * len(case_list), f"timeout > {timeout:.0f} s")
            print(f"  {name:<44} {runs[name][2]}", flush=True)
            continue
        except Exception as error:  # noqa: BLE001 (a failing tool is a result)
            runs[name] = (None, [None] * len(case_list), f"{type(error).__name__}: {error}".splitlines()[0][:160])
            print(f"  {name:<44} failed: {runs[name][2]}", flush=True)
            continue
        seconds = time.perf_counter() - started
        runs[name] = (seconds, lines_per_case(read_geopackage(output), case_list), "")
        print(f"  {name:<44} {seconds:8.2f} s", flush=True)
    return runs


def summarise(tool_name, case_list, per_case, seconds, note, whole_layer, timeout):
    """One table row: speed, output vertices against input vertices, clean lines and deviation."""
    measurements = []
    for case, entry in zip(case_list, per_case):
        if entry is None:
            continue
        geometry, error = entry
        if geometry is None or error:
            measurements.append(
                dataclasses.replace(measure(tool_name, case, None, None, 1), error=error or "no output")
            )
        else:
            measurements.append(measure(tool_name, case, geometry, None, 1))
    done = [m for m in measurements if not m.error]
    outputs = {case.name: entry[0] for case, entry in zip(case_list, per_case) if entry and entry[0] is not None}
    output_vertices = sum(len(vertices_of(outputs[m.case])) for m in done)
    input_vertices = sum(case.vertex_count for case in case_list if case.name in {m.case for m in done})
    deviations = [m for m in done if m.mean_dev_rel is not None]
    return {
        "tool": tool_name,
        "polygons": len(case_list),
        "attempted": len(measurements),
        "done": len(done),
        "failed": len(measurements) - len(done),
        "errors": sorted({m.error for m in measurements if m.error})[:3],
        "seconds": seconds,
        "whole_layer_call": whole_layer,
        "polygons_per_second": len(measurements) / seconds if seconds else None,
        "input_vertices": input_vertices,
        "output_vertices": output_vertices,
        "clean": sum(1 for m in done if m.parts == 1 and m.branches == 1),
        "mean_dev_rel": float(np.mean([m.mean_dev_rel for m in deviations])) if deviations else None,
        "max_dev_rel": float(max(m.max_dev_rel for m in deviations)) if deviations else None,
        "median_max_dev_rel": float(np.median([m.max_dev_rel for m in deviations])) if deviations else None,
        "max_end_gap_rel": float(max(max(m.end_gap_rel) for m in done)) if done else None,
        "note": note,
        "timeout_seconds": timeout if note.startswith("timeout") else None,
    }


def benchmark_layer(name, case_list, tools, qgis, timeout, crs, grass=True):
    """Every tool on one layer; returns the layer's record for ``layer.json``."""
    print(
        f"== {name}: {len(case_list)} polygons, {sum(c.vertex_count for c in case_list):,} boundary vertices",
        flush=True,
    )
    rows = []
    for tool in tools:
        results, note = run_layer(tool, case_list, timeout)
        seconds = sum(entry[0] for entry in results if entry is not None)
        per_case = [None if entry is None else (entry[1], entry[2]) for entry in results]
        rows.append(summarise(tool.name, case_list, per_case, seconds, note, False, timeout))
        print(f"  {tool.name:<44} {seconds:8.2f} s {note}", flush=True)
    if qgis is not None:
        files = LayerFiles(qgis, case_list, crs, name.split()[0].lower() + f"-{len(case_list)}")
        for tool_name, (seconds, geometries, note) in qgis_runs(qgis, files, case_list, timeout, grass).items():
            per_case = [(geometry, "" if geometry is not None else "no output") for geometry in geometries]
            if seconds is None:
                per_case = [None] * len(case_list)
            rows.append(summarise(tool_name, case_list, per_case, seconds, note, True, timeout))
    kinds = [case.axis_kind for case in case_list]
    return {
        "name": name,
        "polygons": len(case_list),
        "vertices": sum(case.vertex_count for case in case_list),
        "islands": sum(len(case.polygon.interiors) for case in case_list),
        "reference": {kind: kinds.count(kind) for kind in sorted(set(kinds))},
        "rows": rows,
    }


def qgis_startup(qgis):
    """Median of three provider-loading ``qgis_process`` calls that run no algorithm (seconds)."""
    durations = []
    for _ in range(3):
        started = time.perf_counter()
        qgis.call(["help", "incircu:polygoncenterline"])
        durations.append(time.perf_counter() - started)
    return sorted(durations)[1]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=400, help="river-like polygons in the layer")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per tool on the river layer")
    parser.add_argument("--outline-timeout", type=float, default=60.0, help="seconds per tool on one outline")
    parser.add_argument("--no-qgis", action="store_true", help="skip the qgis_process runs (IncirCu, GRASS)")
    parser.add_argument("--no-grass", action="store_true", help="skip GRASS (the slowest run)")
    parser.add_argument("--no-outlines", action="store_true", help="the river layer only")
    arguments = parser.parse_args(argv)
    RESULTS_DIR.mkdir(exist_ok=True)
    preload()
    load_before = os.getloadavg()
    started = time.perf_counter()
    tools = core_tools() + peer_tools()
    layers = []
    with tempfile.TemporaryDirectory(prefix="incircu-layer-") as work_dir:
        qgis = None if arguments.no_qgis else QgisProcess(work_dir, plugins=["incircu", "grassprovider"])
        startup = None if qgis is None else qgis_startup(qgis)
        grass = not arguments.no_grass
        rivers = bench_cases.river_cases(arguments.count, arguments.seed)
        name = f"Rivers ({arguments.count}, seed {arguments.seed})"
        layers.append(benchmark_layer(name, rivers, tools, qgis, arguments.timeout, "EPSG:32633", grass))
        if not arguments.no_outlines:
            for case in bench_cases.outline_cases():
                timeout = arguments.outline_timeout
                layers.append(benchmark_layer(case.name, [case], tools, qgis, timeout, OUTLINE_CRS, grass))
    results = {
        "layers": layers,
        "count": arguments.count,
        "grass": grass,
        "seed": arguments.seed,
        "qgis_startup_seconds": startup,
        "tolerance_keyword": core_accepts("tolerance"),
        "tools": {tool.name: tool.note for tool in tools},
        "load_average": {"start": load_before, "end": os.getloadavg()},
        "incircu_version": incircu_version(),
        "wall_seconds": time.perf_counter() - started,
    }
    (RESULTS_DIR / "layer.json").write_text(json.dumps(results, indent=1))
    for layer in layers:
        print(format_layer(layer))
    return 0


if __name__ == "__main__":
    sys.exit(main())
