"""The one home of the QGIS API names that changed between QGIS 3.22 and QGIS 3.40 / 4 (Qt 6).

The rest of the plugin writes the current names (``ProcessingSourceType.VectorPolygon``, ``WkbType.LineString``,
``GeometryType.Polygon``, ``FieldType.Double``...); this module maps them to the running QGIS: the new enums
where QGIS has them, the QGIS 3.22 equivalents otherwise. ``tests/test_plugin_qt6.py`` keeps the old names out
of every other module, the way QGIS's ``pyqt5_to_pyqt6.py`` migration script would.
"""

from types import SimpleNamespace

from qgis.core import Qgis

QGIS_VERSION = Qgis.QGIS_VERSION_INT

if QGIS_VERSION >= 33000:
    WkbType, GeometryType, DistanceUnit = Qgis.WkbType, Qgis.GeometryType, Qgis.DistanceUnit
else:
    from qgis.core import QgsUnitTypes, QgsWkbTypes

    WkbType = QgsWkbTypes.Type
    GeometryType = SimpleNamespace(
        Point=QgsWkbTypes.GeometryType.PointGeometry,
        Line=QgsWkbTypes.GeometryType.LineGeometry,
        Polygon=QgsWkbTypes.GeometryType.PolygonGeometry,
    )
    DistanceUnit = SimpleNamespace(Meters=QgsUnitTypes.DistanceUnit.DistanceMeters)

if QGIS_VERSION >= 33600:
    ProcessingSourceType = Qgis.ProcessingSourceType
    ProcessingParameterFlag = Qgis.ProcessingParameterFlag
    ProcessingFeatureSourceFlag = Qgis.ProcessingFeatureSourceFlag
    CrsWktVariant = Qgis.CrsWktVariant
    ProcessingNumberParameterType = Qgis.ProcessingNumberParameterType
else:
    from qgis.core import (
        QgsCoordinateReferenceSystem,
        QgsProcessing,
        QgsProcessingFeatureSource,
        QgsProcessingParameterDefinition,
        QgsProcessingParameterNumber,
    )

    ProcessingSourceType = SimpleNamespace(
        VectorPoint=QgsProcessing.SourceType.TypeVectorPoint,
        VectorLine=QgsProcessing.SourceType.TypeVectorLine,
        VectorPolygon=QgsProcessing.SourceType.TypeVectorPolygon,
    )
    ProcessingParameterFlag = SimpleNamespace(
        Advanced=QgsProcessingParameterDefinition.Flag.FlagAdvanced,
        Optional=QgsProcessingParameterDefinition.Flag.FlagOptional,
    )
    ProcessingFeatureSourceFlag = SimpleNamespace(
        SkipGeometryValidityChecks=QgsProcessingFeatureSource.Flag.FlagSkipGeometryValidityChecks,
    )
    CrsWktVariant = SimpleNamespace(Wkt2_2019=QgsCoordinateReferenceSystem.WktVariant.WKT2_2019)
    ProcessingNumberParameterType = SimpleNamespace(Double=QgsProcessingParameterNumber.Type.Double)

if QGIS_VERSION >= 33800:
    from qgis.PyQt.QtCore import QMetaType

    #: Field types of ``QgsField`` (``Double``, ``Int``, ``LongLong``, ``Bool``, ``QString``).
    FieldType = QMetaType.Type
else:
    from qgis.PyQt.QtCore import QVariant

    FieldType = SimpleNamespace(
        Double=QVariant.Double,
        Int=QVariant.Int,
        LongLong=QVariant.LongLong,
        Bool=QVariant.Bool,
        QString=QVariant.String,
    )
