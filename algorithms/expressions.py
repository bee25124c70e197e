"""QGIS expression functions ``incircu_centerline`` and ``incircu_label_line``, for geometry generators and labels.

The plugin registers them when it starts and removes them when it is unloaded (:func:`register_functions`,
:func:`unregister_functions`). Each result is cached per geometry, layer CRS and options (a digest of the
geometry's WKB as key, at most :data:`CACHE_ENTRIES` entries, least recently used dropped first), so panning
and zooming a map, which evaluates the expressions for every feature drawn, computes each feature once.
"""

import hashlib
import threading
from collections import OrderedDict

from qgis.core import (
    Qgis,
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsCoordinateTransformContext,
    QgsEllipsoidUtils,
    QgsExpression,
    QgsExpressionFunction,
    QgsGeometry,
)
from qgis.PyQt.QtCore import QCoreApplication

from .compat import GeometryType
from .dependencies import require_core
from .messages import core_text

#: The group of the expression builder the functions are listed in.
GROUP = "IncirCu"

#: Most results kept (each a line of a few hundred vertices at most: some tens of megabytes when full).
CACHE_ENTRIES = 100_000

#: Most argument tuples whose converted options a function remembers (a style uses a few; data-defined options
#: one per distinct value): the memory is cleared when full.
CONVERTED_ENTRIES = 1_000

#: Names of the functions, registered by :func:`register_functions`.
CENTERLINE_FUNCTION = "incircu_centerline"
LABEL_LINE_FUNCTION = "incircu_label_line"

#: The functions registered by this module, kept until unregistered (QGIS holds no Python reference).
REGISTERED = []


class ResultCache:
    """A bounded, thread-safe least-recently-used map (map rendering evaluates expressions in threads)."""

    def __init__(self, size=CACHE_ENTRIES):
        self.size = size
        self.entries = OrderedDict()
        self.lock = threading.Lock()
        self.hits = 0
        self.misses = 0

    def get(self, key):
        """Return ``(True, value)`` for a cached key (marked as recently used), else ``(False, None)``."""
        with self.lock:
            if key in self.entries:
                self.entries.move_to_end(key)
                self.hits += 1
                return True, self.entries[key]
            self.misses += 1
            return False, None

    def put(self, key, value):
        """Store ``value``, dropping the least recently used entry when full."""
        with self.lock:
            self.entries[key] = value
            self.entries.move_to_end(key)
            while len(self.entries) > self.size:
                self.entries.popitem(last=False)

    def clear(self):
        """Forget every result."""
        with self.lock:
            self.entries.clear()
            self.hits = self.misses = 0


CACHE = ResultCache()


def geometry_key(geometry):
    """A 16-byte digest of a geometry's WKB (the cache key's geometry part)."""
    return hashlib.blake2b(bytes(geometry.asWkb()), digest_size=16).digest()


def layer_crs(context):
    """The CRS of the layer an expression is evaluated for, from its context (invalid when unknown)."""
    if context is None:
        return QgsCoordinateReferenceSystem()
    crs = context.variable("_layer_crs")
    if isinstance(crs, QgsCoordinateReferenceSystem):
        return crs
    return QgsCoordinateReferenceSystem(str(context.variable("layer_crs") or ""))


def compute_label(geometry, crs, options):
    """The label line (or point) of a polygon's largest labelled part, in the layer's CRS.

    Parameters
    ----------
    geometry : QgsGeometry
        A polygon or multipolygon in the layer's CRS.
    crs : QgsCoordinateReferenceSystem
        The layer's CRS (in degrees: computed in a local projection, the options' lengths in metres).
    options : dict
        The core's ``label_lines`` keywords.

    Returns
    -------
    QgsGeometry or None
    """
    core = require_core()
    frame = ThreadFrame(geometry, crs)
    shape = frame.to_core(geometry)
    label = core.feature_label(core.label_lines(shape, **options), shape)
    return None if label is None else frame.to_layer(label.geometry)


def compute_centerline(geometry, crs, options):
    """The centerline of every part of a polygon (a MultiLineString), in the layer's CRS; None when none has one.

    Parameters
    ----------
    geometry : QgsGeometry
    crs : QgsCoordinateReferenceSystem
    options : dict
        The core's ``multipolygon_centerlines`` keywords.
    """
    import shapely  # after require_core

    core = require_core()
    frame = ThreadFrame(geometry, crs)
    outcomes = core.multipolygon_centerlines(frame.to_core(geometry), **options)
    lines = [outcome.result.line for outcome in outcomes if outcome.result is not None]
    return frame.to_layer(shapely.MultiLineString(lines)) if lines else None


class ThreadFrame:
    """The working frame of one geometry, as ``convert.WorkingFrame`` with the core's ``LocalProjection``, but
    projecting with QGIS's own transformations: map rendering evaluates expressions in worker threads, where
    pyproj (whose PROJ shares the process with QGIS's) is not safe to call.

    Parameters
    ----------
    geometry : QgsGeometry
        In the layer's CRS.
    crs : QgsCoordinateReferenceSystem
        The layer's CRS; in degrees, the frame is the azimuthal equidistant projection on its ellipsoid centred
        where ``LocalProjection.around`` centres it.
    """

    def __init__(self, geometry, crs):
        self.transform = None
        if crs.isValid() and crs.isGeographic():
            from ..incircu_plugin.core.geodesy import central_longitude  # needs Shapely, checked by require_core

            box = geometry.boundingBox()
            vertices = geometry.constGet().coordinateSequence()
            longitudes = [point.x() for part in vertices for ring in part for point in ring]
            centre = f"+lat_0={(box.yMinimum() + box.yMaximum()) / 2.0!r} +lon_0={central_longitude(longitudes)!r}"
            local = QgsCoordinateReferenceSystem.fromProj(f"+proj=aeqd {centre} {_ellipsoid(crs)} +units=m +no_defs")
            self.transform = QgsCoordinateTransform(crs, local, QgsCoordinateTransformContext())

    def to_core(self, geometry):
        """A layer geometry as a Shapely geometry in the frame."""
        from .convert import to_shapely  # needs Shapely, checked by require_core

        if self.transform is not None:
            geometry = QgsGeometry(geometry)
            geometry.transform(self.transform)
        return to_shapely(geometry)

    def to_layer(self, shape):
        """A Shapely geometry of the frame as a layer geometry."""
        from .convert import from_shapely  # needs Shapely, checked by require_core

        geometry = from_shapely(shape)
        if self.transform is not None:
            geometry.transform(self.transform, Qgis.TransformDirection.Reverse)
        return geometry


def _ellipsoid(crs):
    """PROJ's parameters of the ellipsoid of ``crs`` (``+a=... +rf=...``, or ``+R=...`` for a sphere)."""
    parameters = QgsEllipsoidUtils.ellipsoidParameters(crs.ellipsoidAcronym())
    if not parameters.valid:
        return "+ellps=WGS84"
    if parameters.inverseFlattening == 0:
        return f"+R={parameters.semiMajor!r}"
    return f"+a={parameters.semiMajor!r} +rf={parameters.inverseFlattening!r}"


def cached(name, compute, geometry, crs, options):
    """``compute(geometry, crs, options)`` through :data:`CACHE`; the core's errors about the geometry give None
    (cached too); an invalid option (the core's ``OptionError``) is raised, never cached, so the expression
    reports it.

    A ``points`` option is applied after the cache (False: a point result gives None), so a style asking for
    the line and for the point of the same feature computes it once.
    """
    options = dict(options)
    points = options.pop("points", True)
    key = (name, geometry_key(geometry), crs.authid() or crs.toWkt(), tuple(sorted(options.items())))
    found, value = CACHE.get(key)
    if not found:
        core = require_core()
        try:
            value = compute(geometry, crs, dict(options))
        except core.OptionError:
            raise
        except core.IncirCuError:
            value = None
        CACHE.put(key, value)
    if value is None or (not points and value.type() == GeometryType.Point):
        return None
    return QgsGeometry(value)


class IncirCuFunction(QgsExpressionFunction):
    """An expression function taking a polygon and named options, computed through :func:`cached`.

    Parameters
    ----------
    name : str
    parameters : sequence of (str, object)
        The options after ``geometry``: name and default value (None: the core's default).
    help_text : str
        HTML shown in the expression builder.
    compute : callable
        ``compute(geometry, crs, options)`` -> QgsGeometry or None.
    convert : callable
        ``convert(values)`` -> the options dict given to ``compute`` (raises ValueError on a bad value).
    """

    def __init__(self, name, parameters, help_text, compute, convert):
        arguments = [QgsExpressionFunction.Parameter("geometry")]
        arguments += [QgsExpressionFunction.Parameter(option, True, default) for option, default in parameters]
        super().__init__(name, arguments, GROUP, help_text)
        self.compute = compute
        self.convert = convert
        self.converted = {}

    def options(self, values):
        """``convert(values)``, remembered per argument values: a redraw evaluates the function for every
        feature with the same few arguments, and converting them (checking the end rule against the core's)
        took longer than the cache look-up itself."""
        try:
            key = tuple(values)
            found = self.converted.get(key)
        except TypeError:  # an unhashable argument: converted every time
            return self.convert(values)
        if found is None:
            found = self.convert(values)
            if len(self.converted) >= CONVERTED_ENTRIES:
                self.converted.clear()
            self.converted[key] = found
        return found

    def func(self, values, context, parent, node):
        geometry = values[0]
        if not isinstance(geometry, QgsGeometry) or geometry.isNull() or geometry.isEmpty():
            return None
        try:
            options = self.options(values[1:])
            return cached(self.name(), self.compute, geometry, layer_crs(context), options)
        except Exception as error:  # noqa: BLE001 - any failure becomes the expression's error, not a crash
            # QGIS shows the evaluation error (the expression builder, the message log) and returns NULL.
            parent.setEvalErrorString(f"{self.name()}: {core_text(error)}")
            return None

    def usesGeometry(self, node):
        return False


def _number(value, name):
    """A float option; NULL/None gives None (the core's default)."""
    if value is None:
        return None
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(
            QCoreApplication.translate("IncirCuExpressions", "{} must be a number, not {!r}").format(name, value)
        ) from None


def _end_rule(value):
    core = require_core()
    rule = str(value or "main_stem")
    if rule not in core.END_RULES:
        raise ValueError(
            QCoreApplication.translate("IncirCuExpressions", "end_rule must be one of {}, not {!r}").format(
                ", ".join(core.END_RULES), rule
            )
        )
    return rule


def centerline_options(values):
    """The core's keywords from ``incircu_centerline``'s arguments (tolerance, end_rule)."""
    tolerance = _number(values[0], "tolerance")
    return {"tolerance": tolerance or None, "end_rule": _end_rule(values[1])}


LABEL_OPTIONS = ("trim", "clearance", "bend", "min_elongation", "smoothing")


def label_options(values):
    """The core's keywords from ``incircu_label_line``'s arguments (None values left to the core's defaults)."""
    options = {}
    for name, value in zip(LABEL_OPTIONS, values):
        number = _number(value, name)
        if number is not None:
            options[name] = number
    options["end_rule"] = _end_rule(values[len(LABEL_OPTIONS)])
    options["points"] = bool(values[len(LABEL_OPTIONS) + 1])
    return options


def centerline_help():
    # (No comma after the text: pylupdate5 would not read the call.)
    # fmt: off
    return QCoreApplication.translate(
        "IncirCuExpressions",
        "<h3>incircu_centerline(geometry, tolerance, end_rule)</h3>"
        "<p>The centerline of every part of a polygon (IncirCu's Curve of Incircles, between automatic ends), "
        "as a multi-line in the layer's CRS; NULL when no part has one. For a geometry generator symbol.</p>"
        "<h4>Arguments</h4><ul>"
        "<li><b>geometry</b>: a polygon, usually <code>$geometry</code>.</li>"
        "<li><b>tolerance</b> (optional): largest distance from the exact medial axis, layer units (metres "
        "for a layer in degrees); 0 or NULL: 1/200 of the typical width.</li>"
        "<li><b>end_rule</b> (optional): 'main_stem' (default) or 'longest_path'.</li></ul>"
        "<p>Results are cached per geometry: panning and zooming do not recompute them.</p>"
        "<h4>Example</h4><p><code>incircu_centerline($geometry)</code></p>"
    )
    # fmt: on


def label_line_help():
    # (No comma after the text: pylupdate5 would not read the call.)
    # fmt: off
    return QCoreApplication.translate(
        "IncirCuExpressions",
        "<h3>incircu_label_line(geometry, trim, clearance, bend, min_elongation, smoothing, end_rule, points)</h3>"
        "<p>The line a curved label of a lake or a wide river follows, as the 'Label lines of polygons' "
        "algorithm computes it for the polygon's largest part: the main stem trimmed to where the polygon is "
        "at least <i>trim</i> of its widest width, smoothed, at least <i>clearance</i> local widths off the "
        "shore, bending no tighter than <i>bend</i> local widths, reading from left to right. A compact part "
        "gives a label point (the centre of its largest incircle), or NULL when <i>points</i> is false. Use it "
        "as the label's geometry generator with curved placement.</p>"
        "<h4>Arguments</h4><ul>"
        "<li><b>geometry</b>: a polygon, usually <code>$geometry</code>.</li>"
        "<li><b>trim</b>, <b>clearance</b>, <b>bend</b>, <b>min_elongation</b>, <b>smoothing</b> (optional): "
        "as in the algorithm; NULL: its defaults (0.5, 0.25, 0.5, 3, 0.5).</li>"
        "<li><b>end_rule</b> (optional): 'main_stem' (default) or 'longest_path'.</li>"
        "<li><b>points</b> (optional): true (default) to return a label point for compact parts.</li></ul>"
        "<p>Results are cached per geometry: panning and zooming do not recompute them.</p>"
        "<h4>Example</h4><p><code>incircu_label_line($geometry, points:=false)</code></p>"
    )
    # fmt: on


def register_functions():
    """Register both functions (replacing older registrations of the same names); returns their names."""
    unregister_functions()
    functions = [
        IncirCuFunction(
            CENTERLINE_FUNCTION,
            [("tolerance", 0.0), ("end_rule", "main_stem")],
            centerline_help(),
            compute_centerline,
            centerline_options,
        ),
        IncirCuFunction(
            LABEL_LINE_FUNCTION,
            [*((name, None) for name in LABEL_OPTIONS), ("end_rule", "main_stem"), ("points", True)],
            label_line_help(),
            compute_label,
            label_options,
        ),
    ]
    for function in functions:
        if QgsExpression.isFunctionName(function.name()):
            QgsExpression.unregisterFunction(function.name())
        QgsExpression.registerFunction(function)
        REGISTERED.append(function)
    return [function.name() for function in functions]


def unregister_functions():
    """Remove the functions this module registered, and forget the cached results."""
    while REGISTERED:
        # Python owns each function: it must outlive its removal from QGIS's list.
        function = REGISTERED[-1]
        QgsExpression.unregisterFunction(function.name())
        REGISTERED.pop()
    CACHE.clear()
