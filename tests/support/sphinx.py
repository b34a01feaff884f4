"""Small Sphinx books with the questions extension, built in a test's own folder."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SPHINX_BUILD = Path(sys.executable).with_name("sphinx-build")


def small_book(folder: Path, pages: dict[str, str], conf: str = "") -> Path:
    """A book of the bank's questions in `folder`: conf.py (with the lines `conf` adds), an
    index whose toctree lists `pages` in order, and each page's MyST text."""
    (folder / "conf.py").write_text(textwrap.dedent(f"""\
        import sys
        sys.path.insert(0, {str(ROOT / "book" / "_ext")!r})
        extensions = ["myst_parser", "questions"]
        question_topics = ["physics_figures.bank"]
        root_doc = "index"
        """) + conf)
    (folder / "index.md").write_text("# Book\n\n```{toctree}\n" + "".join(f"{name}\n" for name in pages) + "```\n")
    for name, text in pages.items():
        (folder / f"{name}.md").write_text(text)
    return folder


def sphinx_build(source: Path, builder: str) -> subprocess.CompletedProcess:
    """Build `source` with `builder` into source/_out/BUILDER, warnings as errors."""
    return subprocess.run(
        [str(SPHINX_BUILD), "-W", "--keep-going", "-q", "-b", builder, str(source), str(source / "_out" / builder)],
        check=False, capture_output=True, text=True, timeout=300,
    )


QUICK_CHECK_1 = "```{question} quick-check-1\n```\n"
#: The small book the directives' tests share (tests/build/conftest.py's `directive_book`): a page
#: without questions, a question with the answer key, Your practice and the class page.
DIRECTIVE_PAGES = {
    "plain": "# A page without questions\n\nText.\n",
    "asked": "# Questions\n\n" + QUICK_CHECK_1 + "\n## Key\n\n```{answer-key}\n```\n",
    "progress": "# Your practice\n\nWhat you practised.\n\n```{practice-progress}\n```\n",
    "class": "# The class\n\nWhat the class did.\n\n```{class-progress}\n```\n",
}
DIRECTIVE_CONF = ('myst_enable_extensions = ["dollarmath"]\n'
                  'latex_documents = [("index", "book.tex", "Book", "Author", "manual")]\n')
