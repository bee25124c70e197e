"""The parameters of a run, read once at the top of ``processAlgorithm`` into frozen values.

Each algorithm's ``read_options`` builds its options object (:class:`PolygonOptions`, :class:`LinesOptions`,
:class:`NetworkOptions`) with the readers here; the feature loop then only reads that object. A data-defined
length (a value per feature) is a :class:`PerFeature`, called with the feature.
"""

import math
from dataclasses import dataclass
from typing import Any, Optional

from qgis.core import (
    QgsExpressionContext,
    QgsProcessingException,
    QgsProcessingParameters,
    QgsProperty,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QCoreApplication

from .compat import GeometryType

GEOMETRY_TYPE_NAMES = {
    GeometryType.Point: "point",
    GeometryType.Line: "line",
    GeometryType.Polygon: "polygon",
}


@dataclass(frozen=True)
class PerFeature:
    """A length parameter's value for each input feature (layer units, metres for a layer in degrees).

    Without a data-defined override every feature gets ``value``; with one (a field or an expression of the
    feature), each feature gets its own, and a value that is missing, negative or not a number falls back to
    the parameter's default ``fallback``.
    """

    value: float
    prop: Optional[QgsProperty] = None
    fallback: float = 0.0
    expression_context: Optional[QgsExpressionContext] = None

    @property
    def dynamic(self):
        """True when the value is data-defined (may differ per feature)."""
        return self.prop is not None

    def __call__(self, feature):
        """Return the value for ``feature`` (a ``QgsFeature`` of the parameter's layer)."""
        if self.prop is None:
            return self.value
        context = self.expression_context
        if context.fields() != feature.fields():
            # Fields by name: prepared once the layer's fields are known (those of its first feature).
            context.setFields(feature.fields())
            self.prop.prepare(context)
        context.setFeature(feature)
        number, ok = self.prop.valueAsDouble(context, self.fallback)
        return number if ok and math.isfinite(number) and number >= 0.0 else self.fallback


@dataclass(frozen=True)
class Sampling:
    """``TOLERANCE`` (adaptive sampling, data-defined) and ``SPACING`` (fixed sampling); 0 is "not given"."""

    tolerance: PerFeature
    spacing: float

    def of(self, feature):
        """Return the core's ``tolerance`` and ``spacing`` keywords for ``feature`` (None where 0)."""
        return {"tolerance": self.tolerance(feature) or None, "spacing": self.spacing or None}


@dataclass(frozen=True)
class OutputOptions:
    """How the centerline outputs are written and named.

    Attributes
    ----------
    add_m : bool
        Store the local width as M value.
    transect_interval : PerFeature or None
        Distance between transects (0: each centerline's mean width); None when the algorithm has none.
    transect_style : str
        One of the core's ``TRANSECT_STYLES`` (empty when the algorithm has no transects).
    layer_names : dict
        Rank of :mod:`.styles` (``CENTERLINE``...) -> the name of the loaded output layer.
    group : str
        Name of the layer-tree group of the run's outputs.
    """

    add_m: bool
    transect_interval: Optional[PerFeature]
    transect_style: str
    layer_names: dict
    group: str


@dataclass(frozen=True)
class PolygonOptions:
    """Parameters of 'Centerline of polygons' and 'Label lines of polygons'.

    ``split_points`` and ``guide_lines`` are the layers given (None when not); ``end_cap`` is ``"axis"`` for the
    label lines (trimmed, with no choice); ``label`` holds the core's label keywords (empty for centerlines).
    """

    source: Any
    split_points: Any
    guide_lines: Any
    snap_tolerance: PerFeature
    sampling: Sampling
    islands: str
    end_rule: str
    end_cap: str
    separate_parts: bool
    connect_touching: bool
    outputs: OutputOptions
    label: tuple = ()


@dataclass(frozen=True)
class LinesOptions:
    """Parameters of 'Centerline between two lines': both layers, their pairing fields (empty: one line per
    layer; a guessed shared field is named in ``guessed_field``), sampling, end cap and outputs."""

    source_a: Any
    source_b: Any
    field_a: str
    field_b: str
    guessed_field: bool
    sampling: Sampling
    end_cap: str
    outputs: OutputOptions


@dataclass(frozen=True)
class NetworkOptions:
    """Parameters of 'Centerline network of polygons'."""

    source: Any
    split_points: Any
    id_field: str
    snap_tolerance: PerFeature
    sampling: Sampling
    islands: str
    end_cap: str
    min_arm_ratio: float
    min_arm_length: Optional[float]
    connect_touching: bool
    outputs: OutputOptions


def given(parameters, name):
    """True when the optional parameter ``name`` has a value in ``parameters``."""
    return parameters.get(name) not in (None, "")


def read_source(algorithm, parameters, name, geometry_type, context):
    """Return the feature source of parameter ``name`` after checking its geometry type.

    Raises
    ------
    QgsProcessingException
        When the layer cannot be opened or holds another geometry type.
    """
    source = algorithm.parameterAsSource(parameters, name, context)
    if source is None:
        raise QgsProcessingException(algorithm.invalidSourceError(parameters, name))
    actual = QgsWkbTypes.geometryType(source.wkbType())
    if actual != geometry_type:
        raise QgsProcessingException(
            QCoreApplication.translate(
                "IncirCuAlgorithm", "{} must be a {} layer, but '{}' holds {} geometries."
            ).format(
                algorithm.parameter_label(name),
                GEOMETRY_TYPE_NAMES[geometry_type],
                source.sourceName(),
                GEOMETRY_TYPE_NAMES.get(actual, "no"),
            )
        )
    return source


def read_optional_source(algorithm, parameters, name, geometry_type, context):
    """:func:`read_source` for an optional layer parameter; None when it is not given."""
    return read_source(algorithm, parameters, name, geometry_type, context) if given(parameters, name) else None


def read_per_feature(algorithm, parameters, name, context):
    """Return length parameter ``name`` as a :class:`PerFeature` (data-defined or not)."""
    if not QgsProcessingParameters.isDynamic(parameters, name):
        return PerFeature(algorithm.parameterAsDouble(parameters, name, context))
    fallback = float(algorithm.parameterDefinition(name).defaultValue() or 0.0)
    return PerFeature(
        fallback, QgsProperty(parameters[name]), fallback, QgsExpressionContext(context.expressionContext())
    )


def read_sampling(algorithm, parameters, context):
    """Return ``TOLERANCE`` and ``SPACING`` as a :class:`Sampling`.

    Raises
    ------
    QgsProcessingException
        When both a largest deviation and a fixed sampling distance are given.
    """
    tolerance = read_per_feature(algorithm, parameters, algorithm.TOLERANCE, context)
    spacing = algorithm.parameterAsDouble(parameters, algorithm.SPACING, context)
    if (tolerance.dynamic or tolerance.value) and spacing:
        # fmt: off
        # (No comma after the text: pylupdate5 would not read the call.)
        message = QCoreApplication.translate(
            "IncirCuAlgorithm",
            "Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary sampling "
            "distance, not both; set the other one to 0."
        )
        # fmt: on
        raise QgsProcessingException(message)
    return Sampling(tolerance, spacing)


def read_field(algorithm, parameters, name, source, context):
    """Return the field named by parameter ``name`` (empty when none is given), checked against ``source``.

    Raises
    ------
    QgsProcessingException
        When ``source`` has no field of that name (``qgis_process`` and models accept any text).
    """
    field = algorithm.parameterAsString(parameters, name, context)
    if field and source.fields().lookupField(field) < 0:
        parent = algorithm.parameterDefinition(name).parentLayerParameterName()
        raise QgsProcessingException(
            QCoreApplication.translate("IncirCuAlgorithm", "{}: {} has no field '{}'; its fields are: {}.").format(
                algorithm.parameter_label(name),
                algorithm.parameter_label(parent),
                field,
                ", ".join(source.fields().names()) or QCoreApplication.translate("IncirCuAlgorithm", "none"),
            )
        )
    return field


def read_choice(algorithm, parameters, name, choices, context):
    """Return the choice of enum parameter ``name`` among ``choices`` (the core's, in the drop-down's order)."""
    return choices[algorithm.parameterAsEnum(parameters, name, context)]


def read_outputs(algorithm, parameters, context, layer_name, rule=""):
    """Return the :class:`OutputOptions` of ``algorithm``: ``ADD_M``, the transects' parameters where it has
    them, and the names of its loaded outputs (``layer_name`` the input layer's, ``rule`` what decided the
    lines)."""
    from ..incircu_plugin.core.widths import TRANSECT_STYLES  # needs Shapely, checked by require_core

    names, group = algorithm.output_layer_names(layer_name, rule)
    has = algorithm.parameterDefinition
    add_m = bool(has(algorithm.ADD_M)) and algorithm.parameterAsBoolean(parameters, algorithm.ADD_M, context)
    if not has(algorithm.TRANSECT_INTERVAL):
        return OutputOptions(add_m, None, "", names, group)
    return OutputOptions(
        add_m,
        read_per_feature(algorithm, parameters, algorithm.TRANSECT_INTERVAL, context),
        read_choice(algorithm, parameters, algorithm.TRANSECT_STYLE, TRANSECT_STYLES, context),
        names,
        group,
    )
