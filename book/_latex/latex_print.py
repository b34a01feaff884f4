"""Make the LaTeX/PDF book print like the HTML site reads (LaTeX builder only).

The HTML pages are for a screen: code cells folded away, solutions in dropdowns,
interactive outputs. Before the LaTeX writer runs on the merged book, this
post-transform makes the same doctree fit for paper:

* numbering mirrors the HTML: a chapter the HTML numbers (``numbered: true`` in
  ``_toc.yml``) gets the same number; a chapter it does not number prints
  unnumbered, and its figures, tables and equations share one running count, as
  in the HTML (``\\dynamicschapter`` in ``dynamics-print.sty`` does the counting);
* the root page (``intro``) keeps its own heading, as an unnumbered chapter;
* code cell sources never print (the PDF shows results, not code);
* outputs only a browser can show (HTML, JavaScript, widgets) are dropped instead
  of printing as ``<IPython.core.display.HTML object>``;
* a sphinx-design dropdown prints open, as a framed box with its title, instead
  of a stray unnumbered heading;
* an admonition with class ``definition`` (or ``key-fact``) prints in its own
  framed style (``dynamicsdefinition`` in ``dynamics-print.sty``).

Nothing here changes the stored doctrees or the HTML build.
"""

from __future__ import annotations

import os
import subprocess
from datetime import UTC, datetime
from pathlib import Path

from docutils import nodes
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util import logging
from sphinx_jupyterbook_latex.nodes import RootHeader

logger = logging.getLogger(__name__)

# The mime types the LaTeX writer can print, best first (myst-nb's own LaTeX order).
PRINTABLE_MIME_TYPES = ("application/pdf", "image/png", "image/jpeg", "text/latex", "text/markdown")
# Outputs meant for a browser: in print their text/plain fallback is only a repr.
BROWSER_MIME_TYPES = (
    "text/html",
    "application/javascript",
    "application/vnd.jupyter.widget-view+json",
    "image/svg+xml",
)
BOXED_ADMONITION_CLASSES = ("definition", "key-fact")


def _raw_latex(text: str) -> nodes.raw:
    return nodes.raw("", text + "\n", format="latex")


def _latex_escape(text: str) -> str:
    replacements = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
                    "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}",
                    "^": r"\textasciicircum{}"}
    return "".join(replacements.get(char, char) for char in text)


class BrowserOnlyOutputs(SphinxPostTransform):
    """Drop cell outputs that only a browser can show, before myst-nb picks a mime type."""

    default_priority = 3  # myst-nb's SelectMimeType runs at 4
    formats = ("latex",)

    def run(self, **kwargs) -> None:
        bundles = [
            node
            for node in self.document.findall(nodes.container)
            if node.get("nb_element") == "mime_bundle"
        ]
        for bundle in bundles:
            types = {child.get("mime_type") for child in bundle.children}
            if types & set(BROWSER_MIME_TYPES) and not types & set(PRINTABLE_MIME_TYPES):
                bundle.parent.remove(bundle)
        # A lone text/plain output that is an object repr says nothing on paper either.
        for block in list(self.document.findall(nodes.literal_block)):
            text = block.astext().strip()
            if text.startswith("<") and text.endswith(">") and " object" in text:
                block.parent.remove(block)


class PrintLayout(SphinxPostTransform):
    """Code sources out, dropdowns open, boxed definitions, HTML numbering (see module)."""

    # after sphinx-jupyterbook-latex has arranged parts and chapters (700),
    # before its code-cell wrappers (999)
    default_priority = 800
    formats = ("latex",)

    def run(self, **kwargs) -> None:
        self._remove_code_sources()
        self._open_dropdowns()
        self._box_definitions()
        self._number_like_html()
        self._root_heading()
        self._root_section_headings()

    def _remove_code_sources(self) -> None:
        for node in list(self.document.findall(nodes.container)):
            if node.get("nb_element") == "cell_code_source" or "cell_input" in node["classes"]:
                node.parent.remove(node)

    def _open_dropdowns(self) -> None:
        dropdowns = [
            node
            for node in self.document.findall(nodes.container)
            if node.get("design_component") == "dropdown"
        ]
        for dropdown in dropdowns:
            box = nodes.admonition("", classes=["dropdown-printed"])
            if dropdown.get("has_title"):
                title = dropdown.children[0]
                box += nodes.title("", "", *title.children)
                body = dropdown.children[1:]
            else:
                body = dropdown.children
            box.extend(child.deepcopy() for child in body)
            dropdown.replace_self(box)

    def _box_definitions(self) -> None:
        for admonition in list(self.document.findall(nodes.admonition)):
            if set(admonition["classes"]) & set(BOXED_ADMONITION_CLASSES):
                parent = admonition.parent
                index = parent.index(admonition)
                parent.insert(index + 1, _raw_latex(r"\end{dynamicsdefinition}"))
                parent.insert(index, _raw_latex(r"\begin{dynamicsdefinition}"))

    def _number_like_html(self) -> None:
        # The chapters are the pages the root page's toctrees list (one per part).
        chapters = set(self.env.toctree_includes.get(self.config.root_doc, []))
        for start in self.document.findall(addnodes.start_of_file):
            if start["docname"] not in chapters:
                continue
            number = self.env.toc_secnumbers.get(start["docname"], {}).get("")
            argument = str(number[0]) if number else ""
            start.insert(0, _raw_latex(rf"\dynamicschapter{{{argument}}}"))

    def _root_section_headings(self) -> None:
        """sphinx-jupyterbook-latex prints the root page's headings as bold lines."""
        for header in list(self.document.findall(RootHeader)):
            header.replace_self(
                _raw_latex(rf"\dynamicsrootsection{{{_latex_escape(header.astext())}}}")
            )

    def _root_heading(self) -> None:
        root = self.config.root_doc
        title = self.env.titles.get(root)
        if title is None:
            return
        for section in self.document.findall(nodes.section):
            if section.get("docname") == root:
                heading = _latex_escape(title.astext())
                section.insert(0, _raw_latex(rf"\dynamicsrootchapter{{{heading}}}"))
                return


def version_and_date(root: Path, environ=os.environ) -> tuple[str, str]:
    """The book's version and date, from the commit it is built from: ("version 1a2b3c4",
    "2026-11-23", the commit's date in UTC). Without a git checkout (.git), "unversioned" and
    the date of SOURCE_DATE_EPOCH. Never the clock: the same source gives the same PDFs."""
    if (root / ".git").exists():
        found = subprocess.run(["git", "-C", str(root), "log", "-1", "--format=%h %ct"],
                               capture_output=True, text=True, check=False)
        if found.returncode != 0 or not found.stdout.strip():
            raise ValueError(f"root={str(root)!r} has a .git but git cannot read its last commit: "
                             f"{found.stderr.strip()}")
        commit, seconds = found.stdout.split()
        return f"version {commit}", _utc_date(int(seconds))
    epoch = environ.get("SOURCE_DATE_EPOCH", "")
    if not epoch.isdigit():
        raise ValueError(f"SOURCE_DATE_EPOCH={epoch!r}: with no .git to date the book from, it must be "
                         "set to the build's date in whole seconds since 1970 (the Makefile sets it)")
    return "unversioned", _utc_date(int(epoch))


def _utc_date(seconds: int) -> str:
    return datetime.fromtimestamp(seconds, tz=UTC).strftime("%Y-%m-%d")


def stamp_version(app: Sphinx) -> None:
    """Every PDF (book, sheet, key) shows the version and date on its title and page headers."""
    if app.builder.format != "latex":
        return
    version, date = version_and_date(Path(app.srcdir))
    app.builder.context["release"] = version.removeprefix("version ")
    app.builder.context["releasename"] = "Version" if version.startswith("version") else ""
    app.builder.context["date"] = date
    if not version.startswith("version"):
        app.builder.context["release"] = "Unversioned"


def setup(app: Sphinx) -> dict:
    app.connect("builder-inited", stamp_version)
    app.setup_extension("latex_question_sheets")  # same folder: one line in _config.yml
    app.add_post_transform(BrowserOnlyOutputs)
    app.add_post_transform(PrintLayout)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
