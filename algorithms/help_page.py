"""The offline help page shipped with the plugin (``help/index.html``), which the dialogs' Help button opens.

The page is made from the algorithms themselves (their summary and the help of every parameter and output,
as the dialog's side panel shows it) and the example models' help, after a few plain sentences on the words
the help uses; ``scripts/make_help.py`` writes it and a test keeps it up to date.
"""

import html
import re
from pathlib import Path

from qgis.core import QgsProcessingModelAlgorithm
from qgis.PyQt.QtCore import QUrl

#: The help page, in the plugin folder.
HELP_FILE = Path(__file__).resolve().parent.parent / "help" / "index.html"

#: What the help says before any term: one plain sentence per word, then the word.
WORDS = (
    (
        "Centerline",
        "A line running down the middle of a long shape, such as a river, from one end to the other.",
    ),
    (
        "Incircle",
        "A circle inside the shape that touches both of its sides; its diameter is the local width.",
    ),
    (
        "Medial axis",
        (
            "The line of the centres of all such circles: it runs down the middle of the shape, with a side "
            "branch into every bend and corner. IncirCu keeps one path of it, without side branches."
        ),
    ),
    (
        "Split points",
        "Two points on the outline where the centerline starts and ends (IncirCu finds them when none are given).",
    ),
    (
        "Chains",
        "The two sides of the outline between the split points, such as the left and the right bank of a river.",
    ),
    (
        "Transect",
        "A cross-section from bank to bank through the centerline, with the width there.",
    ),
    (
        "Chainage",
        "The distance along the centerline from its start.",
    ),
)


def help_url(anchor):
    """Return the address of the help page's section ``anchor`` (a local file, so it opens offline)."""
    return f"{QUrl.fromLocalFile(str(HELP_FILE)).toString()}#{anchor}"


def anchor(algorithm):
    """Return the ``id`` of ``algorithm``'s section: its name, spaces and punctuation as hyphens."""
    return re.sub(r"[^0-9A-Za-z]+", "-", algorithm.name()).strip("-").lower()


def body(text):
    """Return what lies between ``<body>`` and ``</body>`` of ``text`` (QGIS's model help is a whole page)."""
    found = re.search(r"<body>(.*)</body>", text, re.DOTALL)
    return found.group(1) if found else text


def page(algorithms):
    """Return the help page of ``algorithms`` (IncirCu's algorithms and example models), HTML in English.

    Each algorithm gets a section whose ``id`` is :func:`anchor` (the Help button's), with its display name, its
    id and the side panel's help (``shortHelpString``); the algorithms come first, then the example models.
    """
    escape = html.escape
    ordered = sorted(
        algorithms, key=lambda algorithm: (isinstance(algorithm, QgsProcessingModelAlgorithm), algorithm.displayName())
    )
    words = "".join(f"<dt>{escape(word)}</dt><dd>{escape(sentence)}</dd>" for word, sentence in WORDS)
    contents = "".join(
        f'<li><a href="#{anchor(algorithm)}">{escape(algorithm.displayName())}</a> ({escape(algorithm.group())})</li>'
        for algorithm in ordered
    )
    sections = "".join(
        f'<section id="{anchor(algorithm)}"><h2>{escape(algorithm.displayName())}</h2>'
        f"<p><code>{escape(algorithm.id())}</code></p>"
        f"<div>{body(algorithm.shortHelpString())}</div></section>\n"
        for algorithm in ordered
    )
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en"><head><meta charset="utf-8"><title>IncirCu help</title>'
        "<style>body{font-family:sans-serif;max-width:52em;margin:2em auto;line-height:1.45;padding:0 1em}"
        "dt{font-weight:bold;margin-top:.5em}section{border-top:1px solid #ccc;margin-top:2em}</style>"
        "</head><body>\n"
        "<h1>IncirCu help</h1>\n"
        "<p>IncirCu draws one line down the middle of each long polygon (a river, a road, a dike), or between two "
        "bank lines, and measures its width all along. Its tools are in the Processing Toolbox under "
        "<i>IncirCu</i>; the example models under <i>Example models</i> combine them with QGIS's own tools.</p>\n"
        f"<h2>Words used here</h2><dl>{words}</dl>\n"
        f"<h2>Contents</h2><ul>{contents}</ul>\n"
        f"{sections}"
        "</body></html>\n"
    )
