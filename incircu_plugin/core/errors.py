"""Typed errors of the geometry core.

Every error the core raises on bad input is an :class:`IncirCuError`, so a caller can catch one class. The
message is written for the person who owns the data: it says what is wrong and, where it helps, where.
"""


class Cancelled(Exception):
    """Raised when the progress callback asks the engine to stop (not an error of the input)."""


class IncirCuError(ValueError):
    """Base class of every error the IncirCu core raises on bad input."""


class InvalidGeometryError(IncirCuError):
    """The geometry is empty, null, has NaN/inf coordinates or is not a valid polygon."""


class SplitPointError(IncirCuError):
    """The split points are missing, not two, identical, or too far from the polygon's boundary."""


class ChainError(IncirCuError):
    """A boundary chain is too short, crosses itself, or folds back over itself."""


class CrossingLinesError(IncirCuError):
    """In open mode the two lines cross or touch each other."""


class CenterlineError(IncirCuError):
    """The computed centerline would be unusable (it crosses itself), so none is returned."""


class OptionError(IncirCuError):
    """A numeric option (spacing, sample count, tolerance) is not a number, not finite, or out of range."""


def format_point(xy):
    """Return ``"(x, y)"`` with coordinates rounded for a message.

    Parameters
    ----------
    xy : sequence of float
        Coordinates, CRS units.

    Returns
    -------
    str
    """
    return f"({float(xy[0]):.10g}, {float(xy[1]):.10g})"
