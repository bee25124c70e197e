"""Write the bundled sample data (``scripts/data``), the test fixtures (``tests/data``) and the test model.

Run from the repository root with the project's Python: ``.venv/bin/python scripts/make_sample_data.py``.
The shapes are analytic (sine meanders, a straight channel with an island), so the files are small and
reproducible; coordinates are rounded to 1 cm (EPSG:2180) or 1e-8 degree (EPSG:4326).
"""

import json
import math
import os
import tempfile
from pathlib import Path

import numpy as np
import pyproj
import shapely
from shapely.geometry import LineString, MultiLineString, Point, Polygon, mapping

ROOT = Path(__file__).resolve().parent.parent
SAMPLE_FOLDER = ROOT / "scripts" / "data"
FIXTURE_FOLDER = ROOT / "tests" / "data"

#: Projected CRS of the data (Poland CS92, metres) and the origin of the shapes in it.
PROJECTED = 2180
ORIGIN = (500_000.0, 400_000.0)

#: Half-width of the meandering river, metres.
RIVER_HALF_WIDTH = 20.0
#: Distance the split points lie outside the river's end caps, metres (snapped with tolerance 1 m).
SPLIT_POINT_OFFSET = 0.4


def shifted(geometry, dx=0.0, dy=0.0):
    """Move a geometry from shape coordinates to CRS coordinates."""
    return shapely.affinity.translate(geometry, ORIGIN[0] + dx, ORIGIN[1] + dy)


def meander_axis(length=1200.0, amplitude=110.0, wavelength=600.0, samples=97):
    """Return a sine meander as a LineString starting at (0, 0), metres."""
    t = np.linspace(0.0, length, samples)
    return LineString(np.column_stack([t, amplitude * np.sin(2.0 * math.pi * t / wavelength)]))


def river(axis, half_width):
    """Return the polygon of a river of constant width around ``axis`` (flat ends)."""
    return shapely.simplify(axis.buffer(half_width, cap_style="flat", join_style="round", quad_segs=4), 0.02)


def end_points(axis, offset):
    """Return the two axis ends pushed ``offset`` outwards along the axis (as split points)."""
    coords = np.asarray(axis.coords)
    start_direction = coords[0] - coords[1]
    end_direction = coords[-1] - coords[-2]
    start = coords[0] + offset * start_direction / np.linalg.norm(start_direction)
    end = coords[-1] + offset * end_direction / np.linalg.norm(end_direction)
    return Point(start), Point(end)


def island_channel():
    """Return a straight channel 800 m x 120 m with an elliptic island 40 m above its middle line."""
    channel = Polygon([(0, -60), (800, -60), (800, 60), (0, 60)])
    island = shapely.affinity.scale(Point(400, 20).buffer(1.0, quad_segs=8), 110.0, 15.0)
    return Polygon(channel.exterior.coords, [island.exterior.coords])


def write_layer(path, features, epsg):
    """Write features ``[(id, geometry, properties)]`` as a GeoJSON file with its CRS."""
    digits = 2 if epsg != 4326 else 8
    collection = {"type": "FeatureCollection", "name": path.stem}
    if epsg != 4326:
        collection["crs"] = {"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{epsg}"}}
    collection["features"] = [
        {
            "type": "Feature",
            "id": feature_id,
            "properties": properties,
            "geometry": mapping(_round(geometry, digits)),
        }
        for feature_id, geometry, properties in features
    ]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(collection, separators=(",", ":")) + "\n", encoding="utf-8")


def _round(geometry, digits):
    """Round every coordinate of a geometry to ``digits`` decimals."""
    return shapely.transform(geometry, lambda xy: np.round(xy, digits))


def to_geographic(geometry):
    """Transform a geometry from EPSG:2180 to EPSG:4326 (longitude, latitude)."""
    transformer = pyproj.Transformer.from_crs(PROJECTED, 4326, always_xy=True)
    return shapely.transform(
        geometry, lambda xy: np.column_stack(transformer.transform(xy[:, 0].tolist(), xy[:, 1].tolist()))
    )


def sample_layers():
    """Return the layers shared by the demo and the tests: ``{name: [(id, geometry, properties)]}``."""
    axis = meander_axis()
    start, end = end_points(axis, SPLIT_POINT_OFFSET)
    island = island_channel()
    bank_axis = meander_axis(length=900.0, amplitude=80.0, wavelength=450.0, samples=73)
    bank_a = bank_axis.offset_curve(25.0, quad_segs=4)
    bank_b = bank_axis.offset_curve(-25.0, quad_segs=4)
    second_axis = LineString([(0, 0), (600, 40)])
    second_a = second_axis.offset_curve(15.0)
    second_b_coords = np.asarray(second_axis.offset_curve(-15.0).coords)
    middle = 0.5 * (second_b_coords[0] + second_b_coords[-1])
    second_b = MultiLineString([[second_b_coords[0], middle], [middle, second_b_coords[-1]]])
    return {
        "river": [
            (1, shifted(river(axis, RIVER_HALF_WIDTH)), {"name": "Meander", "kind": "river"}),
            (2, shifted(island, dy=600.0), {"name": "Island channel", "kind": "river"}),
        ],
        "split_points": [
            (1, shifted(start), {"role": "start"}),
            (2, shifted(end), {"role": "end"}),
        ],
        "banks_a": [
            (1, shifted(bank_a, dy=-600.0), {"reach": "R1", "side": "left"}),
            (2, shifted(second_a, dy=-1000.0), {"reach": "R2", "side": "left"}),
        ],
        "banks_b": [
            (1, shifted(second_b, dy=-1000.0), {"reach": "R2", "side": "right"}),
            (2, shifted(bank_b.reverse(), dy=-600.0), {"reach": "R1", "side": "right"}),
        ],
    }


def bad_layers():
    """Return the layers of the bad-input tests."""
    bowtie = Polygon([(0, 0), (200, 60), (200, 0), (0, 60)])
    straight = Polygon([(0, 0), (300, 0), (300, 40), (0, 40)])
    good = Polygon([(0, 0), (300, 0), (300, 40), (0, 40)])
    return {
        "bad_polygons": [
            (1, shifted(bowtie, dy=2000.0), {"name": "bowtie"}),
            (2, shifted(straight, dy=2100.0), {"name": "three split points"}),
            (3, shifted(good, dy=2200.0), {"name": "good"}),
        ],
        "bad_split_points": [
            (1, shifted(Point(0, 20), dy=2100.0), {}),
            (2, shifted(Point(300, 20), dy=2100.0), {}),
            (3, shifted(Point(150, 0), dy=2100.0), {}),
            (4, shifted(Point(0, 20), dy=2200.0), {}),
            (5, shifted(Point(300, 20), dy=2200.0), {}),
        ],
        "crossing_a": [(1, shifted(LineString([(0, 0), (400, 100)]), dy=3000.0), {})],
        "crossing_b": [(1, shifted(LineString([(0, 100), (400, 0)]), dy=3000.0), {})],
        "multipart": [
            (
                1,
                shifted(
                    shapely.MultiPolygon(
                        [
                            Polygon([(0, 0), (400, 0), (400, 50), (0, 50)]),
                            Polygon([(0, 200), (400, 200), (400, 230), (0, 230)]),
                        ]
                    ),
                    dy=4000.0,
                ),
                {"name": "two reaches"},
            )
        ],
    }


def qgis_application():
    """Start QGIS (without the plugins) for writing models, once per process; the running one when there is one."""
    from qgis.core import QgsApplication

    if QgsApplication.instance() is None:
        qgis_application.started = QgsApplication([], False, tempfile.mkdtemp(prefix="incircu-model-"))
        qgis_application.started.initQgis()
    return QgsApplication.instance()


def write_model(path):
    """Write the graphical model "Fix geometries -> IncirCu -> Smooth" used by the tests."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    os.environ["QT_HASH_SEED"] = "0"  # stable XML attribute order, so the committed model only changes with content
    from qgis.core import (
        QgsProcessing,
        QgsProcessingModelAlgorithm,
        QgsProcessingModelChildAlgorithm,
        QgsProcessingModelChildParameterSource,
        QgsProcessingModelOutput,
        QgsProcessingModelParameter,
        QgsProcessingParameterFeatureSource,
    )
    from qgis.PyQt.QtCore import QPointF

    qgis_application()
    model = QgsProcessingModelAlgorithm("Fix, centerline, smooth", "IncirCu tests", "incircutests")
    # Laid out top to bottom as the modeler draws it: the two inputs side by side, then one step per row.
    for name, label, kind, optional, position in (
        ("polygons", "Polygons", QgsProcessing.SourceType.TypeVectorPolygon, False, (120, 60)),
        ("split_points", "Split points", QgsProcessing.SourceType.TypeVectorPoint, True, (400, 60)),
    ):
        parameter = QgsProcessingParameterFeatureSource(name, label, [kind], optional=optional)
        component = QgsProcessingModelParameter(name)
        component.setPosition(QPointF(*position))
        model.addModelParameter(parameter, component)

    def child(child_id, algorithm_id, sources, position):
        step = QgsProcessingModelChildAlgorithm(algorithm_id)
        step.setChildId(child_id)
        step.setDescription(child_id)
        step.setPosition(QPointF(*position))
        for parameter_name, source in sources.items():
            step.addParameterSources(parameter_name, [source])
        return step

    fixed = child(
        "fix",
        "native:fixgeometries",
        {"INPUT": QgsProcessingModelChildParameterSource.fromModelParameter("polygons")},
        (120, 160),
    )
    centerline = child(
        "centerline",
        "incircu:polygoncenterline",
        {
            "INPUT": QgsProcessingModelChildParameterSource.fromChildOutput("fix", "OUTPUT"),
            "SPLIT_POINTS": QgsProcessingModelChildParameterSource.fromModelParameter("split_points"),
            "SNAP_TOLERANCE": QgsProcessingModelChildParameterSource.fromStaticValue(1.0),
            "TOLERANCE": QgsProcessingModelChildParameterSource.fromStaticValue(0.0),
            "SPACING": QgsProcessingModelChildParameterSource.fromStaticValue(0.0),
            "ISLANDS": QgsProcessingModelChildParameterSource.fromStaticValue(0),
            "END_RULE": QgsProcessingModelChildParameterSource.fromStaticValue(0),
            "END_CAP": QgsProcessingModelChildParameterSource.fromStaticValue(0),
            "CONNECT_TOUCHING": QgsProcessingModelChildParameterSource.fromStaticValue(False),
            "SEPARATE_PARTS": QgsProcessingModelChildParameterSource.fromStaticValue(False),
            "ADD_M": QgsProcessingModelChildParameterSource.fromStaticValue(False),
            "TRANSECT_INTERVAL": QgsProcessingModelChildParameterSource.fromStaticValue(0.0),
            "TRANSECT_STYLE": QgsProcessingModelChildParameterSource.fromStaticValue(0),
        },
        (260, 260),
    )
    smooth = child(
        "smooth",
        "native:smoothgeometry",
        {
            "INPUT": QgsProcessingModelChildParameterSource.fromChildOutput("centerline", "OUTPUT"),
            "ITERATIONS": QgsProcessingModelChildParameterSource.fromStaticValue(2),
            "OFFSET": QgsProcessingModelChildParameterSource.fromStaticValue(0.25),
            "MAX_ANGLE": QgsProcessingModelChildParameterSource.fromStaticValue(180.0),
        },
        (260, 360),
    )
    output = QgsProcessingModelOutput("smoothed", "Smoothed centerlines")
    output.setChildOutputName("OUTPUT")
    output.setChildId("smooth")
    output.setPosition(QPointF(260, 460))
    smooth.setModelOutputs({"smoothed": output})
    for step in (fixed, centerline, smooth):
        model.addChildAlgorithm(step)
    model.updateDestinationParameters()
    if not model.toFile(str(path)):
        raise RuntimeError(f"could not write {path}")


#: The example models shipped with the plugin (``models/``), listed in the toolbox under "Example models".
MODEL_FOLDER = ROOT / "models"


def example_models():
    """Return the example models: file name -> (name, help, inputs, steps, outputs).

    Each input is ``(name, label, source type, optional, guide?)``; each step ``(child id, algorithm id,
    parameters)`` with a parameter's value a number or bool (static), ``("input", name)`` or ``("step", child id,
    output)``; each output ``(name, label, child id, child output)``. Every IncirCu parameter is given, so the
    modeler shows no missing value.
    """
    common = {
        "SNAP_TOLERANCE": 1.0,
        "TOLERANCE": 0.0,
        "SPACING": 0.0,
        "ISLANDS": 0,
        "END_RULE": 0,
        "END_CAP": 0,
        "SEPARATE_PARTS": False,
        "CONNECT_TOUCHING": False,
        "ADD_M": True,
    }
    widths_help = {
        "ALG_DESC": (
            "River widths: repairs the river polygons (QGIS's Fix geometries), draws one centerline through each "
            "and cross-sections from bank to bank every 'Distance between transects' along it. The centerline "
            "carries the width at every vertex (M values) and its length and smallest, mean and largest width "
            "as attributes; each cross-section carries its width and its distance along the centerline."
        ),
        "rivers": "River polygons, one feature per river or reach (any CRS; a layer in degrees is computed in metres).",
        "split_points": "Optional: two points per polygon where its centerline should start and end.",
        "transect_interval": "Distance along the centerline between two cross-sections, layer units; 0 = the mean width.",
        "incircu:centerlines": "The centerlines with their width statistics.",
        "incircu:transects": "The cross-sections with their width and distance along the centerline.",
    }
    guides_help = {
        "ALG_DESC": (
            "Reservoir centerlines with guides: repairs the reservoir polygons (QGIS's Fix geometries) and draws "
            "one centerline through each, from the end where the river enters to the dam. Rough river lines (a "
            "national river network, OpenStreetMap waterways) tell which arms are the river's: the centerline's "
            "ends are those of the internal path that best covers them, so it follows the river rather than the "
            "longest side arm."
        ),
        "reservoirs": "Reservoir or lake polygons (any CRS).",
        "guide_lines": "River lines crossing the reservoirs (any CRS; gaps, offsets and tributaries are fine).",
        "incircu:centerlines": "The centerlines with their width statistics; ends_from says 'guide' where a guide led.",
    }
    return {
        "river_widths.model3": (
            "River widths",
            widths_help,
            [
                ("rivers", "River polygons", "polygon", False),
                ("split_points", "Split points", "point", True),
                ("transect_interval", "Distance between transects", "distance:rivers", False),
            ],
            [
                ("fix", "native:fixgeometries", {"INPUT": ("input", "rivers")}),
                (
                    "incircu",
                    "incircu:polygoncenterline",
                    {
                        "INPUT": ("step", "fix", "OUTPUT"),
                        "SPLIT_POINTS": ("input", "split_points"),
                        **common,
                        "TRANSECT_INTERVAL": ("input", "transect_interval"),
                        "TRANSECT_STYLE": 0,
                    },
                ),
            ],
            [
                ("centerlines", "Centerlines", "incircu", "OUTPUT"),
                ("transects", "Transects", "incircu", "OUTPUT_TRANSECTS"),
            ],
        ),
        "reservoir_centerlines_with_guides.model3": (
            "Reservoir centerlines with guides",
            guides_help,
            [
                ("reservoirs", "Reservoir polygons", "polygon", False),
                ("guide_lines", "Guide lines", "line", False),
            ],
            [
                ("fix", "native:fixgeometries", {"INPUT": ("input", "reservoirs")}),
                (
                    "incircu",
                    "incircu:polygoncenterline",
                    {
                        "INPUT": ("step", "fix", "OUTPUT"),
                        **common,
                        "GUIDE_LINES": ("input", "guide_lines"),
                        "TRANSECT_INTERVAL": 0.0,
                        "TRANSECT_STYLE": 0,
                    },
                ),
            ],
            [("centerlines", "Centerlines", "incircu", "OUTPUT")],
        ),
    }


def write_example_models(folder):
    """Write the example models of :func:`example_models` into ``folder`` (QGIS's Python, no plugin needed)."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    os.environ["QT_HASH_SEED"] = "0"
    from qgis.core import (
        QgsProcessing,
        QgsProcessingModelAlgorithm,
        QgsProcessingModelChildAlgorithm,
        QgsProcessingModelChildParameterSource,
        QgsProcessingModelOutput,
        QgsProcessingModelParameter,
        QgsProcessingParameterDistance,
        QgsProcessingParameterFeatureSource,
    )
    from qgis.PyQt.QtCore import QPointF

    qgis_application()
    kinds = {
        "polygon": QgsProcessing.SourceType.TypeVectorPolygon,
        "point": QgsProcessing.SourceType.TypeVectorPoint,
        "line": QgsProcessing.SourceType.TypeVectorLine,
    }
    folder.mkdir(parents=True, exist_ok=True)
    for file_name, (name, help_content, inputs, steps, outputs) in example_models().items():
        model = QgsProcessingModelAlgorithm(name, "Example models", "examples")
        model.setHelpContent(help_content)
        for column, (input_name, label, kind, optional) in enumerate(inputs):
            if kind.startswith("distance:"):
                parameter = QgsProcessingParameterDistance(input_name, label, 0.0, kind.split(":")[1], False, 0.0)
            else:
                parameter = QgsProcessingParameterFeatureSource(input_name, label, [kinds[kind]], optional=optional)
            component = QgsProcessingModelParameter(input_name)
            component.setPosition(QPointF(120 + 260 * column, 60))
            model.addModelParameter(parameter, component)
        for row, (child_id, algorithm_id, parameters) in enumerate(steps):
            step = QgsProcessingModelChildAlgorithm(algorithm_id)
            step.setChildId(child_id)
            step.setDescription(child_id)
            step.setPosition(QPointF(260, 160 + 100 * row))
            for parameter_name, value in parameters.items():
                if isinstance(value, tuple) and value[0] == "input":
                    source = QgsProcessingModelChildParameterSource.fromModelParameter(value[1])
                elif isinstance(value, tuple):
                    source = QgsProcessingModelChildParameterSource.fromChildOutput(value[1], value[2])
                else:
                    source = QgsProcessingModelChildParameterSource.fromStaticValue(value)
                step.addParameterSources(parameter_name, [source])
            step_outputs = {}
            for column, (output_name, label, child_id_of_output, child_output) in enumerate(outputs):
                if child_id_of_output != child_id:
                    continue
                output = QgsProcessingModelOutput(output_name, label)
                output.setChildOutputName(child_output)
                output.setChildId(child_id)
                output.setPosition(QPointF(260 + 260 * column, 160 + 100 * (len(steps) + 1)))
                step_outputs[output_name] = output
            step.setModelOutputs(step_outputs)
            model.addChildAlgorithm(step)
        model.updateDestinationParameters()
        if not model.toFile(str(folder / file_name)):
            raise RuntimeError(f"could not write {folder / file_name}")


def write_layers(sample_folder, fixture_folder):
    """Write the GeoJSON sample data and fixtures into the given folders."""
    samples = sample_layers()
    for name, features in samples.items():
        write_layer(sample_folder / f"{name}.geojson", features, PROJECTED)
        write_layer(fixture_folder / f"{name}_2180.geojson", features, PROJECTED)
    for name in ("river", "split_points", "banks_b"):
        geographic = [(fid, to_geographic(geometry), props) for fid, geometry, props in samples[name]]
        write_layer(fixture_folder / f"{name}_4326.geojson", geographic, 4326)
    for name, features in bad_layers().items():
        write_layer(fixture_folder / f"{name}_2180.geojson", features, PROJECTED)


def main():
    """Write every file."""
    write_layers(SAMPLE_FOLDER, FIXTURE_FOLDER)
    write_model(FIXTURE_FOLDER / "fix_centerline_smooth.model3")
    write_example_models(MODEL_FOLDER)


if __name__ == "__main__":
    main()
