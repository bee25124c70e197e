"""Toolbox dialog widget of the IncirCu lengths: QGIS's distance box, metres for a layer in degrees.

Like QGIS's own distance widget, a box for the number, a drop-down of length units (the layer's unit first; a
length given in another unit is converted to the layer's) and, for the parameters that offer one, the
data-defined override button (a value per feature, from a field or an expression of the input layer). QGIS's
own widget reads a length in degrees when the layer is geographic, but IncirCu computes such layers in a local
metric projection, so its lengths are metres there (:func:`.units.reading_unit`). The parameters name this
wrapper in their metadata (:func:`.parameters.length_parameter`); Processing imports it only when it builds a dialog,
so ``qgis_process`` never loads this module. The batch dialog and the modeler keep QGIS's own widgets. The
label is QGIS's own (translated "[optional]", help text as tooltip), so it reads like every other one.
"""

from processing.gui.wrappers import DIALOG_STANDARD, WidgetWrapper, WidgetWrapperFactory, dialogTypes
from qgis.core import QgsProcessingParameters, QgsProperty, QgsUnitTypes
from qgis.gui import QgsAbstractProcessingParameterWidgetWrapper, QgsDoubleSpinBox, QgsPropertyOverrideButton
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtWidgets import QComboBox, QHBoxLayout, QWidget

from .compat import DistanceUnit
from .units import reading_unit

#: Parameter copies without the wrapper metadata, kept alive for the QGIS widgets built on them.
PLAIN_PARAMETERS = []

#: The units of the drop-down, after the layer's own: those QGIS's distance widget offers.
UNITS = (
    DistanceUnit.Meters,
    DistanceUnit.Kilometers,
    DistanceUnit.Feet,
    DistanceUnit.Yards,
    DistanceUnit.Miles,
    DistanceUnit.NauticalMiles,
    DistanceUnit.Centimeters,
    DistanceUnit.Millimeters,
)


def unit_name(unit):
    """Return the name of a length unit in the drop-down: British spelling, as the help ("metres"), translated;
    QGIS's name for a unit not listed in :data:`UNITS`."""
    names = {
        DistanceUnit.Meters: QCoreApplication.translate("IncirCuAlgorithm", "metres"),
        DistanceUnit.Kilometers: QCoreApplication.translate("IncirCuAlgorithm", "kilometres"),
        DistanceUnit.Feet: QCoreApplication.translate("IncirCuAlgorithm", "feet"),
        DistanceUnit.Yards: QCoreApplication.translate("IncirCuAlgorithm", "yards"),
        DistanceUnit.Miles: QCoreApplication.translate("IncirCuAlgorithm", "miles"),
        DistanceUnit.NauticalMiles: QCoreApplication.translate("IncirCuAlgorithm", "nautical miles"),
        DistanceUnit.Centimeters: QCoreApplication.translate("IncirCuAlgorithm", "centimetres"),
        DistanceUnit.Millimeters: QCoreApplication.translate("IncirCuAlgorithm", "millimetres"),
    }
    return names.get(unit) or QgsUnitTypes.toString(unit)


def default_wrapper(parameter, dialog, row, col):
    """Return the widget wrapper QGIS itself gives ``parameter`` in ``dialog``."""
    plain = parameter.clone()
    plain.setMetadata({})
    PLAIN_PARAMETERS.append(plain)
    return WidgetWrapperFactory.create_wrapper(plain, dialog, row, col)


class LengthSpinBox(QgsDoubleSpinBox):
    """A spin box keeping six decimals but showing only the significant ones: "1", "2.5", not "1.000000"."""

    def textFromValue(self, value):
        text = super().textFromValue(value)
        decimal_point = self.locale().decimalPoint()
        if decimal_point in text:
            text = text.rstrip("0").rstrip(decimal_point)
        return text


class LengthWidgetWrapper(WidgetWrapper):
    """A non-negative length with a unit drop-down (the layer's unit, metres for degrees) and, for a dynamic
    parameter, the data-defined override button."""

    def __new__(cls, parameter, dialog, row=0, col=0):
        if dialogTypes.get(type(dialog).__name__, DIALOG_STANDARD) != DIALOG_STANDARD:
            return default_wrapper(parameter, dialog, row, col)
        return super().__new__(cls)

    def createLabel(self):
        """Return the label QGIS gives its own widgets: translated "[optional]", the help text as tooltip."""
        return QgsAbstractProcessingParameterWidgetWrapper.createLabel(self)

    def createWidget(self):
        from processing.tools.dataobjects import createContext

        parameter = self.parameterDefinition()
        #: Kept for the layers the override button lists the fields of.
        self.layer_context = createContext()
        self.base_unit = DistanceUnit.Meters
        self.spin_box = LengthSpinBox()
        self.spin_box.setDecimals(6)
        self.spin_box.setRange(max(parameter.minimum(), 0.0), parameter.maximum())
        self.spin_box.setShowClearButton(True)
        self.spin_box.setClearValue(float(parameter.defaultValue() or 0.0))
        self.spin_box.setToolTip(parameter.toolTip())
        self.unit_box = QComboBox()
        self.override = None
        container = QWidget()
        layout = QHBoxLayout(container)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.spin_box, 1)
        layout.addWidget(self.unit_box)
        if parameter.isDynamic():
            self.override = QgsPropertyOverrideButton()
            self.override.init(0, QgsProperty(), parameter.dynamicPropertyDefinition())
            self.override.changed.connect(self.show_override)
            layout.addWidget(self.override)
        self.show_units(self.base_unit)
        return container

    def postInitialize(self, wrappers):
        parent_name = self.parameterDefinition().parentParameterName()
        for wrapper in wrappers:
            if wrapper.parameterDefinition().name() == parent_name:
                wrapper.widgetValueHasChanged.connect(self.follow_layer)
                self.follow_layer(wrapper)

    def follow_layer(self, parent_wrapper):
        """Read lengths in the unit of the layer chosen in ``parent_wrapper``; list its fields for the override."""
        definition = parent_wrapper.parameterDefinition()
        values = {definition.name(): parent_wrapper.parameterValue()}
        crs = QgsProcessingParameters.parameterAsCrs(definition, values, self.layer_context)
        self.show_units(reading_unit(crs) if crs.isValid() else DistanceUnit.Meters)
        if self.override is not None:
            layer = QgsProcessingParameters.parameterAsVectorLayer(definition, values, self.layer_context)
            self.override.setVectorLayer(layer)

    def show_units(self, base_unit):
        """Offer ``base_unit`` (what the algorithm reads) first, then the other units, and select it."""
        self.base_unit = base_unit
        self.unit_box.clear()
        for unit in (base_unit, *(unit for unit in UNITS if unit != base_unit)):
            self.unit_box.addItem(unit_name(unit), unit)
        self.unit_box.setCurrentIndex(0)

    def show_override(self):
        """Grey the box and the units out while a data-defined value replaces them."""
        active = self.override is not None and self.override.isActive()
        self.spin_box.setEnabled(not active)
        self.unit_box.setEnabled(not active)

    def setValue(self, value):
        if isinstance(value, QgsProperty):
            if self.override is not None:
                self.override.setToProperty(value)
                self.show_override()
            return
        if value is not None and value != "":
            self.unit_box.setCurrentIndex(0)
            self.spin_box.setValue(float(value))

    def value(self):
        """The length in the unit the algorithm reads it in, or the data-defined ``QgsProperty``."""
        if self.override is not None and self.override.isActive():
            return self.override.toProperty()
        unit = self.unit_box.currentData()
        return self.spin_box.value() * QgsUnitTypes.fromUnitToUnitFactor(unit, self.base_unit)
