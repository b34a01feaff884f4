"""The sketch choices' figures typeset with the sheets' preamble (xelatex); the figures themselves are
checked in tests/no_site/test_graph_choices.py."""

from __future__ import annotations

import shutil
import subprocess

import pytest

from physics_figures import bank
from physics_figures.worksheets import latex


@pytest.mark.build  # typesets with xelatex, which make test installs before it starts
def test_the_sketches_compile_with_the_sheets_preamble(tmp_path):
    if shutil.which("xelatex") is None:
        pytest.fail("xelatex is not installed: run `make pdf` once (it installs TeX Live from Debian)")
    question = bank.TEMPLATES["force-from-momentum-graph-choice"].variant(0)
    source = (latex.PREAMBLE.replace("@FOOTER@", "test").replace("@TITLE@", "test")
              + "\\begin{document}\n" + latex._part(question, 0, 1) + "\n\\end{document}\n")
    (tmp_path / "sketch.tex").write_text(source, encoding="utf-8")
    result = subprocess.run(["xelatex", "-interaction=nonstopmode", "-halt-on-error", "sketch.tex"],
                            cwd=tmp_path, capture_output=True, text=True, timeout=240, check=False)
    assert result.returncode == 0, result.stdout[-2000:]
