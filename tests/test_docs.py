"""The documentation agrees with the measurements: the README's benchmark numbers are the generated ones, and
those are the benchmark results' (issue 13).

``benchmarks/write_docs.py`` writes ``docs/benchmark-summary.json`` from ``benchmarks/results/*.json`` and the
README's block between the benchmark markers from the summary, every number in bold. These tests recompute
each quoted number from the raw results, so a number edited by hand, a summary not regenerated after a run,
or a README block left stale fails here.
"""

import json
import re

import pytest

from tests.support.project import REPOSITORY as ROOT

RESULTS = ROOT / "benchmarks" / "results"
SUMMARY = json.loads((ROOT / "docs" / "benchmark-summary.json").read_text(encoding="utf-8"))
QUOTES = SUMMARY["quotes"]
START, END = "<!-- benchmark numbers:", "<!-- end of benchmark numbers -->"
#: Relative rounding of a quoted number (two significant digits at worst, see ``write_docs._quote``).
ROUNDING = 0.05


def _results(name):
    path = RESULTS / name
    return json.loads(path.read_text()) if path.exists() else None


def _readme_block():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index(START)
    return text[text.index("-->", start) + 3 : text.index(END, start)]


def _value(text):
    return float(text.replace(",", ""))


def _meander_ratios():
    rows = [r for r in _results("compare.json")["analytic"] if "meander" in r["case"] and r["seconds"]]
    ours = next(r["seconds"] for r in rows if r["tool"] == "IncirCu")
    peers = {r["tool"]: r["seconds"] for r in rows if r["tool"] != "IncirCu" and not r["error"]}
    grass = next((seconds for tool, seconds in peers.items() if tool.startswith("GRASS")), None)
    return min(peers.values()) / ours, None if grass is None else grass / ours


def _accuracy_factors():
    compare = _results("compare.json")
    factors = []
    for records in (compare["analytic"], compare["outlines"]):
        deviations = {}
        for r in records:
            if not r["error"] and r["mean_dev_rel"] is not None:
                deviations.setdefault(r["case"], {})[r["tool"]] = r["mean_dev_rel"]
        for tools in deviations.values():
            ours = tools.pop("IncirCu", None)
            if ours and tools and min(ours, *tools.values()) > SUMMARY["accuracy_floor"]:
                factors.append(min(tools.values()) / ours)
    return factors


def _layer_values():
    layer = _results("layer.json")
    if layer is None:
        return {}
    rows = {row["tool"]: row for row in layer["layers"][0]["rows"] if row["polygons_per_second"]}
    # The core as fast as it runs a layer: traced together when the results have that row.
    ours = rows.get("IncirCu (core, layer together)") or rows["IncirCu (core)"]
    values = {
        "layer_polygons": layer["layers"][0]["polygons"],
        "layer_polygons_per_second": ours["polygons_per_second"],
        "layer_vs_pygeoops": ours["polygons_per_second"] / rows["pygeoops"]["polygons_per_second"],
        "layer_output_vs_input": ours["output_vertices"] / ours["input_vertices"],
    }
    grass = rows.get("GRASS v.voronoi.skeleton (qgis_process)")
    if grass and grass["polygons_per_second"]:
        values["layer_vs_grass"] = rows["IncirCu (qgis_process)"]["polygons_per_second"] / grass["polygons_per_second"]
    return values


def _core_values():
    core = _results("core.json")
    if core is None or "error" in core["end_to_end"]:
        return {}
    end = core["end_to_end"]
    return {
        "end_to_end_vertices": end["vertices"],
        "end_to_end_seconds": end["seconds"],
        "end_to_end_peak_mib": end["peak_bytes"] / 2**20,
    }


def _expected():
    """Every quotable number, recomputed from the raw results."""
    fastest, grass = _meander_ratios()
    factors = _accuracy_factors()
    values = {"meander_vs_fastest_peer": fastest, "meander_vs_grass": grass}
    values.update(accuracy_factor_min=min(factors), accuracy_factor_max=max(factors))
    values.update(_layer_values())
    values.update(_core_values())
    return {key: value for key, value in values.items() if value is not None}


def test_readme_block_quotes_exactly_the_summary():
    quoted = re.findall(r"\*\*([^*]+)\*\*", _readme_block())
    assert sorted(quoted) == sorted(quote["text"] for quote in QUOTES.values())


@pytest.mark.parametrize("key", sorted(QUOTES))
def test_quoted_text_rounds_its_value(key):
    quote = QUOTES[key]
    assert _value(quote["text"]) == pytest.approx(quote["value"], rel=ROUNDING)


def test_summary_holds_every_result_and_nothing_else():
    expected = _expected()
    assert sorted(QUOTES) == sorted(expected)
    for key, value in expected.items():
        assert QUOTES[key]["value"] == pytest.approx(value, rel=1e-9), key
