"""The core's general array helpers (``core/_arrays.py``) against the plain numpy expressions they replace."""

import numpy as np
import pytest

from incircu_plugin.core import _arrays
from incircu_plugin.core._arrays import put_rows


def test_put_rows_writes_the_rows_of_an_index_and_no_others():
    array = np.arange(12.0).reshape(6, 2)
    put_rows(array, np.array([4, 1]), np.array([[-1.0, -2.0], [-3.0, -4.0]]))
    assert array.tolist() == [[0, 1], [-3, -4], [4, 5], [6, 7], [-1, -2], [10, 11]]
    # Values that are not contiguous (a transposed array) are written row by row as well.
    put_rows(array, np.array([0, 5]), np.array([[7.0, 8.0], [9.0, 10.0]]).T)
    assert array[[0, 5]].tolist() == [[7, 9], [8, 10]]
    # A mask, one row to repeat, and arrays that are not C-contiguous float64: as numpy's assignment.
    put_rows(array, np.arange(6) == 2, np.array([[0.5, 0.25]]))
    assert array[2].tolist() == [0.5, 0.25]
    put_rows(array, np.array([1, 3]), np.array([1.5, 2.5]))
    assert array[[1, 3]].tolist() == [[1.5, 2.5], [1.5, 2.5]]
    for other in (np.arange(12).reshape(6, 2), np.asfortranarray(np.zeros((6, 2)))):
        put_rows(other, np.array([4]), np.array([[3.0, 4.0]]))
        assert other[4].tolist() == [3, 4]


@pytest.mark.parametrize("limit", [_arrays.PACKED_LIMIT, 0])
def test_stable_order_is_the_stable_argsort_packed_or_not(monkeypatch, limit):
    """Many equal values (ties in input order), both through the packed sort and through the fallback."""
    monkeypatch.setattr(_arrays, "PACKED_LIMIT", limit)
    values = np.random.default_rng(5).integers(0, 50, size=2000)
    expected = np.argsort(values, kind="stable")
    assert np.array_equal(_arrays.stable_order(values, 50), expected)
    assert len(_arrays.stable_order(values[:0], 50)) == 0


def test_stable_order_falls_back_where_the_packed_values_would_overflow():
    values = np.array([2**61, 0, 2**61, 5, 0, 7, 2**61, 1])
    assert np.array_equal(_arrays.stable_order(values, 2**61 + 1), np.argsort(values, kind="stable"))
