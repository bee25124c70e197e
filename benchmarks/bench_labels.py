"""Label lines: IncirCu against label_centerlines, pygeoops and the centerline -> QGIS Smooth chain (issue 38).

Usage: ``.venv/bin/python benchmarks/bench_labels.py`` (the project's venv: QGIS for the Smooth chain and the
rendering); label_centerlines and pygeoops run in ``benchmarks/.venv-peers`` (made by ``benchmarks/run.sh``)
as child processes of this script (``--peer NAME``), each timing its own calls. Options: ``--count``
(generated lakes), ``--peer-count`` (of them given to the peers, which are slower), ``--render-count`` (lakes
in the rendering benchmark), ``--no-write`` (print only).

Lakes: the 16 real reservoirs of ``tests/data/real_rivers_ne_lonlat.geojson`` (Natural Earth, projected with
``LocalProjection``) and generated lakes (``generated_lakes``: winding channels of varying width with a side
bay, and round or oval lakes), metres.

Per tool and lake set: time per lake; the share of lakes with a line; the share of lines inside the lake with
the clearance (every segment at least 0.25 local widths from the shore, the local width at a point being the
main stem's incircle diameter at the nearest point of the main stem, the same measure for every tool); the
median over lines of the smallest radius of curvature (circle through three consecutive vertices) over the
local width, and the share of lines where it is at least 0.5 everywhere; the median share of the main stem's
length kept. The main stem is IncirCu's centerline (automatic ends). Peers: label_centerlines
``get_centerline(polygon)`` with its defaults (its smoothing, ``smooth_sigma=5``); pygeoops
``centerline(extend=True)``, its longest part; the chain a QGIS user builds today: IncirCu's centerline, then
``native:smoothgeometry`` (1 iteration, its default, and 10). The rendering section draws a layer of
``--render-count`` generated lakes labelled with ``styles/lake_labels.qml`` (``incircu_label_line`` as
geometry generator): the first draw computes every label line, later draws read the cache.

Prints Markdown tables and writes them between the ``labels`` markers of ``docs/benchmark.md``.
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import LineString, Point

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

PEERS_PYTHON = ROOT / "benchmarks" / ".venv-peers" / "bin" / "python"
CLEARANCE = 0.25
BEND = 0.5
SEED = 38
#: Most seconds a peer may take on one lake (its time then counts in its mean, and the lake has no line).
LAKE_LIMIT = 60


def generated_lakes(count, seed=SEED):
    """``count`` lakes in metres on a grid 60 km apart: three in four winding channels with a side bay (4 to
    25 widths long, width 200 to 2,000 m varying along them), one in four round or oval."""
    rng = np.random.default_rng(seed)
    lakes = []
    for index in range(count):
        origin = np.array([(index % 100) * 60_000.0, (index // 100) * 60_000.0])
        width = rng.uniform(200.0, 2000.0)
        if index % 4 == 0:
            ratio = rng.uniform(1.0, 2.2)
            lake = shapely.affinity.scale(Point(0, 0).buffer(width, quad_segs=16), ratio, 1.0)
            lake = shapely.affinity.rotate(lake, rng.uniform(0, 180))
        else:
            length = width * rng.uniform(4.0, 25.0)
            t = np.linspace(0.0, 1.0, 60)
            amplitude = rng.uniform(0.0, 0.25) * length
            waves = rng.uniform(0.5, 2.0)
            axis = np.column_stack([t * length, amplitude * np.sin(2 * math.pi * waves * t + rng.uniform(0, 6))])
            radii = 0.5 * width * (1.0 + 0.35 * np.sin(2 * math.pi * rng.uniform(1, 4) * t + rng.uniform(0, 6)))
            pieces = [
                LineString(axis[i : i + 2]).buffer(min(radii[i], radii[i + 1]), quad_segs=4) for i in range(len(t) - 1)
            ]
            at = int(rng.integers(10, 50))
            direction = axis[at + 1] - axis[at]
            normal = np.array([-direction[1], direction[0]]) / np.hypot(*direction)
            bay = LineString([axis[at], axis[at] + normal * width * rng.uniform(1.0, 2.5)])
            pieces.append(bay.buffer(0.15 * width, quad_segs=4))
            lake = shapely.union_all(pieces).simplify(width / 100.0)
            lake = shapely.affinity.rotate(lake, rng.uniform(0, 360), origin=(0, 0))
        lake = shapely.affinity.translate(lake, *origin)
        if lake.geom_type != "Polygon":
            lake = max(shapely.get_parts(lake), key=lambda part: part.area)
        lakes.append(shapely.Polygon(lake.exterior))
    return lakes


def real_lakes():
    from tests.support.real_rivers import real_rivers

    return [river.polygon for river in real_rivers()]


# --- peers, in the peers' venv -------------------------------------------------------------------------


def run_peer(name, polygon):
    if name == "label_centerlines":
        from label_centerlines import get_centerline

        return get_centerline(polygon)
    import pygeoops

    return pygeoops.centerline(polygon, extend=True)


class LakeTimeout(Exception):
    """A peer took longer than the limit on one lake."""


def _alarm(signum, frame):
    raise LakeTimeout


def peer_main(name, cases_path, out_path, time_limit):
    """Run peer ``name`` on every polygon of ``cases_path`` (WKB hex, JSON), at most ``LAKE_LIMIT`` seconds a
    lake (an alarm) and ``time_limit`` seconds in all; write lines and seconds."""
    import signal

    signal.signal(signal.SIGALRM, _alarm)
    polygons = [shapely.from_wkb(bytes.fromhex(text)) for text in json.loads(Path(cases_path).read_text())]
    results, spent = [], 0.0
    for polygon in polygons:
        if spent > time_limit:
            results.append({"error": "time limit"})
            continue
        started = time.perf_counter()
        signal.alarm(LAKE_LIMIT)
        try:
            line = run_peer(name, polygon)
            signal.alarm(0)
            seconds = time.perf_counter() - started
            results.append({"wkb": shapely.to_wkb(longest_part(line), hex=True), "seconds": seconds})
        except LakeTimeout:
            seconds = time.perf_counter() - started
            results.append({"error": "lake time limit", "seconds": seconds})
        except Exception as error:  # noqa: BLE001 - a peer failing on a lake is a result
            signal.alarm(0)
            seconds = time.perf_counter() - started
            results.append({"error": type(error).__name__, "seconds": seconds})
        spent += seconds
    Path(out_path).write_text(json.dumps(results))


def longest_part(geometry):
    parts = [part for part in shapely.get_parts(shapely.line_merge(geometry)) if part.geom_type == "LineString"]
    return max(parts, key=lambda part: part.length)


def peer_lines(name, polygons, time_limit):
    """Lines and seconds of a peer (None entries where it failed); None when its venv is missing."""
    if not PEERS_PYTHON.exists():
        return None
    with tempfile.TemporaryDirectory() as folder:
        cases, out = Path(folder) / "cases.json", Path(folder) / "out.json"
        cases.write_text(json.dumps([shapely.to_wkb(polygon, hex=True) for polygon in polygons]))
        command = [str(PEERS_PYTHON), __file__, "--peer", name, str(cases), str(out), str(time_limit)]
        done = subprocess.run(command, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            print(done.stderr[-2000:], file=sys.stderr)
            return None
        results = json.loads(out.read_text())
    lines = [shapely.from_wkb(bytes.fromhex(r["wkb"])) if "wkb" in r else None for r in results]
    seconds = [r.get("seconds") for r in results]
    return lines, seconds


# --- measures ----------------------------------------------------------------------------------------


def local_widths(stem, points):
    """The main stem's width at the nearest point of the stem to each point."""
    xy = shapely.get_coordinates(stem.line)
    chainage = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))])
    along = shapely.line_locate_point(stem.line, shapely.points(points))
    return np.interp(along, chainage, stem.widths)


def circumradii(xy):
    a, b, c = xy[:-2], xy[1:-1], xy[2:]
    ab, bc, ca = (np.hypot(*(q - p).T) for p, q in ((a, b), (b, c), (c, a)))
    area = 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(area > 0, ab * bc * ca / (4.0 * area), np.inf)


def measure(polygon, stem, line):
    """``(inside with clearance, smallest radius of curvature / width, share of the main stem kept)``."""
    xy = shapely.get_coordinates(line)
    xy = xy[np.concatenate([[True], np.any(np.diff(xy, axis=0) != 0, axis=1)])]
    widths = local_widths(stem, xy)
    segments = shapely.linestrings(np.stack([xy[:-1], xy[1:]], axis=1))
    distances = shapely.distance(segments, polygon.boundary)
    clear = bool(
        polygon.contains(line) and np.all(distances >= CLEARANCE * np.minimum(widths[:-1], widths[1:]) * (1 - 1e-6))
    )
    bend = float(np.min(circumradii(xy) / widths[1:-1])) if len(xy) > 2 else math.inf
    return clear, bend, line.length / stem.length


def summary(name, polygons, stems, lines, seconds):
    rows = [measure(p, s, line) for p, s, line in zip(polygons, stems, lines) if line is not None and s is not None]
    timed = [value for value in seconds if value is not None]
    if not rows:
        return {"tool": name, "lakes": len(polygons), "lines": 0, "seconds": np.mean(timed) if timed else None}
    clear, bend, kept = (np.array(column, dtype=float) for column in zip(*rows))
    return {
        "tool": name,
        "lakes": len(polygons),
        "lines": len(rows),
        "seconds": float(np.mean(timed)) if timed else None,
        "inside_clear": float(clear.mean()),
        "bend_median": float(np.median(bend)),
        "bend_ok": float(np.mean(bend >= BEND * (1 - 1e-6))),
        "kept": float(np.median(kept)),
    }


# --- IncirCu and the QGIS Smooth chain ---------------------------------------------------------------


def incircu_labels(polygons):
    from incircu_plugin.core import label_lines

    started = time.perf_counter()
    outcomes = label_lines(polygons)
    seconds = (time.perf_counter() - started) / len(polygons)
    labels = [None if isinstance(o, Exception) or o[0].result is None else o[0].result for o in outcomes]
    lines = [label.geometry if label is not None and label.kind == "line" else None for label in labels]
    points = sum(1 for label in labels if label is not None and label.kind == "point")
    stems = [None if label is None else label.centerline for label in labels]
    return lines, stems, seconds, points


def main_stems(polygons):
    from incircu_plugin.core import polygon_centerline

    started = time.perf_counter()
    results = polygon_centerline(list(polygons))
    seconds = (time.perf_counter() - started) / len(polygons)
    return [None if isinstance(r, Exception) else r for r in results], seconds


def start_qgis():
    from qgis.core import QgsApplication

    application = QgsApplication([], False)
    application.initQgis()
    sys.path.insert(0, "/usr/share/qgis/python/plugins")
    from processing.core.Processing import Processing

    Processing.initialize()
    return application


def smooth_chain(stems, iterations):
    """``native:smoothgeometry`` on the centerlines; returns the lines and the seconds per line."""
    import processing
    from qgis.core import QgsFeature, QgsGeometry, QgsVectorLayer

    layer = QgsVectorLayer("LineString?crs=EPSG:3857&field=i:integer", "stems", "memory")
    features = []
    for index, stem in enumerate(stems):
        if stem is None:
            continue
        feature = QgsFeature(layer.fields())
        feature.setAttributes([index])
        feature.setGeometry(QgsGeometry.fromWkt(stem.line.wkt))
        features.append(feature)
    layer.dataProvider().addFeatures(features)
    started = time.perf_counter()
    result = processing.run(
        "native:smoothgeometry",
        {"INPUT": layer, "ITERATIONS": iterations, "OFFSET": 0.25, "MAX_ANGLE": 180, "OUTPUT": "memory:"},
    )
    seconds = (time.perf_counter() - started) / max(len(features), 1)
    lines = [None] * len(stems)
    for feature in result["OUTPUT"].getFeatures():
        lines[feature["i"]] = shapely.from_wkb(bytes(feature.geometry().asWkb()))
    return lines, seconds


def render_benchmark(count):
    """Seconds of the first draw of ``count`` labelled lakes and of later draws (pan, zoom, redraw)."""
    import importlib.util

    from qgis.core import QgsCoordinateReferenceSystem, QgsRectangle

    spec = importlib.util.spec_from_file_location("label_style", ROOT / "scripts" / "make_label_style.py")
    style = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(style)
    cache = style.plugin_expressions().CACHE
    count_lakes = generated_lakes(count)
    layer = style.polygon_layer(count_lakes, [f"Lake {index}" for index in range(count)], "EPSG:3857")
    layer.loadNamedStyle(str(ROOT / "styles" / "lake_labels.qml"))
    crs = QgsCoordinateReferenceSystem("EPSG:3857")
    whole = layer.extent()
    timings = {}
    for name, extent in (
        ("first draw", whole),
        ("redraw", whole),
        (
            "pan",
            QgsRectangle(whole.xMinimum() + 0.1 * whole.width(), whole.yMinimum(), whole.xMaximum(), whole.yMaximum()),
        ),
        (
            "zoom in",
            QgsRectangle(
                whole.xMinimum(),
                whole.yMinimum(),
                whole.xMinimum() + 0.2 * whole.width(),
                whole.yMinimum() + 0.2 * whole.height(),
            ),
        ),
    ):
        started = time.perf_counter()
        style.render(layer, extent, (1600, 1000), crs)
        timings[name] = time.perf_counter() - started
    timings["cached results"] = len(cache.entries)
    return timings


# --- report ------------------------------------------------------------------------------------------


def cell(value, kind):
    if value is None:
        return "–"
    if kind == "share":
        return f"{100 * value:.0f} %"
    if kind == "seconds":
        return f"{value * 1000:.1f} ms" if value < 10 else f"{value:.0f} s"
    return f"{value:.2f}"


def table(rows):
    lines = [
        (
            "| tool | lakes | lines | time per lake | inside with clearance 0.25 | min radius / width (median) "
            "| radius >= 0.5 width | main stem kept (median) |"
        ),
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for row in rows:
        lines.append(
            f"| {row['tool']} | {row['lakes']} | {row['lines']} | {cell(row.get('seconds'), 'seconds')} "
            f"| {cell(row.get('inside_clear'), 'share')} | {cell(row.get('bend_median'), 'ratio')} "
            f"| {cell(row.get('bend_ok'), 'share')} | {cell(row.get('kept'), 'share')} |"
        )
    return "\n".join(lines)


def lake_set(name, polygons, peer_count, time_limit):
    """The rows of one set of lakes."""
    lines, stems, seconds, points = incircu_labels(polygons)
    chain_stems, stem_seconds = main_stems(polygons)
    rows = [summary("IncirCu label lines", polygons, stems, lines, [seconds] * len(polygons))]
    rows[0]["tool"] += f" ({points} label points)"
    for iterations in (1, 10):
        smoothed, smooth_seconds = smooth_chain(chain_stems, iterations)
        rows.append(
            summary(
                f"IncirCu centerline -> QGIS Smooth ({iterations} iteration{'s' * (iterations > 1)})",
                polygons,
                chain_stems,
                smoothed,
                [stem_seconds + smooth_seconds] * len(polygons),
            )
        )
    subset = polygons[:peer_count]
    subset_stems = chain_stems[:peer_count]
    ratios = {}
    for peer in ("label_centerlines", "pygeoops"):
        found = peer_lines(peer, subset, time_limit)
        if found is None:
            rows.append({"tool": f"{peer} (not installed)", "lakes": 0, "lines": 0})
            continue
        peer_found, peer_seconds = found
        rows.append(summary(peer, subset, subset_stems, peer_found, peer_seconds))
        timed = [s for s in peer_seconds if s is not None]
        if timed:
            # The same lakes through IncirCu, for the ratio.
            _, _, own_seconds, _ = incircu_labels(subset)
            ratios[peer] = float(np.mean(timed)) / own_seconds
    return rows, ratios


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--peer", nargs=4, metavar=("NAME", "CASES", "OUT", "TIME_LIMIT"))
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--peer-count", type=int, default=100)
    parser.add_argument("--render-count", type=int, default=10_000)
    parser.add_argument("--time-limit", type=float, default=900.0)
    parser.add_argument("--no-write", action="store_true")
    arguments = parser.parse_args()
    if arguments.peer:
        name, cases, out, limit = arguments.peer
        peer_main(name, cases, out, float(limit))
        return
    application = start_qgis()
    sections = []
    all_ratios = {}
    for name, polygons in (
        ("16 real reservoirs (Natural Earth)", real_lakes()),
        (f"{arguments.count} generated lakes", generated_lakes(arguments.count)),
    ):
        peer_count = min(len(polygons), arguments.peer_count)
        rows, ratios = lake_set(name, polygons, peer_count, arguments.time_limit)
        all_ratios[name] = ratios
        note = "" if peer_count == len(polygons) else f" (peers on the first {peer_count})"
        sections.append(f"**{name}**{note}\n\n{table(rows)}")
        print(sections[-1], flush=True)
    ratio_lines = [
        f"- {name}: label_centerlines / IncirCu time per lake = {r['label_centerlines']:.0f}x"
        for name, r in all_ratios.items()
        if "label_centerlines" in r
    ]
    timings = render_benchmark(arguments.render_count)
    render = (
        f"**Rendering {arguments.render_count} labelled lakes** (QGIS offscreen, 1600 x 1000 px, "
        "`styles/lake_labels.qml`): "
        + ", ".join(f"{name} {value:.2f} s" for name, value in timings.items() if name != "cached results")
        + f"; {timings['cached results']} results cached."
    )
    print("\n".join(ratio_lines))
    print(render)
    del application
    if arguments.no_write:
        return
    from benchmarks.report import write_section

    write_section(
        "labels",
        "## Label lines (issue 38)\n\nGenerated by `benchmarks/bench_labels.py` (see its docstring for the "
        "measures: the local width is the main stem's incircle diameter at the nearest point of the main stem, "
        "the same for every tool).\n\n" + "\n\n".join(sections) + "\n\n" + "\n".join(ratio_lines) + "\n\n" + render,
    )


if __name__ == "__main__":
    main()
