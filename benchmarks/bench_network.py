"""Networks: cost against the centerline, and arms found against the peers; prints Markdown tables.

Usage: ``python benchmarks/bench_network.py [--repeats 3] [--peers] [--grass] [--write]``
(``--peers`` needs pygeoops and pysfcgal: run it with ``benchmarks/.venv-peers/bin/python``, which
``benchmarks/run.sh`` builds; ``--grass`` also runs GRASS ``v.voronoi.skeleton`` through ``qgis_process``.)

1. **Cost.** The network of ``k`` ends traces its ``k - 1`` runs (one chain against the rest of the ring)
   together in one adaptive tracing, then locates the junctions (a few Newton steps each); the automatic
   ends add the skeleton and its pruning. Rows: the three-arm reservoir and six-arm delta of
   ``tests/support/network_cases``, road combs with 12, 50 and 100 arms, the meander of issue 2 with two to
   four given ends; columns: the automatic network, the network between the known ends, and
   ``polygon_centerline`` with automatic ends on the same polygon (best of ``--repeats``).
2. **Arms.** Generated shapes whose arms are known (flat-ended arms: a Y, a T, crossings, a delta, a comb,
   and the same with bank noise at 5 % of the width): per tool, the leaves of its line network (degree-one
   ends after joining coincident vertices) are matched to the true arm ends: an arm is *found* when a leaf
   lies within one typical width ``2 A / P`` of its end; *missing* arms have none; *spurious* leaves are all
   the others (a fork into both corners of a flat end counts one found and one spurious). *Junction error*:
   distance from each closed-form junction to the nearest vertex of degree three or more, in typical widths.
3. **Real.** The 16 reservoirs of ``tests/data``: time and leaves of each tool (no true arms known).

Peers at their defaults: pygeoops ``centerline(extend=True)`` (its own branch pruning), SFCGAL
``approximate_medial_axis`` (what QGIS 4.2's *Approximate medial axis* runs), GRASS
``v.voronoi.skeleton -s thin=-1`` (as ``benchmarks/peers.py`` runs it for the centerline comparison).
``--write`` puts the tables between the ``network`` markers of ``docs/benchmark.md``
(:func:`benchmarks.report.write_section`).
"""

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import shapely

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


def best_time(function, repeats, *args, **kwargs):
    """Return the shortest wall time of ``repeats`` calls (s) and the last result (or exception)."""
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        try:
            result = function(*args, **kwargs)
        except Exception as error:  # noqa: BLE001 - a peer's failure is a result of the benchmark
            result = error
        best = min(best, time.perf_counter() - start)
    return best, result


def typical_width(polygon):
    """``2 A / P``, the polygon's units."""
    return 2.0 * polygon.area / polygon.length


def graph_of(lines, tolerance):
    """Vertices (after joining those within ``tolerance``) and their degrees in a set of lines."""
    points, degree = [], []
    index = None
    for line in lines:
        coordinates = shapely.get_coordinates(line)
        if len(coordinates) < 2:
            continue
        for position in (0, -1):
            xy = coordinates[position]
            if points:
                index = shapely.STRtree(shapely.points(points))
                near = index.query(shapely.Point(xy), predicate="dwithin", distance=tolerance)
                if len(near):
                    degree[int(near[0])] += 1
                    continue
            points.append(xy)
            degree.append(1)
    return np.array(points).reshape(-1, 2), np.array(degree)


def arm_scores(lines, ends, junctions, width):
    """``(found, missing, spurious, junction error in widths or None)`` of a tool's lines."""
    points, degree = graph_of(lines, 1e-6 * width)
    leaves = points[degree == 1]
    found = 0
    for end in ends:
        if len(leaves) and np.min(np.hypot(*(leaves - end).T)) <= width:
            found += 1
    spurious = len(leaves) - found
    error = None
    if len(junctions):
        forks = points[degree >= 3]
        if len(forks):
            error = max(float(np.min(np.hypot(*(forks - junction).T))) for junction in junctions) / width
    return found, len(ends) - found, spurious, error


def incircu_lines(polygon):
    """The automatic network's branches (and its junctions)."""
    from incircu_plugin.core import polygon_network

    network = polygon_network(polygon)
    return [branch.result.line for branch in network.branches], network.junctions


def cost_table(repeats):
    """Section 1: network against centerline."""
    from incircu_plugin.core import polygon_centerline, polygon_network
    from tests.support import geometry_cases, network_cases

    meander = geometry_cases.meander()
    caps = list(meander.split_points)
    banks = [np.asarray(meander.polygon.exterior.interpolate(f, normalized=True).coords[0]) for f in (0.25, 0.7)]
    rows = [
        ("reservoir", *network_cases.reservoir()),
        ("delta", *network_cases.delta()),
        ("road comb", *network_cases.fishbone(sides=5)),
        ("road comb", *network_cases.fishbone(sides=24)),
        ("road comb", *network_cases.fishbone(sides=49)),
        ("meander", meander.polygon, caps),
        ("meander + 1 bank point", meander.polygon, caps + banks[:1]),
        ("meander + 2 bank points", meander.polygon, caps + banks),
    ]
    lines = [
        (
            "| shape | ends | boundary vertices | automatic network (s) | network, given ends (s) | centerline (s) | "
            "automatic / centerline | given / centerline |"
        ),
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for name, polygon, points in rows:
        automatic_time, automatic = best_time(polygon_network, repeats, polygon)
        given_time, _ = best_time(polygon_network, repeats, polygon, points)
        centerline_time, _ = best_time(polygon_centerline, repeats, polygon)
        ends = len(automatic.split_points) if not isinstance(automatic, Exception) else "error"
        lines.append(
            f"| {name} | {len(points)} (automatic: {ends}) | {len(polygon.exterior.coords) - 1} | {automatic_time:.3f} | "
            f"{given_time:.3f} | {centerline_time:.3f} | {automatic_time / centerline_time:.1f} | "
            f"{given_time / centerline_time:.1f} |"
        )
    return lines


def generated_cases():
    """(name, polygon, true arm ends, closed-form junctions) of the generated shapes, clean and noisy."""
    from tests.support import network_cases as cases

    clean = []
    polygon, caps, junctions, _ = cases.symmetric_y()
    clean.append(("Y", polygon, caps, junctions, 10.0))
    polygon, caps, junctions = cases.skewed_y()
    clean.append(("skewed Y", polygon, caps, junctions, 8.0))
    polygon, caps, junctions, _ = cases.t_junction()
    clean.append(("T", polygon, caps, junctions, 6.0))
    polygon, caps, junctions = cases.crossing(90.0)
    clean.append(("plus", polygon, caps, junctions, 6.0))
    polygon, caps, junctions = cases.crossing(60.0)
    clean.append(("oblique crossing", polygon, caps, junctions, 6.0))
    polygon, caps = cases.delta()
    clean.append(("6-arm delta", polygon, caps, [], 8.0))
    polygon, caps = cases.reservoir()
    clean.append(("3-arm reservoir", polygon, caps, [], 6.0))
    polygon, caps = cases.fishbone()
    clean.append(("12-arm road comb", polygon, caps, [], 6.0))
    result = [(name, polygon, np.asarray(caps, dtype=float), junctions) for name, polygon, caps, junctions, _ in clean]
    for name, polygon, caps, junctions, width in clean:
        for seed in (1, 2):
            noisy = cases.noisy(polygon, width, seed)
            result.append((f"{name}, 5 % bank noise ({seed})", noisy, np.asarray(caps, dtype=float), junctions))
    return result


def tools(peers, grass_dir):
    """The tools: (name, function polygon -> (lines, junctions or None))."""
    chosen = [("IncirCu network", incircu_lines)]
    if peers:
        from benchmarks.peers import Case, line_parts, run_pygeoops, run_sfcgal_medial_axis

        def peer(run):
            return lambda polygon: (line_parts(run(Case("network", polygon, (), typical_width(polygon)))), None)

        chosen += [
            ("pygeoops centerline", peer(run_pygeoops)),
            ("SFCGAL approximate medial axis", peer(run_sfcgal_medial_axis)),
        ]
        if grass_dir is not None:
            from benchmarks.peers import GrassRunner

            runner = GrassRunner(grass_dir)
            chosen.append(("GRASS v.voronoi.skeleton", peer(runner)))
    return chosen


def arms_table(chosen, repeats):
    """Section 2: arms found, missing and spurious on the generated shapes, per tool."""
    lines = [
        "| shape | true arms | tool | time (s) | found | missing | spurious | junction error (widths) |",
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    totals = {}
    for name, polygon, ends, junctions in generated_cases():
        width = typical_width(polygon)
        for tool, run in chosen:
            elapsed, output = best_time(run, repeats, polygon)
            total = totals.setdefault(tool, [0, 0, 0, 0, 0.0])
            if isinstance(output, Exception):
                lines.append(
                    f"| {name} | {len(ends)} | {tool} | {elapsed:.3f} | error: {type(output).__name__} | | | |"
                )
                total[3] += 1
                continue
            found, missing, spurious, error = arm_scores(output[0], ends, junctions, width)
            total[0] += missing
            total[1] += spurious
            total[2] += int(spurious > 0)
            total[4] += elapsed
            shown = "" if error is None else f"{error:.2g}"
            lines.append(
                f"| {name} | {len(ends)} | {tool} | {elapsed:.3f} | {found} | {missing} | {spurious} | {shown} |"
            )
    lines += [
        "",
        "| tool | missing arms (all shapes) | spurious leaves (all shapes) | shapes with a spurious leaf | errors | total time (s) |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for tool, (missing, spurious, shapes, errors, elapsed) in totals.items():
        lines.append(f"| {tool} | {missing} | {spurious} | {shapes} | {errors} | {elapsed:.2f} |")
    return lines


def real_table(chosen):
    """Section 3: the 16 reservoirs, time and leaves per tool."""
    from tests.support.real_rivers import real_rivers

    header = "| reservoir | " + " | ".join(f"{tool}: s, leaves" for tool, _ in chosen) + " |"
    lines = [header, "| --- |" + " --- |" * len(chosen)]
    for river in real_rivers():
        cells = []
        width = typical_width(river.polygon)
        for _, run in chosen:
            elapsed, output = best_time(run, 1, river.polygon)
            if isinstance(output, Exception):
                cells.append(f"{elapsed:.2f}, error")
                continue
            _, degree = graph_of(output[0], 1e-6 * width)
            cells.append(f"{elapsed:.2f}, {int(np.sum(degree == 1))}")
        lines.append(f"| {river.name} | " + " | ".join(cells) + " |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--peers", action="store_true", help="also pygeoops and SFCGAL (the peers' venv)")
    parser.add_argument("--grass", action="store_true", help="also GRASS v.voronoi.skeleton via qgis_process")
    parser.add_argument("--write", action="store_true", help="write the section of docs/benchmark.md")
    arguments = parser.parse_args()
    with tempfile.TemporaryDirectory() as grass_dir:
        chosen = tools(arguments.peers, grass_dir if arguments.grass else None)
        sections = [
            ("Cost of a network against the centerline", cost_table(arguments.repeats)),
            ("Arms found on generated shapes (true arms known)", arms_table(chosen, arguments.repeats)),
            ("Real reservoirs (tests/data)", real_table(chosen)),
        ]
    text = "\n".join(f"### {title}\n\n" + "\n".join(table) + "\n" for title, table in sections)
    print(text)
    if arguments.write:
        from benchmarks.report import write_section

        peers = "pygeoops, SFCGAL" + (", GRASS" if arguments.grass else "") if arguments.peers else "no peers"
        write_section(
            "network",
            f"## Networks\n\nGenerated by `benchmarks/bench_network.py` ({peers}; best of "
            f"{arguments.repeats}). See its docstring for what is measured.\n\n{text}",
        )


if __name__ == "__main__":
    main()
