"""Worked-example solutions that open from their whole header, named for what they open.

sphinx-exercise titles a solution "Solution to Exercise 2 (…)" with most of the title a
link back to the question, and sphinx-togglebutton adds a small chevron button that a
screen reader hears as "Toggle hidden content". ``solution-toggles.js`` turns the header
into the one toggle: togglebutton's own button, stretched over the whole header and named
"Show the solution to Example 2" (the page's example number), "Hide …" once open. Without
JavaScript, and in print, the solution is shown as it is.
"""

from __future__ import annotations

import re
from pathlib import Path

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.transforms.post_transforms import SphinxPostTransform

STATIC = Path(__file__).parent / "static"


def _add_static_path(app: Sphinx) -> None:
    app.config.html_static_path.append(str(STATIC))


def _add_page_assets(app: Sphinx, pagename: str, templatename: str, context, doctree) -> None:
    """Only pages with a dropdown solution load the script (after togglebutton.js)."""
    if 'class="solution dropdown' in context.get("body", ""):
        app.add_js_file("solution-toggles.js", loading_method="defer", priority=800)
        app.add_css_file("solution-toggles.css")


class SolutionTitles(SphinxPostTransform):
    """A worked example's solution is "Solution to Example 2 (…)", as its question is labelled
    (_config.yml's numfig_format): sphinx-exercise writes the word "Exercise" into a solution's
    title whatever the format says, in the site and the PDF."""

    default_priority = 23  # after sphinx-exercise's own titles (21) and link texts (22)

    def run(self, **kwargs) -> None:
        label = self.app.config.numfig_format.get("exercise", "")
        if "%s" not in label:
            return
        for title in self.document.findall(nodes.title):
            parent = title.parent
            if parent is None or "solution" not in parent.get("classes", []):
                continue
            for text in list(title.findall(nodes.Text)):
                renamed = re.sub(r"\bExercise (\d+)", lambda m: label % m.group(1), str(text))
                if renamed != str(text):
                    text.parent.replace(text, nodes.Text(renamed))


def setup(app: Sphinx):
    app.add_post_transform(SolutionTitles)
    app.connect("builder-inited", _add_static_path)
    app.connect("html-page-context", _add_page_assets)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
