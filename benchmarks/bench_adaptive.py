"""Adaptive sampling against the engine before it (fixed sampling at the default spacing): speed, memory, size.

Usage::

    git archive <commit before the adaptive engine> | tar -x -C /tmp/before   # once
    python benchmarks/bench_adaptive.py --before /tmp/before [--max-exponent 6] [--repeats 200]

Every row runs both engines in the same run, each in a fresh child process (``OMP_NUM_THREADS=1``), so the
ratio holds even on a loaded machine; absolute times do not. Rows, all at each engine's defaults:

- the 100 x 10 rectangle with 24 boundary vertices: ``polygon_centerline`` per call (median of
  ``--repeats``), the per-call overhead small features pay; and per feature when 1,000 of them are traced
  together (``polygon_centerline`` of an array, as the plugin runs a layer);
- the constant-width meander (2 km, width 20, 2,333 boundary vertices), from the chains, median;
- synthetic rivers (``tests/support/geometry_cases.synthetic_river``, a vertex every quarter width) with
  10^4 .. 10^N boundary vertices, from the chains, end to end: time and peak resident memory of the child
  (input generation included);

each with the output's vertex count against the input's.
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

#: Rectangles traced together in the "per feature, traced together" row (as the plugin runs a layer).
TOGETHER = 1000

#: Longest a child may run, seconds (the engine before the adaptive one needs about 30 s at 10^6 vertices).
CHILD_TIMEOUT = 900


def _child(root, row, size, repeats):
    """In a child process: run one row on the engine under ``root``; print JSON on stdout."""
    sys.path.insert(0, root)
    from incircu_plugin.core import centerline_from_chains, polygon_centerline
    from tests.support import geometry_cases

    if row == "rectangle":
        case = geometry_cases.rectangle(n=11)
        run = lambda: polygon_centerline(case.polygon, case.split_points)
    elif row == "rectangles together":
        case = geometry_cases.rectangle(n=11)
        run = lambda: polygon_centerline([case.polygon] * TOGETHER, [case.split_points] * TOGETHER)[0]
    elif row == "meander":
        case = geometry_cases.meander_with_vertex_count(2333)
        run = lambda: centerline_from_chains(case.chain_a, case.chain_b)
    else:
        case = geometry_cases.synthetic_river(size)
        run = lambda: centerline_from_chains(case.chain_a, case.chain_b)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    if row == "rectangles together":
        times = [duration / TOGETHER for duration in times]
    vertices = len(case.chain_a) + len(case.chain_b) - 2
    print(
        json.dumps(
            {
                "seconds": statistics.median(times),
                "peak_bytes": peak,
                "output": len(result.line.coords),
                "input": vertices,
            }
        )
    )


def _measure(root, row, size, repeats):
    environment = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    try:
        output = subprocess.run(
            [sys.executable, __file__, "--child", root, row, str(size), str(repeats)],
            check=True,
            capture_output=True,
            text=True,
            env=environment,
            timeout=CHILD_TIMEOUT,
        ).stdout
    except subprocess.TimeoutExpired:
        return None
    except subprocess.CalledProcessError as error:
        return {"error": error.stderr.strip().splitlines()[-1]}
    return json.loads(output.strip().splitlines()[-1])


def _cell(row):
    if row is None:
        return f"> {CHILD_TIMEOUT} s", "", ""
    if "error" in row:
        return row["error"][:40], "", ""
    seconds = row["seconds"]
    shown = f"{seconds * 1e3:.2f} ms" if seconds < 1 else f"{seconds:.2f} s"
    return shown, f"{row['peak_bytes'] / 2**20:.0f}", f"{row['output']:,} ({row['output'] / row['input']:.2f}x)"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", help="source tree of the engine to compare with (required)")
    parser.add_argument("--max-exponent", type=int, default=6, help="largest river: 10**N boundary vertices")
    parser.add_argument("--repeats", type=int, default=200, help="runs of the rectangle (median)")
    parser.add_argument("--child", nargs=4, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.child:
        root, row, size, repeats = arguments.child
        _child(root, row, int(size), int(repeats))
        return
    if not arguments.before:
        parser.error("--before is required")

    import numpy
    import shapely

    print(
        f"Machine: {platform.processor() or platform.machine()} ({os.cpu_count()} cores, shared), Python "
        f"{platform.python_version()}, numpy {numpy.__version__}, shapely {shapely.__version__} "
        f"(GEOS {shapely.geos_version_string}). Each row: both engines in the same run, fresh child processes.\n"
    )
    print(
        "| input | before: time | before: peak MiB | before: output vertices | after: time | after: peak MiB | after: output vertices | speed-up |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    rows = [("rectangle 100x10, 24 v, per call", "rectangle", 0, arguments.repeats)]
    rows.append((f"same, per feature of {TOGETHER:,} traced together", "rectangles together", 0, 5))
    rows.append(("meander 2 km, 2,333 v", "meander", 0, max(5, arguments.repeats // 20)))
    rows += [(f"river {10**k:,} v", "river", 10**k, 1) for k in range(4, arguments.max_exponent + 1)]
    for label, row, size, repeats in rows:
        before = _measure(arguments.before, row, size, repeats)
        after = _measure(str(ROOT), row, size, repeats)
        ratio = ""
        if before and after and "error" not in before and "error" not in after:
            ratio = f"{before['seconds'] / after['seconds']:.1f}x"
        print(f"| {label} | {' | '.join(_cell(before))} | {' | '.join(_cell(after))} | {ratio} |", flush=True)


if __name__ == "__main__":
    main()
