"""Import of the geometry core, with an actionable message when Shapely 2 is missing or too old."""

import importlib
import re

from qgis.core import QgsProcessingException
from qgis.PyQt.QtCore import QCoreApplication

#: Oldest Shapely release the core works with.
MINIMUM_SHAPELY = (2, 0)

INSTALL_HINT = (
    "Install it into the Python that QGIS runs, then restart QGIS. Windows (OSGeo4W shell) or macOS: "
    "'python -m pip install \"shapely>=2\"'. Debian/Ubuntu (Shapely must use the system GEOS that QGIS uses): "
    "'sudo apt install libgeos-dev python3-dev build-essential' then "
    "'python3 -m pip install --user --break-system-packages --no-binary shapely \"shapely>=2\"'."
)


def version_tuple(version):
    """Return the release numbers at the start of a version string, e.g. ``"2.0.1"`` -> ``(2, 0, 1)``.

    Reading stops at a part that does not start with a digit, and after the leading digits of a part with a
    suffix, so a pre-release keeps the numbers of its release: ``"2.0rc1"`` -> ``(2, 0)``, ``"2.1b2"`` ->
    ``(2, 1)``, ``"2.0.post1"`` -> ``(2, 0)``.
    """
    parts = []
    for piece in str(version).split("."):
        digits = re.match(r"[0-9]+", piece)
        if digits is None:
            break
        parts.append(int(digits.group()))
        if digits.end() != len(piece):
            break
    return tuple(parts)


def shapely_problem():
    """Say what is wrong with the installed Shapely, or ``None`` when it is usable.

    Returns
    -------
    str or None
        A user-facing message naming the installed version and how to install Shapely 2.
    """
    try:
        shapely = importlib.import_module("shapely")
    except ImportError:
        return (
            QCoreApplication.translate(
                "IncirCuAlgorithm", "IncirCu needs the Python package Shapely 2, which is not installed."
            )
            + " "
            + INSTALL_HINT
        )
    version = getattr(shapely, "__version__", "0")
    if version_tuple(version) < MINIMUM_SHAPELY:
        return (
            QCoreApplication.translate(
                "IncirCuAlgorithm", "IncirCu needs Shapely 2.0 or newer, but Shapely {} is installed."
            ).format(version)
            + " "
            + INSTALL_HINT
        )
    return None


def require_core():
    """Import and return the geometry core package.

    Returns
    -------
    module
        ``incircu_plugin.core`` of this plugin.

    Raises
    ------
    QgsProcessingException
        When Shapely is missing or older than 2.0 (message says what to install and how).
    """
    problem = shapely_problem()
    if problem is not None:
        raise QgsProcessingException(problem)
    return importlib.import_module("..incircu_plugin.core", __package__)
