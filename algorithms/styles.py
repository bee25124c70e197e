"""How the outputs look when QGIS loads them: one symbol per output, stacked so that each one shows.

The algorithm attaches a layer post-processor to every output QGIS will load on completion (the toolbox
dialog, the modeler, ``processing.runAndLoadResults``). When the layer is loaded it gets its symbol and its
name (the input layer's and the rule used: "reservoirs — centerlines (main stem)"), and the outputs of the run
are kept together and in order in the layer tree: in a group of their own (named as the centerlines) at the top
of the tree when the run loads more than one, vertices on top, then the centerline, transects and incircles.
Outputs written to files and opened later keep QGIS's default style.
"""

import math
import uuid

from qgis.core import (
    QgsFillSymbol,
    QgsLayerTree,
    QgsLineSymbol,
    QgsMarkerSymbol,
    QgsProcessingLayerPostProcessorInterface,
    QgsProject,
    QgsProperty,
    QgsSimpleLineSymbolLayer,
    QgsSingleSymbolRenderer,
)

from .compat import SymbolLayerProperty

#: Layer custom properties marking the outputs of one run and their place in the layer tree.
RUN_PROPERTY = "incircu/run"
RANK_PROPERTY = "incircu/rank"

#: QGIS does not keep Python post-processors alive: every one made is held here (a few bytes per output).
LIVE_STYLERS = []

#: Place of each output in the layer tree, top first: the vertices sit on the centerline, so they go above it.
#: The label algorithm's outputs are its lines (``CENTERLINE``) and its points (``LABEL_POINTS``).
VERTICES, CENTERLINE, TRANSECTS, INCIRCLES, LABEL_POINTS = range(5)

CENTERLINE_COLOUR = "215,25,40,255"
CASING_COLOUR = "255,255,255,230"
VERTEX_COLOUR = "80,10,20,255"
#: Dark orange: far from the blues and greens of water fills and from the centerline's red.
TRANSECT_COLOUR = "200,95,0,255"
INCIRCLE_COLOUR = "30,100,200,230"

#: Widths in millimetres on the map at large scales (1:100,000 and larger), narrowing on a log scale to their
#: small-scale values at 1:10,000,000, where a river is a few millimetres wide and a wide line would hide it.
CENTERLINE_WIDTH_MM = 0.55
SMALL_SCALE_CENTERLINE_WIDTH_MM = 0.25
#: The white casing shows this far beyond the line on each side: 0.4 mm, one and a half pixels at 96 dpi.
CASING_MARGIN_MM = 0.4
SMALL_SCALE_CASING_MARGIN_MM = 0.2
CASING_WIDTH_MM = CENTERLINE_WIDTH_MM + 2 * CASING_MARGIN_MM
TRANSECT_WIDTH_MM = 0.26
INCIRCLE_WIDTH_MM = 0.26
#: Diameter of the vertex dots, millimetres: wider than the casing, so each dot stands out of the line.
VERTEX_SIZE_MM = 2.0
#: Share of its channel's drawn mean width a centerline takes at most, and the width it never goes under, mm.
CHANNEL_SHARE = 0.25
THINNEST_MM = 0.15
#: Scale denominators between which the widths narrow (log-linear).
LARGE_SCALE, SMALL_SCALE = 1e5, 1e7
#: Vertices and incircles are shown only at scales where the typical vertex spacing and incircle diameter
#: are at least this many millimetres on the map: closer dots merge into a bead string, smaller circles into a
#: smudge.
READABLE_MM = 3.0


def by_scale(large, small):
    """Return an expression of a width, millimetres: ``large`` at :data:`LARGE_SCALE` and larger scales, ``small``
    at :data:`SMALL_SCALE` and smaller, log-linear between (the legend, without a map scale, uses ``large``)."""
    low, high = math.log10(LARGE_SCALE), math.log10(SMALL_SCALE)
    return f"coalesce(scale_linear(log10(@map_scale), {low:g}, {high:g}, {large:g}, {small:g}), {large:g})"


def round_line_properties(colour, width):
    """Properties of a simple line layer with round caps and joins, ``width`` in millimetres."""
    return {
        "line_color": colour,
        "line_width": str(width),
        "line_width_unit": "MM",
        "capstyle": "round",
        "joinstyle": "round",
    }


def scaled_width(symbol_layer, large, small):
    """Make the stroke width of ``symbol_layer`` follow the map scale (see :func:`by_scale`)."""
    symbol_layer.setDataDefinedProperty(
        SymbolLayerProperty.StrokeWidth, QgsProperty.fromExpression(by_scale(large, small))
    )


def channel_width_mm(metres_per_unit):
    """Return an expression of a centerline feature's mean channel width on the map, millimetres (NULL in the
    legend, or where the line has no width)."""
    return f"(attribute('width_mean') * {metres_per_unit!r} * 1000 / @map_scale)"


def centerline_symbol(metres_per_unit=None):
    """A red line in a white casing, readable over any fill and leaving the polygon's fill visible.

    The local width (the M values) is not drawn: a band as wide as the channel repaints the polygon itself,
    and its buffer would be recomputed for every feature at every redraw. The width stays in the M values,
    the vertices' ``width`` field and the incircles. Both widths narrow at small scales (:func:`by_scale`), and,
    where the layer's unit is known (``metres_per_unit``), the line takes at most :data:`CHANNEL_SHARE` of its
    channel's drawn mean width (``width_mean``) and the casing as much again, never under :data:`THINNEST_MM`:
    at world scale the line is a hairline inside its reservoir, not a band over it.

    Returns
    -------
    QgsLineSymbol
        The casing on rendering pass 0 and the red line on pass 1, so that with symbol levels every casing
        is drawn before any line and centerlines meeting at a junction stay joined.
    """
    line_by_scale = by_scale(CENTERLINE_WIDTH_MM, SMALL_SCALE_CENTERLINE_WIDTH_MM)
    margin_by_scale = by_scale(CASING_MARGIN_MM, SMALL_SCALE_CASING_MARGIN_MM)
    line_width, casing_width = line_by_scale, f"{line_by_scale} + 2 * {margin_by_scale}"
    if metres_per_unit:
        channel = channel_width_mm(metres_per_unit)
        within = f"max({THINNEST_MM:g}, min({line_by_scale}, {CHANNEL_SHARE:g} * {channel}))"
        line_width = f"CASE WHEN {channel} > 0 THEN {within} ELSE {line_by_scale} END"
        casing_width = (
            f"CASE WHEN {channel} > 0 THEN {within} + 2 * min({margin_by_scale}, {CHANNEL_SHARE / 2:g} * {channel})"
            f" ELSE {casing_width} END"
        )
    symbol = QgsLineSymbol.createSimple(round_line_properties(CASING_COLOUR, CASING_WIDTH_MM))
    symbol.symbolLayer(0).setDataDefinedProperty(
        SymbolLayerProperty.StrokeWidth, QgsProperty.fromExpression(casing_width)
    )
    line = QgsSimpleLineSymbolLayer.create(round_line_properties(CENTERLINE_COLOUR, CENTERLINE_WIDTH_MM))
    line.setDataDefinedProperty(SymbolLayerProperty.StrokeWidth, QgsProperty.fromExpression(line_width))
    line.setRenderingPass(1)
    symbol.appendSymbolLayer(line)
    return symbol


def incircle_symbol():
    """Thin blue outlines without fill, so the circles show what lies below and the legend shows a circle's colour."""
    return QgsFillSymbol.createSimple(
        {
            "style": "no",
            "outline_color": INCIRCLE_COLOUR,
            "outline_width": str(INCIRCLE_WIDTH_MM),
            "outline_width_unit": "MM",
        }
    )


def transect_symbol():
    """Thin dark orange lines: they show on a blue or green water fill and are not the centerline's red."""
    symbol = QgsLineSymbol.createSimple(
        {"line_color": TRANSECT_COLOUR, "line_width": str(TRANSECT_WIDTH_MM), "line_width_unit": "MM"}
    )
    scaled_width(symbol.symbolLayer(0), TRANSECT_WIDTH_MM, INCIRCLE_WIDTH_MM / 2.0)
    return symbol


def dot_symbol(colour, size_mm, rim_colour, rim_mm):
    """A round dot of ``colour``, ``size_mm`` across, with a rim of ``rim_colour``, ``rim_mm`` wide."""
    return QgsMarkerSymbol.createSimple(
        {
            "name": "circle",
            "color": colour,
            "size": str(size_mm),
            "size_unit": "MM",
            "outline_color": rim_colour,
            "outline_width": str(rim_mm),
            "outline_width_unit": "MM",
        }
    )


def vertex_symbol():
    """Small dark red dots with a white rim, standing out of the centerline they lie on."""
    return dot_symbol(VERTEX_COLOUR, VERTEX_SIZE_MM, "255,255,255,255", 0.2)


def label_point_symbol():
    """A label point: a dot of the centerline's colour with a white rim, a little larger than a vertex."""
    return dot_symbol(CENTERLINE_COLOUR, 1.5 * VERTEX_SIZE_MM, CASING_COLOUR, 0.4)


def readable_scale(typical_length, metres_per_unit):
    """Return the smallest scale (largest denominator) at which ``typical_length`` (layer units) is
    :data:`READABLE_MM` on the map; 0 (always shown) when it is unknown."""
    if not typical_length or not metres_per_unit or typical_length <= 0.0:
        return 0.0
    return typical_length * metres_per_unit / (READABLE_MM / 1000.0)


def output_renderer(rank, metres_per_unit=None):
    """Return the renderer of the output of ``rank`` (:data:`CENTERLINE`...): one symbol, levels for the centerline
    (whose widths follow its channel's where ``metres_per_unit``, the layer unit's length, is known)."""
    if rank == CENTERLINE:
        symbol = centerline_symbol(metres_per_unit)
    else:
        symbols = {
            VERTICES: vertex_symbol,
            TRANSECTS: transect_symbol,
            INCIRCLES: incircle_symbol,
            LABEL_POINTS: label_point_symbol,
        }
        symbol = symbols[rank]()
    renderer = QgsSingleSymbolRenderer(symbol)
    renderer.setUsingSymbolLevels(rank == CENTERLINE)
    return renderer


class OutputStyler(QgsProcessingLayerPostProcessorInterface):
    """Styles one output layer when QGIS loads it and puts the outputs of its run in order.

    Parameters
    ----------
    run_id : str
        Identifies the outputs of one run.
    rank : int
        :data:`CENTERLINE`, :data:`VERTICES`, :data:`TRANSECTS`, :data:`INCIRCLES` or :data:`LABEL_POINTS`.
    """

    def __init__(self, run_id, rank, name=None, group=None):
        super().__init__()
        self.run_id = run_id
        self.rank = rank
        self.name = name
        self.group = group
        #: Scale denominator beyond which the layer is hidden (0: always shown); set by the writer.
        self.minimum_scale = 0.0
        #: Metres in one unit of the layer's lengths (None: unknown), for widths that follow the channel's.
        self.metres_per_unit = None

    def postProcessLayer(self, layer, context, feedback):
        layer.setRenderer(output_renderer(self.rank, self.metres_per_unit))
        if self.minimum_scale > 0.0:
            layer.setScaleBasedVisibility(True)
            layer.setMinimumScale(self.minimum_scale)
        if self.name:
            layer.setName(self.name)
        layer.setCustomProperty(RUN_PROPERTY, self.run_id)
        layer.setCustomProperty(RANK_PROPERTY, self.rank)
        layer.triggerRepaint()
        order_run_layers(context.project() or QgsProject.instance(), self.run_id, self.group)


def run_group(root, run_id):
    """Return the layer tree group holding the outputs of run ``run_id`` anywhere under ``root``, or None."""
    for child in root.children():
        if QgsLayerTree.isGroup(child):
            if child.customProperty(RUN_PROPERTY) == run_id:
                return child
            found = run_group(child, run_id)
            if found is not None:
                return found
    return None


def outside_other_runs(group, run_id):
    """Return the place (group, index) for the outputs of run ``run_id`` that QGIS loaded into ``group``.

    The top of ``group``; or, when ``group`` is (inside) the group of another run, just above the outermost such
    group. From QGIS 3.44 (and in the desktop before) QGIS loads a run's outputs above the layer panel's current
    node, which after a run is that run's group or one of its layers: a later run must not go into it.
    """
    place, index = group, 0
    node = group
    while node is not None and QgsLayerTree.isGroup(node):
        parent = node.parent()
        if parent is not None and node.customProperty(RUN_PROPERTY) not in (None, run_id):
            place, index = parent, parent.children().index(node)
        node = parent
    return place, index


def order_run_layers(project, run_id, group_name=None):
    """Keep the loaded outputs of one run together in the layer tree, lowest rank on top.

    With ``group_name`` they go into a group of that name made for the run at the top of the group QGIS loaded
    the first of them into (the tree's root, Processing's results group, the group of the panel's current node):
    a later run's group comes above. Without, they are ordered at the place of the topmost. Never inside another
    run's group (:func:`outside_other_runs`). Every post-processor calls this after styling its layer, so the order
    is right once the last output of the run is loaded, whatever order QGIS loads them in.
    """
    root = project.layerTreeRoot()
    nodes = [
        node
        for node in root.findLayers()
        if node.layer() is not None and node.layer().customProperty(RUN_PROPERTY) == run_id
    ]
    if not nodes:
        return
    if group_name:
        group = run_group(root, run_id)
        if group is None:
            place, index = outside_other_runs(nodes[0].parent(), run_id)
            group = place.insertGroup(index, group_name)
            group.setCustomProperty(RUN_PROPERTY, run_id)
        by_parent = {id(group): (group, 0, nodes)}
    else:
        by_parent = {}
        for node in nodes:
            place, index = outside_other_runs(node.parent(), run_id)
            by_parent.setdefault(id(place), (place, index, []))[2].append(node)
    for parent, first, members in by_parent.values():
        children = parent.children()
        inside = [node for node in members if node in children]
        top = min((children.index(node) for node in inside), default=first)
        ordered = sorted(members, key=lambda node: int(node.layer().customProperty(RANK_PROPERTY)))
        if len(inside) == len(members) and [children[top + offset] for offset in range(len(ordered))] == ordered:
            continue
        # A layer leaves the project when its last tree node goes: insert the moved copies before removing.
        for offset, node in enumerate(ordered):
            parent.insertChildNode(top + offset, node.clone())
        for node in members:
            node.parent().removeChildNode(node)


def style_outputs_on_load(context, destinations, names=None, group=None, metres_per_unit=None):
    """Attach an :class:`OutputStyler` to every output that QGIS will load when the algorithm finishes.

    Parameters
    ----------
    context : QgsProcessingContext
    destinations : dict
        Rank (:data:`CENTERLINE`...) -> destination id returned by ``parameterAsSink`` (``None`` when the
        output is skipped).
    names : dict, optional
        Rank -> the name the loaded layer gets (QGIS's own name for the output where absent).
    group : str, optional
        Name of the group the outputs of the run go into when it loads more than one.
    metres_per_unit : float, optional
        Metres in one unit of the outputs' lengths (their ``width_mean``), for :func:`centerline_symbol`.

    Returns
    -------
    dict
        Rank -> the :class:`OutputStyler` of each output that will be loaded (to set its ``minimum_scale``).
    """
    run_id = uuid.uuid4().hex
    names = names or {}
    loaded = {
        rank: destination
        for rank, destination in destinations.items()
        if destination and context.willLoadLayerOnCompletion(destination)
    }
    stylers = {}
    for rank, destination in loaded.items():
        styler = stylers[rank] = OutputStyler(run_id, rank, names.get(rank), group if len(loaded) > 1 else None)
        styler.metres_per_unit = metres_per_unit
        LIVE_STYLERS.append(styler)
        context.layerToLoadOnCompletionDetails(destination).setPostProcessor(styler)
    return stylers
