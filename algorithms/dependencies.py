"""Import of the geometry core, with an actionable message when Shapely 2 is missing or too old.

Shapely is judged by what it can do, not by the version it reports: a distribution's build may report
``0+unknown`` (Debian's ``python3-shapely`` 2.2 does) and still be Shapely 2.
"""

import importlib
import os
import sys
import sysconfig

from qgis.core import QgsProcessingException
from qgis.PyQt.QtCore import QCoreApplication

#: Module-level functions of Shapely 2 the core calls (its vectorised API; Shapely 1.8 has none of them).
#: ``tests/test_plugin_dependencies.py`` keeps this list in step with the core's sources.
SHAPELY2_API = (
    "Geometry",
    "LinearRing",
    "MultiLineString",
    "MultiPolygon",
    "Point",
    "Polygon",
    "STRtree",
    "area",
    "boundary",
    "bounds",
    "box",
    "buffer",
    "centroid",
    "clip_by_rect",
    "contains",
    "contains_xy",
    "covers",
    "delaunay_triangles",
    "difference",
    "distance",
    "dwithin",
    "force_2d",
    "from_wkb",
    "get_coordinates",
    "get_exterior_ring",
    "get_num_coordinates",
    "get_num_geometries",
    "get_parts",
    "get_rings",
    "get_type_id",
    "intersection",
    "intersects",
    "intersects_xy",
    "is_empty",
    "is_missing",
    "is_simple",
    "is_valid",
    "is_valid_reason",
    "length",
    "line_interpolate_point",
    "line_locate_point",
    "line_merge",
    "linearrings",
    "linestrings",
    "points",
    "polygons",
    "prepare",
    "remove_repeated_points",
    "segmentize",
    "shortest_line",
    "simplify",
    "to_wkb",
    "transform",
    "union_all",
)

#: Distributions whose own ``python3-shapely`` package is Shapely 2: ``ID`` of ``/etc/os-release`` and the first
#: such release (``VERSION_ID``); a Debian without ``VERSION_ID`` is testing or unstable.
DISTRIBUTION_SHAPELY2 = {"debian": (13,), "ubuntu": (24, 4)}


def missing_shapely2_api(shapely):
    """Return the names of :data:`SHAPELY2_API` the imported module ``shapely`` lacks (empty for Shapely 2)."""
    return [name for name in SHAPELY2_API if not hasattr(shapely, name)]


def os_release(path="/etc/os-release"):
    """Return the ``KEY=value`` pairs of an ``os-release`` file as a dict (empty when it cannot be read)."""
    fields = {}
    try:
        with open(path, encoding="utf-8") as lines:
            for line in lines:
                key, equals, value = line.strip().partition("=")
                if equals:
                    fields[key] = value.strip("\"'")
    except OSError:
        return {}
    return fields


def release_numbers(version_id):
    """Return the numbers of an ``os-release`` ``VERSION_ID`` (``"24.04"`` -> ``(24, 4)``), ``()`` when absent."""
    numbers = []
    for piece in version_id.split("."):
        if not piece.isdigit():
            break
        numbers.append(int(piece))
    return tuple(numbers)


def install_hint(platform=None, release=None, externally_managed=None):
    """Say how to install Shapely 2 for the Python QGIS runs, with a command that works on this system.

    Parameters
    ----------
    platform : str, optional
        ``sys.platform``; the running one when ``None``.
    release : dict, optional
        The fields of ``/etc/os-release`` (Linux only); read when ``None``.
    externally_managed : bool, optional
        Whether pip refuses to install next to the distribution's packages (PEP 668) unless told
        ``--break-system-packages``; found from the running Python when ``None``.

    Returns
    -------
    str
        One or two sentences with the command(s) to run.
    """
    platform = sys.platform if platform is None else platform
    if not platform.startswith("linux"):
        return (
            "Install it into the Python that QGIS runs, then restart QGIS: in the OSGeo4W Shell (Windows) or a "
            "terminal (macOS), 'python -m pip install \"shapely>=2\"'."
        )
    release = os_release() if release is None else release
    if externally_managed is None:
        externally_managed = os.path.exists(os.path.join(sysconfig.get_path("stdlib"), "EXTERNALLY-MANAGED"))
    distribution = release.get("ID", "")
    first = DISTRIBUTION_SHAPELY2.get(distribution)
    numbers = release_numbers(release.get("VERSION_ID", ""))
    if first is not None and (numbers >= first or (distribution == "debian" and not numbers)):
        return "Install your distribution's Shapely 2, then restart QGIS: 'sudo apt install python3-shapely'."
    override = " --break-system-packages" if externally_managed else ""
    return (
        "Build Shapely on the system's GEOS library, the one QGIS uses (a wheel bundling its own GEOS crashes "
        "QGIS), then restart QGIS: 'sudo apt install libgeos-dev python3-dev python3-pip build-essential' then "
        f"'python3 -m pip install --user{override} --no-binary shapely \"shapely>=2\"'."
    )


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
            + install_hint()
        )
    if missing_shapely2_api(shapely):
        return (
            QCoreApplication.translate(
                "IncirCuAlgorithm", "IncirCu needs Shapely 2.0 or newer, but Shapely {} is installed."
            ).format(getattr(shapely, "__version__", "?"))
            + " "
            + install_hint()
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
        When Shapely is missing or lacks Shapely 2's API (message says what to install and how).
    """
    problem = shapely_problem()
    if problem is not None:
        raise QgsProcessingException(problem)
    return importlib.import_module("..incircu_plugin.core", __package__)
