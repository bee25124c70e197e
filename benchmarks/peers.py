"""Adapters that run IncirCu and every peer centerline tool on one shapely polygon.

Each runner takes a :class:`Case` and returns a shapely geometry made of lines (LineString,
MultiLineString or a collection of them), in the case's units. Everything a user would have to do to
go from a shapely polygon to the tool's lines is inside the runner, so the wall time covers it.

Tools whose parameters are lengths in CRS units (label_centerlines, centerline, GRASS) get them from
the same rule: a tenth of the polygon's mean width ``2 * area / perimeter``. pygeoops' defaults are
already relative to the width; SFCGAL has no parameter.
"""

import inspect
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Point, Polygon

REPO_ROOT = Path(__file__).resolve().parent.parent
if str(REPO_ROOT) not in sys.path:
    sys.path.insert(0, str(REPO_ROOT))

QGIS_PROCESS = shutil.which("qgis_process.bin") or "/usr/bin/qgis_process.bin"


@dataclass
class Case:
    """One benchmark input.

    Attributes
    ----------
    name : str
        Label in the tables.
    polygon : shapely.geometry.Polygon
        The region, in its own units (metres for real outlines, shape units for analytic cases).
    ends : tuple of shapely.geometry.Point
        The two boundary points where the centerline must start and end.
    width : float
        Typical width of the region (same units); deviations are reported as a fraction of it.
    axis_distance : callable or None
        ``axis_distance(points)`` -> distance (same units) from each point of an (n, 2) array to the
        reference axis: the exact analytic axis, or the medial-axis target set of the oracle.
    axis_kind : str
        ``"exact"`` (analytic), ``"oracle"`` (segment Voronoi target set) or ``"none"``.
    spacing : float or None
        IncirCu sample spacing (same units); None for the core's default.
    extra : dict
        Free-form flags (``keep_geometry``: send the tools' outputs back for plotting).
    """

    name: str
    polygon: Polygon
    ends: Sequence[Point]
    width: float
    axis_distance: Optional[Callable] = None
    axis_kind: str = "none"
    spacing: Optional[float] = None
    extra: dict = field(default_factory=dict)

    @property
    def vertex_count(self):
        """Number of distinct boundary vertices of the polygon (exterior and holes)."""
        return int(shapely.get_num_coordinates(self.polygon.boundary)) - 1 - len(self.polygon.interiors)


def mean_width(polygon):
    """Mean width of an elongated polygon, ``2 * area / perimeter`` (polygon units)."""
    return 2.0 * polygon.area / polygon.length


def core_accepts(keyword):
    """Whether ``polygon_centerline`` of the checked-out core takes ``keyword`` (``tolerance`` after issue 9)."""
    from incircu_plugin.core import polygon_centerline

    return keyword in inspect.signature(polygon_centerline).parameters


def incircu_options(case, tolerance=None):
    """Keyword arguments of the core for ``case``: its spacing, and ``tolerance`` (CRS units) when the core has
    that keyword (before issue 9's engine it has not, and the call runs at the default)."""
    options = {"spacing": case.spacing}
    if tolerance is not None and core_accepts("tolerance"):
        options["tolerance"] = tolerance
    return options


def run_incircu(case):
    """IncirCu through the geometry core, split at the case's two ends (spacing: core default)."""
    from incircu_plugin.core import polygon_centerline

    result = polygon_centerline(case.polygon, [case.ends[0], case.ends[1]], **incircu_options(case))
    return result.line


#: Tolerance of the fine IncirCu row of the layer benchmark, × the case width.
FINE_TOLERANCE = 1e-3


def run_incircu_fine(case):
    """IncirCu through the geometry core at ``tolerance`` = ``FINE_TOLERANCE`` × width (when the core has it)."""
    from incircu_plugin.core import polygon_centerline

    options = incircu_options(case, tolerance=FINE_TOLERANCE * case.width)
    return polygon_centerline(case.polygon, [case.ends[0], case.ends[1]], **options).line


def run_incircu_automatic_ends(case):
    """IncirCu through the geometry core, ends found by the core (no split points)."""
    from incircu_plugin.core import polygon_centerline

    return polygon_centerline(case.polygon, **incircu_options(case)).line


def run_incircu_together(cases):
    """IncirCu through the geometry core, the whole layer in one call (``polygon_centerline`` of the array of
    polygons, computed in batches traced together, as the plugin runs a layer): one line or exception per case."""
    from incircu_plugin.core import polygon_centerline

    options = [incircu_options(case) for case in cases]
    columns = {
        name: [option.get(name) for option in options] for name in {name for option in options for name in option}
    }
    outcomes = polygon_centerline(
        [case.polygon for case in cases], [[case.ends[0], case.ends[1]] for case in cases], **columns
    )
    return [outcome if isinstance(outcome, Exception) else outcome.line for outcome in outcomes]


def run_pygeoops(case):
    """pygeoops ``centerline(extend=True)``, width-relative defaults otherwise."""
    import pygeoops

    return pygeoops.centerline(case.polygon, extend=True)


def run_label_centerlines(case):
    """label_centerlines ``get_centerline``; segmentize at width/10, simplify at width/100."""
    from label_centerlines import get_centerline

    width = mean_width(case.polygon)
    return get_centerline(case.polygon, segmentize_maxlen=width / 10.0, simplification=width / 100.0)


def run_centerline(case):
    """centerline ``Centerline`` with ``interpolation_distance`` = width/10."""
    from centerline.geometry import Centerline

    return Centerline(case.polygon, interpolation_distance=mean_width(case.polygon) / 10.0).geometry


def _to_sfcgal(polygon):
    from pysfcgal import geometry as sfcgal_geometry

    return sfcgal_geometry.Geometry.from_wkb(shapely.to_wkb(polygon))


def _from_sfcgal(geometry):
    return shapely.from_wkb(bytes(geometry.to_wkb()))


def run_sfcgal_medial_axis(case):
    """SFCGAL (CGAL) approximate medial axis through pysfcgal."""
    return _from_sfcgal(_to_sfcgal(case.polygon).approximate_medial_axis())


def run_sfcgal_straight_skeleton(case):
    """SFCGAL (CGAL) straight skeleton through pysfcgal."""
    return _from_sfcgal(_to_sfcgal(case.polygon).straight_skeleton())


class QgisProcess:
    """``qgis_process.bin`` in an isolated profile, offscreen, with IncirCu (this checkout) on its plugin path and
    Shapely for QGIS's Python (``.venv/qgis-site``, built by ``make setup``) on its ``PYTHONPATH``."""

    def __init__(self, work_dir, plugins=()):
        self.work_dir = Path(work_dir)
        config_dir = self.work_dir / "qgis-profile"
        plugin_dir = self.work_dir / "plugins"
        config_dir.mkdir(parents=True, exist_ok=True)
        plugin_dir.mkdir(exist_ok=True)
        if not (plugin_dir / "incircu").exists():
            (plugin_dir / "incircu").symlink_to(REPO_ROOT, target_is_directory=True)
        self.env = dict(
            os.environ,
            QT_QPA_PLATFORM="offscreen",
            QGIS_CUSTOM_CONFIG_PATH=str(config_dir),
            QGIS_PLUGINPATH=str(plugin_dir),
            PYTHONPATH=str(REPO_ROOT / ".venv" / "qgis-site"),
        )
        for plugin in plugins:
            self.call(["plugins", "enable", plugin])

    def call(self, arguments, timeout=900):
        """Run ``qgis_process.bin *arguments``; its stdout, or RuntimeError with its stderr when it fails.

        Past ``timeout`` seconds the call and everything it started (GRASS) are killed and
        ``subprocess.TimeoutExpired`` is raised.
        """
        process = subprocess.Popen(
            [QGIS_PROCESS, *arguments],
            env=self.env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            start_new_session=True,
        )
        try:
            stdout, stderr = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            raise
        if process.returncode != 0:
            raise RuntimeError(f"qgis_process {' '.join(arguments[:2])} failed: {stderr[-2000:]}")
        return stdout


class GrassRunner:
    """GRASS ``v.voronoi.skeleton -s thin=-1`` through ``qgis_process`` (provider grass7, QGIS 3.22).

    The input layer is written once per case (outside the timed call); each timed call is one
    ``qgis_process.bin run`` as a QGIS user would launch it, so it includes QGIS's start-up, which
    :meth:`startup` measures alone (a ``help`` call loads the providers as ``run`` does).
    """

    def __init__(self, work_dir):
        self.work_dir = Path(work_dir)
        self._call = QgisProcess(self.work_dir, plugins=["grassprovider"]).call
        self._written = {}

    def startup(self):
        """One provider-loading ``qgis_process`` call that runs no algorithm (for the start-up cost)."""
        self._call(["help", "grass7:v.voronoi.skeleton"])

    def _input_path(self, case):
        key = id(case.polygon)
        if key not in self._written:
            path = self.work_dir / f"input-{len(self._written)}.geojson"
            feature = {"type": "Feature", "properties": {"id": 1}, "geometry": shapely.geometry.mapping(case.polygon)}
            collection = {
                "type": "FeatureCollection",
                "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::3857"}},
                "features": [feature],
            }
            path.write_text(json.dumps(collection))
            self._written[key] = path
        return self._written[key]

    def __call__(self, case):
        """Run the GRASS skeleton on ``case`` and return its lines (smoothness = width/10)."""
        input_path = self._input_path(case)
        with tempfile.TemporaryDirectory(dir=self.work_dir) as out_dir:
            output_path = Path(out_dir) / "skeleton.geojson"
            self._call(
                [
                    "run",
                    "grass7:v.voronoi.skeleton",
                    "--",
                    f"input={input_path}",
                    f"smoothness={mean_width(case.polygon) / 10.0!r}",
                    "thin=-1",
                    "-s=true",
                    f"output={output_path}",
                ]
            )
            features = json.loads(output_path.read_text())["features"]
        return shapely.GeometryCollection([shapely.geometry.shape(feature["geometry"]) for feature in features])


@dataclass
class Tool:
    """A named runner with the shape of its output."""

    name: str
    run: Callable
    single_line: bool
    note: str = ""
    #: Runs another program (qgis_process): no memory cap on the child, which that program would inherit.
    external: bool = False
    #: ``run_all(cases)`` -> one geometry (or exception) per case: the whole layer in one call, as a batch.
    run_all: Optional[Callable] = None


def peer_tools(grass_runner=None):
    """The peers, fastest-to-set-up first; GRASS only when a runner is given."""
    tools = [
        Tool("pygeoops", run_pygeoops, True, "centerline(extend=True)"),
        Tool("label_centerlines", run_label_centerlines, True, "get_centerline, numpy<2 venv"),
        Tool("centerline", run_centerline, False, "Centerline(interpolation_distance=w/10)"),
        Tool("SFCGAL medial axis", run_sfcgal_medial_axis, False, "approximate_medial_axis"),
        Tool("SFCGAL straight skeleton", run_sfcgal_straight_skeleton, False, "straight_skeleton"),
    ]
    if grass_runner is not None:
        tools.append(Tool("GRASS v.voronoi.skeleton", grass_runner, True, "-s thin=-1 via qgis_process", external=True))
    return tools


INCIRCU = Tool("IncirCu", run_incircu, True, "polygon_centerline, default spacing")


def line_parts(geometry):
    """All non-empty LineStrings inside ``geometry`` (points and polygons dropped)."""
    if geometry is None:
        return []
    parts = shapely.get_parts(shapely.get_parts(shapely.get_parts(np.asarray([geometry], dtype=object))))
    return [part for part in parts if isinstance(part, LineString) and not part.is_empty]


def as_lines(geometry):
    """``geometry`` as one MultiLineString (possibly empty)."""
    return shapely.MultiLineString(line_parts(geometry))
