"""Outside polygons: the share that gets one simple line, and the time, IncirCu against its peers.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_outside.py [--quick]`` (``benchmarks/run.sh``
creates that venv; a missing peer is reported as such). Nothing here is committed data: every polygon is
read at run time from what is installed or already in the repository.

Sources (licences):

- *glyphs*: the outlines of the letters and digits of DejaVu Sans and DejaVu Serif, the fonts matplotlib
  ships (``matplotlib.textpath.TextPath``; DejaVu fonts: Bitstream Vera licence and public-domain changes),
  each glyph's parts as separate polygons (the dot of an "i" too), holes nested by containment;
- *countries*: the largest polygon of every country of Natural Earth 1:110m (public domain), from the npm
  package ``world-atlas`` (ISC) that ``benchmarks/run.sh`` unpacks into ``benchmarks/.cache`` (skipped
  when missing), projected to local metres (``benchmarks/outlines.py``);
- *reservoirs*: the 16 Natural Earth 1:10m reservoirs and river lakes of ``tests/data`` (public domain).

Each tool runs on each polygon in a forked child, killed after ``TIME_LIMIT`` seconds (a second, timed run when
the first took under ``WARM_RUN_BELOW``): IncirCu's
``polygon_centerline`` with automatic ends (no split points, its defaults), pygeoops ``centerline``,
label_centerlines ``get_centerline`` and centerline's ``Centerline`` as in ``benchmarks/peers.py``. A tool
*gives a line* when its output, merged (``shapely.line_merge``), is one simple LineString within the polygon
(up to 1e-7 of its size). Prints a Markdown table and writes it between the ``outside`` markers of
``docs/benchmark.md``.
"""

import argparse
import math
import multiprocessing
import os
import string
import sys
import time
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import Polygon

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from benchmarks.outlines import WORLD_ATLAS_DIR, country_polygon
from benchmarks.peers import Case, as_lines, mean_width, run_centerline, run_label_centerlines, run_pygeoops
from benchmarks.report import write_section

#: Seconds a tool may take on one polygon before it is killed (counted as no line, and as this time).
TIME_LIMIT = 20.0

#: A tool that took less than this many seconds runs a second time in its child, and that (warm) run is timed.
WARM_RUN_BELOW = 2.0

#: Glyph height, font units (the outlines are polygons of this size).
GLYPH_SIZE = 100.0

#: Parts of a glyph smaller than this share of its largest part are left out (specks of the outline).
GLYPH_PART_SHARE = 0.01


def glyph_polygons(fonts=("DejaVu Sans", "DejaVu Serif"), characters=string.ascii_letters + string.digits):
    """Return ``[(name, polygon)]``: every part of every glyph, holes nested by containment (font units)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    found = []
    for font in fonts:
        properties = FontProperties(family=font)
        for character in characters:
            rings = [
                Polygon(ring) for ring in TextPath((0, 0), character, size=GLYPH_SIZE, prop=properties).to_polygons()
            ]
            rings = sorted((ring for ring in rings if ring.is_valid and ring.area > 0.0), key=lambda ring: -ring.area)
            depth = [sum(other.contains(ring) for other in rings[:index]) for index, ring in enumerate(rings)]
            parts = []
            for index, ring in enumerate(rings):
                if depth[index] % 2 == 0:
                    holes = [
                        inner.exterior
                        for inner_index, inner in enumerate(rings)
                        if depth[inner_index] == depth[index] + 1 and ring.contains(inner)
                    ]
                    parts.append(Polygon(ring.exterior, holes))
            parts = [part for part in parts if part.is_valid]
            if not parts:
                continue
            largest = max(part.area for part in parts)
            for number, part in enumerate(part for part in parts if part.area >= GLYPH_PART_SHARE * largest):
                found.append((f"{font} {character!r} {number}", part))
    return found


def country_polygons():
    """Return ``[(name, polygon)]``: every Natural Earth 1:110m country's largest polygon, local metres."""
    import json

    path = WORLD_ATLAS_DIR / "countries-110m.json"
    if not path.exists():
        return []
    names = sorted(
        {
            geometry["properties"]["name"]
            for geometry in json.loads(path.read_text())["objects"]["countries"]["geometries"]
        }
    )
    found = []
    for name in names:
        try:
            polygon = country_polygon(name, "110m")
        except (KeyError, ValueError):
            continue
        if polygon.is_valid and len(polygon.exterior.coords) >= 4:
            found.append((name, polygon))
    return found


def reservoir_polygons():
    """Return ``[(name, polygon)]``: the reservoirs of ``tests/data``, local metres."""
    from tests.support.real_rivers import real_rivers

    return [(river.name, river.polygon) for river in real_rivers()]


def run_incircu(polygon):
    from incircu_plugin.core import polygon_centerline

    return polygon_centerline(polygon).line


def peer(runner):
    def run(polygon):
        return as_lines(runner(Case("outside", polygon, (), mean_width(polygon))))

    return run


TOOLS = (
    ("IncirCu", run_incircu),
    ("pygeoops", peer(run_pygeoops)),
    ("label_centerlines", peer(run_label_centerlines)),
    ("centerline", peer(run_centerline)),
)


def gives_a_line(polygon, geometry):
    """Whether ``geometry`` merges into one simple LineString within ``polygon`` (up to 1e-7 of its size)."""
    if geometry is None or geometry.is_empty:
        return False
    if geometry.geom_type != "LineString":
        geometry = shapely.line_merge(as_lines(geometry))
    if geometry.geom_type != "LineString" or len(geometry.coords) < 2 or not geometry.is_simple:
        return False
    west, south, east, north = polygon.bounds
    return polygon.buffer(1e-7 * math.hypot(east - west, north - south)).covers(geometry)


def _child(connection, tool_index, polygon):
    run = TOOLS[tool_index][1]
    try:
        start = time.perf_counter()
        geometry = run(polygon)
        seconds = time.perf_counter() - start
        if seconds < WARM_RUN_BELOW:
            start = time.perf_counter()
            run(polygon)
            seconds = time.perf_counter() - start
        connection.send((gives_a_line(polygon, geometry), seconds, ""))
    except ImportError as error:
        connection.send((False, None, f"missing {error.name}"))
    except Exception as error:  # noqa: BLE001 (a tool failing on an input is a result)
        connection.send((False, time.perf_counter() - start, type(error).__name__))
    finally:
        connection.close()


def run_once(tool_index, polygon):
    """Return ``(gives a line, seconds, error)`` of one tool on one polygon, in a forked child."""
    context = multiprocessing.get_context("fork")
    receiver, sender = context.Pipe(duplex=False)
    process = context.Process(target=_child, args=(sender, tool_index, polygon))
    process.start()
    sender.close()
    if not receiver.poll(TIME_LIMIT):
        process.kill()
        process.join()
        return False, TIME_LIMIT, "timeout"
    try:
        outcome = receiver.recv()
    except EOFError:
        outcome = (False, None, "died")
    process.join()
    return outcome


def table(results, sources):
    """Markdown: per source and tool, the share that gives a line and the total and median time."""
    lines = [
        "| source | polygons | vertices (median) | "
        + " | ".join(f"{name}: line / time (median)" for name, _ in TOOLS)
        + " |",
        "|---|---:|---:|" + "---:|" * len(TOOLS),
    ]
    for source in [*sources, "all"]:
        rows = [row for row in results if source in ("all", row["source"])]
        if not rows:
            continue
        cells = []
        for name, _ in TOOLS:
            outcomes = [row[name] for row in rows]
            if all(error.startswith("missing") for _, _, error in outcomes):
                cells.append("missing")
                continue
            share = np.mean([line for line, _, _ in outcomes])
            seconds = [value for _, value, _ in outcomes if value is not None]
            timeouts = sum(error == "timeout" for _, _, error in outcomes)
            text = f"{100 * share:.0f} % / {sum(seconds):.3g} s ({1e3 * np.median(seconds):.3g} ms)"
            cells.append(text + (f", {timeouts} timeouts" if timeouts else ""))
        vertices = int(np.median([row["vertices"] for row in rows]))
        lines.append(f"| {source} | {len(rows)} | {vertices} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def preload():
    """Import every tool's library here, once, so the forked children start warm (an import is no tool time)."""
    import importlib

    for module in ("incircu_plugin.core", "pygeoops", "label_centerlines", "centerline.geometry"):
        try:
            importlib.import_module(module)
        except ImportError:
            pass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="DejaVu Sans glyphs, 20 countries, 4 reservoirs")
    quick = parser.parse_args().quick
    preload()
    sources = {
        "glyphs": glyph_polygons(("DejaVu Sans",)) if quick else glyph_polygons(),
        "countries": country_polygons()[:: 9 if quick else 1],
        "reservoirs": reservoir_polygons()[: 4 if quick else None],
    }
    results = []
    load_before = os.getloadavg()[0]
    for source, polygons in sources.items():
        for name, polygon in polygons:
            row = {"source": source, "name": name, "vertices": len(polygon.exterior.coords) - 1}
            for index, (tool, _) in enumerate(TOOLS):
                row[tool] = run_once(index, polygon)
            results.append(row)
            failed = [tool for tool, _ in TOOLS if not row[tool][0]]
            print(f"{source:10s} {name:40s} no line: {', '.join(failed) or '-'}", flush=True)
    failures = sorted(row["name"] for row in results if not row["IncirCu"][0])
    markdown = f"""## Outside polygons: share with a line, and time

Generated by `benchmarks/bench_outside.py`: polygons gathered from outside the project at run time (sources
and licences in its docstring: DejaVu glyphs shipped with matplotlib, Natural Earth 1:110m countries from the
npm `world-atlas` package, the Natural Earth reservoirs of `tests/data`). Each tool once per polygon in a
forked child ({TIME_LIMIT:g} s limit; the time of a second run when the first took under {WARM_RUN_BELOW:g} s); *line*: the share whose output merges into one simple line inside the
polygon; *time*: total over the polygons, median per polygon in brackets. IncirCu with automatic ends and its
defaults; the peers as in the comparison above.

{table(results, list(sources))}

IncirCu gives no line on {len(failures)} of {len(results)}: {", ".join(failures) or "none"}. Load average
{load_before:.1f} at the start and {os.getloadavg()[0]:.1f} at the end on {os.cpu_count()} cores (other work on
the machine slows every tool alike; compare the columns, not the times with other sections).
"""
    print(markdown)
    write_section("outside", markdown)


if __name__ == "__main__":
    main()
