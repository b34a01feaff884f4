"""Reading a PDF as poppler-utils read it (pdftotext, pdfinfo, pdffonts, pdfimages)."""

from __future__ import annotations

import subprocess


def poppler(*command: str) -> str:
    """A poppler-utils command's output: poppler("pdfinfo", path)."""
    return subprocess.run(command, check=True, capture_output=True, text=True).stdout
