"""Split points of the polygon algorithms: read once per run with their ids, found per polygon by a spatial index."""

from qgis.core import QgsFeatureRequest, QgsRectangle, QgsSpatialIndex


def layer_margin(distance, geometry, geographic):
    """Return ``distance`` (metres when ``geographic``) as a safe bounding-box margin in layer units."""
    if not geographic:
        return distance
    from ..incircu_plugin.core.geodesy import degrees_covering  # after require_core: the core needs Shapely

    return float(degrees_covering(distance, geometry.boundingBox().center().y()))


class SplitPoints:
    """Every vertex of a point layer, in the polygon layer's CRS (``points``: (x, y) pairs), with the id of its
    feature.

    Parameters
    ----------
    source : QgsProcessingFeatureSource or None
        The point layer; None: no split points.
    crs : QgsCoordinateReferenceSystem
        CRS of the polygon layer (the points are reprojected to it).
    context : QgsProcessingContext
    id_field : str, optional
        Attribute holding each point's id; empty or None: the feature id.
    """

    def __init__(self, source, crs, context, id_field=None):
        self.points, self.ids = [], []
        self.tree = None
        self.index = QgsSpatialIndex()
        self.geographic = crs.isGeographic()
        if source is None:
            return
        field = source.fields().lookupField(id_field) if id_field else -1
        request = QgsFeatureRequest().setDestinationCrs(crs, context.transformContext())
        for feature in source.getFeatures(request):
            point_id = feature.attribute(field) if field >= 0 else feature.id()
            for vertex in feature.geometry().vertices():
                self.index.addFeature(len(self.points), QgsRectangle(vertex.x(), vertex.y(), vertex.x(), vertex.y()))
                self.points.append((vertex.x(), vertex.y()))
                self.ids.append(point_id)

    def near(self, geometry, distance, frame):
        """Return the split points within ``distance`` of a polygon's bounding box, in the working frame.

        Parameters
        ----------
        geometry : QgsGeometry
            The polygon, layer CRS.
        distance : float
            Snap tolerance, layer units (metres for a layer in degrees).
        frame : WorkingFrame
            Frame the core computes in, already centred on the polygon.

        Returns
        -------
        points : ndarray of shape (n, 2)
            In the working frame.
        ids : list
            The id of each point's feature.
        """
        margin = layer_margin(distance, geometry, self.geographic)
        found = self.index.intersects(geometry.boundingBox().buffered(margin))
        return frame.coordinates_to_core([self.points[i] for i in found]), [self.ids[i] for i in found]

    def nearest_distance(self, ring, frame):
        """Return the distance from a ring of the working frame to the nearest split point, or None without any.

        The nearest point is picked in the layer's CRS (for a message: in degrees, nearly the nearest in metres),
        its distance measured in the working frame.

        Parameters
        ----------
        ring : shapely.LinearRing
            A polygon's exterior ring, working frame.
        frame : WorkingFrame
            The frame ``ring`` is in.

        Returns
        -------
        float or None
            Working frame units: layer units, metres for a layer in degrees.
        """
        import shapely  # after require_core, like the core: a missing Shapely gets its install message

        if not self.points:
            return None
        if self.tree is None:
            self.tree = shapely.STRtree(shapely.points(self.points))
        nearest = int(self.tree.query_nearest(frame.to_layer(ring))[0])
        return float(shapely.distance(ring, shapely.points(frame.coordinates_to_core([self.points[nearest]]))[0]))
