"""``CONNECT_TOUCHING`` of the polygon algorithms: the gates between the input's touching features."""

import numpy as np
import shapely

from .convert import to_shapely


class LayerGates:
    """The gates of every feature of a polygon source (see the core's ``touching_gates``), read once.

    Parameters
    ----------
    run : FeatureRun
        The running algorithm's run (its core and its cancellable feature loop).
    source : QgsProcessingFeatureSource
        The polygon layer (layer CRS).
    """

    def __init__(self, run, source):
        ids, shapes = [], []
        for feature in run.source_features(source):
            ids.append(feature.id())
            shapes.append(to_shapely(feature.geometry()) if feature.hasGeometry() else None)
        failed = []
        with_gates, gates = run.core.touching_gates(shapes, errors=failed)
        for index, error in failed:
            # The feature is still computed, without the gates GEOS could not find.
            run.warn_feature(ids[index], error)
        self.by_id = dict(zip(ids, zip(with_gates, gates)))

    def of(self, feature_id, frame):
        """Return a feature's geometry with its gates as vertices and its gates, both in the working frame
        ``frame``, and the gates in layer coordinates; ``(None, empty, empty)`` for an unknown feature."""
        shape, gates = self.by_id.get(feature_id, (None, np.empty((0, 2))))
        if shape is None:
            return None, np.empty((0, 2)), gates
        core_shape = shapely.transform(shape, frame.coordinates_to_core)
        return core_shape, frame.coordinates_to_core(gates) if len(gates) else gates, gates
