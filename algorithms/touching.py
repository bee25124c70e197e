"""``CONNECT_TOUCHING`` of the polygon algorithms: the gates between the input's touching features."""

import numpy as np
import shapely

from .convert import to_shapely


class LayerGates:
    """The gates of every feature of a polygon source (see the core's ``touching_gates``), read once.

    Made by :meth:`.running.FeatureRun.layer_gates`.

    Parameters
    ----------
    ids : list of int
        The feature ids, in the order of the core's inputs.
    with_gates : list of shapely geometry or None
        Each feature's geometry with its gates as vertices, layer CRS.
    gates : list of ndarray of shape (n, 2)
        Each feature's gates, layer CRS.
    """

    def __init__(self, ids, with_gates, gates):
        self.by_id = dict(zip(ids, zip(with_gates, gates)))

    @staticmethod
    def read(run, source):
        """Return the ids and the Shapely geometries (None without one) of every feature of ``source``."""
        ids, shapes = [], []
        for feature in run.source_features(source):
            ids.append(feature.id())
            shapes.append(to_shapely(feature.geometry()) if feature.hasGeometry() else None)
        return ids, shapes

    def layer_geometry(self, feature_id):
        """Return a feature's geometry with its gates as vertices, layer CRS (None for an unknown feature)."""
        return self.by_id.get(feature_id, (None,))[0]

    def of(self, feature_id, frame):
        """Return a feature's geometry with its gates as vertices and its gates, both in the working frame
        ``frame`` (the feature's), and the gates in layer coordinates; ``(None, empty, empty)`` for an unknown
        feature."""
        shape, gates = self.by_id.get(feature_id, (None, np.empty((0, 2))))
        if shape is None:
            return None, np.empty((0, 2)), gates
        core_shape = shapely.transform(shape, frame.coordinates_to_core)
        return core_shape, frame.coordinates_to_core(gates) if len(gates) else gates, gates
