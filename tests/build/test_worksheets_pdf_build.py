"""The worksheets' command line, typeset: the same seed gives the same PDFs byte for byte, and the
issue's example builds (the site's sheets: tests/site/test_worksheets_pdf.py)."""

from __future__ import annotations

import subprocess
import sys

import pytest
from support.pdf import layout_text


@pytest.mark.build
def test_the_same_seed_gives_the_same_pdfs_byte_for_byte(tmp_path):
    command = [sys.executable, "-m", "physics_figures.worksheets", "--templates",
               "graph-skydiver-terminal,parachute-opens-choice", "--versions", "1", "--seed", "11"]
    for run in ("first", "second"):
        subprocess.run([*command, "--out", str(tmp_path / run)], check=True, capture_output=True)
    for name in ("worksheet-A.pdf", "worksheet-key-A.pdf"):
        assert (tmp_path / "first" / name).read_bytes() == (tmp_path / "second" / name).read_bytes(), name
    subprocess.run([*command[:-1], "12", "--out", str(tmp_path / "other")], check=True, capture_output=True)
    assert (tmp_path / "other" / "worksheet-A.pdf").read_bytes() != (tmp_path / "first" / "worksheet-A.pdf").read_bytes()


@pytest.mark.build
def test_cli_builds_the_issues_example(tmp_path):
    """--types drag,two-d --marks N --versions 4: four versions with keys, N marks each."""
    result = subprocess.run(
        [sys.executable, "-m", "physics_figures.worksheets", "--types", "drag,two-d", "--marks", "15",
         "--versions", "4", "--seed", "2027", "--out", str(tmp_path)],
        check=True, capture_output=True, text=True)
    assert "4 versions, 15 marks" in result.stdout
    for letter in "ABCD":
        page = layout_text(tmp_path / f"worksheet-{letter}.pdf")
        assert "Total: 15 marks" in page
        assert (tmp_path / f"worksheet-key-{letter}.pdf").exists()
