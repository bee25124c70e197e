"""Main-stem score on real reservoirs: IncirCu's end rules and guide against pygeoops and label_centerlines.

Usage: ``benchmarks/.venv-peers/bin/python benchmarks/bench_mainstem.py`` (peers skipped when missing;
any Python with the plugin's requirements runs the IncirCu columns).

Data: ``tests/data/real_rivers_ne_lonlat.geojson`` (Natural Earth 1:10m lakes, main stems from the 1:50m
river centerlines; ``tests/data/README.md``), projected with ``LocalProjection`` (metres). Each cell is the
share of the tool's line length within 3 local widths (at least 2 km) of the main stem, and the share of
the main stem covered by the line within the same distance (``tests/support/real_rivers.py``); IncirCu has no split points: automatic ends with ``end_rule`` main stem
or longest path, or the main stem given as ``guide``. Prints a Markdown table and writes it between the
``mainstem`` markers of ``docs/benchmark.md`` (appended when the markers are missing).
"""

import multiprocessing
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.peers import Case, as_lines, mean_width, run_label_centerlines, run_pygeoops
from incircu_plugin.core import polygon_centerline
from tests.support.real_rivers import TOLERANCE_WIDTHS, main_stem_cover, main_stem_share, real_rivers

DOCS = ROOT / "docs" / "benchmark.md"
BEGIN, END = "<!-- mainstem:begin -->", "<!-- mainstem:end -->"
TIME_LIMIT = 300.0


def incircu(rule):
    def run(river):
        if rule == "guide":
            return polygon_centerline(river.polygon, guide=river.main_stem).line
        return polygon_centerline(river.polygon, end_rule=rule).line

    return run


def peer(runner):
    def run(river):
        return as_lines(runner(Case(river.name, river.polygon, (), mean_width(river.polygon))))

    return run


TOOLS = (
    ("IncirCu main stem", incircu("main_stem")),
    ("IncirCu longest path", incircu("longest_path")),
    ("IncirCu guide", incircu("guide")),
    ("pygeoops", peer(run_pygeoops)),
    ("label_centerlines", peer(run_label_centerlines)),
)


def score_in_child(arguments):
    """Run one tool on one river in a child process; return ``(share, cover)`` or a short error text."""
    tool_index, river_index = arguments
    river = real_rivers()[river_index]
    try:
        lines = TOOLS[tool_index][1](river)
        return main_stem_share(river, lines), main_stem_cover(river, lines)
    except ImportError as error:
        return f"missing: {error.name}"
    except Exception as error:  # noqa: BLE001 (a peer failing is a result of the benchmark, not a crash of it)
        return f"failed: {type(error).__name__}"


def score(pool, tool_index, river_index):
    """Return ``(share, cover)``, ``"missing ..."``, ``"failed ..."`` or ``"timeout"``."""
    pending = pool.apply_async(score_in_child, ((tool_index, river_index),))
    try:
        return pending.get(TIME_LIMIT)
    except multiprocessing.TimeoutError:
        return "timeout"


def cell(value):
    """``"share / cover"`` or the error text."""
    return value if isinstance(value, str) else "{:.2f} / {:.2f}".format(*value)


def table(rows, names):
    """Markdown table: one row per water body, one column per tool, then the means and the >= 0.8 count."""
    lines = ["| water body | " + " | ".join(name for name, _ in TOOLS) + " |", "|---|" + "---:|" * len(TOOLS)]
    for name, cells in zip(names, rows):
        lines.append(f"| {name} | " + " | ".join(cell(value) for value in cells) + " |")
    means, good = [], []
    for column in zip(*rows):
        numbers = np.array([value for value in column if not isinstance(value, str)])
        means.append("-" if not len(numbers) else cell(tuple(numbers.mean(axis=0))))
        good.append("-" if not len(numbers) else f"{int(np.sum(numbers[:, 0] >= 0.8))}/{len(column)}")
    lines.append("| **mean** | " + " | ".join(means) + " |")
    lines.append("| **share >= 0.8** | " + " | ".join(good) + " |")
    return "\n".join(lines)


def differences(rows, names):
    """One sentence naming the water bodies where the two end rules' shares differ by 0.01 or more."""
    changed = [
        f"{name} {main[0]:.2f} vs {longest[0]:.2f}"
        for name, (main, longest, *_) in zip(names, rows)
        if not isinstance(main, str) and not isinstance(longest, str) and abs(main[0] - longest[0]) >= 0.01
    ]
    return (
        f"The two end rules' lines differ (share, main stem vs longest path) on {len(changed)} of {len(names)}: "
        + ("; ".join(changed) or "none")
        + "."
    )


def write_docs(markdown):
    """Put ``markdown`` between the markers of ``docs/benchmark.md``."""
    section = f"{BEGIN}\n{markdown}\n{END}"
    page = DOCS.read_text(encoding="utf-8") if DOCS.exists() else ""
    if BEGIN in page and END in page:
        page = page[: page.index(BEGIN)] + section + page[page.index(END) + len(END) :]
    else:
        page = page.rstrip("\n") + "\n\n" + section + "\n"
    DOCS.write_text(page, encoding="utf-8")


def main():
    names = [river.name for river in real_rivers()]
    rows = []
    with multiprocessing.get_context("fork").Pool(1, maxtasksperchild=1) as pool:
        for river_index, name in enumerate(names):
            rows.append([score(pool, tool_index, river_index) for tool_index in range(len(TOOLS))])
            print(name, rows[-1], flush=True)
    markdown = f"""## Main stem on real reservoirs

Generated by `benchmarks/bench_mainstem.py`. {len(names)} reservoirs and river lakes from Natural Earth
1:10m lakes; main stem from the independent Natural Earth 1:50m river centerlines (sources and licences:
`tests/data/README.md`). Cell: *share* of the tool's line length within {TOLERANCE_WIDTHS:g} local
widths (twice the distance to the shore, at least 2 km) of the main stem / *cover*, the share of the main
stem's length inside the polygon within that distance of the tool's line (a short line can have a high
share). IncirCu without split points: automatic ends (`end_rule` main stem or longest path) or the main
stem given as `guide`. Peers as in the comparison above (pygeoops `extend=True`; label_centerlines at
w/10, w/100 of the mean width 2A/P), all in local metres.

{table(rows, names)}

{differences(rows, names)} A high share with a low cover is a line that stops short of the main stem's
ends; a low share with a high cover, side branches left on the line.
"""
    print(markdown)
    write_docs(markdown)


if __name__ == "__main__":
    main()
