"""How numbers are written on the page, at build time and in the browser.

* ``JoinUnits``, a docutils post-transform, joins every number in the prose to its unit,
  and the unit's symbols to each other, with no-break spaces (physics_figures.notation.
  join_units): "12 000 kg m s⁻¹" never breaks across lines, in HTML or in the PDF (the
  LaTeX writer turns U+00A0 into ~). A unit written after a glued value is joined to it.
* ``notation.js``, the browser's number writer, the twin of physics_figures/notation.py.
  Pages that show numbers in the browser (questions, explorables) load it before their
  own scripts with ``add_notation_script``; tests/notation_cases.json is run against both."""

from __future__ import annotations

from pathlib import Path

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.transforms.post_transforms import SphinxPostTransform

from physics_figures.notation import LEADING_UNIT, UNIT_SPACE, join_units

STATIC = Path(__file__).parent / "static"


def add_notation_script(app: Sphinx) -> None:
    """Load notation.js on the page being written, ahead of the scripts that use it."""
    app.add_js_file("notation.js", loading_method="defer", priority=400)


def _add_static_path(app: Sphinx) -> None:
    app.config.html_static_path.append(str(STATIC))


#: Text inside these is code or markup, never prose: left as it is.
_NOT_PROSE = (nodes.literal, nodes.literal_block, nodes.raw, nodes.comment, nodes.math, nodes.math_block,
              nodes.FixedTextElement)


class JoinUnits(SphinxPostTransform):
    """Join numbers to their units in every paragraph, caption, title and table cell."""

    default_priority = 900  # after glued values are pasted in

    def run(self, **kwargs) -> None:
        join_units_in(self.document)


def join_units_in(doctree: nodes.Node) -> None:
    """Every number in the prose of ``doctree`` joined to its unit (no-break spaces)."""
    for block in list(doctree.findall(nodes.TextElement)):
        if isinstance(block, (nodes.Inline, *_NOT_PROSE)):
            continue
        previous = ""  # the text just before, in this block: does it end in a number?
        pending = None  # a text of spaces alone right after a number (MyST splits lines)
        for node in list(block.findall(lambda n: isinstance(n, (nodes.Text, nodes.math)))):
            if isinstance(node, nodes.Text) and isinstance(node.parent, nodes.math):
                continue  # the maths' own source, dealt with as its math node
            if isinstance(node, nodes.math) and node.astext().lstrip().startswith(("^", "_")):
                continue  # a power written as maths (10$^{-6}$ m): the number goes on to its unit
            if isinstance(node, nodes.math) or _inside_code(node, block):
                previous, pending = node.astext(), None
                continue
            if node.parent is None or _owner(node) is not block:
                continue  # a nested block (a list inside a cell) has its own turn
            text = str(node)
            if not text.strip() and previous[-1:].isdigit():
                pending = node
                continue
            after_number = previous[-1:].isdigit() or pending is not None
            joined = join_units(text, after_number=after_number)
            if pending is not None and LEADING_UNIT.match(text):
                _replace(pending, nodes.Text(UNIT_SPACE))  # "2.0" "\n" "m s" -> joined
            pending = None
            if joined != text:
                _replace(node, nodes.Text(joined))
            previous = joined


def _join_late(app: Sphinx, doctree: nodes.document, docname: str) -> None:
    """Text added once the post-transforms have run (e.g. the answer key) is joined too."""
    join_units_in(doctree)


def _replace(old: nodes.Text, new: nodes.Text) -> None:
    """Put ``new`` where ``old`` is. (Element.replace finds a child by ==, and two Text
    nodes with the same text are equal: it could replace another "\n".)"""
    parent = old.parent
    index = next(i for i, child in enumerate(parent.children) if child is old)
    parent.children[index] = new
    new.parent = parent


def _inside_code(node: nodes.Node, block: nodes.Element) -> bool:
    parent = node.parent
    while parent is not None and parent is not block:
        if isinstance(parent, _NOT_PROSE):
            return True
        parent = parent.parent
    return False


def _owner(node: nodes.Node) -> nodes.Element | None:
    """The nearest block (not inline) element holding ``node``."""
    parent = node.parent
    while parent is not None and isinstance(parent, nodes.Inline):
        parent = parent.parent
    return parent


def setup(app: Sphinx):
    app.add_post_transform(JoinUnits)
    app.connect("doctree-resolved", _join_late, priority=900)
    app.connect("builder-inited", _add_static_path)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
