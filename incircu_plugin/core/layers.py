"""Networks of a whole layer: every feature's network, node ids shared where features meet.

:func:`layer_networks` runs :func:`.network.multipolygon_networks` on every feature and numbers the nodes
across the layer: a junction gets an id of its own, an end the id of any earlier end at exactly the same
coordinates. With ``connect_touching`` the features first get their gates (:func:`.touching.touching_gates`):
the middle of every stretch of boundary two features share is an end of both, so their lines meet there and
share the node (a feature whose gates GEOS cannot compute is still computed, alone, with a warning). In a geographic CRS each feature is computed in a :class:`.geodesy.LocalProjection` centred
on it; an end within ``GATE_SNAP`` of the feature's extent from a gate is then given the gate's coordinates
exactly (the projection's round trip moves it by about 1e-15 degrees).
"""

from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import LineString, Point

from .errors import IncirCuError
from .geodesy import LocalProjection
from .network import multipolygon_networks
from .touching import bounding_diagonal, touching_gates
from .widths import width_statistics

#: An end this close to a gate, as a fraction of its feature's bounding-box diagonal, is the gate.
GATE_SNAP = 1e-9


@dataclass
class LayerNetworks:
    """The networks of a layer as flat records.

    Attributes
    ----------
    branches : list of dict
        Per branch: ``feature`` (index in the input), ``part``, ``geometry`` (LineString, input CRS),
        ``widths`` (per vertex, CRS units, metres when geographic), ``from_node``, ``to_node``, ``kind``,
        ``from_point``, ``to_point`` (the split point's index among the candidates, or ``"gate"``,
        ``"auto"``, ``"junction"``), ``length``, ``width_min``, ``width_mean``, ``width_max``, ``n_vertices``.
    nodes : list of dict
        Per node id (its index): ``geometry`` (Point, input CRS), ``degree``, ``radius`` (0 at an end) and
        ``kind`` (``"end"`` or ``"junction"``).
    errors : list of (int, int or None, str)
        Feature, part (None for a single polygon) and message of each failure.
    warnings : list of (int, int or None, str)
        Feature, part and message of what a computed feature's user should know: its gates could not be found
        (``connect_touching``, see :func:`.touching.touching_gates`), so it is not connected to its neighbours.
    """

    branches: list = field(default_factory=list)
    nodes: list = field(default_factory=list)
    errors: list = field(default_factory=list)
    warnings: list = field(default_factory=list)


def layer_networks(
    geometries, split_points=None, *, connect_touching=False, geographic_crs=None, snap_tolerance=None, **options
):
    """Network of every feature of a layer, with node ids shared across features.

    Parameters
    ----------
    geometries : sequence of Polygon or MultiPolygon or None
        The layer's features, CRS units (degrees with ``geographic_crs``).
    split_points : sequence of (x, y), optional
        Candidate split points for all features, same CRS.
    connect_touching : bool
        Make the middle of every boundary stretch shared by two features an end of both (a gate).
    geographic_crs : str, optional
        The CRS of geographic coordinates (e.g. ``"EPSG:4326"``): each feature is computed in metres in a
        local projection; lengths, widths, radii and ``snap_tolerance`` are then metres.
    snap_tolerance : float, optional
        Largest distance of a split point from a part's exterior ring, CRS units (metres when geographic);
        default ``1e-6`` of each feature's extent.
    **options
        Passed to :func:`.network.polygon_network` (``min_arm_ratio``, ``islands``, ``tolerance``, ...).

    Returns
    -------
    LayerNetworks

    Examples
    --------
    A river cut into two reaches: two lines meeting at the middle of the cut, one shared node.

    >>> from shapely.geometry import box
    >>> layer = layer_networks([box(0, 0, 50, 10), box(50, 0, 100, 10)], connect_touching=True)
    >>> [(b["from_node"], b["to_node"]) for b in layer.branches], layer.nodes[0]["geometry"].coords[0]
    ([(0, 1), (0, 2)], (50.0, 5.0))
    """
    geometries = list(geometries)
    gates = [np.empty((0, 2)) for _ in geometries]
    layer = LayerNetworks()
    if connect_touching:
        failed = []
        geometries, gates = touching_gates(geometries, errors=failed)
        layer.warnings.extend((feature, None, str(error)) for feature, error in failed)
    candidates = np.empty((0, 2)) if split_points is None else np.asarray(split_points, dtype=float).reshape(-1, 2)
    end_ids = {}
    for feature, geometry in enumerate(geometries):
        try:
            projection = None
            if geographic_crs is not None and geometry is not None and not geometry.is_empty:
                projection = LocalProjection.around(geometry, geographic_crs)
            local, points, local_gates = geometry, candidates, gates[feature]
            if projection is not None:
                local = projection.to_local(geometry)
                points = projection.to_local(candidates) if len(candidates) else candidates
                local_gates = projection.to_local(gates[feature]) if len(gates[feature]) else gates[feature]
            outcomes = multipolygon_networks(local, points, snap_tolerance=snap_tolerance, gates=local_gates, **options)
        except IncirCuError as error:
            layer.errors.append((feature, None, str(error)))
            continue
        several = len(outcomes) > 1
        extent = bounding_diagonal(geometry)
        for outcome in outcomes:
            if outcome.error is not None:
                layer.errors.append((feature, outcome.part_index if several else None, str(outcome.error)))
                continue
            _add_network(layer, end_ids, feature, outcome, projection, gates[feature], extent)
    return layer


def _add_network(layer, end_ids, feature, outcome, projection, gates, extent):
    """Append one part's branches and nodes to ``layer``; ends at coordinates already seen share their id."""
    network = outcome.result
    nodes = network.nodes if projection is None else projection.to_geographic(network.nodes)
    nodes = np.array(nodes, dtype=float)
    ids = number_nodes(layer.nodes, end_ids, network, nodes, gates, extent)
    for branch in network.branches:
        result = branch.result
        coordinates = shapely.get_coordinates(result.line)
        if projection is not None:
            coordinates = np.array(projection.to_geographic(coordinates), dtype=float)
        coordinates[0], coordinates[-1] = nodes[branch.start_node], nodes[branch.end_node]
        layer.branches.append(
            {
                "feature": feature,
                "part": outcome.part_index,
                "geometry": LineString(coordinates),
                "widths": result.widths,
                "from_node": ids[branch.start_node],
                "to_node": ids[branch.end_node],
                "kind": branch.kind,
                "from_point": _point_name(network, branch.start_point, branch.start_node),
                "to_point": _point_name(network, branch.end_point, branch.end_node),
                **width_statistics([result]),
            }
        )


def number_nodes(layer_nodes, end_ids, network, nodes, gates, extent):
    """Number the nodes of one network across a layer: an end takes the id of an earlier end at exactly the same
    coordinates, a junction a new id; an end within ``GATE_SNAP`` of ``extent`` from a gate is the gate.

    Parameters
    ----------
    layer_nodes : list of dict
        The layer's nodes so far, by id (see :class:`LayerNetworks`); the new ones are appended, degrees added.
    end_ids : dict
        ``(x, y)`` of every end so far -> its node id; updated.
    network : NetworkResult
    nodes : ndarray of shape (n, 2)
        ``network.nodes`` in the layer's CRS; the ends snapped to a gate get its coordinates, in place.
    gates : ndarray of shape (m, 2)
        The feature's gates, layer CRS.
    extent : float
        The feature's :func:`.touching.bounding_diagonal`, layer CRS units.

    Returns
    -------
    list of int
        The node id of each row of ``nodes``.
    """
    count = len(network.split_points)
    for row in range(count):
        if len(gates):
            distance = np.hypot(*(gates - nodes[row]).T)
            nearest = int(np.argmin(distance))
            if distance[nearest] <= GATE_SNAP * extent:
                nodes[row] = gates[nearest]
    ids = []
    degrees, radii = network.node_degrees, network.node_radii
    for row, xy in enumerate(map(tuple, nodes.tolist())):
        if row < count and xy in end_ids:
            node = end_ids[xy]
        else:
            node = len(layer_nodes)
            kind = "end" if row < count else "junction"
            layer_nodes.append({"geometry": Point(xy), "degree": 0, "radius": float(radii[row]), "kind": kind})
            if row < count:
                end_ids[xy] = node
        layer_nodes[node]["degree"] += int(degrees[row])
        ids.append(node)
    return ids


def _point_name(network, point, node):
    """The split point index at a branch end, or ``"gate"``, ``"auto"`` or ``"junction"``."""
    if point is not None:
        return point
    if node >= len(network.split_points):
        return "junction"
    return "gate" if network.end_sources[node] == "gate" else "auto"
