"""Toolbox dialog widget of the IncirCu lengths: the number and its unit, metres for a layer in degrees.

QGIS's own distance widget labels a length "degrees" when the layer is geographic, but IncirCu computes such
layers in a local metric projection, so its lengths are metres there. The parameters name this wrapper in
their metadata (:func:`.base.length_parameter`); Processing imports it only when it builds a dialog, so
``qgis_process`` never loads this module. The batch dialog and the modeler keep QGIS's own widgets.
The label is QGIS's own (translated "[optional]", help text as tooltip), so it reads like every other one.
"""

from processing.gui.wrappers import DIALOG_STANDARD, WidgetWrapper, WidgetWrapperFactory, dialogTypes
from qgis.core import QgsProcessingParameters, QgsUnitTypes
from qgis.gui import QgsAbstractProcessingParameterWidgetWrapper, QgsDoubleSpinBox
from qgis.PyQt.QtWidgets import QHBoxLayout, QLabel, QWidget

from .units import reading_unit

#: Parameter copies without the wrapper metadata, kept alive for the QGIS widgets built on them.
PLAIN_PARAMETERS = []


def default_wrapper(parameter, dialog, row, col):
    """Return the widget wrapper QGIS itself gives ``parameter`` in ``dialog``."""
    plain = parameter.clone()
    plain.setMetadata({})
    PLAIN_PARAMETERS.append(plain)
    return WidgetWrapperFactory.create_wrapper(plain, dialog, row, col)


def unit_text(crs):
    """Return the name of the unit IncirCu reads a length in for a layer of ``crs`` (:func:`.units.reading_unit`),
    empty for an invalid CRS."""
    return QgsUnitTypes.toString(reading_unit(crs)) if crs.isValid() else ""


class LengthSpinBox(QgsDoubleSpinBox):
    """A spin box keeping six decimals but showing only the significant ones: "1", "2.5", not "1.000000"."""

    def textFromValue(self, value):
        text = super().textFromValue(value)
        decimal_point = self.locale().decimalPoint()
        if decimal_point in text:
            text = text.rstrip("0").rstrip(decimal_point)
        return text


class LengthWidgetWrapper(WidgetWrapper):
    """A non-negative number with the unit of the parent layer next to it (metres for degrees)."""

    def __new__(cls, parameter, dialog, row=0, col=0):
        if dialogTypes.get(type(dialog).__name__, DIALOG_STANDARD) != DIALOG_STANDARD:
            return default_wrapper(parameter, dialog, row, col)
        return super().__new__(cls)

    def createLabel(self):
        """Return the label QGIS gives its own widgets: translated "[optional]", the help text as tooltip."""
        return QgsAbstractProcessingParameterWidgetWrapper.createLabel(self)

    def createWidget(self):
        parameter = self.parameterDefinition()
        self.spin_box = LengthSpinBox()
        self.spin_box.setDecimals(6)
        self.spin_box.setRange(max(parameter.minimum(), 0.0), parameter.maximum())
        self.spin_box.setShowClearButton(True)
        self.spin_box.setClearValue(float(parameter.defaultValue() or 0.0))
        self.spin_box.setToolTip(parameter.toolTip())
        self.unit_label = QLabel()
        container = QWidget()
        layout = QHBoxLayout(container)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.spin_box, 1)
        layout.addWidget(self.unit_label)
        return container

    def postInitialize(self, wrappers):
        parent_name = self.parameterDefinition().parentParameterName()
        for wrapper in wrappers:
            if wrapper.parameterDefinition().name() == parent_name:
                wrapper.widgetValueHasChanged.connect(self.show_unit)
                self.show_unit(wrapper)

    def show_unit(self, parent_wrapper):
        """Show the unit of the layer chosen in ``parent_wrapper``."""
        from processing.tools.dataobjects import createContext

        definition = parent_wrapper.parameterDefinition()
        value = parent_wrapper.parameterValue()
        crs = QgsProcessingParameters.parameterAsCrs(definition, {definition.name(): value}, createContext())
        self.unit_label.setText(unit_text(crs))

    def setValue(self, value):
        if value is not None and value != "":
            self.spin_box.setValue(float(value))

    def value(self):
        return self.spin_box.value()
