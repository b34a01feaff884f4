"""Reading a PDF as poppler-utils read it (pdftotext, pdfinfo, pdffonts, pdfimages)."""

from __future__ import annotations

import re
import subprocess
from functools import cache


def poppler(*command: str) -> str:
    """A poppler-utils command's output: poppler("pdfinfo", path)."""
    return subprocess.run(command, check=True, capture_output=True, text=True).stdout


def pdf_pages(path, *pdftotext_options: str) -> list[str]:
    """Each page's text, as pdftotext gives it with `pdftotext_options` ("-layout", say)."""
    count = int(re.search(r"Pages:\s+(\d+)", poppler("pdfinfo", str(path)))[1])
    return [poppler("pdftotext", *pdftotext_options, "-f", str(n), "-l", str(n), str(path), "-")
            for n in range(1, count + 1)]


@cache
def layout_text(path) -> str:
    """A whole PDF's text as laid out on its pages (pdftotext -layout), read once a file."""
    return poppler("pdftotext", "-enc", "UTF-8", "-layout", str(path), "-")
