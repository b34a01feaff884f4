"""Each template's other site variants (Template.site_variants, never the teacher's reserve), for New numbers: a small script of data per template and
an SVG per variant's graph, under the site's _static/questions/, written when the HTML
build finishes. The script also holds the template's answer form as form.py writes it on a
page (window.QuestionForms), for the mock test, whose page holds no form until it draws one:
only a template the mock test can ask (mock_test.mock_asks) carries it.

Working them out (every variant of every template) and drawing 60-odd graphs with
matplotlib takes longer than the rest of a no-op rebuild, so the last build's inputs and
outputs are recorded beside the site (``html-question-variants.json``): with the same
inputs (the templates placed, the files of the bank, its shared modules and the graph
module, this extension's code, matplotlib) and every output still as written, nothing is
redone. When something did change, a graph whose own numbers and drawing code are as
before is not drawn again.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import json
from importlib.metadata import version
from pathlib import Path
from types import SimpleNamespace

from docutils import nodes
from fresh_figures import modules_digest  # book/_ext: the files a module runs, by content

from physics_figures.cores import on_every_core

from . import form, mock_test, store
from .directive import (
    _template_data,
    cursor_text,
    diagram_name,
    form_node,
    square_text,
    write_diagram,
    write_graph,
)

VARIANTS_DIR = "questions"  # under the site's _static/: one file of variants per template

#: The code that writes the variants, and the one that draws a graph: an edit redoes them.
WRITERS = (Path(__file__), Path(__file__).with_name("directive.py"), Path(__file__).with_name("form.py"))
GRAPH_WRITERS = (WRITERS[1], Path(__file__).parents[1] / "svg_compact.py")  # write_graph, svg_file


def record_path(outdir: Path) -> Path:
    """The last build's inputs and outputs, beside the site (no page loads it)."""
    return outdir.parent / f"{outdir.name}-question-variants.json"


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _code(app, modules: list[str], writers=WRITERS) -> str:
    """The files `modules` run, the `writers` and matplotlib's version (from its metadata:
    importing matplotlib takes a second)."""
    digest = hashlib.sha256(modules_digest(app, modules).encode())
    for path in writers:
        digest.update(path.read_bytes())
    digest.update(version("matplotlib").encode())
    return digest.hexdigest()


def _inputs(app, keys: list[str]) -> str:
    modules = [*store.bank_modules(app.config), store.GRAPH_MODULE, store.DIAGRAM_MODULE]
    return _sha256(json.dumps([keys, _code(app, modules)]).encode())


def _unchanged(folder: Path, files: dict[str, str]) -> bool:
    """Every output of the last build is still there, byte for byte."""
    return bool(files) and all((folder / name).is_file() and _sha256((folder / name).read_bytes()) == sha
                               for name, sha in files.items())


def _write(path: Path, content: bytes) -> str:
    if not path.exists() or path.read_bytes() != content:  # an unchanged file keeps its mtime
        path.write_bytes(content)
    return _sha256(content)


def write_variants(app, exception):
    """Each template's variants as a small script, loaded only when New numbers is pressed (a
    <script> element, so it works from file:// too, where fetch() does not)."""
    if exception or app.builder.format != "html":
        return
    keys = sorted({key for keys in store.templates_used(app.env).values() for key in keys})
    if not keys:
        return
    folder = Path(app.outdir) / "_static" / VARIANTS_DIR
    record_file = record_path(Path(app.outdir))
    last = json.loads(record_file.read_text()) if record_file.exists() else {}
    inputs = _inputs(app, keys)
    if last.get("inputs") == inputs and _unchanged(folder, last.get("files", {})):
        return
    folder.mkdir(parents=True, exist_ok=True)
    graph_code = _code(app, [store.GRAPH_MODULE, store.DIAGRAM_MODULE], list(GRAPH_WRITERS))
    graphs = last.get("graphs", {}) if last.get("graph_code") == graph_code else {}
    files, drawn_graphs = {}, {}
    # each template's on a core of its own: drawing the graphs is most of a cold build's last minute
    for written, drawn in on_every_core(functools.partial(_template_files, app, folder, graphs), keys):
        files.update(written)
        drawn_graphs.update(drawn)
    for name in set(last.get("files", {})) - set(files):  # a template no page places any more
        (folder / name).unlink(missing_ok=True)
    record_file.write_text(json.dumps({"inputs": inputs, "files": files, "graph_code": graph_code,
                                       "graphs": drawn_graphs}, indent=1, sort_keys=True))


def _template_files(app, folder: Path, graphs: dict, key: str) -> tuple[dict[str, str], dict[str, dict]]:
    """Write template `key`'s variants' script and figures into `folder` (none for a template
    without New numbers); ({file name: digest}, {figure name: its record}). `graphs`: the last
    build's records, so that a figure whose numbers and drawing code are the same is kept."""
    files, drawn_graphs = {}, {}
    template = store.template(app.config, key)
    if len(template.site_variants) < 2:  # no New numbers: nothing to load
        return files, drawn_graphs
    variants = []
    # the site's variants only: the reserve is the teacher's (physics_figures.variants)
    for index in template.site_variants:
        variant = template.variant(index)
        data = variant.variant_data()
        if variant.graph is not None:  # its own graph, beside the variants' script
            name = f"{key}-{index}.svg"
            drawn = _graph(folder, name, variant.graph, graphs, drawn_graphs)
            data["graph"] = {"src": name, "alt": drawn["alt"], "square": drawn["square"],
                             "cursor": json.loads(drawn["cursor"])}
            files[name] = drawn_graphs[name]["svg"]
        if variant.diagram is not None:  # its own diagram, labelled with its numbers
            name = diagram_name(key, index) + ".svg"
            data["diagram"] = {"src": name, "alt": _diagram(folder, name, variant.diagram, graphs, drawn_graphs)}
            files[name] = drawn_graphs[name]["svg"]
        variants.append(data)
    payload = json.dumps(variants, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    script = f"(window.QuestionVariants = window.QuestionVariants || {{}})[{json.dumps(key)}] = {payload};\n"
    if mock_test.mock_asks(template):  # its form, for the mock test (no other page draws one)
        answer_form = json.dumps(form_html(template), ensure_ascii=False).replace("</", "<\\/")
        script += f"(window.QuestionForms = window.QuestionForms || {{}})[{json.dumps(key)}] = {answer_form};\n"
    files[f"{key}.js"] = _write(folder / f"{key}.js", script.encode())
    return files, drawn_graphs


def _graph(folder: Path, name: str, graph, last: dict, drawn: dict) -> dict:
    """Draw one variant's graph unless the same numbers drew the file that is there; its alt text,
    its small square's size (for the enlarged view) and the graph cursor's data, with the file's
    digest."""
    numbers = _sha256(repr(graph).encode())
    before = last.get(name, {})
    path = folder / name
    if (before.get("numbers") == numbers and "cursor" in before and path.is_file()
            and _sha256(path.read_bytes()) == before["svg"]):
        drawn[name] = before
    else:
        figure = write_graph(folder, name.removesuffix(".svg"), graph, formats=("svg",))
        drawn[name] = {"numbers": numbers, "alt": figure.alt, "svg": _sha256(path.read_bytes()),
                       "square": square_text(path, graph), "cursor": cursor_text(path, graph)}
    return drawn[name]


def _diagram(folder: Path, name: str, diagram, last: dict, drawn: dict) -> str:
    """Draw one variant's diagram unless the same numbers drew the file that is there; its alt text."""
    numbers = _sha256(repr(diagram).encode())
    before = last.get(name, {})
    path = folder / name
    if before.get("numbers") == numbers and path.is_file() and _sha256(path.read_bytes()) == before["svg"]:
        drawn[name] = before
    else:
        figure = write_diagram(folder, name.removesuffix(".svg"), diagram, formats=("svg",))
        drawn[name] = {"numbers": numbers, "alt": figure.alt, "svg": _sha256(path.read_bytes())}
    return drawn[name]["alt"]


def form_html(template) -> str:
    """The template's answer form exactly as form.py writes it on a page (variant 0's words; the
    mock test relabels it with its variant's, as New numbers does), without what a page writes
    once above its first form (the rule table, feedback links, the units hint): the mock test's
    page holds those. form.py writes through a page's translator; this collects what it writes."""
    page = SimpleNamespace(body=[], _q_ideas_written=True, _q_unit_hint_written=True)
    with contextlib.suppress(nodes.SkipNode):
        form.visit_question_form(page, form_node(template.variant(0), _template_data(template)))
    return "".join(page.body)
