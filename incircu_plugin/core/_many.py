"""One function for one geometry or many, as Shapely's: the dispatch behind the public entry points.

A public function (:func:`.api.polygon_centerline` and the others) given one geometry runs its steps alone and
returns its result or raises. Given an array-like of geometries (a list, a numpy array, a GeoSeries) it
returns a list, one outcome per geometry in input order, each the result or the exception (without its
traceback) that geometry alone raises: the geometries are computed in batches (:func:`batches`) whose
tracings are shared (:func:`._steps.run_together`), and a geometry's outcome is the same bytes whichever
batch it falls in. Every other argument is one value for all geometries or a sequence of one per geometry.
"""

import numbers
from functools import partial

import numpy as np
import shapely

from ._steps import reporter, run_alone, run_together
from .errors import Message, OptionError

__all__ = [
    "BATCH_FEATURES",
    "BATCH_VERTICES",
    "batches",
    "compute",
    "detached",
    "is_many",
    "one_or_many",
    "per_geometry",
    "point_sets_per_geometry",
    "run_many_steps",
]

#: Most features in one batch of :func:`batches` (traced together by :func:`._steps.run_together`).
BATCH_FEATURES = 256

#: Most boundary vertices in one batch of :func:`batches`: bounds the memory a batch holds at once.
BATCH_VERTICES = 100_000


def is_many(value):
    """Whether ``value`` is an array-like of geometries (elements that are Shapely geometries or None), rather
    than one geometry (or one coordinate sequence, or None).

    Examples
    --------
    >>> from shapely.geometry import Point
    >>> is_many(Point(0, 0)), is_many([Point(0, 0), None]), is_many([(0, 0), (1, 0)]), is_many(None), is_many([])
    (False, True, False, False, True)
    """
    if value is None or isinstance(value, (shapely.Geometry, str, bytes)):
        return False
    if isinstance(value, np.ndarray):
        return value.dtype == object
    try:
        elements = list(value)
    except TypeError:
        return False
    return all(element is None or isinstance(element, shapely.Geometry) for element in elements)


def per_geometry(value, count, name):
    """``value`` as a list of ``count`` values, one per geometry: a sequence of that length as it is, anything
    else (a number, a string, a geometry, None) repeated.

    Raises
    ------
    OptionError
        If ``value`` is a sequence of another length.
    """
    if value is None or isinstance(value, (numbers.Number, str, bytes, shapely.Geometry)):
        return [value] * count
    values = list(value)
    if len(values) != count:
        raise OptionError(Message("values_per_geometry", name=name, given=len(values), count=count))
    return values


def compute(make_steps, geometries, per_element, progress=None, batch_features=None):
    """The outcome of ``make_steps(geometry, **options)`` run for each of ``geometries``, in batches.

    Parameters
    ----------
    make_steps : callable
        A step generator function (:mod:`._steps`), called with one geometry (or a tuple of them, spread as
        positional arguments) and keywords.
    geometries : list
        One element per feature: a geometry, or a tuple of positional arguments.
    per_element : dict
        Keywords with one value per feature (lists of ``len(geometries)``).
    progress : callable, optional
        Called with the fraction done (0 to 1); when it returns False, :class:`.errors.Cancelled` is raised.
    batch_features : int, optional
        Most features in one batch (default :data:`BATCH_FEATURES`): fewer for heavy features that share no
        tracing, so progress and cancel come between them.

    Returns
    -------
    list
        Per feature, its result or the exception it raised (without traceback).
    """
    report = reporter(progress)
    outcomes = [None] * len(geometries)
    done = 0
    for batch in batches(range(len(geometries)), partial(_vertex_count_of, geometries), batch_features):
        generators, positions = [], []
        for index in batch:
            arguments = geometries[index] if isinstance(geometries[index], tuple) else (geometries[index],)
            try:
                generators.append(
                    make_steps(*arguments, **{name: values[index] for name, values in per_element.items()})
                )
                positions.append(index)
            except Exception as error:  # noqa: BLE001 - a feature's error is its outcome
                outcomes[index] = detached(error)
        part = partial(_batch_report, report, done / len(geometries), len(batch) / len(geometries))
        for index, outcome in zip(positions, run_together(generators, part)):
            outcomes[index] = detached(outcome) if isinstance(outcome, Exception) else outcome
        done += len(batch)
    return outcomes


def one_or_many(make_steps, geometry, split_points, options, progress, point_sets=(), batch_features=None):
    """``make_steps(geometry, split_points, **options)`` run alone for one geometry, else for each geometry of
    an array-like, in batches traced together (:func:`._many.compute`); ``split_points`` and every option are
    then one value for all or one per geometry, except ``split_points`` and the options named in
    ``point_sets`` (sequences of points): None, or one sequence (or None) per geometry; ``batch_features`` as
    for :func:`compute`."""
    if not is_many(geometry):
        return run_alone(make_steps(geometry, split_points, **options, progress=progress))
    geometries = list(geometry)
    per_element = {
        name: point_sets_per_geometry(value, len(geometries), name)
        if name in point_sets
        else per_geometry(value, len(geometries), name)
        for name, value in options.items()
    }
    per_element["split_points"] = point_sets_per_geometry(split_points, len(geometries))
    return compute(make_steps, geometries, per_element, progress, batch_features)


def point_sets_per_geometry(points, count, name="split_points"):
    """The points (split points, gates) of each of ``count`` geometries: None for all, or one sequence (or None)
    per geometry."""
    return [None] * count if points is None else per_geometry(points, count, name)


def _batch_report(report, begin, share, fraction):
    """``report`` of the whole run, given a batch's ``fraction`` done (the batch starts at ``begin`` of the run
    and is ``share`` of it)."""
    return report(begin + share * fraction)


def _vertex_count_of(geometries, index):
    """Number of vertices of ``geometries[index]`` (see :func:`_vertex_count`)."""
    return _vertex_count(geometries[index])


def _vertex_count(geometry):
    """Number of vertices of a feature's geometries (0 for anything that is not a geometry)."""
    parts = geometry if isinstance(geometry, tuple) else (geometry,)
    return sum(int(shapely.get_num_coordinates(part)) if isinstance(part, shapely.Geometry) else 0 for part in parts)


def run_many_steps(generators, progress=None):
    """Run step generators together (:func:`._steps.run_together`): per generator its result or the exception
    it raised, without traceback. What the deprecated ``centerlines_together`` of 0.2 did."""
    return [
        detached(outcome) if isinstance(outcome, Exception) else outcome
        for outcome in run_together(generators, progress)
    ]


def detached(error):
    """Return ``error`` without its traceback (nor those of its causes), so a kept error holds no frame.

    A traceback holds the frames it passed through and their locals (here the outcome list, and the caller's
    ``progress`` callback with everything it refers to); an error stored in a result would tie them into a
    reference cycle that keeps them alive until the garbage collector runs, possibly never.
    """
    seen, current = set(), error
    while current is not None and id(current) not in seen:
        seen.add(id(current))
        current.__traceback__ = None
        current = current.__cause__ or current.__context__
    return error


def batches(items, vertex_count, features=None):
    """Split ``items`` into consecutive lists of at most :data:`BATCH_FEATURES` items and
    :data:`BATCH_VERTICES` vertices (a larger item alone).

    Parameters
    ----------
    items : iterable
        Read lazily: a batch is yielded as soon as it is full.
    vertex_count : callable
        ``vertex_count(item)`` -> the item's number of boundary vertices.
    features : int, optional
        Most items in a batch instead of :data:`BATCH_FEATURES`.

    Yields
    ------
    list
        The next batch, in input order.

    Examples
    --------
    >>> [len(batch) for batch in batches(range(600), lambda item: 1)]
    [256, 256, 88]
    """
    features = BATCH_FEATURES if features is None else features
    batch, vertices = [], 0
    for item in items:
        count = vertex_count(item)
        if batch and vertices + count > BATCH_VERTICES:
            yield batch
            batch, vertices = [], 0
        batch.append(item)
        vertices += count
        if len(batch) >= features or vertices >= BATCH_VERTICES:
            yield batch
            batch, vertices = [], 0
    if batch:
        yield batch
