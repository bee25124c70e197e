"""A whole layer of rivers through ``qgis_process``, as a cartographer runs it: every feature written, time, memory.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_scale.py [--count 50000] [--seed 7]``

Input: rivers ``0`` to ``--count - 1`` of ``rivers.river_layer(seed=--seed)`` (about 296 boundary vertices each,
some with islands; 50,000 of them have 14.8 million), drawn in two processes and written to GeoPackages (the
polygons and their split points) through ``qgis_process`` itself (:class:`bench_layer.LayerFiles`). Then two runs
of ``incircu:polygoncenterline`` through ``qgis_process.bin`` (this checkout, isolated profile, as
:class:`peers.QgisProcess` sets it up): with the split-point layer, and with automatic ends. Columns:

- **written / skipped**: output features and the run's ``SKIPPED_COUNT`` (a skipped river is a lost one: the
  layer's rivers are all valid and elongated);
- **wall**: the ``qgis_process`` call, QGIS start-up and GeoPackage writing included; **features/s**;
- **peak memory**: the largest resident set of the ``qgis_process`` process (``ru_maxrss``), MiB: it stays flat
  over the run when nothing is held per feature;
- **output / input vertices**.

Prints a Markdown table, writes ``benchmarks/results/scale.json`` and the section between the ``scale`` markers
of ``docs/benchmark.md``. No issue sets a target; what it guards is that no feature of a large layer is lost.
"""

import argparse
import json
import multiprocessing
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BENCH_DIR = Path(__file__).resolve().parent
if str(BENCH_DIR) not in sys.path:
    sys.path.insert(0, str(BENCH_DIR))

import shapely
from bench_compare import incircu_version
from bench_layer import LayerFiles, read_geopackage
from peers import QGIS_PROCESS, QgisProcess
from report import write_section
from rivers import river_layer

RESULTS = BENCH_DIR / "results" / "scale.json"

#: Rivers drawn per task of the two drawing processes.
DRAW_CHUNK = 2_000

#: Runs ``argv[1:]`` and writes its peak resident set (KiB, the last line of stderr) after the child's output.
_PEAK_OF_CHILD = (
    "import resource, subprocess, sys\n"
    "code = subprocess.call(sys.argv[1:])\n"
    "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr)\n"
    "sys.exit(code)\n"
)


def _draw(arguments):
    """Rivers ``first`` to ``first + count - 1`` of the layer of ``seed`` (one drawing task)."""
    first, count, seed = arguments
    return river_layer(count, seed=seed, first=first)


def draw_rivers(count, seed):
    """The first ``count`` rivers of the layer of ``seed``, drawn in two processes."""
    tasks = [(first, min(DRAW_CHUNK, count - first), seed) for first in range(0, count, DRAW_CHUNK)]
    with multiprocessing.get_context("fork").Pool(2) as pool:
        return [river for chunk in pool.map(_draw, tasks) for river in chunk]


def measured_run(qgis, arguments):
    """Run ``qgis_process.bin arguments`` in a child that reports its peak memory: (stdout, seconds, MiB)."""
    started = time.perf_counter()
    completed = subprocess.run(
        [sys.executable, "-c", _PEAK_OF_CHILD, QGIS_PROCESS, *arguments],
        env=qgis.env,
        capture_output=True,
        text=True,
        check=False,
    )
    seconds = time.perf_counter() - started
    if completed.returncode != 0:
        raise RuntimeError(f"qgis_process {' '.join(arguments[:2])} failed: {completed.stderr[-2000:]}")
    return completed.stdout, seconds, int(completed.stderr.strip().splitlines()[-1]) / 1024.0


def skipped_count(stdout):
    """The ``SKIPPED_COUNT`` output of a run's log."""
    for line in stdout.splitlines():
        if line.startswith("SKIPPED_COUNT:"):
            return int(float(line.split(":", 1)[1]))
    raise RuntimeError("The run printed no SKIPPED_COUNT.")


def run(qgis, files, name, extra):
    """One run of the algorithm on the layer: its row of the table."""
    output = files.directory / f"{name.replace(' ', '-')}.gpkg"
    arguments = ["run", "incircu:polygoncenterline", "--", f"INPUT={files.polygons}", *extra, f"OUTPUT={output}"]
    stdout, seconds, peak = measured_run(qgis, arguments)
    lines = read_geopackage(output)
    print(f"  {name}: {seconds:.1f} s, {len(lines)} lines, peak {peak:.0f} MiB", flush=True)
    return {
        "run": name,
        "written": len(lines),
        "skipped": skipped_count(stdout),
        "seconds": seconds,
        "peak_mib": peak,
        "output_vertices": int(sum(shapely.get_num_coordinates(line) for line in lines)),
    }


def table(result):
    """The Markdown table of ``result`` (what :func:`main` saves)."""
    rows = [
        "| run | features | written | skipped | wall | features/s | peak memory | output / input vertices |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for row in result["runs"]:
        rows.append(
            f"| {row['run']} | {result['features']:,} | {row['written']:,} | {row['skipped']:,} "
            f"| {row['seconds']:.1f} s | {result['features'] / row['seconds']:.0f} | {row['peak_mib']:.0f} MiB "
            f"| {row['output_vertices'] / result['input_vertices']:.3f} |"
        )
    return "\n".join(rows)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=50_000)
    parser.add_argument("--seed", type=int, default=7)
    options = parser.parse_args(argv)
    load_before = os.getloadavg()
    started = time.perf_counter()
    rivers = draw_rivers(options.count, options.seed)
    input_vertices = sum(river.vertex_count for river in rivers)
    print(f"drew {len(rivers):,} rivers ({input_vertices:,} vertices) in {time.perf_counter() - started:.0f} s")
    with tempfile.TemporaryDirectory(prefix="incircu-scale-") as work:
        qgis = QgisProcess(work, plugins=["incircu"])
        files = LayerFiles(qgis, rivers, "EPSG:32633", "layer")
        del rivers
        runs = [
            run(qgis, files, "split points", [f"SPLIT_POINTS={files.ends}"]),
            run(qgis, files, "automatic ends", []),
        ]
    result = {
        "commit": incircu_version(),
        "features": options.count,
        "seed": options.seed,
        "input_vertices": input_vertices,
        "runs": runs,
        "load_before": load_before,
        "load_after": os.getloadavg(),
    }
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text(json.dumps(result, indent=1), encoding="utf-8")
    markdown = f"""## A large layer through qgis_process

Generated by `benchmarks/bench_scale.py`: rivers 0 to {options.count - 1:,} of `rivers.river_layer(seed={options.seed})`
({input_vertices:,} boundary vertices), each run one `qgis_process run incircu:polygoncenterline` on the whole
GeoPackage, at commit `{result["commit"]}`. Peak memory: the largest resident set of the `qgis_process` process.
Load average before: {", ".join(f"{value:.2f}" for value in load_before)}.

{table(result)}
"""
    print(markdown)
    write_section("scale", markdown)


if __name__ == "__main__":
    main()
