"""The private step protocol: centerlines computed as steps, so that many features can share one tracing.

Tracing one small feature costs a few dozen rounds of numpy calls on arrays of a few hundred items: the
calls' overhead, not the arithmetic, sets the time. The public functions' work is therefore written as private
generators (``api._polygon_centerline_steps`` and the others) that do all their per-feature work in Python and
*yield* a :class:`TraceRequest`
where they need the axis points of a pair of chains; the driver sends the :class:`.contacts.AxisPoints`
back, and then a :class:`.lines.LineRequest` to have those points made into its line. :func:`run_alone`
answers each request at once (what a public function given one geometry does); :func:`run_together`
(what it does with an array, :mod:`._many`) advances many generators side by side and answers all their pending
requests with one tracing (:func:`.tracing.trace_together`), and makes all their lines at once
(:func:`.lines.lines_together`), so a layer of small features pays the rounds' overhead once per batch
instead of once per feature. A polygon without split points first yields
an :class:`EndsRequest` (its automatic ends, :func:`.ends.find_ends`); :func:`run_together` answers all
those of a batch at once (:func:`.ends.find_ends_together`) before the tracing.

Both drivers pause Python's cyclic garbage collector and numpy's huge-page advice while they run
(:func:`run_settings_paused`).
"""

import gc
import threading
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cached_property
from typing import Callable

import numpy as np

from .ends import find_ends, find_ends_together
from .errors import Cancelled
from .lines import LineRequest, lines_together
from .tracing import trace_one, trace_together

#: Share of a batch's progress taken by its round of automatic ends (the tracing takes the rest).
ENDS_SHARE = 0.2


@dataclass
class TraceRequest:
    """What one pair of chains asks of the adaptive tracer (see :func:`.tracing.adaptive_axis_points`).

    Attributes
    ----------
    chains : list of two ndarray of shape (n, 2)
        The chains in their local frame, CRS units.
    sides : tuple of two float
        +1 when the region lies left of the chain, -1 when right.
    closed : bool
        Whether the chains share both end points.
    tolerance : float
        Largest chord error of the axis's parabolas, CRS units.
    width, max_t, min_t : float
        First trial radius, largest disk parameter searched, smallest contact, CRS units.
    report : callable
        ``report(fraction)`` for this request alone; raises :class:`Cancelled` to stop.
    rounding : float
        The rounding of the chains' coordinates in the input's frame (:func:`.polyline.coordinate_rounding`),
        CRS units.
    """

    chains: list
    sides: tuple
    closed: bool
    tolerance: float
    width: float
    max_t: float
    min_t: float
    report: Callable[[float], None]
    rounding: float = 0.0

    @property
    def segment_count(self):
        """Number of segments of both chains."""
        return sum(len(chain) - 1 for chain in self.chains)

    @cached_property
    def extent(self):
        """Larger side of the chains' bounding box, CRS units."""
        points = np.concatenate(self.chains)
        return float(np.max(points.max(axis=0) - points.min(axis=0)))


class _RunPause:
    """Who pauses the process-wide settings (:func:`run_settings_paused`): the number of runs under way, and
    the settings before the first."""

    lock = threading.Lock()
    holders = 0
    was_collecting = False
    was_advising = False


def _huge_page_advice_setter():
    """numpy's switch of its huge-page advice (``_set_madvise_hugepage``: sets it, returns the previous
    state), or None when this numpy has none."""
    try:
        from numpy._core.multiarray import _set_madvise_hugepage
    except ImportError:
        # numpy before 1.26 has no ``numpy._core``.
        try:
            from numpy.core.multiarray import _set_madvise_hugepage
        except ImportError:
            return None
    return _set_madvise_hugepage


@contextmanager
def run_settings_paused():
    """Pause Python's cyclic garbage collector and numpy's huge-page advice for the duration, then restore
    both as they were. Neither changes a computed value.

    The collector: the tracer creates and drops millions of short-lived objects; every few hundred of them set
    off a collection, and now and then a full one walks every live object of the process. In a large host
    such as QGIS (hundreds of thousands of objects) that made a layer about 10% slower. A run creates no
    reference cycles worth collecting meanwhile.

    The advice: numpy asks the kernel to back every array of 4 MiB or more with transparent huge pages; where
    the kernel then compacts memory to find them on first touch (Debian's default ``defrag=madvise``), a run's
    large arrays cost up to a second of system time at 10**6 boundary vertices, varying from run to run (0.4
    to 1.6 s); without the advice about 0.65 s, every run.

    Runs in several threads share one pause: both settings return when the last of them ends.
    """
    setter = _huge_page_advice_setter()
    with _RunPause.lock:
        if _RunPause.holders == 0:
            _RunPause.was_collecting = gc.isenabled()
            gc.disable()
            _RunPause.was_advising = setter(False) if setter is not None else False
        _RunPause.holders += 1
    try:
        yield
    finally:
        with _RunPause.lock:
            _RunPause.holders -= 1
            if _RunPause.holders == 0:
                if _RunPause.was_collecting:
                    gc.enable()
                if setter is not None:
                    setter(_RunPause.was_advising)


@dataclass
class EndsRequest:
    """What a polygon without split points asks of the automatic ends (see :func:`.ends.find_ends`).

    Attributes
    ----------
    polygon : Polygon
        CRS units.
    rule : {"main_stem", "longest_path"}
    guide : LineString or MultiLineString or None
        CRS units.
    progress : callable or None
        ``progress(fraction)`` for this request alone; returning False stops with :class:`Cancelled`.
    """

    polygon: object
    rule: str
    guide: object
    progress: Callable[[float], object] = None


#: The order in which :func:`run_together` answers the kinds of request pending together.
_ORDER = (EndsRequest, TraceRequest, LineRequest)


def answer_alone(request):
    """The answer to one request: the :class:`.ends.EndsResult` of an :class:`EndsRequest`, the line of a
    :class:`.lines.LineRequest`, else the axis points of a :class:`TraceRequest`."""
    if isinstance(request, EndsRequest):
        return find_ends(request.polygon, rule=request.rule, guide=request.guide, progress=request.progress)
    if isinstance(request, LineRequest):
        line = lines_together([request])[0]
        if isinstance(line, Exception):
            raise line
        return line
    return trace_alone(request)


def trace_alone(request):
    """The axis points of one request (:class:`.contacts.AxisPoints`), reporting to its own ``report``."""
    return trace_one(request, request.report)


def run_alone(steps):
    """Drive one step generator to its end, tracing each of its requests alone; returns its value.

    A request that fails (a tracing, or automatic ends) raises its exception inside the generator, at the
    request, as :func:`run_together` does (a multipart feature then loses that part only).
    """
    with run_settings_paused():
        try:
            request = next(steps)
            while True:
                try:
                    points = answer_alone(request)
                except Cancelled:
                    raise
                except Exception as error:  # noqa: BLE001 - the generator decides what a failed tracing means
                    request = steps.throw(error)
                    continue
                request = steps.send(points)
        except StopIteration as stop:
            return stop.value


def run_together(step_generators, progress=None):
    """Drive many step generators side by side, tracing their pending requests together.

    Parameters
    ----------
    step_generators : iterable of generator
        Each yields :class:`EndsRequest` and :class:`TraceRequest` objects, receives their answers (ends,
        axis points) and returns its result. All pending ends requests are answered first, together
        (:func:`.ends.find_ends_together`), so the generators' tracing requests that follow are traced
        together too.
    progress : callable, optional
        Called with the fraction done (0 to 1); when it returns False, :class:`Cancelled` is raised.

    Returns
    -------
    list
        Per generator, in order: its return value, or the exception (an ``Exception`` instance, without
        traceback) it raised.

    Raises
    ------
    Cancelled
        If ``progress`` returned False.
    """
    with run_settings_paused():
        return _run_together(list(step_generators), progress)


def _run_together(generators, progress):
    """:func:`run_together` on a list of generators."""
    outcomes = [None] * len(generators)
    pending = {}
    for index, steps in enumerate(generators):
        _advance(steps, index, lambda s: next(s), pending, outcomes)
    report = reporter(progress)
    done, traced = 0.0, False
    while pending:
        # Ends before tracings (so the tracings that follow go together), tracings before lines.
        kind = next(kind for kind in _ORDER if any(isinstance(request, kind) for request in pending.values()))
        indices = [index for index, request in pending.items() if isinstance(request, kind)]
        requests = [pending.pop(index) for index in indices]
        # The ends take ENDS_SHARE of what is left; the first round of tracing 0.9, each later round (a
        # multipart feature asks once per part) half of what is left; lines take no share.
        share = {EndsRequest: ENDS_SHARE, TraceRequest: 0.5 if traced else 0.9}.get(kind, 0.0) * (1.0 - done)
        traced = traced or kind is TraceRequest
        answer = {EndsRequest: _found_ends, TraceRequest: _traced, LineRequest: _lines}[kind]
        answers = answer(requests, lambda fraction, begin=done, width=share: report(begin + width * fraction))
        done += share
        for index, value in zip(indices, answers):
            steps = generators[index]
            if isinstance(value, Exception):
                _advance(steps, index, lambda s, e=value: s.throw(e), pending, outcomes)
            else:
                _advance(steps, index, lambda s, v=value: s.send(v), pending, outcomes)
    report(1.0)
    return outcomes


def _advance(steps, index, step, pending, outcomes):
    """Run ``step(steps)``; file its next request in ``pending`` or its end in ``outcomes``."""
    try:
        pending[index] = step(steps)
    except StopIteration as stop:
        outcomes[index] = stop.value
    except Cancelled:
        raise
    except Exception as error:  # noqa: BLE001 - one feature's failure is its outcome, not the batch's
        error.__traceback__ = None
        outcomes[index] = error


def _found_ends(requests, report):
    """The ends of every :class:`EndsRequest` (or the exception :func:`.ends.find_ends` raises for it), found
    together per rule; each request's own ``progress`` is told when its ends are known (it may cancel)."""
    answers = [None] * len(requests)
    rules = sorted({request.rule for request in requests})
    for number, rule in enumerate(rules):
        positions = [position for position, request in enumerate(requests) if request.rule == rule]
        found = find_ends_together(
            [requests[position].polygon for position in positions],
            rule=rule,
            guides=[requests[position].guide for position in positions],
            progress=lambda fraction, begin=number: report((begin + fraction) / len(rules)),
        )
        for position, value in zip(positions, found):
            answers[position] = value
    for request in requests:
        if request.progress is not None and request.progress(1.0) is False:
            raise Cancelled()
    return answers


def _traced(requests, report):
    """Axis points of every request, traced together; per request alone when the joint tracing fails
    (then a request whose own tracing fails gets its exception instead)."""
    return _together_else_alone(requests, lambda together: trace_together(together, report), trace_alone)


def _lines(requests, report):
    """The line of every :class:`.lines.LineRequest` (or the exception it raised), made together; each request
    alone when that fails unexpectedly."""
    return _together_else_alone(requests, lines_together, lambda request: lines_together([request])[0])


def _together_else_alone(requests, together, alone):
    """``together(requests)``; when it fails (unless cancelled), ``alone(request)`` for each request, or the
    exception that raised, so one failing request does not take the others with it."""
    try:
        return together(requests)
    except Cancelled:
        raise
    except Exception:  # noqa: BLE001 - find which request fails, and let the others through
        results = []
        for request in requests:
            try:
                results.append(alone(request))
            except Cancelled:
                raise
            except Exception as error:  # noqa: BLE001
                results.append(error)
        return results


def reporter(progress):
    """``report(fraction)`` calling ``progress`` and raising :class:`Cancelled` when it returns False."""

    def report(fraction):
        if progress is not None and progress(min(max(float(fraction), 0.0), 1.0)) is False:
            raise Cancelled()

    return report
