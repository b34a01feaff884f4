"""The teachers' sheet builder: worksheets and keys made in the browser, no Python, no server::

    ```{sheet-builder}
    ```

The page holds the form (question types, total marks, versions, seed). When the HTML build
finishes, this module writes the teachers-only data the builder reads, ``teachers/sheet-data.js``
(not under _static: the site's own pages never load it, and the service worker keeps it only once
it has been opened, outside the first install). It holds, from physics_figures, the topic's types
(titles, exam counts) and every bank template (key, type, title, marks, one-wording flag, the
reserve's indices) with, for each reserve variant, its sheet body and key body as HTML
(physics_figures.worksheets.html: the PDF key's information), its graph inline as SVG. Each is
held as pieces, and a piece that several sheets and keys print (the question's text in its sheet
and its key, a graph's axes and grid, a template's answer spaces) is held once
(sheet_pieces.py): the file is half what it was whole. static/sheet-builder.js draws the sheets
with static/question-draw.js, the one draw the command line runs too (physics_figures.worksheets.draw,
under Node), and joins each sheet's and key's pieces; static/sheet-builder-page.js only assembles
the pages: it computes no physics and no key. The file is a script: the page fetches it and keeps it in its own cache (the Cache API) for offline
use, and from file://, where fetch() cannot read, a <script> element loads it.

Working every reserve variant out and drawing 76 graphs takes most of a minute, so, as for the
site's variants (variants.py), the last build's inputs and output are recorded beside the site:
the same inputs and the file as written redo nothing, and a graph whose numbers and drawing code
are unchanged is not drawn again.
"""

from __future__ import annotations

import json
import re
from html import escape
from pathlib import Path

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read the page when the bank changes
from sphinx.errors import ExtensionError
from sphinx.util.docutils import SphinxDirective
from svg_compact import ID_ATTRIBUTE, XML_HEAD, compact_svg  # book/_ext: a graph in fewer bytes

from physics_figures.cores import on_every_core

from . import store
from .sheet_pieces import ID_MARK, cut, share
from .variants import _code, _sha256, _unchanged, _write

DIRECTIVE = "sheet-builder"
#: Beside the PDFs of the kit (make worksheets), relative to the site's root.
DATA_FILE = "teachers/sheet-data.js"
#: The source's README, which the page links for the command line (the site has no other copy).
README = "teachers/README.txt"
#: What the data file is made from besides the topics: the sheets' HTML and its helpers, the
#: draws (physics_figures.worksheets), the graphs and the sketches.
SOURCES = ("physics_figures.worksheets", "physics_figures.worksheets.html", store.GRAPH_MODULE,
           store.DIAGRAM_MODULE, "physics_figures.figures.sketches")
NEEDS_BROWSER = ("The sheet builder runs in your web browser: open this page in the web version of the book, "
                 "with JavaScript on, to use it.")
DEFAULTS = {"marks": 30, "versions": 3, "seed": 2027}


class sheet_builder(nodes.General, nodes.Element):
    """The builder's form (HTML); a note elsewhere."""


class SheetBuilderDirective(SphinxDirective):
    def run(self):
        store.docs(self.env, DIRECTIVE).add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        topic = store.topics(self.config)[0]
        types = [{"key": kind.key, "title": kind.title, "versions": type_versions(topic, kind.key)}
                 for kind in topic.types]
        return [sheet_builder(types=types)]


def type_versions(topic, key: str) -> int:
    """How many versions a sheet of this type can have: each version its own numbers for every
    template of the type (the draw's worksheets.usable_versions), at most 26 (A to Z)."""
    from physics_figures.worksheets import MAX_VERSIONS, bank_templates, usable_versions

    return min([MAX_VERSIONS, *(usable_versions(t, topic) for t in bank_templates(topic) if t.type == key)])


#: The form, the status line and where the sheets go (hidden until the script runs). Every
#: control has its label; Enter in a field or the button makes the sheets (a form's submit).
#: Each type's box says how many versions its questions allow (data-versions): the Versions
#: field's label and limit follow the boxes ticked (sheet-builder-page.js).
PAGE = """\
<div class="sb" data-src="{src}">
<p class="sb-needs-js">{needs}</p>
<form class="sb-form" hidden novalidate>
<fieldset class="sb-types"><legend>Question types</legend>
{types}
</fieldset>
<div class="sb-numbers">
<label for="sb-marks">Total marks <input type="number" id="sb-marks" name="marks" min="1" step="1" value="{marks}"
 inputmode="numeric"></label>
<label for="sb-versions"><span>Versions (<span class="sb-versions-range">1 to {most}</span>)</span> <input type="number"
 id="sb-versions" name="versions" min="1" max="{most}" step="1" value="{versions}" inputmode="numeric"
 aria-describedby="sb-versions-why"></label>
<label for="sb-seed">Seed <input type="number" id="sb-seed" name="seed" min="0" step="1" value="{seed}"
 inputmode="numeric"></label>
</div>
<p class="sb-hint" id="sb-versions-why">{why}</p>
<fieldset class="sb-make-what"><legend>Make</legend>
<label class="sb-type"><input type="radio" name="make" value="both" checked> Sheets and their keys</label>
<label class="sb-type"><input type="radio" name="make" value="sheets"> Question sheets only</label>
<label class="sb-type"><input type="radio" name="make" value="keys"> Answer keys only</label>
</fieldset>
<div class="sb-buttons"><button type="submit" class="sb-make">Make the sheets</button>
<button type="button" class="sb-print" hidden>Print</button></div>
<p class="sb-status" role="status" aria-live="polite"></p>
</form>
<div class="sb-output" hidden></div>
</div>
"""


def versions_why(most: int) -> str:
    """What the Versions field's limit means, for the types ticked (the script rewrites it)."""
    return (f"The types ticked allow up to {most} versions: each version has its own numbers for every "
            "question, from those the site does not show. Untick a type to allow more.")


def visit_sheet_builder(self, node):
    types = "\n".join(
        f'<label class="sb-type"><input type="checkbox" name="types" value="{escape(kind["key"])}" '
        f'data-versions="{kind["versions"]}" checked> {escape(kind["title"])}</label>' for kind in node["types"])
    most = min(kind["versions"] for kind in node["types"])
    depth = self.builder.current_docname.count("/")  # the data file is at the site's root
    self.body.append(PAGE.format(src=escape("../" * depth + DATA_FILE), needs=escape(NEEDS_BROWSER), types=types,
                                 most=most, why=escape(versions_why(most)),
                                 **{**DEFAULTS, "versions": min(DEFAULTS["versions"], most)}))
    raise nodes.SkipNode


def fill(app, doctree, docname):
    """Outside HTML the page's text says the builder is on the website."""
    if app.builder.format != "html":
        for node in list(doctree.findall(sheet_builder)):
            node.replace_self(nodes.paragraph(text=NEEDS_BROWSER))


def add_assets(app, pagename, templatename, context, doctree):
    if pagename in store.docs(app.env, DIRECTIVE):
        app.add_css_file("sheet-builder.css")
        # the shared draws, the plan, then the page
        for script in ("question-draw.js", "sheet-builder.js", "sheet-builder-page.js"):
            app.add_js_file(script, loading_method="defer")


# ------------------------------------------------------------------------- the data file


def record_path(outdir: Path) -> Path:
    """The last build's inputs and output, beside the site (no page loads it)."""
    return outdir.parent / f"{outdir.name}-sheet-builder.json"


def graphs_folder(outdir: Path) -> Path:
    """The graphs drawn for the data file, kept beside the site for the next build."""
    return outdir.parent / f"{outdir.name}-sheet-builder-graphs"


def inline_svg(svg: str, *, prefix: str, alt: str) -> str:
    """A graph's SVG file as an element of a page: no XML prologue or metadata, no line breaks
    inside paths, compact (compact_svg), the ids nothing refers to dropped and the others made
    short and unique to this graph (several graphs share a page), sized by the page (viewBox
    kept) and named by its alt text."""
    svg = XML_HEAD.sub("", svg)
    svg = re.sub(r"\s*\n\s*", " ", svg).replace("> <", "><").strip()
    svg = compact_svg(svg)
    used = list(dict.fromkeys(re.findall(r'(?:href="#|url\(#)([^")]+)', svg)))
    short = {name: f"{prefix}{n}" for n, name in enumerate(used)}
    svg = ID_ATTRIBUTE.sub(lambda m: f' id="{short[m[1]]}"' if m[1] in short else "", svg)
    svg = re.sub(r'(href="#|url\(#)([^")]+)', lambda m: m[1] + short[m[2]], svg)
    return re.sub(r'<svg\b[^>]*?\swidth="[^"]*"\s+height="[^"]*"', lambda m: re.sub(
        r'\s(?:width|height)="[^"]*"', "", m[0]) + f' role="img" aria-label="{escape(alt)}"', svg, count=1)


def short_prefix(name: str) -> str:
    """The prefix of a graph's ids on a page: short, and the graph's own (write_data checks
    that no two graphs share one)."""
    return f"g{_sha256(name.encode())[:7]}-"


def _graph(folder: Path, name: str, graph, last: dict) -> tuple[dict, str]:
    """A variant's graph as inline SVG, drawn again only when its numbers changed; its record
    (its numbers' and its file's digests) and the SVG."""
    numbers = _sha256(repr(graph).encode())
    path = folder / f"{name}.svg"
    before = last.get(name, {})
    if not (before.get("numbers") == numbers and path.is_file() and _sha256(path.read_bytes()) == before.get("svg")):
        from physics_figures.figures.question_diagram import question_diagram
        from physics_figures.figures.question_graph import question_graph
        from physics_figures.questions import Diagram

        figure = question_diagram(graph) if isinstance(graph, Diagram) else question_graph(graph)
        text = inline_svg(figure.svg(), prefix=short_prefix(name), alt=figure.alt)
        figure.figure.clear()  # matplotlib keeps figures alive until cleared
        before = {"numbers": numbers, "svg": _write(path, text.encode())}
    return before, path.read_text(encoding="utf-8")


def picture_name(key: str, index: int) -> str:
    """The name of a reserve variant's graph (or diagram) in the builder's data and files."""
    return f"{key}-{index}"


def builder_pictures(topic) -> dict:
    """{picture_name: the graph to read or the situation drawn} of every reserve variant that
    prints one, as builder_pages draws them."""
    from physics_figures.worksheets import bank_templates

    pictures = {}
    for template in bank_templates(topic):
        for index in template.reserve_variants:
            question = template.variant(index)
            if (picture := question.graph or question.diagram) is not None:
                pictures[picture_name(template.key, index)] = picture
    return pictures


def builder_index(topic) -> dict:
    """What the builder draws from: the topic's types (title, exam count) and every bank
    template (key, type, title, marks, one-wording flag, the reserve's indices, the variants the
    ready-made worksheets print and where), in the bank's order; and the data line and mark codes every sheet and key prints."""
    from physics_figures.worksheets import DATA_LINE, bank_templates, ready_made, template_marks
    from physics_figures.worksheets.latex import KEY_CODES

    made = ready_made(topic)
    templates = [{"key": template.key, "type": template.type, "title": template.title,
                  "marks": template_marks(template), "oneWording": bool(template.one_wording),
                  "reserve": list(template.reserve_variants),
                  "readyMade": {str(i): where for i, where in made.get(template.key, {}).items()}}
                 for template in bank_templates(topic)]
    types = [{"key": kind.key, "title": kind.title, "examCount": kind.exam_count} for kind in topic.types]
    return {"topic": topic.name, "dataLine": DATA_LINE, "keyCodes": KEY_CODES, "types": types,
            "templates": templates}


def builder_data(topic, graph_svg) -> dict:
    """The index and every reserve variant's sheet and key (builder_pages)."""
    return {**builder_index(topic), **builder_pages(topic, graph_svg)}


def builder_pages(topic, graph_svg, keys: list[str] | None = None) -> dict:
    """For each bank template's reserve variant, its sheet and key as HTML, cut into pieces
    (sheet_pieces: what more than one variant prints is held once, in ``pieces``), with its
    graph's id prefix. ``graph_svg(name, graph)`` gives a graph's inline SVG, its ids prefixed
    by short_prefix(name). ``keys``: only these templates' variants (a test's few)."""
    from physics_figures.worksheets import bank_templates
    from physics_figures.worksheets.html import key_body, sheet_body

    pages, texts = [], []
    for template in bank_templates(topic):
        if keys is not None and template.key not in keys:
            continue
        for index in template.reserve_variants:
            question = template.variant(index)
            picture = question.graph or question.diagram  # a graph to read, or the situation drawn
            name = picture_name(template.key, index)
            svg = "" if picture is None else graph_svg(name, picture)
            pages.append((template.key, str(index), short_prefix(name) if svg else ""))
            texts += [sheet_body(question, svg), key_body(question)]
    return shared_pages(pages, texts)


def shared_pages(pages: list[tuple[str, str, str]], texts: list[str]) -> dict:
    """``pieces`` and ``variants``: each page's (key, index, graph's id prefix) sheet and key
    (``texts``: a sheet, then its key) as pieces, a graph's ids written ID_MARK."""
    marked = []
    for (key, index, ids), text in zip([p for p in pages for _ in (0, 1)], texts, strict=True):
        if ID_MARK in text:
            raise ExtensionError(f"sheet_builder: {key}-{index} prints {ID_MARK!r}, the graphs' id mark")
        marked.append(cut(text.replace(ids, ID_MARK) if ids else text))
    pieces, lists = share(marked)
    variants: dict[str, dict] = {}
    for n, (key, index, ids) in enumerate(pages):
        variants.setdefault(key, {})[index] = {"sheet": lists[2 * n], "key": lists[2 * n + 1],
                                               **({"ids": ids} if ids else {})}
    return {"idMark": ID_MARK, "pieces": pieces, "variants": variants}


def write_data(app, exception):
    """Write teachers/sheet-data.js, unless the last build wrote it from the same inputs."""
    if exception or app.builder.format != "html" or not store.docs(app.env, DIRECTIVE):
        return
    outdir = Path(app.outdir)
    target = outdir / DATA_FILE
    record_file = record_path(outdir)
    last = json.loads(record_file.read_text()) if record_file.exists() else {}
    modules = [*store.bank_modules(app.config), *SOURCES]
    inputs = _code(app, modules, (Path(__file__), Path(__file__).with_name("sheet_pieces.py")))
    readme = Path(app.confdir) / "README.md"
    if readme.is_file():  # a small copy, redone only when it changed
        (outdir / README).parent.mkdir(parents=True, exist_ok=True)
        _write(outdir / README, readme.read_bytes())
    if last.get("inputs") == inputs and _unchanged(outdir, last.get("files", {})):
        return
    graph_code = _code(app, [store.GRAPH_MODULE, store.DIAGRAM_MODULE], (Path(__file__),))
    last_graphs = last.get("graphs", {}) if last.get("graph_code") == graph_code else {}
    folder = graphs_folder(outdir)
    folder.mkdir(parents=True, exist_ok=True)
    topic = store.topics(app.config)[0]
    pictures = builder_pictures(topic)
    # each graph on a core of its own: drawing them one after another kept the book's build
    # waiting on one core for half a minute
    made = dict(zip(pictures, on_every_core(lambda name: _graph(folder, name, pictures[name], last_graphs),
                                            list(pictures)), strict=True))
    drawn = {name: record for name, (record, _) in made.items()}
    data = builder_data(topic, lambda name, graph: made[name][1])
    prefixes = {short_prefix(name) for name in drawn}
    if len(prefixes) != len(drawn):
        raise ExtensionError("sheet_builder: two graphs' ids share a prefix (short_prefix): lengthen it")
    payload = json.dumps(data, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    target.parent.mkdir(parents=True, exist_ok=True)
    files = {DATA_FILE: _write(target, f"window.SheetBuilderData = {payload};\n".encode())}
    record_file.write_text(json.dumps({"inputs": inputs, "files": files, "graph_code": graph_code,
                                       "graphs": drawn}, indent=1, sort_keys=True))


def setup(app):
    app.add_node(sheet_builder, html=(visit_sheet_builder, None))
    app.add_directive(DIRECTIVE, SheetBuilderDirective)
    app.connect("doctree-resolved", fill)
    app.connect("html-page-context", add_assets)
    app.connect("build-finished", write_data)
