"""How the outputs look when QGIS loads them: one symbol per output and the centerline on top.

The algorithm attaches a layer post-processor to every output QGIS will load on completion (the toolbox
dialog, the modeler, ``processing.runAndLoadResults``). When the layer is loaded it gets its symbol, and the
outputs of the run are ordered in the layer tree: centerline on top, then vertices, transects and incircles.
Outputs written to files and opened later keep QGIS's default style.
"""

import uuid

from qgis.core import (
    QgsFillSymbol,
    QgsGeometryGeneratorSymbolLayer,
    QgsLineSymbol,
    QgsMarkerSymbol,
    QgsProcessingLayerPostProcessorInterface,
    QgsProject,
    QgsSingleSymbolRenderer,
    QgsWkbTypes,
)

#: Layer custom properties marking the outputs of one run and their place in the layer tree.
RUN_PROPERTY = "incircu/run"
RANK_PROPERTY = "incircu/rank"

#: QGIS does not keep Python post-processors alive: every one made is held here (a few bytes per output).
LIVE_STYLERS = []

#: Place of each output in the layer tree, top first.
CENTERLINE, VERTICES, TRANSECTS, INCIRCLES = range(4)

CENTERLINE_COLOUR = "200,30,45,255"
WIDTH_BAND_COLOUR = "240,150,40,80"
INCIRCLE_COLOUR = "30,110,180,45"
TRANSECT_COLOUR = "60,60,60,220"
VERTEX_COLOUR = "120,20,30,200"


def centerline_symbol(width_band):
    """A bold red line with a white casing, optionally over the band of local widths.

    Parameters
    ----------
    width_band : bool
        Draw, under the line, the band whose width is the M value of each vertex (the local width), built by
        the ``buffer_by_m`` expression; only meaningful when M is in the layer's units.

    Returns
    -------
    QgsLineSymbol
    """
    symbol = QgsLineSymbol.createSimple(
        {"line_color": "255,255,255,230", "line_width": "1.6", "line_width_unit": "MM", "capstyle": "round"}
    )
    line = QgsLineSymbol.createSimple(
        {"line_color": CENTERLINE_COLOUR, "line_width": "0.9", "line_width_unit": "MM", "capstyle": "round"}
    )
    symbol.appendSymbolLayer(line.symbolLayer(0).clone())
    if width_band:
        band = QgsGeometryGeneratorSymbolLayer.create(
            {"geometryModifier": "buffer_by_m($geometry)", "SymbolType": "Fill"}
        )
        band.setSubSymbol(QgsFillSymbol.createSimple({"color": WIDTH_BAND_COLOUR, "outline_style": "no"}))
        symbol.insertSymbolLayer(0, band)
    return symbol


def incircle_symbol():
    """Thin translucent outlines without fill, so the circles never hide what lies below."""
    return QgsFillSymbol.createSimple(
        {
            "style": "no",
            "outline_color": INCIRCLE_COLOUR,
            "outline_width": "0.1",
            "outline_width_unit": "MM",
        }
    )


def transect_symbol():
    """Thin dark lines."""
    return QgsLineSymbol.createSimple({"line_color": TRANSECT_COLOUR, "line_width": "0.25", "line_width_unit": "MM"})


def vertex_symbol():
    """Small dark red dots."""
    return QgsMarkerSymbol.createSimple(
        {"name": "circle", "color": VERTEX_COLOUR, "size": "1.8", "size_unit": "MM", "outline_style": "no"}
    )


def output_symbol(rank, layer):
    """Return the symbol of the output of ``rank`` (:data:`CENTERLINE`...) for ``layer``."""
    if rank == CENTERLINE:
        return centerline_symbol(QgsWkbTypes.hasM(layer.wkbType()) and not layer.crs().isGeographic())
    return {VERTICES: vertex_symbol, TRANSECTS: transect_symbol, INCIRCLES: incircle_symbol}[rank]()


class OutputStyler(QgsProcessingLayerPostProcessorInterface):
    """Styles one output layer when QGIS loads it and puts the outputs of its run in order.

    Parameters
    ----------
    run_id : str
        Identifies the outputs of one run.
    rank : int
        :data:`CENTERLINE`, :data:`VERTICES`, :data:`TRANSECTS` or :data:`INCIRCLES`.
    """

    def __init__(self, run_id, rank):
        super().__init__()
        self.run_id = run_id
        self.rank = rank

    def postProcessLayer(self, layer, context, feedback):
        layer.setRenderer(QgsSingleSymbolRenderer(output_symbol(self.rank, layer)))
        layer.setCustomProperty(RUN_PROPERTY, self.run_id)
        layer.setCustomProperty(RANK_PROPERTY, self.rank)
        layer.triggerRepaint()
        order_run_layers(context.project() or QgsProject.instance(), self.run_id)


def order_run_layers(project, run_id):
    """Order the loaded outputs of one run in the layer tree: lowest rank on top, at the place of the topmost.

    Every post-processor calls this after styling its layer, so the order is right once the last output of
    the run is loaded, whatever order QGIS loads them in.
    """
    by_parent = {}
    for node in project.layerTreeRoot().findLayers():
        layer = node.layer()
        if layer is not None and layer.customProperty(RUN_PROPERTY) == run_id:
            by_parent.setdefault(id(node.parent()), (node.parent(), []))[1].append(node)
    for parent, nodes in by_parent.values():
        children = parent.children()
        top = min(children.index(node) for node in nodes)
        ordered = sorted(nodes, key=lambda node: int(node.layer().customProperty(RANK_PROPERTY)))
        if [children[top + offset] for offset in range(len(ordered))] == ordered:
            continue
        # A layer leaves the project when its last tree node goes: insert the moved copies before removing.
        for offset, node in enumerate(ordered):
            parent.insertChildNode(top + offset, node.clone())
        for node in nodes:
            parent.removeChildNode(node)


def style_outputs_on_load(context, destinations):
    """Attach an :class:`OutputStyler` to every output that QGIS will load when the algorithm finishes.

    Parameters
    ----------
    context : QgsProcessingContext
    destinations : dict
        Rank (:data:`CENTERLINE`...) -> destination id returned by ``parameterAsSink`` (``None`` when the
        output is skipped).
    """
    run_id = uuid.uuid4().hex
    for rank, destination in destinations.items():
        if destination and context.willLoadLayerOnCompletion(destination):
            styler = OutputStyler(run_id, rank)
            LIVE_STYLERS.append(styler)
            context.layerToLoadOnCompletionDetails(destination).setPostProcessor(styler)
