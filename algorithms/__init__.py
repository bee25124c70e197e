"""Processing algorithms of IncirCu: thin adapters between QGIS layers and the geometry core."""
