"""Make the README of a release zip self-contained: links to files left out of the zip become absolute.

``make package`` zips only what a user installs; the README there still links the demo image and the
benchmark pages. This rewrites every relative Markdown link or image whose target is not in the zip to the
file in the project's repository (``repository`` in ``metadata.txt``, branch ``main``).

Usage: ``python3 scripts/release_links.py dist/incircu-0.1.0.zip``
"""

import configparser
import re
import sys
import zipfile
from pathlib import Path

#: ``[text](target)`` and ``![alt](target)``; the target ends at whitespace or ``)``.
LINK = re.compile(r"(!?\[[^\]]*\]\()([^)\s]+)(\))")
ABSOLUTE = re.compile(r"^([a-z][a-z0-9+.-]*:|#|/)", re.IGNORECASE)


def absolute_links(readme, present, repository):
    """Return ``readme`` with relative link targets that are not in ``present`` made absolute.

    Parameters
    ----------
    readme : str
        Markdown text.
    present : set of str
        Paths (relative to the plugin folder) that the zip holds.
    repository : str
        Web address of the repository, e.g. ``https://github.com/owner/name``.
    """

    def rewrite(match):
        opening, target, closing = match.groups()
        path = target.split("#")[0]
        if ABSOLUTE.match(target) or path in present:
            return match.group(0)
        kind = "raw" if opening.startswith("!") else "blob"
        return f"{opening}{repository.rstrip('/')}/{kind}/main/{target}{closing}"

    return LINK.sub(rewrite, readme)


def main(archive_path):
    """Rewrite the README inside the zip at ``archive_path`` in place."""
    archive_path = Path(archive_path)
    with zipfile.ZipFile(archive_path) as archive:
        entries = [(info, archive.read(info)) for info in archive.infolist()]
    prefix = entries[0][0].filename.split("/")[0] + "/"
    files = {info.filename: data for info, data in entries}
    present = {name[len(prefix) :] for name in files}
    metadata = configparser.ConfigParser(interpolation=None)
    metadata.read_string(files[prefix + "metadata.txt"].decode("utf-8"))
    repository = metadata["general"]["repository"]
    with zipfile.ZipFile(archive_path, "w", zipfile.ZIP_DEFLATED) as archive:
        for info, data in entries:
            if info.filename == prefix + "README.md":
                data = absolute_links(data.decode("utf-8"), present, repository).encode("utf-8")
            archive.writestr(info, data)


if __name__ == "__main__":
    main(sys.argv[1])
