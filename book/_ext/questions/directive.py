"""The ``question`` directive and the data it writes.

A page places a template of one of the book's topics (physics_figures.topics; _config.yml
names them in question_topics) by its key; the
template writes its own text, with the printed numbers (variant 0)::

    ```{question} quick-check-1
    ```

The directive makes the question's nodes: title, text, graph, the printed answer lines
(with their prompt and marks as data, which the question sheet reads), the answer form
(written by form.py) and the worked answer with its mark scheme. After the build, each
template's other variants go to a small script of data, loaded by New numbers (variants.py).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective
from svg_compact import svg_file  # book/_ext: a figure in fewer bytes

from . import store

logger = logging.getLogger(__name__)


class question(nodes.General, nodes.Element):
    """A question: title, text, answer lines, answer boxes (HTML) and worked answer."""


class question_form(nodes.General, nodes.Element):
    """The answer boxes, marked in the browser (HTML only)."""


class worked_answer(nodes.General, nodes.Element):
    """The worked answer and mark scheme, shown after an attempt (HTML only)."""


class graph_view(nodes.General, nodes.Element):
    """The question's graph as a button that opens it enlarged (static/graph-view.js): ``square``
    is a small square's width and height as fractions of the image's width, ``cursor`` the graph
    cursor's data (JSON, static/graph-cursor.js). In HTML only; print
    shows the image alone (print_form.py)."""


class QuestionDirective(SphinxDirective):
    """A template of the bank, named by its key; its text comes with its numbers."""

    optional_arguments = 1
    final_argument_whitespace = True
    has_content = True

    def run(self):
        template = self._template()
        data, title = template.variant(0), template.title
        if self.content:
            raise self.error(f"question {template.key}: a template writes its own text; "
                             "leave the directive empty")
        # An edit to these (or to what they import) re-reads this page.
        uses_modules(self.env, *store.bank_modules(self.config))
        if data.graph is not None:
            uses_modules(self.env, store.GRAPH_MODULE)
        store.templates_used(self.env).setdefault(self.env.docname, []).append(template.key)

        node = question(qid=data.key, data=data.browser_data(), ids=[f"question-{data.key}"],
                        template=_template_data(template))
        self.set_source_info(node)
        node += nodes.paragraph("", "", nodes.strong(text=title), classes=["q-title"])
        node += nodes.container("", *text_nodes(data.text), classes=["q-text"])
        if data.graph is not None:
            node += self._graph(template.key, data.graph)
        if data.diagram is not None:
            uses_modules(self.env, store.DIAGRAM_MODULE)
            node += self._diagram(template.key, data.diagram)
        lines = nodes.container(classes=["q-answer-lines"])
        marks = data.part_marks()  # the one count the browser, sheets and Moodle use
        for index, part in enumerate(data.parts):
            lines += answer_lines(data.label(index), part, marks[index])
        lines += nodes.paragraph(text=f"Total: {store.count(sum(marks), 'mark', 'marks')}", classes=["q-total"],
                                 marks=sum(marks))
        node += lines
        node += form_node(data, node["template"], node["data"])
        worked = worked_answer()
        worked += mark_scheme_nodes(data)
        node += worked

        self._record(node, data, title, worked)
        return [node]

    def _template(self):
        if not self.arguments:
            raise self.error("question: name a template of the book's topics")
        try:
            return store.template(self.config, self.arguments[0])
        except ValueError as error:
            raise self.error(f"question: {error}") from error

    def _format(self) -> str:
        """The format this build prints a question's figures in: PDF for the book (LaTeX), SVG
        for the site. Each builder keeps its own environment and its own folder of figures
        (GRAPHS_DIR beside its doctrees), so neither draws the other's: a PDF is half a second of
        matplotlib's font subsetting that the site never shows."""
        return "pdf" if self.env.app.builder.format == "latex" else "svg"

    def _graph(self, key: str, graph) -> graph_view:
        """The printed variant's graph, drawn now in this build's format (_format): an image
        Sphinx copies like any other; on the site, inside the button that enlarges it."""
        folder = Path(self.env.doctreedir).parent / GRAPHS_DIR
        drawn = write_graph(folder, f"{key}-0", graph, formats=(self._format(),))
        here = Path(self.env.srcdir) / Path(self.env.docname).parent
        uri = Path(os.path.relpath(folder / f"{key}-0", here)).as_posix() + ".*"
        image = nodes.image(uri=uri, alt=drawn.alt, classes=["q-graph"])
        if self._format() != "svg":  # print: no enlarged view, no cursor
            return graph_view("", image, square="", cursor="")
        return graph_view("", image, square=square_text(folder / f"{key}-0.svg", graph),
                          cursor=cursor_text(folder / f"{key}-0.svg", graph))

    def _diagram(self, key: str, diagram) -> nodes.image:
        """The printed variant's diagram, in this build's format (_format), like its graph."""
        folder = Path(self.env.doctreedir).parent / GRAPHS_DIR
        drawn = write_diagram(folder, diagram_name(key, 0), diagram, formats=(self._format(),))
        here = Path(self.env.srcdir) / Path(self.env.docname).parent
        uri = Path(os.path.relpath(folder / diagram_name(key, 0), here)).as_posix() + ".*"
        return nodes.image(uri=uri, alt=drawn.alt, classes=["q-diagram"])

    def _record(self, node: question, data, title: str, worked: worked_answer) -> None:
        for docname, asked in store.questions(self.env).items():
            if any(q["key"] == data.key for q in asked):
                logger.warning(f"question {data.key} is asked twice (also in {docname})",
                               location=self.get_location())
        store.questions(self.env).setdefault(self.env.docname, []).append({
            "key": data.key, "title": title, "marks": data.marks, "try_first": node["template"]["tryFirst"],
            "graph": data.graph is not None,  # the page loads the enlarged graph view
            "kinds": sorted({part.kind for part in data.parts}),  # the page loads these kinds' markers
            "assets": sorted({asset for part in data.parts for asset in part.page_assets}),  # its kinds' own
            "answers": [data.label(i) + f"{p.prompt}: {p.answer_text}" for i, p in enumerate(data.parts)],
            "scheme": [child.deepcopy() for child in worked.children],
        })


class Paper:
    """What a part kind's ``print_lines`` builds its printed lines with (docutils nodes): the
    part on paper and on the page without JavaScript (physics_figures/parts/__init__.py)."""

    @staticmethod
    def line(text: str, **attributes) -> nodes.paragraph:
        """A line of plain text; attributes (classes, data) for the question sheet to read."""
        return nodes.paragraph(text=text, **attributes)

    @staticmethod
    def options(items: list[list[nodes.Node]]) -> nodes.enumerated_list:
        """Options lettered A, B, C, ..., each from its nodes."""
        options = nodes.enumerated_list(enumtype="upperalpha", classes=["q-options-print"])
        for item in items:
            options += nodes.list_item("", *item)
        return options

    @staticmethod
    def rich(source: str) -> list[nodes.Node]:
        """Text in the bank's text format."""
        return text_nodes(source)

    @staticmethod
    def figure(svg: str, tikz: str) -> list[nodes.Node]:
        """A drawing given as SVG (the page) and TikZ (the PDF book): a sketch part's blank axes."""
        return [nodes.raw("", svg, format="html"), nodes.raw("", tikz, format="latex")]

    @staticmethod
    def sketch(sketch) -> list[nodes.Node]:
        """A sketch graph (SVG on the page, TikZ in the PDF)."""
        return sketch_nodes(sketch)


def answer_lines(label: str, part, marks: int) -> list[nodes.Node]:
    """What a part prints on paper, as its kind prints it (its options and a box for the
    letter, lines for an explanation, a line for a value...); each ends with the part's
    marks, [2], as on a Cambridge paper."""
    return part.print_lines(label, marks, Paper)


def sketch_nodes(sketch) -> list[nodes.Node]:
    """A sketch option on paper and without JavaScript: the same drawing as SVG (HTML) and
    TikZ (the PDF book, whose tcolorbox loads TikZ)."""
    from physics_figures.figures.sketches import sketch_svg, sketch_tikz

    return [nodes.raw("", sketch_svg(sketch), format="html"), nodes.raw("", sketch_tikz(sketch), format="latex")]


def form_node(data, template: dict, browser_data: dict | None = None) -> question_form:
    """The answer form of a variant (`data`) of a template (`template`: _template_data), which
    form.py writes: on its page, and into the variants' data file for the mock test."""
    return question_form(data=browser_data or data.browser_data(), template=template,
                         labels=[data.label(i) for i in range(len(data.parts))],
                         legends=[data.label(i) + p.prompt[:1].upper() + p.prompt[1:]
                                  for i, p in enumerate(data.parts)])


def _template_data(template) -> dict:
    return {"key": template.key, "type": template.type, "kinds": list(template.kinds),
            "variants": len(template.site_variants), "tryFirst": bool(template.try_first)}


_TAG_NODES = {"sup": nodes.superscript, "sub": nodes.subscript, "em": nodes.emphasis,
              "strong": nodes.strong}


def _inline_nodes(spans) -> list[nodes.Node]:
    out = []
    for span in spans:
        node = nodes.Text(span.text)
        for tag in reversed(span.tags):
            node = _TAG_NODES[tag]("", "", node)
        out.append(node)
    return out


def text_nodes(source: str) -> list[nodes.Node]:
    """Paragraphs of docutils nodes from physics_figures.textformat (HTML, LaTeX, text alike)."""
    from physics_figures import textformat

    return [nodes.paragraph("", "", *_inline_nodes(spans)) for spans in textformat.parse(source)]


def mark_scheme_nodes(data) -> list[nodes.Node]:
    from physics_figures import textformat

    items = nodes.bullet_list(classes=["q-scheme"])
    for label, text, code in data.mark_lines():
        line = nodes.paragraph()
        if label:
            line += [nodes.strong(text=label), nodes.Text(" ")]
        for spans in textformat.parse(text):
            line += _inline_nodes(spans)
        if code:
            line += [nodes.Text(" "), nodes.strong(text=code)]
        items += nodes.list_item("", line)
    return [items]


GRAPHS_DIR = "question-graphs"  # beside the doctrees: the printed variants' graphs, as sources


def square_text(svg: Path, graph) -> str:
    """A small square's size in the drawn SVG as the enlarged view reads it (data-square):
    width and height as fractions of the image's width, "0.01535 0.01784"."""
    from physics_figures.figures.question_graph import small_square

    return " ".join(f"{fraction:.5g}" for fraction in small_square(svg.read_text(encoding="utf-8"), graph))


def cursor_text(svg: Path, graph) -> str:
    """The graph cursor's data (static/graph-cursor.js) as compact JSON: axes, readings at
    each half small square, the plot area (physics_figures/figures/question_graph.py)."""
    from physics_figures.figures.question_graph import cursor_data

    return json.dumps(cursor_data(svg.read_text(encoding="utf-8"), graph), ensure_ascii=False, separators=(",", ":"))


def _write_figure(folder: Path, name: str, drawn, formats: tuple[str, ...]):
    """Write a drawn question figure into folder/name.<format>, rewriting a file only when its
    bytes change (so an unchanged figure is not copied again). Returns the BookFigure."""
    folder.mkdir(parents=True, exist_ok=True)
    for extension in formats:
        # the site's SVG compact (svg_compact.py): a page's graphs weigh a third less
        content = svg_file(drawn.svg()).encode() if extension == "svg" else drawn.pdf()
        path = folder / f"{name}.{extension}"
        if not path.exists() or path.read_bytes() != content:
            path.write_bytes(content)
    drawn.figure.clear()  # matplotlib keeps figures alive until cleared
    return drawn


def write_graph(folder: Path, name: str, graph, *, formats: tuple[str, ...]):
    """Draw a question's graph into folder/name.<format> (see _write_figure)."""
    from physics_figures.figures.question_graph import question_graph

    return _write_figure(folder, name, question_graph(graph), formats)


def diagram_name(key: str, index: int) -> str:
    """A variant's diagram's file name, without its extension."""
    return f"{key}-diagram-{index}"


def write_diagram(folder: Path, name: str, diagram, *, formats: tuple[str, ...]):
    """Draw a question's diagram into folder/name.<format> (physics_figures.figures.question_diagram;
    see _write_figure)."""
    from physics_figures.figures.question_diagram import question_diagram

    return _write_figure(folder, name, question_diagram(diagram), formats)
