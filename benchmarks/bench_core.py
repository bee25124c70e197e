"""Speed and memory of the IncirCu geometry core; prints a Markdown table.

Usage: ``python benchmarks/bench_core.py [--max-exponent 6] [--repeats 5]``

Rows:
- synthetic rivers (``tests/support/geometry_cases.synthetic_river``) with 10^3 .. 10^6 boundary vertices, sampled at
  their vertices only (the spacing exceeds the vertex spacing, so samples = vertices): wall time, time per
  sample, peak resident memory of a fresh process (input generation included), and growth against the
  previous row;
- the constant-width meander of issue 2 (length 2 km, width 20, 2,333 boundary vertices, spacing = width/10),
  median of ``--repeats`` runs, end to end from the chains;
- the same meander through ``polygon_centerline`` without split points (ends found automatically), and with
  40 islands (radius 2 to 4, off the axis; main-channel mode), median of ``--repeats`` runs;
- end to end (issue 9): the largest river through ``polygon_centerline`` from the polygon and its split points,
  at the core's defaults, in a fresh process: wall time and peak resident memory (input generation included);
  when that run fails (memory or time limit), the same at a tenth of the size.

``--json PATH`` also writes every number to PATH (``benchmarks/run.sh`` writes ``benchmarks/results/core.json``
for ``write_docs.py``).

Targets (issue 2): <= 5 us per sample at 10^6 samples on one core, growth <= 11x per 10x samples, peak
memory <= 1 GiB at 10^6 samples, meander <= 20 ms.
"""

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _measure_river(n_samples):
    """Run in a child process: time one river, report JSON on stdout."""
    sys.path.insert(0, str(ROOT))
    from incircu_plugin.core import centerline_from_chains
    from tests.support import geometry_cases

    case = geometry_cases.synthetic_river(n_samples)
    start = time.perf_counter()
    result = centerline_from_chains(case.chain_a, case.chain_b, spacing=1e12)
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"seconds": seconds, "peak_bytes": peak, "vertices": len(result.radii)}))


def _measure_end_to_end(n_vertices):
    """Run in a child process: one river from its polygon and split points at the defaults, JSON on stdout."""
    sys.path.insert(0, str(ROOT))
    from incircu_plugin.core import polygon_centerline
    from tests.support import geometry_cases

    case = geometry_cases.synthetic_river(n_vertices)
    start = time.perf_counter()
    result = polygon_centerline(case.polygon, case.split_points)
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(
        json.dumps(
            {
                "seconds": seconds,
                "peak_bytes": peak,
                "vertices": case.vertex_count,
                "output_vertices": len(result.line.coords),
            }
        )
    )


#: Longest run of one child (s) and the address space it may use: past them the row reports why it stopped.
CHILD_TIMEOUT_SECONDS = 900
CHILD_MEMORY_BYTES = 8 * 2**30


def _limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (CHILD_MEMORY_BYTES, CHILD_MEMORY_BYTES))


def _child_row(option, n, environment):
    """Run this script with ``option n`` in a fresh process (capped at ``CHILD_MEMORY_BYTES`` of address space
    and ``CHILD_TIMEOUT_SECONDS``) and return its JSON row, or ``{"error": why}``."""
    try:
        completed = subprocess.run(
            [sys.executable, __file__, option, str(n)],
            capture_output=True,
            text=True,
            env=environment,
            timeout=CHILD_TIMEOUT_SECONDS,
            preexec_fn=_limit_memory,
            check=False,
        )
    except subprocess.TimeoutExpired:
        return {"error": f"stopped after {CHILD_TIMEOUT_SECONDS} s", "vertices": n}
    if completed.returncode != 0:
        last = (completed.stderr.strip().splitlines() or ["no message"])[-1][:160]
        if "MemoryError" in last:
            last = f"MemoryError: over {CHILD_MEMORY_BYTES / 2**30:.0f} GiB of address space"
        return {"error": last, "vertices": n}
    return json.loads(completed.stdout.strip().splitlines()[-1])


def _measure_meander(repeats):
    sys.path.insert(0, str(ROOT))
    from incircu_plugin.core import centerline_from_chains
    from tests.support import geometry_cases

    case = geometry_cases.meander_with_vertex_count(2333)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        centerline_from_chains(case.chain_a, case.chain_b, spacing=case.width / 10.0)
        times.append(time.perf_counter() - start)
    return statistics.median(times), case.vertex_count


def _measure_hydro(repeats):
    """Median times (s) of the meander without split points and of the meander with 40 islands."""
    sys.path.insert(0, str(ROOT))
    import numpy as np
    from shapely.geometry import Point, Polygon

    from incircu_plugin.core import polygon_centerline
    from tests.support import geometry_cases

    case = geometry_cases.meander_with_vertex_count(2333)
    axis = np.asarray(case.axis_line.coords)
    rng = np.random.default_rng(0)
    stations = np.linspace(0.05, 0.95, 40) * (len(axis) - 1)
    islands = [
        Point(axis[int(i)] + (0.0, rng.uniform(-4.0, 4.0))).buffer(rng.uniform(2.0, 4.0), quad_segs=4) for i in stations
    ]
    with_islands = Polygon(case.polygon.exterior.coords, [island.exterior.coords for island in islands])
    runs = {
        "no split points": lambda: polygon_centerline(case.polygon, spacing=case.width / 10.0),
        "40 islands": lambda: polygon_centerline(with_islands, case.split_points, spacing=case.width / 10.0),
    }
    times = {}
    for name, run in runs.items():
        samples = []
        for _ in range(repeats):
            start = time.perf_counter()
            run()
            samples.append(time.perf_counter() - start)
        times[name] = statistics.median(samples)
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-exponent", type=int, default=6, help="largest river: 10**N vertices")
    parser.add_argument("--repeats", type=int, default=20, help="runs of the meander (median)")
    parser.add_argument("--json", type=Path, help="also write the results to this JSON file")
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--child-end-to-end", type=int, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.child:
        _measure_river(arguments.child)
        return
    if arguments.child_end_to_end:
        _measure_end_to_end(arguments.child_end_to_end)
        return

    import numpy
    import shapely

    print(
        f"Machine: {platform.processor() or platform.machine()} ({os.cpu_count()} cores), Python {platform.python_version()}, numpy {numpy.__version__}, shapely {shapely.__version__} (GEOS {shapely.geos_version_string})\n"
    )
    print("| samples | time (s) | us / sample | growth (x) | peak memory (MiB) |")
    print("|---:|---:|---:|---:|---:|")
    previous = None
    environment = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    load_before = os.getloadavg()
    rows = []
    for exponent in range(3, arguments.max_exponent + 1):
        n = 10**exponent
        row = dict(_child_row("--child", n, environment), samples=n)
        rows.append(row)
        if "error" in row:
            print(f"| {n:,} | {row['error']} | | | |")
            break
        growth = "" if previous is None else "{:.1f}".format(row["seconds"] / previous)
        print(
            "| {:,} | {:.3f} | {:.2f} | {} | {:.0f} |".format(
                n, row["seconds"], row["seconds"] / n * 1e6, growth, row["peak_bytes"] / 2**20
            )
        )
        previous = row["seconds"]
    end_to_end = _child_row("--child-end-to-end", 10**arguments.max_exponent, environment)
    smaller = None
    if "error" in end_to_end:
        print(
            f"\nEnd to end from the polygon, core defaults, {end_to_end['vertices']:,} vertices: {end_to_end['error']}"
        )
        smaller = _child_row("--child-end-to-end", 10 ** (arguments.max_exponent - 1), environment)
        if "error" not in smaller:
            print(
                f"At {smaller['vertices']:,} vertices: {smaller['seconds']:.2f} s, "
                f"peak memory {smaller['peak_bytes'] / 2**20:.0f} MiB."
            )
    else:
        print(
            f"\nEnd to end from the polygon, core defaults: {end_to_end['vertices']:,} boundary vertices in "
            f"{end_to_end['seconds']:.2f} s, peak memory {end_to_end['peak_bytes'] / 2**20:.0f} MiB, "
            f"{end_to_end['output_vertices']:,} output vertices."
        )
    median, vertices = _measure_meander(arguments.repeats)
    print(
        f"\nConstant-width meander (2 km, width 20, {vertices:,} boundary vertices, spacing 2): "
        f"median {median * 1e3:.1f} ms over {arguments.repeats} runs (target <= 20 ms)."
    )
    hydro = _measure_hydro(arguments.repeats)
    for name, seconds in hydro.items():
        print(f"The same meander, {name}: median {seconds * 1e3:.1f} ms over {arguments.repeats} runs.")
    if arguments.json:
        results = {
            "rivers": rows,
            "end_to_end": end_to_end,
            "end_to_end_smaller": smaller,
            "meander_seconds": median,
            "meander_variants": hydro,
            "load_average": {"start": load_before, "end": os.getloadavg()},
        }
        arguments.json.write_text(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
