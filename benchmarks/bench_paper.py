"""The paper's Fig. 4 and Table 1, reproduced on shapes in the spirit of its cases a-e.

Fig. 4: mean distance between IncirCu and the medial axis against the number of samples per chain on a
shape like the paper's case d (an irregular channel of varying width with reflex vertices on both
sides). Table 1: mean distance from IncirCu to the medial axis and to the straight skeleton on five
shapes, dimensionless (divided by the shape's width), next to the paper's values.

Medial axis: the exact target set of the segment-Voronoi oracle ``tests/support/oracle.py`` (the medial axis
between the two chains). Straight skeleton: SFCGAL's (CGAL), all branches. The distance between two axes
is the mean, along the IncirCu line sampled every 1/200 of the width, of the distance to the reference
(one-sided, as a subset of a skeleton is compared with the whole skeleton).

Writes ``benchmarks/results/paper.json`` and ``benchmarks/results/fig4.png``.
"""

import json
import sys
import time
from pathlib import Path

import numpy as np

BENCH_DIR = Path(__file__).resolve().parent
if str(BENCH_DIR) not in sys.path:
    sys.path.insert(0, str(BENCH_DIR))

import cases as bench_cases
from cases import geometry_cases, oracle
from metrics import NearestDistance, densified_points
from peers import run_sfcgal_straight_skeleton

RESULTS_DIR = BENCH_DIR / "results"

#: Table 1 of the paper: average distance from IncirCu to the straight skeleton, medial axis and iCMR,
#: and the average distance between the two edges' vertices (the shapes' width scale), shape units.
PAPER_TABLE_1 = {
    "a": {"straight_skeleton": 0.00, "medial_axis": 0.00, "icmr": 0.00, "vertex_distance": 3.69},
    "b": {"straight_skeleton": 0.05, "medial_axis": 0.00, "icmr": 0.04, "vertex_distance": 3.61},
    "c": {"straight_skeleton": 0.01, "medial_axis": 0.00, "icmr": 0.07, "vertex_distance": 3.47},
    "d": {"straight_skeleton": 0.01, "medial_axis": 0.00, "icmr": 0.06, "vertex_distance": 1.69},
    "e": {"straight_skeleton": 0.01, "medial_axis": 0.00, "icmr": 0.05, "vertex_distance": 2.51},
}

#: Samples per chain for Fig. 4.
FIG4_SAMPLES = (1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192)


def paper_shapes():
    """Five shapes in the spirit of the paper's cases a-e, as ``geometry_cases.Case`` objects.

    a: a rectangle (straight, convex: every skeleton agrees); b: an annulus sector (a bend: reflex
    vertices along the inner arc); c: a constant-width meander; d: an irregular channel of varying width
    with jittered vertices on both banks (the paper's case d is the one of Fig. 4); e: the Gambia (Natural
    Earth 1:10m, UTM metres), a real outline with many more boundary vertices.
    """
    return {
        "a": ("rectangle 100×10", geometry_cases.rectangle(n=11)),
        "b": ("annulus sector r 40..60", geometry_cases.annulus_sector(n=61)),
        "c": ("meander L 800, W 20", geometry_cases.meander(length=800.0, amplitude=40.0, n=(301, 287))),
        "d": ("irregular channel (wavy)", geometry_cases.wavy_channel()),
        "e": ("Gambia (NE 1:10m, UTM)", geometry_cases.gambia()),
    }


def incircu(shape, samples_per_chain=None):
    """IncirCu on a shape's own split points (default spacing, or ``samples_per_chain`` per chain)."""
    from incircu_plugin.core import polygon_centerline

    return polygon_centerline(shape.polygon, shape.split_points, samples_per_chain=samples_per_chain)


def medial_oracle(shape):
    """Segment-Voronoi oracle on the shape's chains, restricted to its polygon."""
    return oracle.MedialOracle(shape.chain_a, shape.chain_b, region=shape.polygon)


def mean_vertex_distance(shape):
    """Average distance from every vertex of one chain to the other chain (the paper's last column)."""
    to_b = oracle.segment_distances(shape.chain_a[1:-1], shape.chain_b)
    to_a = oracle.segment_distances(shape.chain_b[1:-1], shape.chain_a)
    return float(np.concatenate([to_a, to_b]).mean())


def table_1():
    """Rows of the reproduced Table 1 (dimensionless distances: divided by the shape's width)."""
    rows = []
    for key, (label, shape) in paper_shapes().items():
        line = incircu(shape).line
        points = densified_points(line, shape.width / 200.0)
        to_medial_axis = medial_oracle(shape).distance(points)
        skeleton = run_sfcgal_straight_skeleton(bench_cases.Case(label, shape.polygon, (), shape.width))
        to_skeleton = NearestDistance(skeleton)(points)
        paper = PAPER_TABLE_1[key]
        rows.append(
            {
                "case": key,
                "shape": label,
                "width": shape.width,
                "vertex_distance": mean_vertex_distance(shape),
                "medial_axis_rel": float(to_medial_axis.mean()) / shape.width,
                "straight_skeleton_rel": float(to_skeleton.mean()) / shape.width,
                "paper_medial_axis": paper["medial_axis"],
                "paper_straight_skeleton": paper["straight_skeleton"],
                "paper_vertex_distance": paper["vertex_distance"],
                "paper_medial_axis_rel": paper["medial_axis"] / paper["vertex_distance"],
                "paper_straight_skeleton_rel": paper["straight_skeleton"] / paper["vertex_distance"],
            }
        )
        print(
            f"  {key}) {label:<28} MA {rows[-1]['medial_axis_rel']:.2e}  SS {rows[-1]['straight_skeleton_rel']:.2e}",
            flush=True,
        )
    return rows


def figure_4():
    """Mean and largest distance IncirCu -> medial axis against samples per chain, on case d."""
    label, shape = paper_shapes()["d"]
    medial = medial_oracle(shape)
    rows = []
    for samples in FIG4_SAMPLES:
        started = time.perf_counter()
        result = incircu(shape, samples_per_chain=samples)
        seconds = time.perf_counter() - started
        distances = medial.distance(densified_points(result.line, shape.width / 200.0))
        rows.append(
            {
                "samples_per_chain": samples,
                "vertices": len(result.line.coords),
                "mean_rel": float(distances.mean()) / shape.width,
                "max_rel": float(distances.max()) / shape.width,
                "hausdorff_from_target_rel": medial.hausdorff_from_target(result.line) / shape.width,
                "seconds": seconds,
            }
        )
        print(
            f"  n={samples:>5} vertices={rows[-1]['vertices']:>6} mean {rows[-1]['mean_rel']:.2e} "
            f"max {rows[-1]['max_rel']:.2e}",
            flush=True,
        )
    return label, shape, rows


def plot_figure_4(label, shape, rows, path):
    """Fig. 4 as a log-log plot, with the shape and its centerline as an inset."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (axes, inset) = plt.subplots(1, 2, figsize=(10, 4), dpi=110, gridspec_kw={"width_ratios": [3, 2]})
    samples = [row["samples_per_chain"] for row in rows]
    axes.loglog(samples, [row["mean_rel"] for row in rows], marker="o", label="mean distance / width")
    axes.loglog(samples, [row["max_rel"] for row in rows], marker="s", linewidth=1, label="largest distance / width")
    axes.loglog(
        samples,
        [row["hausdorff_from_target_rel"] for row in rows],
        marker="^",
        linewidth=1,
        label="medial axis → IncirCu (Hausdorff) / width",
    )
    axes.set_xlabel("samples per chain (equidistant, plus every vertex)")
    axes.set_ylabel("distance to the medial axis / width")
    axes.set_title("Fig. 4 reproduced: IncirCu vs medial axis (case d)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8)
    x, y = shape.polygon.exterior.xy
    inset.fill(x, y, color="#dddddd")
    line = incircu(shape).line
    inset.plot(*line.xy, color="C3", linewidth=1.5, label="IncirCu")
    for segment in medial_oracle(shape).segments:
        inset.plot(segment[:, 0], segment[:, 1], color="k", linewidth=0.6)
    inset.set_title(label, fontsize=9)
    inset.set_aspect("equal")
    inset.set_xticks([])
    inset.set_yticks([])
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def main():
    RESULTS_DIR.mkdir(exist_ok=True)
    print("== Table 1 (paper) reproduced", flush=True)
    table = table_1()
    print("== Fig. 4 (paper) reproduced", flush=True)
    label, shape, fig4 = figure_4()
    plot_figure_4(label, shape, fig4, RESULTS_DIR / "fig4.png")
    (RESULTS_DIR / "paper.json").write_text(
        json.dumps({"table_1": table, "figure_4": fig4, "figure_4_shape": label}, indent=1)
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
