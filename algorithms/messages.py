"""The core's messages in the user's language: each is a template of the core's ``MESSAGES`` with its values.

The core (no Qt) words its errors and notes in English as :class:`~incircu_plugin.core.errors.Message` objects
that keep their code and values; here the template of that code is translated (``i18n/``, context
``IncirCuCore``) and filled with the same values, nouns among them translated too, the lengths' unit named as
the layer's and QGIS's own tool names in QGIS's language.
"""

from qgis.core import QgsApplication
from qgis.PyQt.QtCore import QCoreApplication


def fix_geometries_name():
    """QGIS's name of its "Fix geometries" tool, in the language QGIS runs in ("Napraw geometrie" in Polish)."""
    algorithm = QgsApplication.processingRegistry().algorithmById("native:fixgeometries")
    return algorithm.displayName() if algorithm is not None else "Fix geometries"


def core_text(message, units=None):
    """Return a core message (a ``Message``, an ``IncirCuError`` or plain text) in the user's language.

    Parameters
    ----------
    message : Message, IncirCuError or str
        Plain text (an error raised without a code) is returned as it is.
    units : str, optional
        How to name the unit of the message's lengths (the layer's, "m"); the core says "CRS units".

    Returns
    -------
    str
    """
    # Imported here: the core needs Shapely, which the run has checked by now.
    from ..incircu_plugin.core.errors import CONTEXT, MESSAGES, IncirCuError

    if isinstance(message, IncirCuError):
        message = message.message
    code = getattr(message, "code", None)
    if code not in MESSAGES:
        return str(message)
    values = {
        name: core_text(value, units) if hasattr(value, "code") else value for name, value in message.values.items()
    }
    values["fix_geometries"] = fix_geometries_name()
    if units:
        values["units"] = units
    try:
        return QCoreApplication.translate(CONTEXT, MESSAGES[code]).format(**values)
    except (KeyError, IndexError, ValueError):
        # A translation naming a value the template has not: the English text is better than none.
        return str(message)
