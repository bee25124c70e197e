"""Data-frame API: the centerline (or the label line) of every polygon of a GeoPandas or dask-geopandas frame.

GeoPandas (and, for lazy frames, dask-geopandas) is imported only when :func:`centerlines`, :func:`frame_labels` or
:func:`networks` is called, so the core itself still needs nothing but numpy, Shapely and pyproj.

Example
-------
>>> import geopandas
>>> from shapely.geometry import box
>>> rivers = geopandas.GeoSeries([box(0, 0, 100, 10), box(0, 0, 1, 1).buffer(-1)], crs="EPSG:2180")
>>> result = centerlines(rivers)
>>> round(float(result.loc[0, "width_max"]), 6), result.loc[1, "error"], result["error"].isna().tolist()
(10.0, 'The polygon is empty.', [True, False])
"""

import numpy as np
import shapely
from shapely.geometry import LineString, MultiLineString, MultiPolygon

from .api import multipolygon_centerlines
from .ends import GUIDE_SEARCH_SHARE
from .errors import IncirCuError
from .geodesy import LocalProjection, degrees_covering
from .labels import BEND, CLEARANCE, MIN_ELONGATION, SMOOTHING, TRIM, feature_label, label_lines
from .widths import width_statistics

#: Columns of the result besides the geometry, with their pandas dtypes (widths and lengths in metres for
#: geographic CRSs, CRS units otherwise). Nullable types, missing as ``<NA>``: GeoParquet keeps them.
RESULT_COLUMNS = {
    "length": "float64",
    "width_min": "float64",
    "width_mean": "float64",
    "width_max": "float64",
    "ends_found": "boolean",
    "ends_from": "string",
    "error": "string",
}

#: Columns of :func:`frame_labels`' result besides the geometry, with their pandas dtypes (lengths and widths in
#: metres for geographic CRSs, CRS units otherwise).
LABEL_COLUMNS = {
    "kind": "string",
    "length": "float64",
    "width_min": "float64",
    "elongation": "float64",
    "error": "string",
}


def centerlines(
    data,
    split_points=None,
    *,
    tolerance=None,
    islands="main_channel",
    end_rule=None,
    guide=None,
    spacing=None,
    snap_tolerance=1.0,
    end_cap="runout",
):
    """Centerline of every (multi)polygon of a GeoSeries or GeoDataFrame, eager or dask-geopandas.

    Each row is computed as the ``incircu:polygoncenterline`` algorithm computes a feature: every part of a
    multipolygon takes the split points within ``snap_tolerance`` of its exterior ring (two: its ends; none:
    found automatically); in a geographic CRS each feature is computed in a :class:`LocalProjection` centred
    on it, so ``spacing``, ``tolerance``, ``snap_tolerance``, lengths and widths are in metres. A row that
    fails gets its reason in ``error`` and never stops the others.

    Parameters
    ----------
    data : geopandas.GeoSeries, geopandas.GeoDataFrame or dask_geopandas.GeoDataFrame
        Polygons and multipolygons (the active geometry column), any CRS.
    split_points : GeoSeries, GeoDataFrame or sequence of shapely geometries, optional
        Every vertex is a candidate split point; reprojected to ``data``'s CRS when both have one; a sequence
        without a CRS is taken in ``data``'s CRS. A dask frame is computed first (it should be small).
    tolerance : float, optional
        Largest distance between the line and the exact medial axis, CRS units (metres when geographic);
        passed to the core only when given.
    islands : {"main_channel", "ignore"}
        See :func:`polygon_centerline`.
    end_rule : str, optional
        How automatic ends are chosen; passed to the core only when given.
    guide : GeoSeries, GeoDataFrame or sequence of line geometries, optional
        Guide lines; each feature gets those whose bounding box meets its own grown by a quarter of its
        larger side (as the plugin), as one MultiLineString. Passed to the core only when one is near.
    spacing : float, optional
        Distance between boundary samples, CRS units (metres when geographic); None: automatic.
    snap_tolerance : float
        Largest distance between a split point and a part's exterior ring, CRS units (metres when
        geographic); 0 or None: a millionth of the feature's size. Default 1, as in the plugin.
    end_cap : {"runout", "axis"}
        How each line crosses its end caps (see :func:`polygon_centerline`): straight along the channel's axis
        (the default, as in the plugin: for maps) or the exact medial axis.

    Returns
    -------
    geopandas.GeoDataFrame or dask_geopandas.GeoDataFrame
        Same index and CRS as ``data`` (lazy for a dask frame). ``geometry``: a LineString per polygon, a
        MultiLineString of the successful parts per multipolygon, None when nothing succeeded; ``length``,
        ``width_min``, ``width_mean``, ``width_max`` (metres when geographic, NaN without a line);
        ``ends_found`` (True when every part found its ends itself, <NA> without a line); ``ends_from``
        (``split_points``, ``guide`` or ``automatic``, comma-separated over the parts); ``error`` (<NA>, or
        the message of the core's typed error, prefixed with ``part i:`` for a part of a multipolygon).

    Examples
    --------
    See the module docstring.
    """
    options = {
        "islands": islands,
        "spacing": spacing,
        "end_cap": end_cap,
        **_given(tolerance=tolerance, end_rule=end_rule),
    }
    return _frame_result(data, split_points, guide, snap_tolerance, options, None)


def frame_labels(
    data,
    split_points=None,
    *,
    trim=TRIM,
    clearance=CLEARANCE,
    bend=BEND,
    smoothing=SMOOTHING,
    min_elongation=MIN_ELONGATION,
    tolerance=None,
    islands="main_channel",
    end_rule=None,
    guide=None,
    spacing=None,
    snap_tolerance=1.0,
):
    """Label line (or label point) of every (multi)polygon of a GeoSeries or GeoDataFrame, eager or dask.

    Each row is computed as :func:`.labels.label_lines` computes a feature, with its main stem found as in
    :func:`centerlines` (split points within ``snap_tolerance`` of a part, guide lines near the feature, a
    :class:`LocalProjection` around each feature in a geographic CRS); a multipolygon's row gets the label of
    its largest part that has one (:func:`.labels.feature_label`, what QGIS labels by default). A row that
    fails gets its reason in ``error`` and never stops the others.

    Parameters
    ----------
    data : geopandas.GeoSeries, geopandas.GeoDataFrame or dask_geopandas.GeoDataFrame
        Polygons and multipolygons (the active geometry column), any CRS.
    split_points : GeoSeries, GeoDataFrame or sequence of shapely geometries, optional
        As for :func:`centerlines`.
    trim, clearance, bend, smoothing, min_elongation : float
        See :func:`.labels.label_lines` (shares of the local or widest width; no unit).
    tolerance : float, optional
        As for :func:`centerlines`, CRS units (metres when geographic).
    islands : {"main_channel", "ignore"}
    end_rule : str, optional
    guide : GeoSeries, GeoDataFrame or sequence of line geometries, optional
        As for :func:`centerlines`.
    spacing : float, optional
        Distance between boundary samples, CRS units (metres when geographic); None: automatic.
    snap_tolerance : float
        As for :func:`centerlines`, CRS units (metres when geographic).

    Returns
    -------
    geopandas.GeoDataFrame or dask_geopandas.GeoDataFrame
        Same index and CRS as ``data`` (lazy for a dask frame). ``geometry``: the label LineString (reading
        left to right) or Point, None without a label; ``kind`` (``line`` or ``point``); ``length`` (0 for a
        point), ``width_min`` (narrowest width along the label stretch; for a point, the widest incircle's
        diameter), metres when geographic; ``elongation``; ``error`` (<NA>, or the core's message, prefixed
        with ``part i:`` for a part of a multipolygon, also when another part gave the label).

    Examples
    --------
    >>> import geopandas
    >>> from shapely.geometry import Point, box
    >>> lakes = geopandas.GeoSeries([box(0, 0, 100, 10), Point(0, 0).buffer(50)], crs="EPSG:2180")
    >>> lakes_labels = frame_labels(lakes)
    >>> lakes_labels["kind"].tolist(), lakes_labels.geometry.iloc[1].distance(Point(0, 0)) < 1e-6
    (['line', 'point'], True)
    """
    options = {"islands": islands, "spacing": spacing, **_given(tolerance=tolerance, end_rule=end_rule)}
    label_options = {
        "trim": trim,
        "clearance": clearance,
        "bend": bend,
        "smoothing": smoothing,
        "min_elongation": min_elongation,
    }
    return _frame_result(data, split_points, guide, snap_tolerance, options, label_options)


def _given(**values):
    """The keywords whose value is not None: passed to the core only when given."""
    return {name: value for name, value in values.items() if value is not None}


def _frame_result(data, split_points, guide, snap_tolerance, options, label_options):
    """The result of :func:`centerlines` (``label_options`` None) or :func:`frame_labels`, lazy for a dask frame."""
    geometry = _geometry_of(data)
    points = None if split_points is None else _coordinates_in(split_points, geometry.crs)
    guides = None if guide is None else _geometries_in(guide, geometry.crs)
    arguments = (points, guides, snap_tolerance, options, label_options)
    if hasattr(data, "npartitions"):
        meta = _empty_result(data._meta, RESULT_COLUMNS if label_options is None else LABEL_COLUMNS)
        return data.map_partitions(_frame_centerlines, *arguments, meta=meta)
    return _frame_centerlines(data, *arguments)


def _geometry_of(data):
    """The active geometry column of a frame, or the series itself."""
    return data if not hasattr(data, "columns") else data.geometry


def _geometries_in(geometries, crs):
    """Return the geometries of a (dask) GeoSeries/GeoDataFrame or a sequence as an array in ``crs``."""
    if hasattr(geometries, "compute"):
        geometries = geometries.compute()
    if hasattr(geometries, "crs"):
        geometries = _geometry_of(geometries)
        if geometries.crs is not None and crs is not None and geometries.crs != crs:
            geometries = geometries.to_crs(crs)
        return np.asarray(geometries.values, dtype=object)
    return np.asarray(list(geometries), dtype=object)


def _coordinates_in(points, crs):
    """Return every vertex of the split points as an ``(n, 2)`` array in ``crs``."""
    return shapely.get_coordinates(_geometries_in(points, crs))


def _empty_result(like, result_columns):
    """An empty result frame with the columns and dtypes of ``result_columns`` (a dask ``meta``)."""
    import geopandas
    import pandas

    index = like.index[:0]
    columns = {name: pandas.Series([], dtype=dtype, index=index) for name, dtype in result_columns.items()}
    return geopandas.GeoDataFrame(columns, geometry=geopandas.GeoSeries([], index=index), crs=_geometry_of(like).crs)


def _frame_centerlines(data, points, guides, snap_tolerance, options, label_options=None):
    """Centerlines (or, with ``label_options``, labels) of one (partition of a) frame; see :func:`centerlines`."""
    import geopandas
    import pandas

    geometry = _geometry_of(data)
    shapes = np.asarray(geometry.values, dtype=object)
    crs = geometry.crs
    geographic = crs is not None and crs.is_geographic
    nearby_points = _nearby(
        shapes, _margins(shapes, snap_tolerance or 0.0, geographic), None if points is None else shapely.points(points)
    )
    nearby_guides = _nearby(shapes, _guide_margins(shapes), guides)
    crs_name = crs.srs if geographic else None
    result_columns, row_of = (RESULT_COLUMNS, _row) if label_options is None else (LABEL_COLUMNS, _label_row)
    starts = [_row_start(shapes[i], nearby_points[i], nearby_guides[i], crs_name) for i in range(len(shapes))]
    ready = [i for i, start in enumerate(starts) if not isinstance(start, Exception)]
    compute = multipolygon_centerlines if label_options is None else label_lines
    computed = compute(
        [starts[i][1] for i in ready],
        [starts[i][2] for i in ready],
        guide=[starts[i][3] for i in ready],
        snap_tolerance=snap_tolerance or None,
        **options,
        **(label_options or {}),
    )
    outcomes = dict(zip(ready, computed))
    rows = []
    for i, start in enumerate(starts):
        outcome = outcomes.get(i, start)
        failed = isinstance(outcome, Exception)
        rows.append(_failed(outcome, result_columns) if failed else row_of(shapes[i], start[0], outcome))
    columns = {
        name: pandas.Series([row[1][name] for row in rows], dtype=dtype, index=geometry.index)
        for name, dtype in result_columns.items()
    }
    lines = geopandas.GeoSeries([row[0] for row in rows], index=geometry.index, crs=crs)
    return geopandas.GeoDataFrame(columns, geometry=lines, crs=crs)


def _margins(shapes, distance, geographic):
    """Bounding-box margin of each shape for a search distance, CRS units (degrees from metres if geographic)."""
    if not geographic:
        return np.full(len(shapes), float(distance))
    bounds = shapely.bounds(shapes)
    latitudes = np.nan_to_num(0.5 * (bounds[:, 1] + bounds[:, 3]))
    return np.asarray(degrees_covering(float(distance), latitudes), dtype=float).reshape(len(shapes))


def _guide_margins(shapes):
    """Bounding-box margin for guide lines, as the plugin's: ``GUIDE_SEARCH_SHARE`` of each box's larger side."""
    bounds = shapely.bounds(shapes)
    return GUIDE_SEARCH_SHARE * np.maximum(bounds[:, 2] - bounds[:, 0], bounds[:, 3] - bounds[:, 1])


def _nearby(shapes, margins, candidates):
    """For each shape, the candidates whose bounding box meets the shape's, widened by its margin."""
    found = [[] for _ in shapes]
    if candidates is None or len(candidates) == 0:
        return found
    bounds = shapely.bounds(shapes)
    usable = np.flatnonzero(np.isfinite(bounds).all(axis=1))
    boxes = shapely.box(*(bounds[usable] + np.outer(margins[usable], [-1.0, -1.0, 1.0, 1.0])).T)
    shape_index, candidate_index = shapely.STRtree(candidates).query(boxes, predicate="intersects")
    for i, j in zip(usable[shape_index], candidate_index):
        found[i].append(candidates[j])
    return found


def _row_start(shape, points, guides, crs_name):
    """What one row's computation needs: ``(projection or None, shape, split points or None, guide or None)``,
    the last three in the frame computed in (the local projection of a geographic frame); or the exception
    raised."""
    try:
        geographic = crs_name is not None and shape is not None and not shape.is_empty
        projection = LocalProjection.around(shape, crs_name) if geographic else None
        local = shape if projection is None else projection.to_local(shape)
        candidates = [np.asarray(point.coords[0]) for point in points]
        guide_lines = [part for guide in guides for part in shapely.get_parts(guide) if part.geom_type == "LineString"]
        guide = MultiLineString([line for line in guide_lines if not line.is_empty]) or None
        if projection is not None:
            candidates = [projection.to_local(point) for point in candidates]
            guide = None if guide is None else projection.to_local(guide)
        return projection, local, candidates or None, guide
    except Exception as error:  # noqa: BLE001 - one bad row must not stop a frame of millions
        return error


def _row(shape, projection, outcomes):
    """A row's ``(geometry, attributes)`` from its parts' outcomes; the parts that failed are named in ``error``."""
    try:
        several = isinstance(shape, MultiPolygon)
        error = _part_errors(shape, outcomes)
        results = [outcome.result for outcome in outcomes if outcome.error is None]
        if not results:
            return None, {**dict.fromkeys(RESULT_COLUMNS), "error": error}
        statistics = width_statistics(results)
        attributes = {name: statistics[name] for name in RESULT_COLUMNS if name in statistics}
        attributes["error"] = error or None
        lines = [result.line if projection is None else projection.to_geographic(result.line) for result in results]
        return (MultiLineString(lines) if several else LineString(lines[0])), attributes
    except Exception as error:  # noqa: BLE001 - as in _row_start
        return _failed(error)


def _label_row(shape, projection, outcomes):
    """A row of :func:`frame_labels`: the largest labelled part's label; the parts that failed in ``error``."""
    try:
        error = _part_errors(shape, outcomes)
        label = feature_label(outcomes, shape)
        if label is None:
            return None, {**dict.fromkeys(LABEL_COLUMNS), "error": error}
        attributes = {name: getattr(label, name) for name in LABEL_COLUMNS if name != "error"}
        attributes["error"] = error or None
        return (label.geometry if projection is None else projection.to_geographic(label.geometry)), attributes
    except Exception as error:  # noqa: BLE001 - as in _row_start
        return _failed(error, LABEL_COLUMNS)


def _part_errors(shape, outcomes):
    """The messages of a row's failed parts, ``part i:`` first for a multipolygon's; empty when none failed."""
    several = isinstance(shape, MultiPolygon)
    return "; ".join(
        (f"part {outcome.part_index}: " if several else "") + _message(outcome.error)
        for outcome in outcomes
        if outcome.error is not None
    )


def _failed(error, result_columns=RESULT_COLUMNS):
    """The ``(geometry, attributes)`` of a row that failed with ``error``."""
    return None, {**dict.fromkeys(result_columns), "error": _message(error)}


def _message(error):
    """The message of a core error, or the kind and message of an unexpected one."""
    if isinstance(error, IncirCuError):
        return str(error)
    return f"unexpected {type(error).__name__}: {error}"


#: Columns of :func:`networks`' branch frame besides the geometry, with their pandas dtypes.
NETWORK_COLUMNS = {
    "source": "object",
    "part": "Int64",
    "from_node": "Int64",
    "to_node": "Int64",
    "kind": "string",
    "from_point": "string",
    "to_point": "string",
    "length": "float64",
    "width_min": "float64",
    "width_mean": "float64",
    "width_max": "float64",
    "n_vertices": "Int64",
    "error": "string",
}


def networks(
    data,
    split_points=None,
    *,
    connect_touching=False,
    min_arm_ratio=None,
    min_arm_length=None,
    islands="main_channel",
    tolerance=None,
    spacing=None,
    snap_tolerance=1.0,
    end_cap="runout",
    nodes=False,
):
    """Network of every (multi)polygon of a GeoSeries or GeoDataFrame: one row per branch.

    Each feature is computed as the ``incircu:polygonnetwork`` algorithm computes it (see
    :func:`.layers.layer_networks`): ends from the split points near each part (two or more), else found
    automatically; with ``connect_touching``, the middle of each boundary stretch two features share is an
    end of both. Node ids are shared by every branch meeting there, across features. A dask frame is computed
    first (the node ids and the gates need the whole layer).

    Parameters
    ----------
    data : geopandas.GeoSeries, geopandas.GeoDataFrame or dask_geopandas.GeoDataFrame
        Polygons and multipolygons, any CRS (geographic: computed in metres around each feature).
    split_points : GeoSeries, GeoDataFrame or sequence of shapely geometries, optional
        Every vertex is a candidate split point (reprojected to ``data``'s CRS).
    connect_touching : bool
        Gates between touching features.
    min_arm_ratio, min_arm_length, islands
        See :func:`.network.polygon_network` (``min_arm_length`` in metres when geographic; passed when given).
    tolerance, spacing, snap_tolerance : float, optional
        As for :func:`centerlines`.
    end_cap : {"runout", "axis"}
        At an end on the outline, as the algorithm's ``END_CAP`` (default, as there, the straight run-out).
    nodes : bool
        Also return the node frame.

    Returns
    -------
    geopandas.GeoDataFrame or (geopandas.GeoDataFrame, geopandas.GeoDataFrame)
        Branches: ``source`` (the feature's index label), ``part``, ``from_node``, ``to_node``, ``kind``,
        ``from_point``, ``to_point`` (the split point's position among the candidate vertices, ``gate``,
        ``auto`` or ``junction``), ``length``, ``width_min``, ``width_mean``, ``width_max``, ``n_vertices``,
        ``error`` (a failed feature or part: one row without geometry); same CRS. Nodes (with ``nodes``):
        indexed by node id, ``degree``, ``radius``, ``kind``.

    Examples
    --------
    >>> import geopandas
    >>> from shapely.geometry import box
    >>> reaches = geopandas.GeoSeries([box(0, 0, 50, 10), box(50, 0, 100, 10)], crs="EPSG:2180")
    >>> branches = networks(reaches, connect_touching=True)
    >>> branches[["source", "from_node", "to_node", "from_point"]].values.tolist()
    [[0, 0, 1, 'gate'], [1, 0, 2, 'gate']]
    """
    from .layers import layer_networks

    if hasattr(data, "npartitions"):
        data = data.compute()
    geometry = _geometry_of(data)
    crs = geometry.crs
    geographic = crs is not None and crs.is_geographic
    options = {"islands": islands, "spacing": spacing, "end_cap": end_cap}
    given = (("tolerance", tolerance), ("min_arm_ratio", min_arm_ratio), ("min_arm_length", min_arm_length))
    options.update({name: value for name, value in given if value is not None})
    points = None if split_points is None else _coordinates_in(split_points, crs)
    layer = layer_networks(
        list(geometry.values),
        points,
        connect_touching=connect_touching,
        geographic_crs=crs.srs if geographic else None,
        snap_tolerance=snap_tolerance or None,
        **options,
    )
    branches = _branch_frame(layer, list(geometry.index), crs)
    return (branches, _node_frame(layer, crs)) if nodes else branches


def _branch_frame(layer, labels, crs):
    """The branch frame of :func:`networks` from a :class:`.layers.LayerNetworks` (``labels``: the features'
    index labels)."""
    import geopandas
    import pandas

    rows = [
        {**{name: branch.get(name) for name in NETWORK_COLUMNS}, "source": labels[branch["feature"]]}
        for branch in layer.branches
    ]
    rows += [{"source": labels[feature], "part": part, "error": message} for feature, part, message in layer.errors]
    shapes = [branch["geometry"] for branch in layer.branches] + [None] * len(layer.errors)
    for row in rows:
        for end in ("from_point", "to_point"):
            row[end] = None if row.get(end) is None else str(row[end])
    columns = {
        name: pandas.Series([row.get(name) for row in rows], dtype=dtype) for name, dtype in NETWORK_COLUMNS.items()
    }
    return geopandas.GeoDataFrame(columns, geometry=geopandas.GeoSeries(shapes, crs=crs), crs=crs)


def _node_frame(layer, crs):
    """The node frame of :func:`networks`, indexed by node id."""
    import geopandas
    import pandas

    node_frame = geopandas.GeoDataFrame(
        {
            "degree": pandas.Series([node["degree"] for node in layer.nodes], dtype="Int64"),
            "radius": pandas.Series([node["radius"] for node in layer.nodes], dtype="float64"),
            "kind": pandas.Series([node["kind"] for node in layer.nodes], dtype="string"),
        },
        geometry=geopandas.GeoSeries([node["geometry"] for node in layer.nodes], crs=crs),
        crs=crs,
    )
    node_frame.index.name = "node"
    return node_frame
