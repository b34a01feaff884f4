"""The browser's number writer, ``notation.js``: the twin of physics_figures/notation.py.

Pages that show numbers in the browser (questions, explorables) load it before their own
scripts with ``add_notation_script``; tests/notation_cases.json is run against both."""

from __future__ import annotations

from pathlib import Path

from sphinx.application import Sphinx

STATIC = Path(__file__).parent / "static"


def add_notation_script(app: Sphinx) -> None:
    """Load notation.js on the page being written, ahead of the scripts that use it."""
    app.add_js_file("notation.js", loading_method="defer", priority=400)


def _add_static_path(app: Sphinx) -> None:
    app.config.html_static_path.append(str(STATIC))


def setup(app: Sphinx):
    app.connect("builder-inited", _add_static_path)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
