"""Error-bounded adaptive tracing of the medial axis between pairs of chains (the engine's default).

Along the first chain of each pair the point where a maximal disk touches it moves over *spans* (edges and
reflex vertices' fans); between two samples whose first contacts are different sites the *event* where both
are equally far is computed in closed form and probed with the exact contact solver, round after round, until
every interval between neighbouring samples touches one site; a parabola then gets stations whose chords stay
within the tolerance. Every vertex is exactly on the medial axis. docs/tracing.md gives the arguments and the
module map: :mod:`.spans`, :mod:`.sites`, :mod:`.closed_form`, :mod:`.intervals`, :mod:`.samples`,
:mod:`.probes`, :mod:`.initial`, :mod:`.events`, :mod:`.walks`, :mod:`.settling`, :mod:`.tracer`,
:mod:`.joint`; :mod:`.options` holds the options and the stats tests observe.
"""

from .joint import JOINT_BATCH_RATIO, JOINT_CELL, JOINT_EXTENT_RATIO, JOINT_SEGMENTS, trace_together
from .options import TraceOptions, TraceStats, observed
from .settling import SETTLED_CHORD
from .spans import EDGE, FAN
from .tracer import Tracer, adaptive_axis_points, trace_one

__all__ = [
    "EDGE",
    "FAN",
    "JOINT_BATCH_RATIO",
    "JOINT_CELL",
    "JOINT_EXTENT_RATIO",
    "JOINT_SEGMENTS",
    "SETTLED_CHORD",
    "TraceOptions",
    "TraceStats",
    "Tracer",
    "adaptive_axis_points",
    "observed",
    "trace_one",
    "trace_together",
]
