"""Turn a physics_figures figure output into a numbered, captioned, alt-texted figure.

A figure cell's output (``physics_figures.figures.book_figure.BookFigure``) is a mime
bundle: the image as SVG and PDF, the alt text as ``text/plain``, and the caption
as ``text/markdown`` that starts with the MyST comment ``% physics-figure <name>``.
myst-nb renders every format into the doctree and picks one per builder later
(its ``SelectMimeType`` post-transform). Before that, this transform:

1. takes the name from the comment and the caption from the parsed Markdown
   (CommonMark by default: emphasis, Unicode units such as m s⁻¹);
2. puts the alt text on every image of the bundle;
3. drops the text formats and wraps the bundle in a ``figure`` node with the
   caption and the name, so Sphinx numbers it and ``{numref}`` can point to it;
4. puts the figure's description and "Data" disclosure (an HTML block after the caption:
   the longer description and the table of plotted values) right after the figure, and
   names the description in the image's ``aria-describedby`` (issue 28). It is raw HTML, so the PDF
   leaves it out: the PDF keeps the caption, and the table and description stay online.

The page therefore carries one line per figure and never repeats its words.
"""

from __future__ import annotations

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.transforms import SphinxTransform
from sphinx.util import logging
from sphinx.writers.html5 import HTML5Translator

logger = logging.getLogger(__name__)


def _mime_child(bundle: nodes.Element, mime_type: str) -> nodes.Element | None:
    for child in bundle.children:
        if isinstance(child, nodes.container) and child.get("mime_type") == mime_type:
            return child
    return None


def _figure_name(markdown: nodes.Element | None) -> str | None:
    """The name in a leading ``% physics-figure <name>`` line, if there is one.

    myst-nb parses Markdown outputs as CommonMark by default
    (``nb_render_markdown_format``), where that line is a paragraph; as MyST it
    is a comment. Both are accepted.
    """
    if markdown is None or not markdown.children:
        return None
    first = markdown.children[0]
    if not isinstance(first, (nodes.comment, nodes.paragraph)):
        return None
    # imported here: book_figure imports matplotlib (a second at start-up), needed only when
    # a page with figures is read
    from physics_figures.figures.book_figure import FIGURE_MARKER

    words = first.astext().lstrip("% ").split()
    if len(words) == 2 and words[0] == FIGURE_MARKER:
        return words[1]
    return None


def _description_id(name: str) -> str:
    from physics_figures.figures.book_figure import description_id  # (see _figure_name)

    return description_id(name)


class FigureFromOutput(SphinxTransform):
    """Wrap each marked figure output in a named figure with caption and alt text."""

    # before SphinxDomains (850) collects the labels that {numref} resolves
    default_priority = 400

    def apply(self, **kwargs) -> None:
        bundles = [
            node
            for node in self.document.findall(nodes.container)
            if node.get("nb_element") == "mime_bundle"
        ]
        for bundle in bundles:
            markdown = _mime_child(bundle, "text/markdown")
            name = _figure_name(markdown)
            if name is None:
                continue
            plain = _mime_child(bundle, "text/plain")
            alt = plain.astext().strip() if plain is not None else ""
            if not alt:
                logger.warning(
                    "figure %r has no alt text", name, location=bundle, type="figure_captions"
                )
            paragraphs = [n for n in markdown.children[1:] if isinstance(n, nodes.paragraph)]
            if len(paragraphs) != 1:
                logger.warning(
                    "figure %r needs a caption of one paragraph (got %d)",
                    name,
                    len(paragraphs),
                    location=bundle,
                    type="figure_captions",
                )
                continue
            disclosure = [n for n in markdown.children[1:] if isinstance(n, nodes.raw)]
            if not disclosure:
                logger.warning(
                    "figure %r has no data table and description (BookFigure.data_html)",
                    name,
                    location=bundle,
                    type="figure_captions",
                )
            bundle.remove(markdown)
            if plain is not None:
                bundle.remove(plain)
            for image in bundle.findall(nodes.image):
                image["alt"] = alt
                if disclosure:
                    image[DESCRIBED_BY] = _description_id(name)
                # the theme dims images in dark mode unless they are marked as ready for
                # it; _static/figures.css gives ours a light paper card instead
                image["classes"].append("dark-light")

            caption = nodes.caption(paragraphs[0].rawsource, "", *paragraphs[0].children)
            figure = nodes.figure("", classes=["physics-figure"])
            figure.source, figure.line = bundle.source, bundle.line
            caption.source, caption.line = bundle.source, bundle.line
            bundle.replace_self(figure)
            figure += bundle
            figure += caption
            figure["names"].append(nodes.fully_normalize_name(name))
            self.document.note_explicit_target(figure, figure)
            figure.parent.insert(figure.parent.index(figure) + 1, disclosure)


#: Image attribute naming the element that describes it (written as aria-describedby).
DESCRIBED_BY = "describedby"


def visit_image_described(self, node: nodes.image) -> None:
    """HTML: the standard <img>, plus aria-describedby when the figure has a description
    (docutils images carry no ARIA attributes of their own)."""
    HTML5Translator.visit_image(self, node)
    target = node.get(DESCRIBED_BY)
    if target and self.body and self.body[-1].startswith("<img "):
        tag = self.body[-1]
        end = tag.rindex("/>") if tag.rstrip().endswith("/>") else tag.rindex(">")
        self.body[-1] = f'{tag[:end].rstrip()} aria-describedby="{target}" {tag[end:]}'


def setup(app: Sphinx) -> dict:
    app.add_transform(FigureFromOutput)
    app.add_node(nodes.image, override=True, html=(visit_image_described, HTML5Translator.depart_image))
    return {"parallel_read_safe": True, "parallel_write_safe": True}
