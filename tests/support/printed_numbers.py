# ruff: noqa: RUF001, RUF003  (× and the Unicode minus as the book prints them)
"""Numbers as the book prints them, read back from its pages, graphs and PDFs: a power of ten
written with more figures than the book gives (tests/no_site/test_graph_labels.py and
tests/site/test_graph_labels_site.py)."""

from __future__ import annotations

import re

#: A number in powers of ten as the book prints it, and as pdftotext reads one from the PDFs
#: (LaTeX's raised power comes out as plain digits: "1.12 × 105").
POWER_FORM = re.compile(r"(\d+(?:\.\d+)?)\s?×\s?10(?:[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+|\^\{?-?\d+\}?|−?\d+)")
MOST_FIGURES = 3


def too_many_figures(text: str) -> list[str]:
    """Each number in ``text`` written in powers of ten with more than 3 significant figures."""
    return [m[0] for m in POWER_FORM.finditer(text) if len(m[1].replace(".", "").lstrip("0")) > MOST_FIGURES]
