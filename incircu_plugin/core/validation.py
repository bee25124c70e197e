"""Checks of the public API's input: coordinates float64 can compute with, split points, the snap tolerance.

The engine checks its own options (``spacing``, ``samples_per_chain``, ``tolerance``).

Every check raises a typed :class:`IncirCuError` whose message says what to change; plain Python type misuse
(a string where a geometry is expected) raises ``TypeError``.
"""

import math
import numbers

import numpy as np
import shapely
from shapely.geometry import MultiPoint, Point

from .errors import InvalidGeometryError, Message, OptionError, SplitPointError, noun

#: Largest coordinate magnitude, CRS units. The core multiplies up to three coordinates together (areas,
#: circumcentres); below this their products stay far inside float64's range (about 1e308).
MAX_COORDINATE = 1e50

#: Smallest extent (bounding-box diagonal), CRS units: products of up to three lengths must stay far above
#: float64's underflow (about 1e-308).
MIN_EXTENT = 1e-50

#: Smallest extent relative to the largest coordinate magnitude. Float64 resolves about 2e-16 of a
#: coordinate; below this ratio the shape spans too few representable steps to be computed reliably.
MIN_RELATIVE_EXTENT = 1e-9


def check_coordinates(coordinates, name, whole=True):
    """Check that coordinates are finite and at a scale float64 geometry can compute with.

    Parameters
    ----------
    coordinates : ndarray of shape (n, 2)
        CRS units.
    name : str
        How messages call the geometry ("polygon", "first line", ...).
    whole : bool
        The coordinates are the whole input, so their extent is checked too (not for one of two lines).

    Returns
    -------
    float or None
        With ``whole``, the coordinates' extent (their bounding box's diagonal, CRS units; 0 for none or one
        point); else None.

    Raises
    ------
    InvalidGeometryError
        On a NaN or infinite coordinate, a coordinate beyond ``MAX_COORDINATE``, or (``whole``) a positive
        extent under ``MIN_EXTENT`` or under ``MIN_RELATIVE_EXTENT`` of the coordinates' magnitude. A zero
        extent is left to the callers, whose messages name the degenerate geometry.
    """
    coordinates = np.asarray(coordinates, dtype=float).reshape(-1, 2)
    if not np.isfinite(coordinates).all():
        bad = coordinates[~np.all(np.isfinite(coordinates), axis=1)][0]
        raise InvalidGeometryError(Message("not_finite", name=noun(name), value=tuple(bad.tolist())))
    if len(coordinates) == 0:
        return 0.0 if whole else None
    # The largest |coordinate| from the extremes: no array of absolute values.
    magnitude = max(float(coordinates.max()), -float(coordinates.min()))
    if magnitude > MAX_COORDINATE:
        raise InvalidGeometryError(
            Message("coordinate_too_large", name=noun(name), magnitude=magnitude, limit=MAX_COORDINATE)
        )
    if not whole:
        return None
    x, y = coordinates[:, 0], coordinates[:, 1]
    extent = float(np.hypot(x.max() - x.min(), y.max() - y.min()))
    if extent == 0:
        return extent
    if extent < MIN_EXTENT:
        raise InvalidGeometryError(Message("extent_too_small", name=noun(name), extent=extent, limit=MIN_EXTENT))
    if extent < MIN_RELATIVE_EXTENT * magnitude:
        raise InvalidGeometryError(
            Message(
                "extent_too_small_here",
                name=noun(name),
                extent=extent,
                magnitude=magnitude,
                limit=MIN_RELATIVE_EXTENT,
            )
        )
    return extent


def tolerance_length(value, name):
    """Return an optional non-negative tolerance as a float (None stays None: the caller's default).

    Raises
    ------
    OptionError
        If the value is not a number, NaN, infinite or negative (a NaN tolerance would accept any distance).
    """
    if value is None:
        return None
    number = _number(value, name)
    if not math.isfinite(number) or number < 0:
        raise OptionError(Message("option_bad_distance", name=name, value=value))
    return number


def _number(value, name):
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, np.number)):
        raise OptionError(Message("option_not_number", name=name, kind=type(value).__name__, value=value))
    return float(value)


def split_point_coordinates(split_points):
    """Return split points as an ``(n, 2)`` array (``n`` may be 0), checking each point.

    Parameters
    ----------
    split_points : None, MultiPoint, or sequence of Point or (x, y)
        CRS units. A MultiPoint gives its points.

    Raises
    ------
    SplitPointError
        If a point is empty, not a point, has not two coordinates, or is not finite or at a usable scale.
    """
    if split_points is None:
        return np.empty((0, 2))
    if isinstance(split_points, np.ndarray) and split_points.ndim == 2 and split_points.dtype.kind in "iuf":
        # Already coordinates (what this function returns, passed on by the public functions): the same
        # checks as point by point below.
        if split_points.shape[1] not in (2, 3) and len(split_points):
            raise SplitPointError(Message("split_point_pair", index=0, value=split_points[0]))
        return _checked_split_points(np.array(split_points[:, :2], dtype=float).reshape(-1, 2))
    if isinstance(split_points, MultiPoint):
        split_points = list(split_points.geoms)
    elif isinstance(split_points, shapely.Geometry):
        raise SplitPointError(Message("split_points_kind", kind=split_points.geom_type))
    if isinstance(split_points, (str, bytes)):
        raise TypeError(f"Split points must be a sequence of points, got {type(split_points).__name__}.")
    split_points = list(split_points)
    if split_points and all(isinstance(point, tuple) for point in split_points):
        # (x, y) tuples (the usual case): numbers only give a numeric array, checked as one.
        try:
            array = np.array(split_points)
        except ValueError:
            array = None
        if array is not None and array.ndim == 2 and array.dtype.kind in "iuf" and array.shape[1] in (2, 3):
            return _checked_split_points(np.array(array[:, :2], dtype=float))
    if split_points and all(isinstance(point, Point) for point in split_points):
        # Points only (the usual case): their coordinates in one call, the same checks as point by point.
        empty = shapely.is_empty(split_points)
        if empty.any():
            raise SplitPointError(Message("split_point_empty", index=int(np.argmax(empty))))
        return _checked_split_points(shapely.get_coordinates(split_points))
    coordinates = [_split_point(index, point) for index, point in enumerate(split_points)]
    return _checked_split_points(np.array(coordinates, dtype=float).reshape(-1, 2))


def _checked_split_points(coordinates):
    """``coordinates`` (split points, an (n, 2) float array, CRS units) once :func:`check_coordinates` passes."""
    try:
        check_coordinates(coordinates, "split points", whole=False)
    except InvalidGeometryError as error:
        raise SplitPointError(error.message) from None
    return coordinates


def _split_point(index, point):
    if isinstance(point, Point):
        if point.is_empty:
            raise SplitPointError(Message("split_point_empty", index=index))
        return point.coords[0][:2]
    if isinstance(point, shapely.Geometry):
        raise SplitPointError(Message("split_point_kind", index=index, kind=point.geom_type))
    if isinstance(point, (numbers.Real, np.number)):
        raise SplitPointError(Message("split_point_number", index=index, value=point))
    if isinstance(point, (str, bytes)) or not np.iterable(point):
        raise TypeError(f"Split point {index} must be a Point or an (x, y) pair, got {type(point).__name__}.")
    values = list(point)
    if len(values) not in (2, 3) or not all(isinstance(v, (numbers.Real, np.number)) for v in values):
        raise SplitPointError(Message("split_point_pair", index=index, value=point))
    return values[:2]
