"""Write the plugin's offline help page ``help/index.html`` from the algorithms and example models.

Run with QGIS's Python (``make help``): it loads the plugin from this folder as QGIS does and writes the page
:func:`algorithms.help_page.page` makes of its provider's algorithms.
"""

import os
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main():
    """Write ``help/index.html``."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication

    application = QgsApplication([], False, tempfile.mkdtemp(prefix="incircu-help-"))
    application.initQgis()
    sys.path.append(str(Path(QgsApplication.pkgDataPath()) / "python" / "plugins"))
    from processing.core.Processing import Processing

    Processing.initialize()
    folder = Path(tempfile.mkdtemp(prefix="incircu-plugin-"))
    (folder / "incircu").symlink_to(ROOT, target_is_directory=True)
    sys.path.insert(0, str(folder))
    import incircu
    from incircu.algorithms.help_page import HELP_FILE, page

    plugin = incircu.classFactory(None)
    plugin.initProcessing()
    HELP_FILE.parent.mkdir(exist_ok=True)
    HELP_FILE.write_text(page(plugin.provider.algorithms()), encoding="utf-8")
    plugin.unload()
    print(HELP_FILE)


if __name__ == "__main__":
    main()
