"""Where IncirCu's time goes: cProfile of ``polygon_centerline`` on the meander, on the first rivers of the
layer benchmark (one profile over all of them), on the 24-vertex rectangle (many calls: the per-feature
overhead) and on a synthetic river of 10^4 vertices (at 10^5 the adaptive engine of issue 9 needed minutes
and gigabytes; the scaling run and ``bench_core.py`` cover sizes). Each input's stages (validation,
splitting, islands, the engine's chains, the tracing, the line and the final check) are printed per call.

Writes ``benchmarks/results/profile.json`` (the top functions by own time, per input) for
docs/benchmark.md, and prints the same.
"""

import cProfile
import json
import pstats
import statistics
import sys
import time
from pathlib import Path

BENCH_DIR = Path(__file__).resolve().parent
if str(BENCH_DIR) not in sys.path:
    sys.path.insert(0, str(BENCH_DIR))

import cases as bench_cases
from harness import limit_memory
from peers import run_incircu

from tests.support import geometry_cases

RESULTS_DIR = BENCH_DIR / "results"
TOP_FUNCTIONS = 12

#: Rivers of the layer benchmark profiled together.
LAYER_RIVERS = 20

#: Calls of the rectangle profiled together.
RECTANGLE_CALLS = 200

#: Stages of ``polygon_centerline`` whose cumulative time is reported (``trace_alone``: the adaptive tracing;
#: ``centerline_from_chains`` holds it, the chains' cleaning and the engine's frame; ``lines_together``: the line).
STAGES = (
    "validate_polygon",
    "split_polygon",
    "bridge_islands",
    "_clean_chains",
    "trace_alone",
    "lines_together",
    "_checked",
    "centerline_from_chains",
)


def profile(name, case_list, repeats):
    """Median wall time of ``repeats`` runs over ``case_list``, then the top functions of one profiled run."""

    def run_all():
        for case in case_list:
            run_incircu(case)

    run_all()
    durations = []
    for _ in range(repeats):
        started = time.perf_counter()
        run_all()
        durations.append(time.perf_counter() - started)
    profiler = cProfile.Profile()
    profiler.enable()
    run_all()
    profiler.disable()
    stats = pstats.Stats(profiler)
    total = stats.total_tt
    rows = []
    for (filename, line, function), (_, calls, own, cumulative, _) in stats.stats.items():
        rows.append(
            {
                "function": f"{Path(filename).name}:{line}({function})",
                "calls": calls,
                "own_seconds": own,
                "cumulative_seconds": cumulative,
            }
        )
    rows.sort(key=lambda row: row["own_seconds"], reverse=True)
    stages = {}
    for stage in STAGES:
        matching = [row["cumulative_seconds"] for row in rows if row["function"].endswith(f"({stage})")]
        if matching:
            stages[stage] = max(matching)
    vertices = sum(case.vertex_count for case in case_list)
    return {
        "case": name,
        "calls": len(case_list),
        "vertices": vertices,
        "median_seconds": statistics.median(durations),
        "profiled_seconds": total,
        "stages": stages,
        "top": rows[:TOP_FUNCTIONS],
    }


def main():
    RESULTS_DIR.mkdir(exist_ok=True)
    limit_memory()
    meander, river = bench_cases.meander_case(), bench_cases.river_case(10_000)
    rivers = bench_cases.river_cases(LAYER_RIVERS, seed=0, with_reference=False)
    rectangle = bench_cases.from_geometry_case(geometry_cases.rectangle(n=11), "rectangle 100×10", with_oracle=False)
    results = [
        profile(meander.name, [meander], repeats=7),
        profile(f"the layer's first {LAYER_RIVERS} rivers", rivers, repeats=1),
        profile(f"rectangle 100×10, {RECTANGLE_CALLS} calls", [rectangle] * RECTANGLE_CALLS, repeats=3),
        profile(river.name, [river], repeats=1),
    ]
    for result in results:
        print(
            f"== {result['case']}: {result['median_seconds'] * 1e3:.1f} ms median, "
            f"{result['profiled_seconds'] * 1e3:.1f} ms under the profiler"
        )
        stages = ", ".join(
            f"{stage} {seconds / result['calls'] * 1e3:.3f}" for stage, seconds in result["stages"].items()
        )
        print(f"  stages, ms per call under the profiler: {stages}")
        for row in result["top"]:
            print(
                f"  {row['own_seconds'] * 1e3:9.1f} ms own {row['cumulative_seconds'] * 1e3:9.1f} ms cum "
                f"{row['calls']:>8}  {row['function']}"
            )
    (RESULTS_DIR / "profile.json").write_text(json.dumps(results, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
