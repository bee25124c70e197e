"""Draw one real reservoir with its main stem and IncirCu's automatic centerlines, and its network (README pictures).

Usage: ``benchmarks/.venv-peers/bin/python scripts/plot_real_reservoir.py ["Kuybyshev Reservoir (Volga)"]``
(any Python with matplotlib and the plugin's requirements; matplotlib is not a plugin requirement).
Writes ``docs/images/real_reservoir_main_stem.png``: the Natural Earth 1:10m polygon, the independent
1:50m river line (the main stem), and IncirCu's lines with ``end_rule`` main stem and longest path, in
local metres (``tests/support/real_rivers.py``); and ``docs/images/real_reservoir_network.png``: the
network (``polygon_network``) between the three ends the two rules found, i.e. the confluence of the main
river and its side arm; and ``docs/images/real_network_vs_sfcgal.png``: the automatic network (no split
points) beside SFCGAL's approximate medial axis (what QGIS 4.2's *Approximate medial axis* runs; needs
``pysfcgal``, in ``benchmarks/.venv-peers``).
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import shapely

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from incircu_plugin.core import polygon_centerline, polygon_network
from tests.support.real_rivers import main_stem_share, real_rivers

OUTPUT = ROOT / "docs" / "images" / "real_reservoir_main_stem.png"
NETWORK_OUTPUT = ROOT / "docs" / "images" / "real_reservoir_network.png"
AUTOMATIC_OUTPUT = ROOT / "docs" / "images" / "real_network_vs_sfcgal.png"
BRANCH_COLOURS = ("#b2182b", "#2166ac", "#1b7837", "#762a83", "#e08214")


def draw_lines(axes, lines, **style):
    """Plot every part of ``lines`` (metres) in kilometres; only the first part gets the label."""
    for index, part in enumerate(shapely.get_parts(lines)):
        xy = shapely.get_coordinates(part) / 1000.0
        axes.plot(xy[:, 0], xy[:, 1], **(style if index == 0 else {**style, "label": None}))


def draw_polygon(axes, polygon):
    """Fill ``polygon`` (metres) in kilometres, islands white, outlines thin."""
    for index, ring in enumerate([polygon.exterior, *polygon.interiors]):
        xy = shapely.get_coordinates(ring) / 1000.0
        axes.fill(xy[:, 0], xy[:, 1], color="#cfe3f3" if index == 0 else "white", lw=0)
        axes.plot(xy[:, 0], xy[:, 1], color="#5b8db8", lw=0.6)


def finish(figure, axes, title, output):
    """Label, save and close one figure."""
    axes.set_aspect("equal")
    axes.set_xlabel("km (local azimuthal equidistant)")
    axes.set_title(title)
    axes.legend(loc="upper left", fontsize=8, framealpha=0.9)
    figure.tight_layout()
    output.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(output)
    plt.close(figure)
    print(output)


def main(name):
    (river,) = [river for river in real_rivers() if river.name == name]
    figure, axes = plt.subplots(figsize=(7.5, 7.5), dpi=110)
    draw_polygon(axes, river.polygon)
    draw_lines(
        axes,
        river.main_stem.intersection(river.polygon.buffer(2000.0)),
        color="#222222",
        lw=1.2,
        ls=(0, (4, 3)),
        label="main stem: Natural Earth 1:50m river line",
    )
    ends = []
    for rule, color, width in (("longest_path", "#e08214", 2.2), ("main_stem", "#b2182b", 1.6)):
        line = polygon_centerline(river.polygon, end_rule=rule).line
        ends.extend(shapely.get_coordinates(line)[[0, -1]])
        share = main_stem_share(river, line)
        label = f"IncirCu, END_RULE = {rule.replace('_', ' ')} ({share:.0%} near the main stem)"
        draw_lines(axes, line, color=color, lw=width, label=label)
        axes.plot(*(shapely.get_coordinates(line)[[0, -1]] / 1000.0).T, "o", color=color, ms=5)
    finish(figure, axes, f"{name}: Natural Earth 1:10m polygon, automatic ends", OUTPUT)
    draw_network(river, ends)
    draw_automatic_network(river)


def draw_network(river, ends):
    """The network between the distinct ends of both rules (a confluence where they differ)."""
    distinct = []
    for point in ends:
        if all(shapely.distance(shapely.Point(point), shapely.Point(other)) > 1.0 for other in distinct):
            distinct.append(point)
    network = polygon_network(river.polygon, distinct)
    figure, axes = plt.subplots(figsize=(7.5, 7.5), dpi=110)
    draw_polygon(axes, river.polygon)
    for index, branch in enumerate(network.branches):
        colour = BRANCH_COLOURS[index % len(BRANCH_COLOURS)]
        draw_lines(axes, branch.result.line, color=colour, lw=1.8, label=f"branch {index + 1}")
    if len(network.junctions):
        axes.plot(*(network.junctions / 1000.0).T, "s", color="black", ms=6, label="junction")
    axes.plot(*(shapely.get_coordinates(shapely.points(distinct)) / 1000.0).T, "o", color="black", ms=5)
    title = f"{river.name}: incircu:polygonnetwork between {len(distinct)} split points"
    finish(figure, axes, title, NETWORK_OUTPUT)


def draw_automatic_network(river):
    """The automatic network beside SFCGAL's approximate medial axis, side by side."""
    from pysfcgal import geometry as sfcgal_geometry

    network = polygon_network(river.polygon)
    medial = sfcgal_geometry.Geometry.from_wkb(shapely.to_wkb(river.polygon)).approximate_medial_axis()
    medial = shapely.from_wkb(bytes(medial.to_wkb()))
    figure, (left, right) = plt.subplots(1, 2, figsize=(13.0, 7.0), dpi=110, sharex=True, sharey=True)
    for axes in (left, right):
        draw_polygon(axes, river.polygon)
    for index, branch in enumerate(network.branches):
        draw_lines(left, branch.result.line, color="#b2182b", lw=1.4, label="branch" if index == 0 else None)
    left.plot(*(network.junctions / 1000.0).T, "s", color="black", ms=4, label="junction")
    left.plot(*(network.split_points / 1000.0).T, "o", color="black", ms=4, label="arm end (automatic)")
    draw_lines(right, medial, color="#2166ac", lw=0.9, label="SFCGAL approximate medial axis")
    right.set_aspect("equal")
    right.set_title(f"SFCGAL approximate medial axis ({len(shapely.get_parts(medial))} segments)")
    right.legend(loc="upper left", fontsize=8, framealpha=0.9)
    title = f"{river.name}: IncirCu automatic network, {len(network.split_points)} arms"
    finish(figure, left, title, AUTOMATIC_OUTPUT)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "Kuybyshev Reservoir (Volga)")
