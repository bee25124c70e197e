"""Per call and per array (issue 39): what one feature costs alone and in an array, and whether its bytes change.

Rows, each timed in this process after a warm-up, median of ``--repeats`` runs:

- the 24-vertex rectangle (100 x 10, sides cut every 10 units) with its split points: ``polygon_centerline``
  called alone, and per feature in an array of 200 (``polygon_centerline(array)``), against pygeoops'
  ``centerline`` when it is installed (the peers' venv of ``benchmarks/run.sh``);
- a 300-vertex river of :mod:`rivers` with its split points, the same two ways;
- the 400 rivers of the layer benchmark with their split points: in a loop of single calls, and as one array.

Then the identity check: the rivers of a seeded layer (``--identity`` of them, 1,000 by default) each alone,
as one array, reversed, and in 8 slices (as 8 dask partitions or a selection would split them): the number of
rivers whose line, radii or feet differ in any bit from alone (must be 0).

Usage: ``python benchmarks/bench_calls.py [--repeats 5] [--identity 1000] [--write]``; ``--write`` puts the
table in its section of ``docs/benchmark.md``.
"""

import argparse
import statistics
import sys
import time
from functools import partial
from pathlib import Path

import numpy as np
from shapely.geometry import Polygon

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from benchmarks.report import write_section
from benchmarks.rivers import river_layer
from fuzz.checks import outcome_key
from incircu_plugin.core import polygon_centerline

#: Features in the array of the per-feature "in an array" rows.
ARRAY = 200


def pygeoops_centerline():
    """pygeoops' ``centerline`` function, or None when pygeoops is not installed."""
    try:
        import pygeoops
    except ImportError:
        return None
    return pygeoops.centerline


def median_seconds(run, repeats, per=1):
    """Median wall time of ``run()`` over ``repeats`` runs after one warm-up, divided by ``per``, seconds."""
    run()
    times = []
    for _ in range(repeats):
        started = time.perf_counter()
        run()
        times.append(time.perf_counter() - started)
    return statistics.median(times) / per


def cases():
    """``(name, polygon, split points)`` of the single-feature rows."""
    # Long sides cut every 10 units, short sides in the middle: 24 vertices.
    rectangle = Polygon(
        [(x, 0.0) for x in range(0, 100, 10)]
        + [(100.0, 0.0), (100.0, 5.0)]
        + [(x, 10.0) for x in range(100, 0, -10)]
        + [(0.0, 10.0), (0.0, 5.0)]
    )
    river = river_layer(1, seed=3, boundary_vertices=300)[0]
    return [
        (f"rectangle, {len(rectangle.exterior.coords) - 1} vertices", rectangle, [(0.0, 5.0), (100.0, 5.0)]),
        (f"river, {len(river.polygon.exterior.coords) - 1} vertices", river.polygon, [e.coords[0] for e in river.ends]),
    ]


def timing_rows(repeats):
    """Rows ``(case, IncirCu alone, IncirCu per feature in an array, pygeoops alone)``, milliseconds."""
    peer = pygeoops_centerline()
    rows = []
    for name, polygon, ends in cases():
        alone = median_seconds(partial(polygon_centerline, polygon, ends), repeats * 20)
        array = median_seconds(partial(polygon_centerline, [polygon] * ARRAY, [ends] * ARRAY), repeats, ARRAY)
        other = None if peer is None else median_seconds(partial(peer, polygon), repeats * 20)
        rows.append((name, alone, array, other))
    rivers = river_layer(400)
    polygons = [river.polygon for river in rivers]
    ends = [[end.coords[0] for end in river.ends] for river in rivers]
    loop = median_seconds(lambda: [polygon_centerline(p, e) for p, e in zip(polygons, ends)], repeats, len(rivers))
    array = median_seconds(lambda: polygon_centerline(polygons, ends), repeats, len(rivers))
    other = None if peer is None else median_seconds(lambda: [peer(p) for p in polygons], repeats, len(rivers))
    rows.append(("400 rivers (per river)", loop, array, other))
    return rows


def identity_counts(count):
    """Per way of computing the rivers (one array, reversed, 8 slices), how many differ in any bit from alone."""
    rivers = river_layer(count, seed=11)
    polygons = [river.polygon for river in rivers]
    ends = [[end.coords[0] for end in river.ends] for river in rivers]
    alone = [outcome_key(_outcome(polygon_centerline, p, e)) for p, e in zip(polygons, ends)]
    ways = {
        "one array": list(range(count)),
        "reversed": list(range(count))[::-1],
    }
    counts = {}
    for way, order in ways.items():
        outcomes = polygon_centerline([polygons[i] for i in order], [ends[i] for i in order])
        counts[way] = sum(outcome_key(o) != alone[i] for i, o in zip(order, outcomes))
    sliced = 0
    for part in np.array_split(np.arange(count), 8):
        outcomes = polygon_centerline([polygons[i] for i in part], [ends[i] for i in part])
        sliced += sum(outcome_key(o) != alone[i] for i, o in zip(part, outcomes))
    counts["8 slices"] = sliced
    return counts


def _outcome(function, *arguments):
    try:
        return function(*arguments)
    except Exception as error:  # noqa: BLE001 - an error is an outcome to compare too
        return error


def markdown(rows, counts, identity):
    """The section's text."""
    lines = [
        "## One feature alone, and in an array (issue 39)",
        "",
        (
            "`python benchmarks/bench_calls.py`: milliseconds per feature, median of repeated runs in one process "
            "(times depend on the machine and its load: compare the columns)."
        ),
        "",
        "| case | IncirCu alone | IncirCu in an array | pygeoops alone |",
        "| --- | --- | --- | --- |",
    ]
    for name, alone, array, other in rows:
        peer = "–" if other is None else f"{1e3 * other:.2f}"
        lines.append(f"| {name} | {1e3 * alone:.2f} | {1e3 * array:.2f} | {peer} |")
    lines += [
        "",
        f"Same input, same bytes: {identity} rivers each alone against the same rivers "
        + ", ".join(f"{way}: **{count}** differ" for way, count in counts.items())
        + " (line, radii or feet differing in any bit).",
    ]
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--identity", type=int, default=1000, help="rivers of the identity check")
    parser.add_argument("--write", action="store_true", help="write the section of docs/benchmark.md")
    arguments = parser.parse_args(argv)
    text = markdown(timing_rows(arguments.repeats), identity_counts(arguments.identity), arguments.identity)
    print(text)
    if arguments.write:
        write_section("calls", text)


if __name__ == "__main__":
    main()
