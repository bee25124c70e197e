"""Paths and metadata of the repository (the plugin folder), shared by the plugin tests and their fixtures."""

import configparser
import os
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parents[2]
DATA = REPOSITORY / "tests" / "data"
ARTIFACTS = REPOSITORY / "tests" / "artifacts"
PLUGIN_NAME = "incircu"
#: Shapely built against the system GEOS for QGIS's own Python (``make setup``); numpy and pyproj come from Debian.
QGIS_SITE = Path(os.environ.get("INCIRCU_QGIS_SITE", REPOSITORY / ".venv" / "qgis-site"))


def metadata():
    """Return the ``[general]`` section of the repository's ``metadata.txt``."""
    parser = configparser.ConfigParser(interpolation=None)
    parser.read(REPOSITORY / "metadata.txt", encoding="utf-8")
    return parser["general"]


def version_number(text):
    """Turn ``"3.22"`` or ``"3.22.16-Białowieża"`` into QGIS's integer form (32200, 32216)."""
    numbers = [int("".join(c for c in piece if c.isdigit()) or 0) for piece in text.split("-")[0].split(".")]
    numbers += [0] * (3 - len(numbers))
    return numbers[0] * 10000 + numbers[1] * 100 + numbers[2]
