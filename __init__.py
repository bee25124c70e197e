"""QGIS entry point of the IncirCu plugin (the repository root is the plugin folder ``incircu``)."""


def classFactory(iface):
    """Create the plugin object; QGIS calls this when it loads the plugin.

    Parameters
    ----------
    iface : qgis.gui.QgisInterface or None
        The QGIS desktop interface; ``None`` under ``qgis_process``.

    Returns
    -------
    IncirCuPlugin
        The plugin object QGIS keeps for the session.
    """
    from .incircu_plugin.plugin import IncirCuPlugin

    return IncirCuPlugin(iface)
