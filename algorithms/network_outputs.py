"""Output layer of ``incircu:polygonnetwork``: one line feature per branch of each network."""

import numpy as np
from qgis.core import QgsFeature, QgsFeatureSink, QgsGeometry, QgsProcessingException, QgsProcessingUtils, QgsWkbTypes
from qgis.PyQt.QtCore import QCoreApplication

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
from .units import length_decimals, metres_per_unit

#: Fields added to the input attributes on every branch (lengths and widths in layer units, metres when
#: geographic). ``from_point``/``to_point``: id of the split point at the branch's start/end, or "junction";
#: ``right_chain``/``left_chain``: the boundary chain on either side, named "a-b" after the ids of the split
#: points at its ends (counter-clockwise); ``source_fid``: the id of the input feature.
BRANCH_FIELDS = (
    ("source_fid", FEATURE_ID),
    ("from_point", STRING),
    ("to_point", STRING),
    ("right_chain", STRING),
    ("left_chain", STRING),
    ("length", DOUBLE),
    ("width_min", DOUBLE),
    ("width_mean", DOUBLE),
    ("width_max", DOUBLE),
    ("n_vertices", INTEGER),
)

#: Value of ``from_point``/``to_point`` at a junction.
JUNCTION = "junction"


class NetworkWriter:
    """Creates the branch layer of the network algorithm and writes networks into it.

    Parameters
    ----------
    algorithm : IncirCuAlgorithm
    parameters, context : dict, QgsProcessingContext
    input_fields : QgsFields
        Attributes copied from the input features.
    crs : QgsCoordinateReferenceSystem
    add_m : bool
        Store the local width as M value.
    """

    def __init__(self, algorithm, parameters, context, input_fields, crs, add_m):
        self.add_m = add_m
        line_type = QgsWkbTypes.addM(WkbType.LineString) if add_m else WkbType.LineString
        self.fields = QgsProcessingUtils.combineFields(input_fields, make_fields(BRANCH_FIELDS))
        self.sink, self.sink_id = primary_key_sink(algorithm, parameters, context, self.fields, line_type, crs)
        self.decimals = length_decimals(crs)
        self.centerline_count = 0
        self.output_name = algorithm.OUTPUT
        style_outputs_on_load(
            context,
            {CENTERLINE: self.sink_id},
            *algorithm.output_layer_names(parameters, context),
            metres_per_unit=metres_per_unit(crs),
        )

    def close(self):
        """Flush and release the branch layer's sink, which closes (commits) its file; safe to call twice."""
        release_sinks(self, ("sink",))

    def destinations(self):
        """Return the output id keyed by parameter name."""
        return {self.output_name: self.sink_id}

    def write(self, attributes, source_fid, parts, frame):
        """Write one feature per branch of the networks of one input feature.

        Every branch carries ``attributes`` (the input feature's values), ``source_fid`` (the input feature's
        id) and its own statistics. ``parts`` holds, per successful part, its index, its ``NetworkResult`` and
        the ids of the split points the network's indices refer to; ``frame`` is the working frame the
        networks are expressed in.
        """
        for _, network, ids in parts:
            names = [str(point_id) for point_id in ids]
            chains = [f"{names[start]}-{names[end]}" for start, end in network.chains]
            for branch in network.branches:
                result = branch.result
                coordinates = frame.to_layer(np.asarray(result.line.coords, dtype=float))
                statistics = rounded_statistics([result], self.decimals)
                added = {
                    "source_fid": source_fid,
                    "from_point": JUNCTION if branch.start_point is None else names[branch.start_point],
                    "to_point": JUNCTION if branch.end_point is None else names[branch.end_point],
                    "right_chain": chains[branch.right_chain],
                    "left_chain": chains[branch.left_chain],
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
