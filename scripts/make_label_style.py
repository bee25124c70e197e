"""Write the example lake-label style ``styles/lake_labels.qml`` and its README picture, rendered by QGIS.

The style fills the lakes in blue and labels them with rule-based labels: a curved label along
``incircu_label_line($geometry, points:=false)`` (the label line as a geometry generator), and a horizontal
label on the label point of a compact lake. The picture ``docs/images/label_lines.png`` is four real
reservoirs from ``tests/data/real_rivers_ne_lonlat.geojson`` (Natural Earth 1:10m lakes), each rendered
offscreen by QGIS's map renderer with that style.

Run from the repository root with a QGIS Python: ``QT_QPA_PLATFORM=offscreen .venv/bin/python
scripts/make_label_style.py`` (``make label-style``). The tests load :func:`render` from here.
"""

import json
import sys
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parent.parent
STYLE = REPOSITORY / "styles" / "lake_labels.qml"
PICTURE = REPOSITORY / "docs" / "images" / "label_lines.png"
DATA = REPOSITORY / "tests" / "data" / "real_rivers_ne_lonlat.geojson"
#: The reservoirs of the picture, and the map's size of each, pixels.
PICTURE_LAKES = (
    "Lake Kariba (Zambezi)",
    "Lake Powell (Colorado)",
    "Kakhovka Reservoir (Dnieper)",
    "Cahora Bassa (Zambezi)",
)
PANEL = (640, 420)

LINE_EXPRESSION = "incircu_label_line($geometry, points:=false)"
POINT_EXPRESSION = "incircu_label_line($geometry)"
POINT_FILTER = f"geometry_type({POINT_EXPRESSION}) = 'Point'"


def text_format(size):
    """Dark blue italic text in a white halo, ``size`` points (the cartographic convention for water names)."""
    from qgis.core import QgsTextBufferSettings, QgsTextFormat
    from qgis.PyQt.QtGui import QColor, QFont

    text = QgsTextFormat()
    font = QFont("DejaVu Sans")
    font.setItalic(True)
    text.setFont(font)
    text.setSize(size)
    text.setColor(QColor("#0b3c7d"))
    halo = QgsTextBufferSettings()
    halo.setEnabled(True)
    halo.setSize(0.8)
    halo.setColor(QColor(255, 255, 255, 200))
    text.setBuffer(halo)
    return text


def labeling(field="name", size=11.0):
    """Rule-based labeling: curved along the label line; over the label point of a compact lake."""
    from qgis.core import QgsLabeling, QgsPalLayerSettings, QgsRuleBasedLabeling, QgsWkbTypes

    curved = QgsPalLayerSettings()
    curved.fieldName = field
    curved.placement = QgsPalLayerSettings.Curved
    curved.geometryGeneratorEnabled = True
    curved.geometryGenerator = LINE_EXPRESSION
    curved.geometryGeneratorType = QgsWkbTypes.LineGeometry
    curved.lineSettings().setPlacementFlags(QgsLabeling.LinePlacementFlag.OnLine)
    curved.repeatDistance = 0
    curved.setFormat(text_format(size))

    point = QgsPalLayerSettings()
    point.fieldName = field
    point.placement = QgsPalLayerSettings.OverPoint
    point.geometryGeneratorEnabled = True
    point.geometryGenerator = POINT_EXPRESSION
    point.geometryGeneratorType = QgsWkbTypes.PointGeometry
    point.setFormat(text_format(size))

    root = QgsRuleBasedLabeling.Rule(None)
    line_rule = QgsRuleBasedLabeling.Rule(curved)
    line_rule.setDescription("Along the label line (incircu_label_line)")
    point_rule = QgsRuleBasedLabeling.Rule(point, filterExp=POINT_FILTER)
    point_rule.setDescription("Compact lakes: on the label point")
    root.appendChild(line_rule)
    root.appendChild(point_rule)
    return QgsRuleBasedLabeling(root)


def apply_style(layer, size=11.0):
    """Give ``layer`` the lake fill and the label-line labels."""
    from qgis.core import QgsFillSymbol, QgsSingleSymbolRenderer

    fill = QgsFillSymbol.createSimple(
        {"color": "166,206,227,255", "outline_color": "31,120,180,255", "outline_width": "0.3"}
    )
    layer.setRenderer(QgsSingleSymbolRenderer(fill))
    layer.setLabeling(labeling(size=size))
    layer.setLabelsEnabled(True)


def polygon_layer(polygons, names, crs="EPSG:4326"):
    """A memory layer of Shapely polygons with their ``name`` (a string field)."""
    from qgis.core import QgsFeature, QgsGeometry, QgsVectorLayer

    layer = QgsVectorLayer(f"Polygon?crs={crs}&field=name:string", "lakes", "memory")
    features = []
    for polygon, name in zip(polygons, names):
        feature = QgsFeature(layer.fields())
        feature.setAttributes([name])
        feature.setGeometry(QgsGeometry.fromWkt(polygon.wkt))
        features.append(feature)
    layer.dataProvider().addFeatures(features)
    layer.updateExtents()
    return layer


def lakes_layer(names=None):
    """A memory layer (EPSG:4326) of the reservoirs of the test data, with their ``name``."""
    import shapely.geometry

    features = json.loads(DATA.read_text(encoding="utf-8"))["features"]
    lakes = [
        (shapely.geometry.shape(feature["geometry"]), feature["properties"]["name"])
        for feature in features
        if feature["properties"]["role"] == "polygon" and (names is None or feature["properties"]["name"] in names)
    ]
    return polygon_layer(*zip(*lakes))


def plugin_expressions():
    """Register the plugin's expression functions, imported as QGIS imports the plugin (the package ``incircu``
    from ``out/plugins``); return their module."""
    plugins = REPOSITORY / "out" / "plugins"
    plugins.mkdir(parents=True, exist_ok=True)
    if not (plugins / "incircu").exists():
        (plugins / "incircu").symlink_to(REPOSITORY, target_is_directory=True)
    sys.path.insert(0, str(plugins))
    from incircu.algorithms import expressions

    expressions.register_functions()
    return expressions


def render(layer, extent, size, crs=None):
    """Render ``layer`` offscreen; return the image and the labeling results.

    Parameters
    ----------
    layer : QgsVectorLayer
    extent : QgsRectangle
        In ``crs`` (the layer's when None).
    size : tuple of int
        Width and height, pixels.
    crs : QgsCoordinateReferenceSystem, optional
        The map's CRS.
    """
    from qgis.core import QgsMapRendererSequentialJob, QgsMapSettings
    from qgis.PyQt.QtCore import QSize
    from qgis.PyQt.QtGui import QColor

    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(crs or layer.crs())
    settings.setOutputSize(QSize(*size))
    settings.setOutputDpi(96)
    settings.setBackgroundColor(QColor("white"))
    settings.setExtent(extent)
    job = QgsMapRendererSequentialJob(settings)
    job.start()
    job.waitForFinished()
    return job.renderedImage(), job.takeLabelingResults()


def to_map(layer, crs):
    """The transformation from ``layer``'s CRS to ``crs``."""
    from qgis.core import QgsCoordinateTransform, QgsProject

    return QgsCoordinateTransform(layer.crs(), crs, QgsProject.instance())


def lake_extent(layer, name, crs):
    """The extent of lake ``name`` in ``crs``, grown by 5 %."""
    feature = next(f for f in layer.getFeatures() if f["name"] == name)
    box = to_map(layer, crs).transformBoundingBox(feature.geometry().boundingBox())
    box.scale(1.05)
    return box


def write_style():
    """Save the style as ``styles/lake_labels.qml`` (symbology and labels)."""
    from qgis.core import QgsVectorLayer

    layer = QgsVectorLayer("Polygon?crs=EPSG:4326&field=name:string", "lakes", "memory")
    apply_style(layer)
    STYLE.parent.mkdir(exist_ok=True)
    message, saved = layer.saveNamedStyle(str(STYLE))
    if not saved:
        sys.exit(message)


def write_picture():
    """Render the four reservoirs with the shipped style into one picture."""
    from qgis.core import QgsCoordinateReferenceSystem
    from qgis.PyQt.QtGui import QColor, QImage, QPainter

    layer = lakes_layer(PICTURE_LAKES)
    layer.loadNamedStyle(str(STYLE))
    crs = QgsCoordinateReferenceSystem("EPSG:3857")
    width, height = PANEL
    picture = QImage(2 * width + 10, 2 * height + 10, QImage.Format.Format_ARGB32)
    picture.fill(QColor("white"))
    painter = QPainter(picture)
    for index, name in enumerate(PICTURE_LAKES):
        image, _ = render(layer, lake_extent(layer, name, crs), PANEL, crs)
        painter.drawImage((index % 2) * (width + 10), (index // 2) * (height + 10), image)
    painter.end()
    picture.save(str(PICTURE))


def main():
    from qgis.core import QgsApplication

    application = QgsApplication([], False)
    application.initQgis()
    plugin_expressions()
    write_style()
    write_picture()
    print(STYLE, PICTURE)


if __name__ == "__main__":
    main()
