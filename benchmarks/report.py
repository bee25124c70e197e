"""Markdown tables of the benchmark measurements (printed by the scripts and written to docs/benchmark.md)."""

from pathlib import Path

#: The benchmark page that ``write_docs.py`` writes and the later scripts add their sections to.
BENCHMARK_PAGE = Path(__file__).resolve().parents[1] / "docs" / "benchmark.md"


def write_section(name, markdown):
    """Put ``markdown`` between the ``name`` markers of ``docs/benchmark.md`` (appended when they are missing)."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    section = f"{begin}\n{markdown}\n{end}"
    page = BENCHMARK_PAGE.read_text(encoding="utf-8") if BENCHMARK_PAGE.exists() else ""
    if begin in page and end in page:
        page = page[: page.index(begin)] + section + page[page.index(end) + len(end) :]
    else:
        page = page.rstrip("\n") + "\n\n" + section + "\n"
    BENCHMARK_PAGE.write_text(page, encoding="utf-8")


def _number(value, digits=3):
    if value is None:
        return "–"
    if value == 0:
        return "0"
    magnitude = abs(value)
    if magnitude >= 1e4 or magnitude < 1e-3:
        return f"{value:.1e}"
    return f"{value:.{digits}g}"


def _seconds(value):
    if value is None:
        return "–"
    if value < 1.0:
        return f"{value * 1e3:.3g} ms"
    return f"{value:.3g} s"


def format_measurements(measurements, title):
    """One Markdown table, grouped by case, with each tool's time ratio to IncirCu on that case."""
    header = (
        f"\n### {title}\n\n"
        "| input | tool | time (median) | × IncirCu | runs | parts | branches | mean dev /w | max dev /w "
        "| max vertex dev /w | mean dev from analytic axis /w | end gaps /w | outside /w |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
    )
    rows = []
    reference = {m["case"] if isinstance(m, dict) else m.case: None for m in measurements}
    records = [m if isinstance(m, dict) else m.__dict__ for m in measurements]
    for record in records:
        if record["tool"] == "IncirCu" and record["seconds"]:
            reference[record["case"]] = record["seconds"]
    for record in records:
        if record["error"]:
            rows.append(
                f"| {record['case']} | {record['tool']} | – | – | – | – | – | – | – | – | – | – | "
                f"{record['error'].replace('|', '/')} |"
            )
            continue
        base = reference.get(record["case"])
        ratio = record["seconds"] / base if base and record["seconds"] else None
        gaps = record["end_gap_rel"]
        gap_text = " / ".join(_number(gap, 2) for gap in gaps) if gaps else "–"
        rows.append(
            f"| {record['case']} | {record['tool']} | {_seconds(record['seconds'])} | {_number(ratio, 3)} | "
            f"{record['runs']} | {record['parts']} | {record['branches']} | {_number(record['mean_dev_rel'])} | "
            f"{_number(record['max_dev_rel'])} | {_number(record['max_vertex_dev_rel'])} | "
            f"{_number(record.get('mean_analytic_dev_rel'))} | {gap_text} | "
            f"{_number(record['outside_rel'])} |"
        )
    return header + "\n".join(rows) + "\n"


#: The core's row for a whole layer traced together (how the plugin runs a layer), when the core can.
LAYER_TOGETHER = "IncirCu (core, layer together)"


def core_layer_row(layer):
    """IncirCu's fastest way through the core for a layer: the layer traced together, else polygon by polygon."""
    rows = {r["tool"]: r for r in layer["rows"] if r["polygons_per_second"]}
    return rows.get(LAYER_TOGETHER) or rows.get("IncirCu (core)")


def layer_reference(layer, row):
    """The IncirCu row a row's speed is compared with: the whole-layer ``qgis_process`` run for whole-layer
    calls, otherwise the core as fast as it runs a layer (:func:`core_layer_row`)."""
    if row["whole_layer_call"]:
        return next(
            (r for r in layer["rows"] if r["tool"] == "IncirCu (qgis_process)" and r["polygons_per_second"]), None
        )
    return core_layer_row(layer)


def format_layer(layer):
    """One Markdown table for one layer of the layer benchmark (``bench_layer.py``)."""
    reference_kinds = ", ".join(f"{kind}: {count}" for kind, count in layer["reference"].items())
    text = (
        f"\n### {layer['name']}: {layer['polygons']:,} polygons, {layer['vertices']:,} boundary vertices"
        f", {layer['islands']} islands (reference axis: {reference_kinds})\n\n"
        "| tool | polygons/s | IncirCu × faster | time | done | one clean line | output v / polygon "
        "| output v / input v | mean dev /w | median max dev /w | max dev /w | largest end gap /w | note |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n"
    )
    for row in layer["rows"]:
        reference = layer_reference(layer, row)
        rate = row["polygons_per_second"]
        ratio = reference["polygons_per_second"] / rate if reference and rate else None
        done = row["done"]
        per_polygon = row["output_vertices"] / done if done else None
        out_in = row["output_vertices"] / row["input_vertices"] if row["input_vertices"] else None
        note = "; ".join(filter(None, [row["note"], *row["errors"]])).replace("|", "/")
        text += (
            f"| {row['tool']} | {_number(rate)} | {_number(ratio)} | {_seconds(row['seconds'])} | "
            f"{done} of {row['polygons']} | {row['clean']} | {_number(per_polygon)} | {_number(out_in)} | "
            f"{_number(row['mean_dev_rel'])} | {_number(row['median_max_dev_rel'])} | {_number(row['max_dev_rel'])} | "
            f"{_number(row['max_end_gap_rel'])} | {note} |\n"
        )
    return text
