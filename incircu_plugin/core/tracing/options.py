"""What a tracing is asked (:class:`TraceOptions`) and what it did (:class:`TraceStats`).

The options hold one value per chain, so that one tracing serves many features (chains ``2k`` and ``2k + 1``
are feature ``k``). The stats count what the tracing did and carry switches that turn single rules off; tests
read and set them through :func:`observed` instead of replacing the tracer's functions. With the switches at
their defaults, counting changes no computed value.
"""

import contextlib
import contextvars
import math
from dataclasses import dataclass, field

import numpy as np

#: The stats a tracing started in this context reports to (:func:`observed`); None: a tracing keeps its own.
_OBSERVED = contextvars.ContextVar("incircu_trace_stats", default=None)


@dataclass(frozen=True)
class TraceOptions:
    """The options of a tracing, one value per chain (arrays of equal length, even: chains come in pairs).

    Attributes
    ----------
    sides : ndarray of float
        +1 when the region lies left of the chain, -1 when right.
    closed : ndarray of bool
        Whether the chain's pair shares both end points (a split polygon; else two bank lines).
    tolerance : ndarray of float
        Largest distance between a chord of the line and the axis, CRS units.
    width : ndarray of float
        Typical width (a first trial radius follows from it), CRS units.
    max_t, min_t : ndarray of float
        Largest disk parameter searched and smallest contact the solver sees, CRS units.
    """

    sides: np.ndarray
    closed: np.ndarray
    tolerance: np.ndarray
    width: np.ndarray
    max_t: np.ndarray
    min_t: np.ndarray

    @classmethod
    def from_requests(cls, requests):
        """The options of ``requests`` (:class:`.._steps.TraceRequest` objects) traced together, in their order."""
        return cls(
            sides=np.asarray([side for request in requests for side in request.sides], dtype=float),
            **{
                name: np.repeat([getattr(request, name) for request in requests], 2)
                for name in ("closed", "tolerance", "width", "max_t", "min_t")
            },
        )

    @classmethod
    def from_request(cls, request):
        """The options of one :class:`.._steps.TraceRequest` traced alone."""
        return cls.from_requests([request])


@dataclass
class Solution:
    """One call of the contact solver recorded by :class:`TraceStats` (``record_solutions``).

    ``stage`` is ``"initial"`` (the samples before the rounds) or ``"probes"`` (a round's probes); ``chain``
    and ``position`` (arc length along it, CRS units) are those of the samples solved, in the order solved;
    ``length`` and ``u`` are the probes' span lengths and parameters (None for the initial stage); ``corners``
    counts the samples on a convex corner's bisector.
    """

    stage: str
    chain: np.ndarray
    position: np.ndarray
    length: np.ndarray = None
    u: np.ndarray = None
    corners: int = 0


@dataclass
class TraceStats:
    """Counts of what tracings did, and switches of single rules (all on by default: the engine's behaviour).

    Switches: ``predict_approaches`` (:func:`.walks.approaches`), ``cross_split_points``
    (:func:`.events.across_split_points`), ``settle_off_axis`` (:func:`.settling.off_the_axis`),
    ``settle_at_event`` (:func:`.settling.settled_at_event`); off, the intervals they would close are found by
    halving instead. Diagnostics (off by default, they cost time): ``record_solutions`` keeps every solver call
    in ``solutions``; ``check_settled`` probes 15 places inside every interval settled at its event and keeps
    in ``settled_worst`` the largest excess of a probe's centre over the tolerance from the interval's chord
    (CRS units; at most 0 when the settling is right).
    """

    predict_approaches: bool = True
    cross_split_points: bool = True
    settle_off_axis: bool = True
    settle_at_event: bool = True
    record_solutions: bool = False
    check_settled: bool = False
    #: Tracings run, and rounds of probes over all of them.
    tracings: int = 0
    rounds: int = 0
    #: Events computed in closed form for predicted walks, and sites of the walks predicted by approaches.
    predicted_events: int = 0
    approach_sites: int = 0
    #: Samples placed on the bisectors of convex corners.
    corner_samples: int = 0
    #: Intervals closed as off the axis; intervals judged at their event and those settled there.
    off_the_axis: int = 0
    judged_at_event: int = 0
    settled_at_event: int = 0
    #: With ``check_settled``: intervals checked and the worst excess (CRS units).
    settled_checked: int = 0
    settled_worst: float = -math.inf
    solutions: list = field(default_factory=list)


@contextlib.contextmanager
def observed(stats=None):
    """Let every tracing started inside the block report to ``stats`` (a new :class:`TraceStats` when None).

    Sets a context variable for the block only (restored on exit, also on an error); yields the stats.
    """
    stats = TraceStats() if stats is None else stats
    token = _OBSERVED.set(stats)
    try:
        yield stats
    finally:
        _OBSERVED.reset(token)


def current_stats():
    """The stats a tracing started now reports to: those of the enclosing :func:`observed`, else new ones."""
    stats = _OBSERVED.get()
    return TraceStats() if stats is None else stats
