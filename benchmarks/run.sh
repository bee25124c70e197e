#!/usr/bin/env bash
# One command for the whole side-by-side benchmark (issue 4): `make bench` or `bash benchmarks/run.sh`.
#
# Set-up (idempotent, skipped when already done):
#   - Debian packages: grass-core (GRASS GIS, for v.voronoi.skeleton) and the QGIS GRASS provider;
#     qgis_process.bin comes with the QGIS packages the plugin is developed against.
#   - benchmarks/.venv-peers: a venv with requirements-bench.txt (numpy<2, so label_centerlines' np.math
#     calls work unpatched; pygeoops, centerline, pysfcgal, pyvoronoi, matplotlib, shapely 2, pyproj).
#   - benchmarks/.cache/world-atlas: the npm package `world-atlas` (Natural Earth countries, ISC licence),
#     fetched with `npm pack`.
# Then runs bench_compare.py (tools side by side + scaling), bench_layer.py (whole layers: 400 river-like
# polygons and the real outlines, issue 9), bench_core.py (10^6 vertices end to end, peak memory),
# bench_paper.py (Fig. 4 and Table 1 of the paper), profile_incircu.py, and writes docs/benchmark.md,
# docs/benchmark-summary.json and the README's generated numbers, with the PNG plots in benchmarks/results/;
# then bench_mainstem.py (main stem on real reservoirs, tests/data) and bench_outside.py (outside polygons: glyphs,
# countries, reservoirs) add their sections to that page,
# bench_plugin.py prints the plugin's cost per feature against the core's, and bench_scale.py (50,000 rivers
# through qgis_process: features written and skipped, time, peak memory) adds its section.
#
# Options: --quick (no GRASS, 40 rivers, smaller scaling range: a smoke run of a few minutes); --no-setup.
set -euo pipefail

BENCH_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO_ROOT="$(dirname "$BENCH_DIR")"
VENV="$BENCH_DIR/.venv-peers"
CACHE="$BENCH_DIR/.cache"
WORLD_ATLAS_VERSION="2.0.2"
QUICK=""
SETUP=1
for argument in "$@"; do
  case "$argument" in
    --quick) QUICK="--quick" ;;
    --no-setup) SETUP=0 ;;
    *) echo "unknown option: $argument" >&2; exit 2 ;;
  esac
done

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

setup_debian() {
  local missing=()
  for package in grass-core qgis-provider-grass qgis-plugin-grass python3-venv; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "== apt-get install ${missing[*]}"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
  fi
  command -v qgis_process.bin >/dev/null || { echo "qgis_process.bin not found (install qgis)" >&2; exit 1; }
}

setup_venv() {
  local stamp="$VENV/.requirements-bench.txt"
  if [ ! -x "$VENV/bin/python" ] || ! cmp -s "$REPO_ROOT/requirements-bench.txt" "$stamp"; then
    echo "== venv $VENV"
    /usr/bin/python3 -m venv --clear "$VENV"
    "$VENV/bin/python" -m pip install --quiet --upgrade pip
    "$VENV/bin/python" -m pip install --quiet -r "$REPO_ROOT/requirements-bench.txt"
    cp "$REPO_ROOT/requirements-bench.txt" "$stamp"
  fi
}

setup_world_atlas() {
  local target="$CACHE/world-atlas"
  if [ ! -f "$target/package/countries-10m.json" ]; then
    echo "== npm pack world-atlas@$WORLD_ATLAS_VERSION"
    mkdir -p "$target"
    (cd "$CACHE" && npm pack --silent "world-atlas@$WORLD_ATLAS_VERSION" >/dev/null)
    tar -xzf "$CACHE/world-atlas-$WORLD_ATLAS_VERSION.tgz" -C "$target"
  fi
}

if [ "$SETUP" -eq 1 ]; then
  setup_debian
  setup_venv
  setup_world_atlas
fi

cd "$REPO_ROOT"
PYTHON="$VENV/bin/python"
started=$(date +%s)
"$PYTHON" "$BENCH_DIR/bench_compare.py" $QUICK
if [ -n "$QUICK" ]; then
  "$PYTHON" "$BENCH_DIR/bench_layer.py" --count 40 --no-grass --no-outlines
  "$PYTHON" "$BENCH_DIR/bench_core.py" --max-exponent 5 --repeats 5 --json "$BENCH_DIR/results/core.json"
else
  "$PYTHON" "$BENCH_DIR/bench_layer.py"
  "$PYTHON" "$BENCH_DIR/bench_core.py" --json "$BENCH_DIR/results/core.json"
fi
"$PYTHON" "$BENCH_DIR/bench_paper.py"
"$PYTHON" "$BENCH_DIR/profile_incircu.py"
"$PYTHON" "$BENCH_DIR/write_docs.py"
"$PYTHON" "$BENCH_DIR/bench_mainstem.py"   # after write_docs.py: adds its marked section to docs/benchmark.md
# Outside polygons (glyphs, Natural Earth countries and reservoirs): share with a line and time against the
# peers; adds its marked section.
"$PYTHON" "$BENCH_DIR/bench_outside.py" $QUICK
# One feature alone and in an array, against pygeoops; same bytes alone, as one array, reversed and in 8 slices
# (issue 39); adds its marked section.
if [ -n "$QUICK" ]; then
  "$PYTHON" "$BENCH_DIR/bench_calls.py" --repeats 1 --identity 100 --write
else
  "$PYTHON" "$BENCH_DIR/bench_calls.py" --write
fi
# Networks: cost against the centerline, arms found against pygeoops, SFCGAL (and GRASS); adds its section.
if [ -n "$QUICK" ]; then
  "$PYTHON" "$BENCH_DIR/bench_network.py" --peers --repeats 1 --write
else
  "$PYTHON" "$BENCH_DIR/bench_network.py" --peers --grass --write
fi
# The plugin's feature loop against the core per feature (issue 9's small features); prints its table.
if [ -n "$QUICK" ]; then
  "$PYTHON" "$BENCH_DIR/bench_plugin.py" --count 500 --repeats 1
else
  "$PYTHON" "$BENCH_DIR/bench_plugin.py"
fi
# A whole layer of 50,000 rivers through qgis_process: every feature written, time and peak memory; adds its
# marked section to docs/benchmark.md.
if [ -n "$QUICK" ]; then
  "$PYTHON" "$BENCH_DIR/bench_scale.py" --count 1000
else
  "$PYTHON" "$BENCH_DIR/bench_scale.py"
fi
# Label lines (issue 38): IncirCu against label_centerlines, pygeoops and the centerline -> QGIS Smooth chain, and
# 10,000 lakes labelled through the expression function; needs the project's venv (QGIS), runs the peers in
# this venv; adds its marked section to docs/benchmark.md. profile_label_redraw.py prints where a warm-cache
# redraw of the labelled lakes spends its time (IncirCu's expression function or QGIS).
if [ -x "$REPO_ROOT/.venv/bin/python" ]; then
  if [ -n "$QUICK" ]; then
    "$REPO_ROOT/.venv/bin/python" "$BENCH_DIR/bench_labels.py" --count 100 --peer-count 20 --render-count 1000
    "$REPO_ROOT/.venv/bin/python" "$BENCH_DIR/profile_label_redraw.py" --count 1000
  else
    "$REPO_ROOT/.venv/bin/python" "$BENCH_DIR/bench_labels.py"
    "$REPO_ROOT/.venv/bin/python" "$BENCH_DIR/profile_label_redraw.py" --count 10000
  fi
else
  echo "== bench_labels.py skipped: no $REPO_ROOT/.venv (run make setup)"
fi
# Last, bench_frames.py prints its table: the data-frame API on 1 and 2 dask workers against qgis_process
# (issue 12). It needs the project's venv (geopandas, dask-geopandas, QGIS): make setup.
if [ -x "$REPO_ROOT/.venv/bin/python" ]; then
  "$REPO_ROOT/.venv/bin/python" "$BENCH_DIR/bench_frames.py" $QUICK
else
  echo "== bench_frames.py skipped: no $REPO_ROOT/.venv (run make setup)"
fi
echo "== benchmark done in $(( $(date +%s) - started )) s; see docs/benchmark.md"
