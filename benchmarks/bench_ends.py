"""Speed of the automatic ends (``find_ends``); prints a Markdown table.

Usage: ``python benchmarks/bench_ends.py [--repeats 3] [--batches-only]``

Rows: boxes ``1 x h`` from ``h = 1e-1`` down to ``1e-6`` (4 vertices, the skeleton's sample count grows
with the aspect ratio up to ``skeleton.MAX_SAMPLES``), the issue's meander with 2,333 to 100,000 boundary
vertices, synthetic rivers (``geometry_cases.synthetic_river``) and the Gambia outline (Natural Earth 1:10m,
``tests/data``). Columns: input vertices, boundary samples of the skeleton (after simplification and
densification), median wall and CPU time of ``--repeats`` runs (the CPU time does not count waiting for a
core on a shared machine), and CPU microseconds per input vertex and per sample.

Target (issue 14): thin boxes well under a second; <= 3 us per boundary vertex on large real-like outlines.

A second table compares many small features one by one (``find_ends`` per polygon) with the same features
together (``find_ends_together``, what a batch of an array of polygons uses): 1,000 rectangles
``100 x (10 + i / 100)`` segmentized every 10 (24 vertices each) and the 400 rivers of
``rivers.river_layer(count=400)`` (about 290 vertices each, some with islands). Columns: CPU microseconds per
boundary vertex and per polygon, median of ``--repeats`` runs. Target (issue 9): <= 3 us per boundary vertex
in batches; not met: 3.5 us on the 400 rivers together in the run of 2026-12-04 (3.9 before stop 33, 4.8 before
branch ``ends2``, 5.0 to 5.3 before branch ``ends``), of which the GEOS calls take about 1.9 us (see
``docs/ends-benchmark.md``).
"""

import argparse
import statistics
import sys
import time
from pathlib import Path

import shapely
from shapely.geometry import box

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.rivers import river_layer
from incircu_plugin.core import find_ends
from incircu_plugin.core.ends import find_ends_together
from incircu_plugin.core.skeleton import boundary_samples
from tests.support import geometry_cases


def sample_count(polygon):
    """Return the number of boundary samples the skeleton triangulates (before conforming splits)."""
    return sum(len(ring) for ring in boundary_samples(polygon)[0])


def cases():
    """Yield ``(name, polygon)`` pairs."""
    for exponent in range(1, 7):
        yield f"box 1 x 1e-{exponent}", box(0.0, 0.0, 1.0, 10.0**-exponent)
    for count in (2_333, 20_000, 100_000):
        yield f"meander, {count:,} v", geometry_cases.meander_with_vertex_count(count).polygon
    for count in (10_000, 100_000):
        yield f"synthetic river, {count:,} v", geometry_cases.synthetic_river(count).polygon
    yield "Gambia (NE 10m, UTM)", geometry_cases.gambia().polygon


def batch_cases():
    """Yield ``(name, polygons)`` pairs of many small features."""
    yield (
        "1,000 rectangles 100 x 10",
        [box(0.0, 0.0, 100.0, 10.0 + index / 100.0).segmentize(10.0) for index in range(1000)],
    )
    yield "400 rivers (river_layer)", [river.polygon for river in river_layer(count=400)]


def boundary_vertices(polygon):
    """Return the number of distinct vertices of a polygon's rings."""
    return int(shapely.get_num_coordinates(polygon)) - 1 - len(polygon.interiors)


def median_cpu(function, repeats):
    """Return the median CPU time of ``repeats`` calls of ``function()``, seconds."""
    times = []
    for _ in range(repeats):
        start = time.process_time()
        function()
        times.append(time.process_time() - start)
    return statistics.median(times)


def batch_table(repeats):
    """Print the one-by-one versus together table."""
    print()
    print(
        "| features | polygons | vertices | one by one: CPU us / vertex | us / polygon "
        "| together: CPU us / vertex | us / polygon | speed-up |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, polygons in batch_cases():
        vertices = sum(boundary_vertices(polygon) for polygon in polygons)
        alone = median_cpu(lambda items=polygons: [find_ends(polygon) for polygon in items], repeats)
        together = median_cpu(lambda items=polygons: find_ends_together(items), repeats)
        print(
            f"| {name} | {len(polygons):,} | {vertices:,} | {1e6 * alone / vertices:.1f} "
            f"| {1e6 * alone / len(polygons):.0f} | {1e6 * together / vertices:.1f} "
            f"| {1e6 * together / len(polygons):.0f} | {alone / together:.1f}x |",
            flush=True,
        )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--batches-only", action="store_true", help="print only the one-by-one/together table")
    arguments = parser.parse_args()
    if arguments.batches_only:
        batch_table(arguments.repeats)
        return
    print("| input | vertices | samples | wall (s) | CPU (s) | CPU us / vertex | CPU us / sample |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, polygon in cases():
        vertices = boundary_vertices(polygon)
        samples = sample_count(polygon)
        walls, cpus = [], []
        for _ in range(arguments.repeats):
            wall, cpu = time.perf_counter(), time.process_time()
            find_ends(polygon)
            walls.append(time.perf_counter() - wall)
            cpus.append(time.process_time() - cpu)
        cpu = statistics.median(cpus)
        print(
            f"| {name} | {vertices:,} | {samples:,} | {statistics.median(walls):.3f} | {cpu:.3f} "
            f"| {1e6 * cpu / vertices:.1f} | {1e6 * cpu / samples:.1f} |",
            flush=True,
        )
    batch_table(arguments.repeats)


if __name__ == "__main__":
    main()
