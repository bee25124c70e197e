"""IncirCu: the geometry core (``core``, free of QGIS) and the QGIS plugin glue (``plugin``, ``provider``)."""
