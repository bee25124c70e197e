"""General numpy helpers of the core: row gathers and writes, owner/rank ranges, a fast stable order, vector turns.

Nothing here knows about chains, contacts or skeletons; the modules that do (``contacts``, ``adaptive``,
``skeleton``, ``paths``, ``ends``, ``lines``, ``fixed_sampling``) import these from here. Several helpers exist
only because numpy's general indexing is several times slower on the small two-column arrays the tracer handles
thousands of times; each gives the same values (bytes) as the plain numpy expression it replaces.
"""

from dataclasses import fields
from functools import cache

import numpy as np

__all__ = [
    "PACKED_LIMIT",
    "ArrayRecord",
    "group_minima",
    "left_normal",
    "put_rows",
    "ranges",
    "rotate",
    "rows",
    "stable_order",
]

#: Largest integer :func:`stable_order` packs a value and its index into (below ``2**63``).
PACKED_LIMIT = 2**62


class ArrayRecord:
    """Mixin for a dataclass whose fields are arrays with one row per item (samples, points, intervals).

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Pairs(ArrayRecord):
    ...     key: np.ndarray
    ...     value: np.ndarray
    >>> pairs = Pairs(np.arange(4), np.arange(4) * 10.0)
    >>> pairs.subset(np.array([3, 1])).value.tolist()
    [30.0, 10.0]
    >>> pairs.subset(pairs.key % 2 == 0).key.tolist()
    [0, 2]
    >>> Pairs.concatenate([pairs.subset(slice(0, 1)), pairs.subset(slice(3, 4))]).key.tolist()
    [0, 3]
    """

    def subset(self, index):
        """The items ``index`` (an index array, a mask or a slice).

        Parameters
        ----------
        index : ndarray of int or bool, or slice
            The items to keep; a mask must have one entry per item.

        Returns
        -------
        ArrayRecord
            A record of the same type holding those items only.

        Raises
        ------
        IndexError
            When a mask's length is not the number of items.
        """
        columns = (getattr(self, name) for name in _field_names(type(self)))
        if isinstance(index, np.ndarray) and index.dtype.kind in "iu":
            return type(self)(*(rows(column, index) for column in columns))
        if isinstance(index, np.ndarray) and index.dtype == bool:
            # compress: numpy's indexing of a two-column array by a mask is several times slower (and it takes a
            # short mask, which indexing refuses).
            columns = list(columns)
            if len(index) != len(columns[0]):
                raise IndexError(f"a mask of {len(index)} items for {len(columns[0])} rows")
            return type(self)(*(column.compress(index, axis=0) for column in columns))
        return type(self)(*(column[index] for column in columns))

    @classmethod
    def concatenate(cls, parts):
        """All items of ``parts``, one after the other.

        Parameters
        ----------
        parts : sequence of ArrayRecord
            Records of this type (at least one).

        Returns
        -------
        ArrayRecord
        """
        return cls(*(np.concatenate([getattr(part, name) for part in parts]) for name in _field_names(cls)))


@cache
def _field_names(record_type):
    """The names of the fields of a dataclass, in their order (looked up once per class: the tracer's rounds
    take subsets of small records thousands of times)."""
    return tuple(field.name for field in fields(record_type))


def rows(array, index):
    """``array[index]`` for an integer array ``index``.

    Gathered with :meth:`numpy.ndarray.take`: numpy's indexing copies the rows of a two-column array several
    times slower, and the method skips the Python layers of :func:`numpy.take`, which small inputs, gathering a
    few rows thousands of times, feel.

    Parameters
    ----------
    array : ndarray of shape (n, ...)
    index : ndarray of shape (m,) of int

    Returns
    -------
    ndarray of shape (m, ...)

    Examples
    --------
    >>> rows(np.arange(6.0).reshape(3, 2), np.array([2, 0])).tolist()
    [[4.0, 5.0], [0.0, 1.0]]
    """
    return array.take(index, axis=0)


def put_rows(array, index, values):
    """``array[index] = values`` for two-column rows, fast where it can be.

    Into a C-contiguous float64 ``array`` each row is written as one complex number (numpy's indexed assignment
    of a two-column array's rows is about ten times slower; the bytes written are the same), otherwise (or for
    one row to repeat) by numpy's assignment.

    Parameters
    ----------
    array : ndarray of shape (n, 2)
        Written in place.
    index : ndarray of int, or ndarray of shape (n,) of bool
        The rows to write.
    values : array_like of shape (m, 2), or of shape (2,) to repeat
        One row per row written.

    Examples
    --------
    >>> array = np.zeros((3, 2))
    >>> put_rows(array, np.array([2, 0]), np.array([[1.0, 2.0], [3.0, 4.0]]))
    >>> array.tolist()
    [[3.0, 4.0], [0.0, 0.0], [1.0, 2.0]]
    """
    values = np.asarray(values)
    if array.dtype != np.float64 or not array.flags.c_contiguous or values.ndim != 2:
        array[index] = values
        return
    array.view(np.complex128)[:, 0][index] = np.ascontiguousarray(values, dtype=float).view(np.complex128)[:, 0]


def ranges(counts):
    """For ``counts[i]`` items owned by ``i``: the owner of each item and its rank among the owner's items.

    Parameters
    ----------
    counts : ndarray of shape (k,) of int
        Non-negative item counts per owner.

    Returns
    -------
    owner, rank : ndarray of shape (sum(counts),) of int

    Examples
    --------
    >>> owner, rank = ranges(np.array([2, 0, 3]))
    >>> owner.tolist(), rank.tolist()
    ([0, 0, 2, 2, 2], [0, 1, 0, 1, 2])
    """
    owner = np.repeat(np.arange(len(counts)), counts)
    # Each item's index less its owner's first item's, subtracted in place.
    rank = np.arange(len(owner))
    rank -= np.repeat(np.cumsum(counts) - counts, counts)
    return owner, rank


def stable_order(values, bound):
    """Return ``np.argsort(values, kind="stable")`` of non-negative integers below ``bound``.

    Each value is packed with its index into one integer (``value * n + index``, all distinct) and those are
    sorted, several times faster than a stable argsort; when the packed integers could exceed
    ``PACKED_LIMIT``, the stable argsort itself.

    Parameters
    ----------
    values : ndarray of shape (n,) of int
        Non-negative, below ``bound``.
    bound : int
        An upper bound of the values (exclusive).

    Returns
    -------
    ndarray of shape (n,) of int

    Examples
    --------
    >>> stable_order(np.array([2, 0, 2, 1, 0]), 3).tolist()
    [1, 4, 3, 0, 2]
    """
    count = len(values)
    if int(bound) * max(count, 1) > PACKED_LIMIT:
        return np.argsort(values, kind="stable")
    packed = values.astype(np.int64) * count + np.arange(count, dtype=np.int64)
    packed.sort()
    return packed % count


def group_minima(group, size, *values):
    """Minimum of each of ``values`` per group id; inf for empty groups.

    Parameters
    ----------
    group : ndarray of shape (n,) of int
        Each row's group id, below ``size``; each group's rows consecutive.
    size : int
        Number of groups.
    *values : ndarray of shape (n,) of float

    Returns
    -------
    list of ndarray of shape (size,) of float
        One per array of ``values``.

    Examples
    --------
    >>> [m.tolist() for m in group_minima(np.array([0, 0, 2]), 3, np.array([5.0, 1.0, 7.0]))]
    [[1.0, inf, 7.0]]
    """
    results = [np.full(size, np.inf) for _ in values]
    if len(group):
        starts = np.concatenate([[True], group[1:] != group[:-1]]).nonzero()[0]
        for result, value in zip(results, values):
            result[group[starts]] = np.minimum.reduceat(value, starts)
    return results


def left_normal(vectors):
    """The vectors turned a quarter turn counter-clockwise.

    Parameters
    ----------
    vectors : ndarray of shape (n, 2)

    Returns
    -------
    ndarray of shape (n, 2) of float

    Examples
    --------
    >>> left_normal(np.array([[1.0, 0.0], [0.0, 2.0]])).tolist()
    [[-0.0, 1.0], [-2.0, 0.0]]
    """
    # Filled column by column: the same values as stacking the two columns, with fewer Python layers.
    turned = np.empty(vectors.shape)
    np.negative(vectors[:, 1], out=turned[:, 0])
    turned[:, 1] = vectors[:, 0]
    return turned


def rotate(vectors, angles):
    """The vectors turned counter-clockwise by ``angles``.

    Parameters
    ----------
    vectors : ndarray of shape (n, 2)
    angles : float or ndarray of shape (n,)
        Radians.

    Returns
    -------
    ndarray of shape (n, 2) of float

    Examples
    --------
    >>> np.round(rotate(np.array([[2.0, 0.0]]), np.pi / 2), 12).tolist()
    [[0.0, 2.0]]
    """
    cos, sin = np.cos(angles), np.sin(angles)
    return np.stack([cos * vectors[:, 0] - sin * vectors[:, 1], sin * vectors[:, 0] + cos * vectors[:, 1]], axis=1)
