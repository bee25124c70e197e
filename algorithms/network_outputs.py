"""Output layer of ``incircu:polygonnetwork``: one line feature per branch of each network."""

import numpy as np
from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsPointXY,
    QgsProcessingException,
    QgsProcessingUtils,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QCoreApplication

from ..incircu_plugin.core.layers import number_nodes
from .compat import WkbType
from .convert import line_with_m
from .outputs import (
    DOUBLE,
    FEATURE_ID,
    INTEGER,
    STRING,
    make_fields,
    primary_key_sink,
    release_sinks,
    rounded_statistics,
)
from .styles import CENTERLINE, style_outputs_on_load
from .units import length_decimals, metres_per_unit, rounded

#: Fields added to the input attributes on every branch (lengths and widths in layer units, metres when
#: geographic). ``from_point``/``to_point``: id of the split point at the branch's start/end, "auto" at an end
#: found automatically, or "junction"; ``from_node``/``to_node``: ids of the nodes at the branch's start and
#: end, shared by every branch meeting there (also across features whose ends coincide exactly); ``kind``:
#: "arm", "inner" or "loop"; ``right_chain``/``left_chain``: the boundary chain on either side, named "a-b"
#: after the ids of the ends at its ends (counter-clockwise, "auto:<node>" for an automatic end);
#: ``source_fid``: the id of the input feature.
BRANCH_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("from_point", STRING),
    ("to_point", STRING),
    ("from_node", FEATURE_ID),
    ("to_node", FEATURE_ID),
    ("kind", STRING),
    ("right_chain", STRING),
    ("left_chain", STRING),
    ("length", DOUBLE),
    ("width_min", DOUBLE),
    ("width_mean", DOUBLE),
    ("width_max", DOUBLE),
    ("n_vertices", INTEGER),
)

#: Fields of the optional node layer: its id (as in the branches' ``from_node``/``to_node``), the number of
#: branch ends there, the radius of the junction's circle (0 at an end; layer units, metres when geographic)
#: and "end" or "junction".
NODE_FIELDS = (("node", FEATURE_ID), ("degree", INTEGER), ("radius", DOUBLE), ("kind", STRING))

#: Value of ``from_point``/``to_point`` at a junction.
JUNCTION = "junction"

#: Value of ``from_point``/``to_point`` at an end found automatically.
AUTOMATIC = "auto"

#: Value of ``from_point``/``to_point`` at a gate (``CONNECT_TOUCHING``).
GATE = "gate"


class NetworkWriter:
    """Creates the branch layer of the network algorithm and writes networks into it.

    Parameters
    ----------
    algorithm : IncirCuAlgorithm
    parameters, context : dict, QgsProcessingContext
        For the sinks (``OUTPUT``, ``OUTPUT_NODES``).
    options : NetworkOptions
        The run's options (``source``: the input layer, ``outputs``: M values and layer names).
    """

    def __init__(self, algorithm, parameters, context, options):
        input_fields, crs = options.source.fields(), options.source.sourceCrs()
        self.crs = crs
        self.add_m = add_m = options.outputs.add_m
        line_type = QgsWkbTypes.addM(WkbType.LineString) if add_m else WkbType.LineString
        self.fields = QgsProcessingUtils.combineFields(input_fields, make_fields(BRANCH_FIELDS))
        self.sink, self.sink_id = primary_key_sink(algorithm, parameters, context, self.fields, line_type, crs)
        self.nodes, self.nodes_id = algorithm.parameterAsSink(
            parameters, algorithm.OUTPUT_NODES, context, make_fields(NODE_FIELDS), WkbType.Point, crs
        )
        self.decimals = length_decimals(crs)
        self.centerline_count = 0
        self.output_name = algorithm.OUTPUT
        self.nodes_name = algorithm.OUTPUT_NODES
        # The layer's nodes by id (as the core's ``LayerNetworks.nodes``) and the ids of the ends by coordinates.
        self.node_table = []
        self.end_ids = {}
        style_outputs_on_load(
            context,
            {CENTERLINE: self.sink_id},
            options.outputs.layer_names,
            options.outputs.group,
            metres_per_unit=metres_per_unit(crs),
        )

    def close(self):
        """Write the node layer, then flush and release the sinks, which closes (commits) their files; safe to
        call twice."""
        if self.nodes is not None:
            for node, row in enumerate(self.node_table):
                feature = QgsFeature(make_fields(NODE_FIELDS))
                feature.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(row["geometry"].x, row["geometry"].y)))
                feature.setAttributes([node, row["degree"], rounded(row["radius"], self.decimals), row["kind"]])
                self.nodes.addFeature(feature, QgsFeatureSink.Flag.FastInsert)
            self.node_table = []
        release_sinks(self, ("sink", "nodes"))

    def destinations(self):
        """Return the output ids keyed by parameter name."""
        return {self.output_name: self.sink_id, self.nodes_name: self.nodes_id}

    def write(self, feature, parts, frame):
        """Write one feature per branch of the networks of one input feature.

        Every branch carries the input ``feature``'s attributes, its id (``source_fid``) and its own statistics.
        ``parts`` holds, per successful part, its index, its ``NetworkResult``, the ids of the split points the
        network's indices refer to, the feature's gates (layer CRS) and its extent (the core's
        ``bounding_diagonal``, layer units); ``frame`` is the working frame the networks are expressed in.
        """
        attributes, source_fid = feature.attributes(), feature.id()
        for _, network, ids, gates, extent in parts:
            nodes = np.array(frame.to_layer(network.nodes), dtype=float)
            gates = np.asarray(gates, dtype=float).reshape(-1, 2)
            node_ids = number_nodes(self.node_table, self.end_ids, network, nodes, gates, extent)
            names = [
                str(ids[index]) if index is not None else f"{network.end_sources[row][:4]}:{node_ids[row]}"
                for row, index in enumerate(network.point_indices)
            ]
            chains = [f"{names[start]}-{names[end]}" for start, end in network.chain_nodes]
            for branch in network.branches:
                result = branch.result
                coordinates = np.array(frame.to_layer(np.asarray(result.line.coords, dtype=float)), dtype=float)
                # The ends exactly at their nodes (a gate's coordinates after a geographic round trip).
                coordinates[0], coordinates[-1] = nodes[branch.start_node], nodes[branch.end_node]
                statistics = rounded_statistics([result], self.decimals)
                added = {
                    "source_fid": source_fid,
                    "from_point": self._point_name(network, branch.start_point, branch.start_node, ids),
                    "to_point": self._point_name(network, branch.end_point, branch.end_node, ids),
                    "from_node": node_ids[branch.start_node],
                    "to_node": node_ids[branch.end_node],
                    "kind": branch.kind,
                    "right_chain": self._chain_name(chains, branch.right_chain),
                    "left_chain": self._chain_name(chains, branch.left_chain),
                    **statistics,
                }
                feature = QgsFeature(self.fields)
                feature.setGeometry(QgsGeometry(line_with_m(coordinates, result.widths if self.add_m else None)))
                feature.setAttributes([*attributes, *(added[name] for name, _ in BRANCH_FIELDS)])
                if not self.sink.addFeature(feature, QgsFeatureSink.Flag.FastInsert):
                    raise QgsProcessingException(
                        QCoreApplication.translate("IncirCuAlgorithm", "Could not write a branch: {}").format(
                            self.sink.lastError()
                        )
                    )
                self.centerline_count += 1

    @staticmethod
    def _chain_name(chains, chain):
        """Return a chain's name, or "island:<j>" for channel island ``j`` (``ISLANDS`` = channels)."""
        return chains[chain] if chain < len(chains) else f"island:{chain - len(chains)}"

    @staticmethod
    def _point_name(network, point, node, ids):
        """Return ``from_point``/``to_point``: the split point's id, "gate", "auto" or "junction"."""
        if point is not None:
            return str(ids[point])
        if node >= len(network.split_points):
            return JUNCTION
        return GATE if network.end_sources[node] == "gate" else AUTOMATIC
