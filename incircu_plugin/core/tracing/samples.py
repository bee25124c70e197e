"""The solved samples of one tracing, stored as growing columns, and the axis points made of them."""

import numpy as np

from .._arrays import rows
from ..contacts import CHUNK, AxisPoints

#: Types of the per-sample columns (indices fit int32, see :class:`.contacts.Boundary`).
STORE_TYPES = {"span": np.int32, "u": float, "t": float, "centre": float, "emit": bool, "other_site": np.int32}


class SampleStore:
    """Every solved sample of a tracing: its span and parameter, first-contact parameter ``t``, disk centre,
    whether it is emitted as an axis point and the site of its foot on the other chain.

    A sample's point and direction follow from its span and parameter (:meth:`.spans.Spans.points`,
    :meth:`.spans.Spans.directions`), so they are not stored.
    """

    def __init__(self):
        self.count = 0
        self.store = {}

    def add(self, span, u, t, centre, emit, other_site):
        """Append solved samples (at parameters ``u`` of spans ``span``, disk centres ``centre``); returns
        their indices. ``other_site`` gives the foot on the other chain.

        The arrays grow by half, so a round costs its own samples only.
        """
        if len(t) == 0 and self.store:
            return np.arange(self.count, self.count)
        columns = {"span": span, "u": u, "t": t, "centre": centre, "emit": emit, "other_site": other_site}
        start, self.count = self.count, self.count + len(t)
        for name, values in columns.items():
            stored = self.store.get(name)
            if stored is None or len(stored) < self.count:
                size = max(self.count + self.count // 2, 64)
                grown = np.empty((size,) + values.shape[1:], dtype=STORE_TYPES[name])
                if stored is not None:
                    grown[:start] = stored[:start]
                self.store[name] = stored = grown
            stored[start : self.count] = values
        return np.arange(start, self.count)

    @property
    def t(self):
        """First-contact parameter of every sample so far (a view)."""
        return self.store["t"][: self.count]

    @property
    def emit(self):
        """Whether each sample so far is an axis point (a view: writable)."""
        return self.store["emit"][: self.count]

    @property
    def other_site(self):
        """The site of each sample's foot on the other chain (a view: writable)."""
        return self.store["other_site"][: self.count]

    def centres(self, index):
        """Centres of the disks of samples ``index``."""
        return rows(self.store["centre"], index)

    def axis_points(self, spans, sites):
        """The emitted samples as :class:`.contacts.AxisPoints`, and the chain each was sampled on (the first
        chain of its pair, so its foot is ``foot_a``). Empties the store; works ``CHUNK`` points at a time, so
        that only the output is held in full."""
        store, self.store = self.store, {}
        index = np.flatnonzero(store["emit"][: self.count] & np.isfinite(store["t"][: self.count]))
        span, u, t, centre, other_site = (
            rows(store[name], index) for name in ("span", "u", "t", "centre", "other_site")
        )
        del store, index
        foot_a, foot_b = np.empty((len(t), 2)), np.empty((len(t), 2))
        position_a, position_b = np.empty(len(t)), np.empty(len(t))
        for begin in range(0, len(t), CHUNK):
            part = slice(begin, begin + CHUNK)
            foot_a[part], along = spans.points(span[part], u[part])
            position_a[part] = spans.position[span[part]] + along
            foot_b[part], position_b[part] = sites.feet(other_site[part], centre[part])
        return AxisPoints(centre, t, foot_a, foot_b, position_a, position_b), spans.chain[span]
