"""Throughput of the data-frame API on dask: features per second on 1 and 2 worker processes, and the cost
per feature against the QGIS algorithm on the same layer; prints a Markdown table.

Usage: ``.venv/bin/python benchmarks/bench_frames.py [--count 10000] [--spacing 20] [--quick] [--no-qgis]``
(the project's venv: it has geopandas, dask-geopandas and distributed from ``requirements-dev.txt``).

The layer is ``tests/support/frame_cases.channels_lonlat``: small bent channels in EPSG:4326, split points at their
ends (every 50th finds its ends itself), a few bad rows. Rows:

- ``centerlines`` on the GeoPandas frame in this process (no dask), the reference the others must equal;
- the same on a dask-geopandas frame (16 partitions) on a ``LocalCluster`` of 1, then 2, worker processes with
  one thread each, timed from submission to the computed frame, after a warm-up that imports the core on
  every worker (cluster start-up excluded); the speedup is 1 worker's time over 2 workers';
- ``incircu:polygoncenterline`` through ``qgis_process`` (the plugin from this repository) on the same layer
  as GeoJSON with the same parameters, net of QGIS's start-up: (time on the layer - time on its first
  ``SMALL`` rows) / (rows - ``SMALL``).

Target (issue 12): 2 workers >= 1.7x 1 worker on an idle 2-core machine. The load average is printed: numbers
taken while other processes share the cores are not the machine's.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import geopandas
import numpy as np

from incircu_plugin.core import centerlines
from tests.support import frame_cases

#: Default boundary sampling, metres (the paper's fixed sampling); ``--spacing 0`` takes the core's default.
SPACING = 20.0
PARTITIONS = 16
#: Rows of the small layer whose qgis_process time is taken as QGIS's start-up.
SMALL = 10


def make_layer(count, seed=12):
    """The channels and their split points as GeoDataFrames in EPSG:4326."""
    channels, split_points, _ = frame_cases.channels_lonlat(count, seed)
    layer = geopandas.GeoDataFrame({"row": np.arange(count)}, geometry=channels, crs="EPSG:4326")
    return layer, geopandas.GeoDataFrame(geometry=split_points, crs="EPSG:4326")


def time_serial(layer, ends, spacing):
    """Seconds for ``centerlines`` on the whole frame in this process, and the result."""
    started = time.perf_counter()
    result = centerlines(layer, ends, spacing=spacing)
    return time.perf_counter() - started, result


def time_dask(layer, ends, workers, spacing):
    """Seconds for the lazy ``centerlines`` on a LocalCluster of ``workers`` processes, and the result."""
    import dask_geopandas
    import distributed

    os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    frame = dask_geopandas.from_geopandas(layer, npartitions=PARTITIONS, sort=False)
    with (
        distributed.LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        client.run(_import_core)
        centerlines(frame.head(4 * workers, npartitions=-1, compute=False), ends, spacing=spacing).compute()
        started = time.perf_counter()
        result = centerlines(frame, ends, spacing=spacing).compute()
        return time.perf_counter() - started, result


def _import_core():
    import incircu_plugin.core  # noqa: F401 - warm-up on a worker


def time_qgis(layer, ends, spacing, work_dir):
    """Seconds per feature of ``incircu:polygoncenterline`` in ``qgis_process``, net of its start-up."""
    executable = shutil.which("qgis_process.bin") or shutil.which("qgis_process")
    if executable is None:
        raise RuntimeError("qgis_process is not installed")
    plugins = work_dir / "plugins"
    plugins.mkdir()
    (plugins / "incircu").symlink_to(ROOT, target_is_directory=True)
    environment = dict(
        os.environ,
        QT_QPA_PLATFORM="offscreen",
        QGIS_CUSTOM_CONFIG_PATH=str(work_dir / "profile"),
        QGIS_PLUGINPATH=str(plugins),
        PYTHONPATH=str(ROOT / ".venv" / "qgis-site"),
    )

    def run(*arguments):
        completed = subprocess.run(
            [executable, *arguments], env=environment, capture_output=True, text=True, timeout=3600, check=False
        )
        if completed.returncode != 0:
            raise RuntimeError(f"qgis_process {arguments[0]} failed: {completed.stderr[-1500:]}")

    run("plugins", "enable", "incircu")
    (work_dir / "ends.geojson").write_text(ends.to_json())
    seconds = {}
    for name, rows in (("small", layer.iloc[:SMALL]), ("layer", layer)):
        (work_dir / f"{name}.geojson").write_text(rows.to_json())
        started = time.perf_counter()
        run(
            "run",
            "incircu:polygoncenterline",
            "--",
            f"INPUT={work_dir / f'{name}.geojson'}",
            f"SPLIT_POINTS={work_dir / 'ends.geojson'}",
            "SNAP_TOLERANCE=1",
            f"SPACING={spacing or 0}",
            f"OUTPUT={work_dir / f'{name}-out.gpkg'}",
        )
        seconds[name] = time.perf_counter() - started
    return (seconds["layer"] - seconds["small"]) / (len(layer) - SMALL), seconds


def same_results(one, other):
    """True when two result frames hold the same lines, numbers and errors, row by row."""
    lines = all(
        (a is None and b is None) or (a is not None and b is not None and a.equals_exact(b, 0.0))
        for a, b in zip(one.geometry, other.geometry)
    )
    numbers = np.array_equal(one["length"].to_numpy(), other["length"].to_numpy(), equal_nan=True)
    return lines and numbers and one["error"].fillna("").tolist() == other["error"].fillna("").tolist()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=10_000, help="channels in the layer")
    parser.add_argument("--spacing", type=float, default=SPACING, help="metres; 0: the core's default sampling")
    parser.add_argument("--quick", action="store_true", help="1,000 channels (a smoke run)")
    parser.add_argument("--no-qgis", action="store_true", help="skip the qgis_process row")
    arguments = parser.parse_args(argv)
    count = 1_000 if arguments.quick else arguments.count
    spacing = arguments.spacing or None
    layer, ends = make_layer(count)
    load_before = os.getloadavg()[0]
    rows = []
    serial_seconds, serial = time_serial(layer, ends, spacing)
    rows.append(("centerlines, GeoPandas, this process", serial_seconds, True))
    dask_seconds = {}
    for workers in (1, 2):
        dask_seconds[workers], result = time_dask(layer, ends, workers, spacing)
        name = f"centerlines, dask-geopandas, {workers} worker process{'es' if workers > 1 else ''}"
        rows.append((name, dask_seconds[workers], same_results(result, serial)))
    qgis_note = ""
    if not arguments.no_qgis:
        with tempfile.TemporaryDirectory() as work_dir:
            per_feature, seconds = time_qgis(layer, ends, spacing, Path(work_dir))
        rows.append(("incircu:polygoncenterline, qgis_process (net of start-up)", per_feature * count, None))
        qgis_note = f"qgis_process: {seconds['layer']:.1f} s on the layer, {seconds['small']:.1f} s on {SMALL} rows."
    sampling = f"spacing {spacing:g} m" if spacing else "the core's default sampling"
    print(f"{count:,} channels (EPSG:4326), {sampling}, {PARTITIONS} partitions, {os.cpu_count()} cores\n")
    print("| run | seconds | features/s | ms per feature | × serial cost | same as serial |")
    print("|---|---:|---:|---:|---:|---|")
    for name, seconds, same in rows:
        same_text = "–" if same is None else ("yes" if same else "**no**")
        print(
            f"| {name} | {seconds:.2f} | {count / seconds:,.0f} | {seconds / count * 1e3:.3f} | "
            f"{seconds / serial_seconds:.2f} | {same_text} |"
        )
    print(f"\nSpeedup, 2 worker processes over 1: {dask_seconds[1] / dask_seconds[2]:.2f}× (target ≥ 1.7× when idle).")
    if qgis_note:
        print(qgis_note)
    print(f"Load average (1 min) before / after: {load_before:.1f} / {os.getloadavg()[0]:.1f}.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
