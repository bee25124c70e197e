"""Side-by-side benchmark: IncirCu against the centerline tools QGIS users pick today (issue 4).

Runs every tool on the analytic shapes (exact axis known) and on real outlines (Natural Earth,
reference axis from the segment-Voronoi oracle), then the scaling run (time against boundary
vertices of a synthetic meandering river, 10^3 to 10^6), prints the tables and writes ``benchmarks/results/``:
``compare.json`` (every measurement), ``scaling.png`` and ``outlines.png``.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_compare.py [--quick]``
(``benchmarks/run.sh`` sets everything up and calls it).
"""

import argparse
import dataclasses
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BENCH_DIR = Path(__file__).resolve().parent
if str(BENCH_DIR) not in sys.path:
    sys.path.insert(0, str(BENCH_DIR))

import cases as bench_cases
from harness import preload, run_tool
from peers import INCIRCU, GrassRunner, peer_tools
from report import format_measurements

RESULTS_DIR = BENCH_DIR / "results"

#: Scaling sizes (boundary vertices of the synthetic river: meandering, width 20 ± 25 %, a vertex every
#: quarter width, so a longer river has more vertices, as in real data).
SCALING_SIZES = (1_000, 10_000, 100_000, 1_000_000)

#: A tool is not run at a size where its time, extrapolated from the smaller sizes, exceeds this.
SCALING_SKIP_SECONDS = 60.0

#: Growth exponent assumed from a single size: the peers measured here grow as n^1.3 to n^1.6.
ASSUMED_GROWTH = 1.5

#: Time limits in the scaling run (IncirCu must be allowed to finish its 10^6 vertices).
SCALING_TIMEOUT_SECONDS = {"IncirCu": 300.0, "peer": 90.0}


def incircu_version():
    """The repository's commit, marked when the core has uncommitted changes (what is being measured)."""

    def git(*arguments):
        completed = subprocess.run(
            ["git", "-C", str(BENCH_DIR.parent), *arguments], capture_output=True, text=True, check=False
        )
        return completed.stdout.strip()

    commit = git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = git("status", "--porcelain", "--", "incircu_plugin")
    return commit + (" + uncommitted changes to incircu_plugin/" if dirty else "")


def side_by_side(case_list, tools, timeout_seconds):
    """Measure IncirCu then every tool on every case; returns the measurements and kept geometries."""
    measurements, geometries = [], {}
    for case in case_list:
        for tool in [INCIRCU, *tools]:
            started = time.perf_counter()
            measurement, geometry = run_tool(tool, case, timeout_seconds=timeout_seconds)
            measurements.append(measurement)
            if geometry is not None:
                geometries[(case.name, tool.name)] = geometry
            print(
                f"  {case.name:<28} {tool.name:<26} {time.perf_counter() - started:7.1f} s  {measurement.error}",
                flush=True,
            )
    return measurements, geometries


def predicted_seconds(history, size):
    """Time at ``size`` extrapolated from (size, seconds) pairs: the last measured growth, at least linear
    (``ASSUMED_GROWTH`` while only one size is known)."""
    if not history:
        return 0.0
    if len(history) == 1:
        exponent = ASSUMED_GROWTH
    else:
        (size_a, time_a), (size_b, time_b) = history[-2], history[-1]
        exponent = max(1.0, math.log(time_b / time_a) / math.log(size_b / size_a))
    last_size, last_time = history[-1]
    return last_time * (size / last_size) ** exponent


def scaling(tools, sizes):
    """Time every tool on the synthetic river at each size; skip a size whose prediction is too long."""
    rows = []
    history = {tool.name: [] for tool in [INCIRCU, *tools]}
    for size in sizes:
        case = bench_cases.river_case(size)
        for tool in [INCIRCU, *tools]:
            prediction = predicted_seconds(history[tool.name], case.vertex_count)
            if prediction > SCALING_SKIP_SECONDS:
                rows.append(
                    {
                        "tool": tool.name,
                        "vertices": case.vertex_count,
                        "seconds": None,
                        "note": f"skipped: predicted {prediction:.0f} s",
                    }
                )
                print(f"  {case.name:<28} {tool.name:<26} skipped (predicted {prediction:.0f} s)", flush=True)
                continue
            limit = SCALING_TIMEOUT_SECONDS["IncirCu" if tool is INCIRCU else "peer"]
            measurement, _ = run_tool(tool, case, timeout_seconds=limit, budget_seconds=1.0)
            rows.append(
                {
                    "tool": tool.name,
                    "vertices": case.vertex_count,
                    "seconds": measurement.seconds,
                    "note": measurement.error,
                    "mean_dev_rel": measurement.mean_dev_rel,
                    "parts": measurement.parts,
                    "branches": measurement.branches,
                }
            )
            print(
                f"  {case.name:<28} {tool.name:<26} {measurement.seconds or 0:8.3f} s {measurement.error}", flush=True
            )
            if measurement.seconds is None:
                history[tool.name].append((case.vertex_count, float("inf")))
            else:
                history[tool.name].append((case.vertex_count, measurement.seconds))
    return rows


def plot_scaling(rows, path):
    """Log-log plot of time against boundary vertices, one line per tool."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4.5), dpi=110)
    for tool in dict.fromkeys(row["tool"] for row in rows):
        points = [(row["vertices"], row["seconds"]) for row in rows if row["tool"] == tool and row["seconds"]]
        if points:
            xs, ys = zip(*points)
            axes.loglog(xs, ys, marker="o", linewidth=2.5 if tool == INCIRCU.name else 1.2, label=tool)
    axes.set_xlabel("boundary vertices (synthetic meandering river)")
    axes.set_ylabel("wall time per run (s)")
    axes.set_title(f"Scaling (peers skipped past a predicted {SCALING_SKIP_SECONDS:.0f} s)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def plot_outlines(case_list, tool_names, geometries, path):
    """Grid of panels, one row per real outline and one column per tool: each tool's lines on the polygon."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from peers import line_parts

    aspects = []
    for case in case_list:
        x0, y0, x1, y1 = case.polygon.bounds
        aspects.append(min(max((y1 - y0) / (x1 - x0), 0.4), 3.0))
    figure, grid = plt.subplots(
        len(case_list),
        len(tool_names),
        dpi=72,
        squeeze=False,
        figsize=(1.9 * len(tool_names), 1.9 * sum(aspects) + 0.6),
        gridspec_kw={"height_ratios": aspects},
    )
    for row, case in zip(grid, case_list):
        for axes, tool_name in zip(row, tool_names):
            x, y = case.polygon.exterior.xy
            axes.fill(x, y, color="#dddddd", linewidth=0)
            geometry = geometries.get((case.name, tool_name))
            for part in line_parts(geometry):
                axes.plot(
                    *part.xy,
                    linewidth=1.2 if tool_name == INCIRCU.name else 0.7,
                    color="C3" if tool_name == INCIRCU.name else "C0",
                )
            if geometry is None:
                axes.text(
                    0.5,
                    0.5,
                    "no output\n(failed or timed out)",
                    ha="center",
                    va="center",
                    transform=axes.transAxes,
                    fontsize=7,
                )
            axes.set_aspect("equal")
            axes.set_xticks([])
            axes.set_yticks([])
            if case is case_list[0]:
                axes.set_title(tool_name.replace(" ", "\n", 1), fontsize=8)
        row[0].set_ylabel(case.name, fontsize=9)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller scaling range, no GRASS (a smoke run)")
    parser.add_argument(
        "--timeout",
        type=float,
        default=45.0,
        help="seconds allowed per tool and input, runs included (scaling: SCALING_TIMEOUT_SECONDS)",
    )
    arguments = parser.parse_args(argv)
    RESULTS_DIR.mkdir(exist_ok=True)
    preload()
    load_before = os.getloadavg()
    core_version = incircu_version()

    with tempfile.TemporaryDirectory(prefix="incircu-bench-") as work_dir:
        grass = None if arguments.quick else GrassRunner(work_dir)
        tools = peer_tools(grass)
        startup = None
        if grass is not None:
            grass.startup()
            durations = []
            for _ in range(3):
                started = time.perf_counter()
                grass.startup()
                durations.append(time.perf_counter() - started)
            startup = sorted(durations)[1]

        print("== Analytic shapes (exact axis)", flush=True)
        analytic = bench_cases.analytic_cases()
        analytic_measurements, _ = side_by_side(analytic, tools, arguments.timeout)

        print("== Real outlines (Natural Earth 1:10m, oracle medial axis)", flush=True)
        outlines = bench_cases.outline_cases()
        for case in outlines:
            case.extra["keep_geometry"] = True
        outline_measurements, outline_geometries = side_by_side(outlines, tools, arguments.timeout)
        plot_outlines(
            outlines, [tool.name for tool in [INCIRCU, *tools]], outline_geometries, RESULTS_DIR / "outlines.png"
        )

        print("== Scaling (synthetic river)", flush=True)
        sizes = SCALING_SIZES[:3] if arguments.quick else SCALING_SIZES
        scaling_rows = scaling(tools, sizes)
        plot_scaling(scaling_rows, RESULTS_DIR / "scaling.png")

    results = {
        "analytic": [dataclasses.asdict(m) for m in analytic_measurements],
        "outlines": [dataclasses.asdict(m) for m in outline_measurements],
        "outline_info": [
            {"name": c.name, "vertices": c.vertex_count, "width_m": c.width, "axis_kind": c.axis_kind} for c in outlines
        ],
        "analytic_info": [{"name": c.name, "vertices": c.vertex_count, "width": c.width} for c in analytic],
        "scaling": scaling_rows,
        "grass_startup_seconds": startup,
        "tools": {tool.name: tool.note for tool in [INCIRCU, *tools]},
        "quick": arguments.quick,
        "load_average": {"start": load_before, "end": os.getloadavg()},
        "incircu_version": core_version,
    }
    (RESULTS_DIR / "compare.json").write_text(json.dumps(results, indent=1))
    print(format_measurements(analytic_measurements, "Analytic shapes"))
    print(format_measurements(outline_measurements, "Real outlines"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
