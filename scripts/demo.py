"""``make demo``: run IncirCu with ``qgis_process`` on the bundled sample data and draw the result.

Writes ``out/demo.gpkg`` (centerlines, incircles, transects, bank-line centerline) and ``out/demo.png``, a map of
the river polygons, the split points and the centerlines rendered by QGIS itself, offscreen.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parent.parent
SAMPLES = REPOSITORY / "scripts" / "data"
OUT = REPOSITORY / "out"
GEOPACKAGE = OUT / "demo.gpkg"
PICTURE = OUT / "demo.png"
#: Distance between transects, metres.
TRANSECT_INTERVAL = 60.0


def qgis_environment():
    """Environment of a ``qgis_process`` that finds the plugin in ``out/plugins`` and Shapely for QGIS."""
    plugins = OUT / "plugins"
    plugins.mkdir(parents=True, exist_ok=True)
    link = plugins / "incircu"
    if not link.exists():
        link.symlink_to(REPOSITORY, target_is_directory=True)
    environment = dict(os.environ)
    environment.update(
        {
            "QT_QPA_PLATFORM": "offscreen",
            "QGIS_CUSTOM_CONFIG_PATH": str(OUT / "qgis-profile"),
            "QGIS_PLUGINPATH": str(plugins),
            "PYTHONPATH": str(REPOSITORY / ".venv" / "qgis-site"),
        }
    )
    return environment


def qgis_process(*arguments):
    """Run ``qgis_process`` and stop the demo when it fails."""
    executable = shutil.which("qgis_process.bin") or shutil.which("qgis_process")
    if executable is None:
        sys.exit("qgis_process is not installed: run `make setup`")
    print("qgis_process", " ".join(arguments[:2]))
    done = subprocess.run([executable, *arguments], check=False, env=qgis_environment(), capture_output=True, text=True)
    if done.returncode != 0 and "already enabled" not in done.stdout + done.stderr:
        sys.exit(done.stdout + done.stderr)
    print("\n".join(line for line in done.stdout.splitlines() if "COUNT" in line))


def table(name):
    """A GeoPackage table as a ``qgis_process`` output value."""
    return f"ogr:dbname='{GEOPACKAGE}' table=\"{name}\" (geom)"


def compute():
    """Run both algorithms into ``out/demo.gpkg``."""
    if GEOPACKAGE.exists():
        GEOPACKAGE.unlink()
    qgis_process("plugins", "enable", "incircu")
    qgis_process(
        "run",
        "incircu:polygoncenterline",
        "--",
        "INPUT={}".format(SAMPLES / "river.geojson"),
        "SPLIT_POINTS={}".format(SAMPLES / "split_points.geojson"),
        "SNAP_TOLERANCE=1",
        "OUTPUT={}".format(table("centerlines")),
        "OUTPUT_CIRCLES={}".format(table("incircles")),
        "OUTPUT_TRANSECTS={}".format(table("transects")),
        f"TRANSECT_INTERVAL={TRANSECT_INTERVAL}",
    )
    qgis_process(
        "run",
        "incircu:linescenterline",
        "--",
        "LINES_A={}".format(SAMPLES / "banks_a.geojson"),
        "LINES_B={}".format(SAMPLES / "banks_b.geojson"),
        "PAIR_FIELD_A=reach",
        "PAIR_FIELD_B=reach",
        "OUTPUT={}".format(table("bank_centerlines")),
    )


def render():
    """Start QGIS offscreen, draw the map into ``out/demo.png`` and stop QGIS."""
    os.environ["QT_QPA_PLATFORM"] = "offscreen"
    from qgis.core import QgsApplication

    application = QgsApplication([], True, str(OUT / "qgis-profile"))
    application.initQgis()
    picture = draw_map()
    if not picture.save(str(PICTURE)):
        sys.exit(f"cannot write {PICTURE}")
    application.exitQgis()
    print("wrote", GEOPACKAGE, "and", PICTURE)


def draw_map():
    """Draw polygons, bank lines, every 25th incircle, transects, split points and centerlines (a QImage)."""
    from qgis.core import (
        QgsFillSymbol,
        QgsLineSymbol,
        QgsMapRendererParallelJob,
        QgsMapSettings,
        QgsMarkerSymbol,
        QgsVectorLayer,
    )
    from qgis.PyQt.QtCore import QSize, Qt
    from qgis.PyQt.QtGui import QColor, QFont, QImage, QPainter

    layers = []

    def add(uri, symbol, subset=None):
        layer = QgsVectorLayer(str(uri), Path(str(uri)).stem, "ogr")
        if not layer.isValid():
            sys.exit(f"cannot open {uri}")
        if subset:
            layer.setSubsetString(subset)
        layer.renderer().setSymbol(symbol)
        layers.insert(0, layer)
        return layer

    river = add(
        SAMPLES / "river.geojson",
        QgsFillSymbol.createSimple({"color": "166,206,227", "outline_color": "31,120,180", "outline_width": "0.4"}),
    )
    add(SAMPLES / "banks_a.geojson", QgsLineSymbol.createSimple({"line_color": "31,120,180", "line_width": "0.6"}))
    add(SAMPLES / "banks_b.geojson", QgsLineSymbol.createSimple({"line_color": "31,120,180", "line_width": "0.6"}))
    add(
        f"{GEOPACKAGE}|layername=incircles",
        QgsFillSymbol.createSimple({"style": "no", "outline_color": "90,90,90", "outline_width": "0.15"}),
        '"fid" % 25 = 0',
    )
    add(
        f"{GEOPACKAGE}|layername=transects",
        QgsLineSymbol.createSimple({"line_color": "51,160,44", "line_width": "0.3"}),
    )
    for name in ("centerlines", "bank_centerlines"):
        add(
            f"{GEOPACKAGE}|layername={name}",
            QgsLineSymbol.createSimple({"line_color": "215,48,31", "line_width": "0.7"}),
        )
    add(
        SAMPLES / "split_points.geojson",
        QgsMarkerSymbol.createSimple({"name": "circle", "color": "0,0,0", "size": "2.4"}),
    )

    settings = QgsMapSettings()
    settings.setLayers(layers)
    settings.setDestinationCrs(river.crs())
    extent = river.extent()
    for layer in layers:
        extent.combineExtentWith(layer.extent())
    settings.setExtent(extent.buffered(40.0))
    settings.setOutputSize(QSize(1400, 1500))
    settings.setOutputDpi(150)
    settings.setBackgroundColor(QColor("white"))
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    header = 70
    picture = QImage(settings.outputSize().width(), settings.outputSize().height() + header, QImage.Format.Format_RGB32)
    picture.fill(QColor("white"))
    painter = QPainter(picture)
    painter.drawImage(0, header, job.renderedImage())
    painter.setPen(QColor("black"))
    painter.setFont(QFont("Sans", 11))
    painter.drawText(
        picture.rect().adjusted(20, 10, -20, 0),
        Qt.AlignmentFlag.AlignTop | Qt.AlignmentFlag.AlignLeft | Qt.TextFlag.TextWordWrap,
        "IncirCu centerlines (red): a meandering river between its split points (black), a channel with an "
        "island (ends found automatically; the line takes the wider side) and two pairs of bank lines. "
        f"Grey: every 25th incircle; green: transects every {TRANSECT_INTERVAL:g} m.",
    )
    painter.end()
    return picture


if __name__ == "__main__":
    OUT.mkdir(exist_ok=True)
    compute()
    render()
