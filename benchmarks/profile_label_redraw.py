"""Where a warm-cache redraw of labelled lakes spends its time (issue 38): IncirCu's expression function or QGIS.

Usage: ``.venv/bin/python benchmarks/profile_label_redraw.py [--count 2000]`` (the project's venv, QGIS offscreen).

A layer of ``--count`` generated lakes (``bench_labels.generated_lakes``, EPSG:3857) styled with
``styles/lake_labels.qml`` (``incircu_label_line`` as the labels' geometry generator and in the point rule's
filter). The expression cache is filled first with the label of every lake computed as an array
(``label_lines``, the same labels the first draw would compute one by one, minutes for thousands), so every
draw measured reads the cache. Then the whole layer is drawn twice, a fifth of it zoomed in once, and the
whole layer without labels twice (1600 x 1000 px). For each: the draw's seconds, the seconds spent inside
IncirCu's expression function (timed around its ``func``; the rendering thread's Python) and its calls.
The rest of a labelled draw is QGIS: drawing the polygons (the draw without labels), evaluating the rules and
the geometry generator, and placing the curved labels.
"""

import argparse
import importlib.util
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

import bench_labels


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=2000)
    count = parser.parse_args().count
    application = bench_labels.start_qgis()
    from qgis.core import QgsCoordinateReferenceSystem, QgsRectangle

    spec = importlib.util.spec_from_file_location("label_style", ROOT / "scripts" / "make_label_style.py")
    style = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(style)
    expressions = style.plugin_expressions()
    from incircu.algorithms.convert import from_shapely, to_shapely
    from incircu.incircu_plugin import core

    layer = style.polygon_layer(
        bench_labels.generated_lakes(count), [f"Lake {index}" for index in range(count)], "EPSG:3857"
    )
    layer.loadNamedStyle(str(ROOT / "styles" / "lake_labels.qml"))
    crs = QgsCoordinateReferenceSystem("EPSG:3857")
    features = list(layer.getFeatures())
    shapes = [to_shapely(feature.geometry()) for feature in features]
    options = (("end_rule", "main_stem"),)  # the style's arguments, as the function's cache key holds them
    for feature, shape, outcomes in zip(features, shapes, core.label_lines(shapes)):
        label = None if isinstance(outcomes, Exception) else core.feature_label(outcomes, shape)
        key = ("incircu_label_line", expressions.geometry_key(feature.geometry()), crs.authid(), options)
        expressions.CACHE.put(key, None if label is None else from_shapely(label.geometry))

    inside = [0.0, 0]
    func = expressions.IncirCuFunction.func

    def timed(self, *arguments):
        started = time.perf_counter()
        try:
            return func(self, *arguments)
        finally:
            inside[0] += time.perf_counter() - started
            inside[1] += 1

    expressions.IncirCuFunction.func = timed
    whole = layer.extent()
    zoom = QgsRectangle(
        whole.xMinimum(),
        whole.yMinimum(),
        whole.xMinimum() + 0.2 * whole.width(),
        whole.yMinimum() + 0.2 * whole.height(),
    )
    print(f"{count} lakes, cache filled: {len(expressions.CACHE.entries)} results\n")
    print("| draw | seconds | in incircu_label_line | calls | cache misses | labels placed |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    for name, extent, labelled in (
        ("whole layer", whole, True),
        ("whole layer again", whole, True),
        ("zoom in (a fifth)", zoom, True),
        ("whole layer, no labels", whole, False),
        ("whole layer, no labels, again", whole, False),
    ):
        layer.setLabelsEnabled(labelled)
        inside[:] = [0.0, 0]
        expressions.CACHE.misses = 0
        started = time.perf_counter()
        _, results = style.render(layer, extent, (1600, 1000), crs)
        seconds = time.perf_counter() - started
        placed = len(results.allLabels())
        print(f"| {name} | {seconds:.2f} | {inside[0]:.2f} | {inside[1]} | {expressions.CACHE.misses} | {placed} |")
    del application


if __name__ == "__main__":
    main()
