"""Speed of the automatic ends (``find_ends``); prints a Markdown table.

Usage: ``python benchmarks/bench_ends.py [--repeats 3]``

Rows: boxes ``1 x h`` from ``h = 1e-1`` down to ``1e-6`` (4 vertices, the skeleton's sample count grows
with the aspect ratio up to ``skeleton.MAX_SAMPLES``), the issue's meander with 2,333 to 100,000 boundary
vertices, synthetic rivers (``geometry_cases.synthetic_river``) and the Gambia outline (Natural Earth 1:10m,
``tests/data``). Columns: input vertices, boundary samples of the skeleton (after simplification and
densification), median wall and CPU time of ``--repeats`` runs (the CPU time does not count waiting for a
core on a shared machine), and CPU microseconds per input vertex and per sample.

Target (issue 14): thin boxes well under a second; <= 3 us per boundary vertex on large real-like outlines.
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

from incircu_plugin.core import find_ends
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    arguments = parser.parse_args()
    print("| input | vertices | samples | wall (s) | CPU (s) | CPU us / vertex | CPU us / sample |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, polygon in cases():
        vertices = int(shapely.get_num_coordinates(polygon)) - 1 - len(polygon.interiors)
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


if __name__ == "__main__":
    main()
