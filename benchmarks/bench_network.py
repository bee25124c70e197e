"""Cost of a network against the centerline of the same polygon; prints a Markdown table.

Usage: ``python benchmarks/bench_network.py [--repeats 3]``

A network of ``k`` split points runs the engine ``k - 1`` times on the whole polygon (one chain against the
rest of the ring), so it should cost about ``k - 1`` centerlines, plus the junctions (a few Newton steps
each) and the labelling of the vertices (O(k log n) nearest-chain queries per run). Rows: the three-arm
reservoir and the six-arm delta of ``tests/support/network_cases``, and the constant-width meander of issue 2
(2,333 boundary vertices) split at its two caps plus zero, one or two points on its banks. Default sampling
of the engine; best of ``--repeats`` runs.
"""

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def best_time(function, repeats, *args):
    """Return the shortest wall time of ``repeats`` calls ``function(*args)`` (s) and the last result."""
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        result = function(*args)
        best = min(best, time.perf_counter() - start)
    return best, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    repeats = parser.parse_args().repeats
    sys.path.insert(0, str(ROOT))
    from incircu_plugin.core import polygon_centerline, polygon_network
    from tests.support import geometry_cases, network_cases

    meander = geometry_cases.meander()
    caps = list(meander.split_points)
    banks = [meander.polygon.exterior.interpolate(f, normalized=True) for f in (0.25, 0.7)]
    rows = [
        ("reservoir", *network_cases.reservoir()),
        ("delta", *network_cases.delta()),
        ("meander", meander.polygon, caps),
        ("meander", meander.polygon, caps + banks[:1]),
        ("meander", meander.polygon, caps + banks),
    ]
    print("| shape | k | boundary vertices | network (s) | centerline (s) | ratio | branches | junctions |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for name, polygon, points in rows:
        network_time, network = best_time(polygon_network, repeats, polygon, points)
        centerline_time, _ = best_time(polygon_centerline, repeats, polygon, points[:2])
        print(
            f"| {name} | {len(points)} | {len(polygon.exterior.coords) - 1} | {network_time:.3f} | "
            f"{centerline_time:.3f} | {network_time / centerline_time:.1f} | {len(network.branches)} | "
            f"{len(network.junctions)} |"
        )


if __name__ == "__main__":
    main()
