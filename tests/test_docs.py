"""The documentation agrees with the measurements: every ratio the README quotes is in the benchmark page."""

import re

from tests.support.project import REPOSITORY

#: A ratio as the benchmark page writes it: "1.4×", "297×", "8.25e+03×".
RATIO = re.compile(r"(\d[\d.,]*(?:e[+-]\d+)?)×")


def readme_section(title):
    """Return the text of the README section headed ``## title`` (up to the next ``## `` heading)."""
    text = (REPOSITORY / "README.md").read_text(encoding="utf-8")
    start = text.index(f"\n## {title}\n")
    end = text.find("\n## ", start + 1)
    return text[start : end if end >= 0 else len(text)]


def test_every_ratio_in_the_readme_is_in_the_benchmark_page():
    quoted = RATIO.findall(readme_section("Accuracy and speed"))
    measured = set(RATIO.findall((REPOSITORY / "docs" / "benchmark.md").read_text(encoding="utf-8")))
    assert len(quoted) >= 3, "the README no longer quotes the benchmark's ratios; update this test"
    assert [ratio for ratio in quoted if ratio not in measured] == []
