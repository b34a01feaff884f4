"""A site that is fast, private and offline: no CDN, no heavy scripts, no console errors.

What this extension does to the HTML build (the PDF build is untouched):

- **Maths at build time.** TeX is rendered to SVG by MathJax 3 (npm ``mathjax``, run
  by ``node`` through ``tex2svg.js``), with the MathML beside it for screen readers. The
  site ships no maths JavaScript and no maths fonts, so it renders with the network
  off and nothing shifts while the page loads. A TeX error fails the build.
- **Icons without the 1.5 MB Font Awesome script.** The theme draws its icons with the
  Font Awesome font; a subset with only the glyphs the theme uses (a few kB) replaces
  the 150 kB font (``_static/site.css`` points at it), and the template ``layout.html``
  drops the script.
- **One stylesheet, no blocking scripts.** Every screen stylesheet (the theme's and each
  extension's, root ``_static/*.css`` included) is joined into one bundle per set of
  stylesheets; scripts are deferred. A phone on a slow network paints sooner.
- **No dead weight or errors.** Thebe (live code via Binder: not used, and its script is
  added twice) is removed; the search index is loaded on the search page only; myst-nb's
  code toggles and the navigation's toggles get names that match what they show.
- **Menus that work.** ``static/site-menus.js`` binds the sidebar toggles a reader
  sees (the themes bind hidden duplicates); the search page loads Sphinx's search
  scripts deferred like the rest (``book/_templates/search.html``).
- **Findable.** Each page gets a meta description (its first paragraph), the site a
  ``robots.txt`` and a root ``index.html`` that is a real page leading to the book.

Needs ``node`` and ``npm ci`` (package.json at the repository root pins mathjax).
"""

from __future__ import annotations

import hashlib
import html
import json
import os
import re
import shutil
import subprocess
import threading
from pathlib import Path
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.errors import ExtensionError
from sphinx.locale import _
from sphinx.util import logging
from sphinx.util.math import get_node_equation_number

logger = logging.getLogger(__name__)

HERE = Path(__file__).resolve().parent
ASSETS = "site-assets"  # folder under the site's _static/ for what this extension writes

# ---------------------------------------------------------------- maths to SVG


class TexToSvg:
    """A long-lived ``node tex2svg.js`` process: one request and one reply per line."""

    def __init__(self, mathjax_dir: Path):
        self.mathjax_dir = mathjax_dir
        self._process: subprocess.Popen | None = None
        self._lock = threading.Lock()
        self._cache: dict[tuple[str, bool], tuple[str, str]] = {}

    def _start(self) -> subprocess.Popen:
        node = shutil.which("node")
        if node is None:
            raise ExtensionError("site_assets: `node` is missing (apt-get install nodejs npm)")
        if not (self.mathjax_dir / "package.json").exists():
            raise ExtensionError(
                f"site_assets: MathJax is missing at {self.mathjax_dir}: run `npm ci` at the "
                "repository root (package.json pins it)"
            )
        return subprocess.Popen(
            [node, str(HERE / "tex2svg.js"), str(self.mathjax_dir)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            encoding="utf-8",
        )

    def render(self, tex: str, *, display: bool) -> tuple[str, str]:
        """(svg, mathml) for `tex`; ValueError with MathJax's message on a TeX error."""
        key = (tex, display)
        if key in self._cache:
            return self._cache[key]
        with self._lock:
            if self._process is None or self._process.poll() is not None:
                self._process = self._start()
            self._process.stdin.write(json.dumps({"tex": tex, "display": display}) + "\n")
            self._process.stdin.flush()
            line = self._process.stdout.readline()
        if not line:
            raise ExtensionError("site_assets: the MathJax process stopped (is `npm ci` done?)")
        reply = json.loads(line)
        if reply["error"]:
            raise ValueError(reply["error"])
        mathml = re.sub(r">\s+<", "><", reply["mathml"].strip())
        self._cache[key] = (reply["svg"], mathml)
        return self._cache[key]

    def close(self) -> None:
        if self._process is not None:
            self._process.stdin.close()
            self._process.wait(timeout=10)
            self._process = None


def _math_markup(translator, node, tex: str, *, display: bool) -> str:
    """The SVG (hidden from screen readers) followed by its MathML (hidden from sight)."""
    try:
        svg, mathml = translator.builder.app._site_tex.render(tex, display=display)
    except ValueError as error:
        logger.warning("TeX error in %r: %s", tex, error, location=node, type="site_assets")
        return f'<code class="math-error">{html.escape(tex)}</code>'
    svg = svg.replace("<svg ", '<svg aria-hidden="true" ', 1)
    return f'{svg}<span class="math-mathml">{mathml}</span>'


def visit_math(self, node: nodes.math) -> None:
    tex = node.astext()
    # A power or index written as maths right after a word (the s^{-1} of "m s$^{-1}$")
    # must not wrap to the next line on its own: the word and the maths go in one
    # unbreakable span.
    word = ""
    if tex.lstrip().startswith(("^", "_")) and self.body and not self.body[-1].endswith(">"):
        before, word = re.match(r"(.*?)(\S*)$", self.body[-1], flags=re.DOTALL).groups()
        self.body[-1] = before
    if word:
        self.body.append(f'<span class="math-with-word">{word}')
    # data-tex keeps the source: for copying, and for tests that read the page's text.
    self.body.append(self.starttag(node, "span", "", CLASS="math notranslate nohighlight",
                                   **{"data-tex": tex}))
    self.body.append(_math_markup(self, node, tex, display=False) + "</span>")
    if word:
        self.body.append("</span>")
    raise nodes.SkipNode


def visit_displaymath(self, node: nodes.math_block) -> None:
    self.body.append(self.starttag(node, "div", CLASS="math notranslate nohighlight",
                                   **{"data-tex": node.astext()}))
    if node["number"] and not node["nowrap"]:
        self.body.append(f'<span class="eqno">({get_node_equation_number(self, node)})')
        self.add_permalink_ref(node, _("Link to this equation"))
        self.body.append("</span>")
    tex = node.astext()
    if not node["nowrap"]:
        # As Sphinx's MathJax writer: blank-line separated equations are aligned.
        parts = [part for part in tex.split("\n\n") if part.strip()]
        if len(parts) > 1:
            tex = r"\begin{aligned}" + r"\\".join(parts) + r"\end{aligned}"
        elif r"\\" in tex:
            tex = r"\begin{split}" + tex + r"\end{split}"
    markup = _math_markup(self, node, tex, display=True)
    self.body.append(f'<span class="math-display">{markup}</span></div>\n')
    raise nodes.SkipNode


# ---------------------------------------------------------------- icon font subset


def _theme_dirs() -> list[Path]:
    import pydata_sphinx_theme
    import sphinx_book_theme

    return [
        Path(pydata_sphinx_theme.__file__).parent / "theme" / "pydata_sphinx_theme",
        Path(sphinx_book_theme.__file__).parent / "theme" / "sphinx_book_theme",
    ]


def icon_code_points() -> set[int]:
    """Every Font Awesome glyph the themes' templates or stylesheets can show."""
    pydata, book = _theme_dirs()
    css = (pydata / "static/styles/pydata-sphinx-theme.css").read_text()
    by_class = {}
    for selectors, code in re.findall(r'([^{}]+)\{content:"\\([0-9a-f]{4})"\}', css):
        for selector in selectors.split(","):
            if match := re.fullmatch(r"\s*\.(fa-[a-z0-9-]+):before\s*", selector):
                by_class[match[1]] = int(code, 16)
    # Templates, and the Python that writes HTML (e.g. the navigation's chevrons).
    sources = [pydata.parents[1], book.parents[1], HERE.parents[1] / "_templates"]
    templates = " ".join(
        p.read_text() for d in sources if d.exists() for p in d.rglob("*") if p.suffix in {".html", ".py"}
    )
    points = {by_class[name] for name in re.findall(r"\bfa-[a-z0-9-]+", templates) if name in by_class}
    # Icons drawn by CSS alone (admonition titles, arrows, dropdown carets).
    book_css = (book / "static/styles/sphinx-book-theme.css").read_text()
    points |= {ord(ch) for ch in re.findall(r'--pst-icon-[a-z-]+:"(.)"', css)}
    points |= {int(code, 16) for code in re.findall(r'content:"\\(f[0-9a-f]{3})"', book_css)}
    return points


def write_icon_font(app: Sphinx) -> Path:
    """A WOFF font with only the Font Awesome glyphs the theme uses (it ships all 1,400).

    ``_static/site.css`` declares it under the theme's font name, after the theme's own
    declaration, so the browser never fetches the 150 kB original.
    """
    from fontTools import subset
    from fontTools.ttLib import TTFont

    source = _theme_dirs()[0] / "static/vendor/fontawesome/webfonts/fa-solid-900.ttf"
    target = Path(app.outdir) / "_static" / ASSETS / "icons.woff"
    newest_input = max(source.stat().st_mtime, Path(__file__).stat().st_mtime)
    if target.exists() and target.stat().st_mtime >= newest_input:
        return target
    options = subset.Options()
    options.flavor = "woff"  # zlib compression: needs no brotli module
    options.layout_features = []
    options.name_IDs = [1, 2]
    font = TTFont(source)
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=sorted(icon_code_points()))
    subsetter.subset(font)
    target.parent.mkdir(parents=True, exist_ok=True)
    font.flavor = "woff"
    font.save(target)
    return target


# ---------------------------------------------------------------- one stylesheet

# The theme's own stylesheets, which its layout links by hand (book/_templates/layout.html
# leaves them to the bundle).
THEME_CSS = ["_static/basic.css", "_static/styles/pydata-sphinx-theme.css"]
URL = re.compile(r"""url\(\s*(['"]?)([^'")]+)\1\s*\)""")


def _bundle_name(stylesheets: list[str]) -> str:
    digest = hashlib.sha256("\n".join(stylesheets).encode()).hexdigest()[:12]
    return f"_static/{ASSETS}/bundle-{digest}.css"


def write_bundle(outdir: Path, name: str, stylesheets: list[str]) -> None:
    """Concatenate `stylesheets` (paths in the site) into `name`, fixing relative url()s.

    Thirteen small stylesheets cost a phone on a slow network a round trip each before
    the first paint; one file costs one.
    """
    target = outdir / name
    parts = []
    for stylesheet in stylesheets:
        source = outdir / stylesheet
        text = source.read_text(encoding="utf-8")

        def rebase(match: re.Match, folder=Path(stylesheet).parent) -> str:
            url = match[2].strip()
            if re.match(r"^([a-z]+:|/|#)", url):
                return match[0]
            path, query = re.fullmatch(r"([^?#]*)(.*)", url).groups()
            moved = Path(os.path.relpath(outdir / folder / path, target.parent)).as_posix()
            return f'url("{moved}{query}")'

        parts.append(f"/* {stylesheet} */\n" + URL.sub(rebase, re.sub(r"@charset[^;]*;", "", text)))
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text("\n".join(parts), encoding="utf-8")


def bundle_registry(outdir: Path) -> Path:
    """Which stylesheets make each bundle, kept between builds beside the site (not in it:
    no page loads it)."""
    return outdir.parent / f"{outdir.name}-css-bundles.json"


def unpruned_bundle(outdir: Path, name: str) -> Path:
    """Where a bundle is kept as written, before pruning: beside the site, not in it."""
    return outdir.parent / f"{outdir.name}-css-unpruned" / Path(name).name


BUNDLE_LINK = re.compile(rf"_static/{ASSETS}/bundle-[0-9a-f]{{12}}\.css")


def linked_bundles(outdir: Path) -> set[str]:
    """The bundles the site's pages link (paths in the site)."""
    found = set()
    for page in outdir.rglob("*.html"):
        found.update(BUNDLE_LINK.findall(page.read_text(encoding="utf-8")))
    return found


def prune_bundles(app: Sphinx, outdir: Path, names: list[str]) -> None:
    """Keep only the rules the pages use (PurgeCSS under node, prune-css.js): a bundle
    shrinks from about 92 KB to 31 KB gzip. The unpruned bundle is write_bundle's."""
    run_node(app, "prune-css.js", [str(outdir), *names], doing="pruning the CSS")


def run_node(app: Sphinx, script: str, arguments: list[str], *, doing: str) -> None:
    """Run one of this extension's node scripts in the project (its node_modules)."""
    node = shutil.which("node")
    if node is None:
        raise ExtensionError("site_assets: `node` is missing (apt-get install nodejs npm)")
    done = subprocess.run([node, str(HERE / script), *arguments], cwd=app.confdir,
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise ExtensionError(f"site_assets: {doing} failed (is `npm ci` done?): {done.stderr.strip()}")


def own_scripts(app: Sphinx) -> list[str]:
    """The site's own scripts (the project's static folders: the extensions' and _static),
    as paths in the site. The theme's and Sphinx's come minified already."""
    project = Path(app.confdir).resolve()
    found = []
    for folder in app.config.html_static_path:
        source = Path(app.confdir, folder).resolve()
        if source.is_dir() and source.is_relative_to(project) and "site-packages" not in source.parts:
            found += [f"_static/{p.relative_to(source).as_posix()}" for p in sorted(source.rglob("*.js"))]
    return found


def minify_scripts(app: Sphinx, outdir: Path) -> None:
    """Minify the copies of the site's own scripts (terser under node, minify-js.js): the
    explorables' and the questions' scripts shrink by about 40 % gzip.

    Sphinx copies the sources over them only in a build that writes pages, so a copy is
    minified again only when it is not the output recorded last time (a no-op build leaves
    the site, and the service worker's content hashes, as they were).
    """
    record_path = outdir.parent / f"{outdir.name}-minified-scripts.json"
    record = json.loads(record_path.read_text()) if record_path.exists() else {}

    def digest(name: str) -> str:
        return hashlib.sha256((outdir / name).read_bytes()).hexdigest()

    todo = [name for name in own_scripts(app) if (outdir / name).exists() and record.get(name) != digest(name)]
    if todo:
        run_node(app, "minify-js.js", [str(outdir), *todo], doing="minifying the scripts")
        record.update({name: digest(name) for name in todo})
        record_path.write_text(json.dumps(record, indent=1, sort_keys=True))


# ---------------------------------------------------------------- page context


def _first_paragraph(body: str, limit: int = 155) -> str:
    for paragraph in re.findall(r"<p>(.*?)</p>", body, flags=re.DOTALL):
        # Maths: keep the MathML's text only would be odd, so drop it; the words stay.
        text = re.sub(r'<svg.*?</svg>|<span class="math-mathml">.*?</span>', "", paragraph, flags=re.DOTALL)
        text = html.unescape(re.sub(r"<[^>]+>", "", text))
        text = " ".join(text.split())
        if len(text) >= 40:
            return text if len(text) <= limit else text[: limit - 1].rsplit(" ", 1)[0] + "…"
    return ""


# Pages Sphinx writes with no text of their own to describe them.
GENERATED_PAGE_DESCRIPTIONS = {
    "search": "Search {title}: every page of the notes, the worked examples, the exam methods and the questions.",
}


def theme_digest() -> str:
    """The cache-busting digest the theme appends to its own CSS and JS links."""
    macros = (_theme_dirs()[0] / "static" / "webpack-macros.html").read_text()
    return re.search(r"\?digest=([0-9a-f]+)", macros)[1]


def _name_toggles(toctree):
    """Give each expand/collapse toggle of the navigation a name (axe: summary-name).

    `toctree` is the theme's parsed navigation (BeautifulSoup); changed in place.
    """
    for details in toctree.select("li > details") if hasattr(toctree, "select") else []:
        link = details.parent.find("a")
        summary = details.find("summary")
        if link is not None and summary is not None:
            summary["aria-label"] = f"Sections of {' '.join(link.get_text().split())}"
    return toctree


#: Scripts of the theme's extensions, and what a page's body must hold to need each.
_CODE = re.compile(r'class="highlight')
ONLY_WHERE_NEEDED = {
    "clipboard.min.js": _CODE,
    "copybutton.js": _CODE,
    "design-tabs.js": re.compile(r"sd-tab-set"),
    "togglebutton.js": re.compile(r'class="(?:[^"]*\s)?(?:toggle|dropdown)(?:\s[^"]*)?"'),
}


def _page_context(app: Sphinx, pagename: str, templatename: str, context: dict[str, Any], doctree) -> None:
    # Thebe runs code on a remote Binder kernel: not used here, and sphinx-thebe adds its
    # config script twice (a console error). Drop its scripts and stylesheet.
    context["script_files"] = [
        js for js in context.get("script_files", [])
        if "thebe" not in (js.filename or "").lower() and "THEBE" not in js.attributes.get("body", "")
    ]
    # Only the scripts a page needs: a copy button only where there is code to copy, tabs
    # only where there are tabs, the toggle script only where something toggles.
    body = context.get("body", "")
    context["script_files"] = [
        js for js in context["script_files"]
        if not (need := ONLY_WHERE_NEEDED.get(Path((js.filename or "").split("?")[0]).name)) or need.search(body)
    ]
    stylesheets = [css for css in context.get("css_files", []) if "thebe" not in css.filename]
    # One stylesheet for the screen: the theme's, then every extension's, in their order.
    screen = [css for css in stylesheets if css.attributes.get("media", "all") in ("all", "screen")
              and "://" not in css.filename and css.attributes.get("rel", "stylesheet") == "stylesheet"]
    bundled = THEME_CSS + [css.filename.split("?")[0] for css in screen]
    name = _bundle_name(bundled)
    app._site_bundles[name] = bundled
    context["site_css_bundle"] = name
    context["css_files"] = [css for css in stylesheets if css not in screen]
    # Scripts never block the first paint: all run after parsing, in order. Only
    # documentation_options.js stays synchronous (inline scripts in the head use it).
    for js in context["script_files"]:
        if js.filename and "documentation_options" not in js.filename and "async" not in js.attributes:
            js.attributes.setdefault("defer", "defer")
    context["site_theme_digest"] = app._site_theme_digest
    # myst-nb labels its "Show code cell source" toggles "Toggle hidden content": a name
    # that hides the visible text (axe: label-content-name-mismatch). The text is the name.
    if "body" in context:
        context["body"] = context["body"].replace('<summary aria-label="Toggle hidden content">', "<summary>")
    if "generate_toctree_html" in context:
        generate = context["generate_toctree_html"]
        context["generate_toctree_html"] = lambda *args, **kwargs: _name_toggles(generate(*args, **kwargs))
    description = (
        _first_paragraph(context.get("body", ""))
        or GENERATED_PAGE_DESCRIPTIONS.get(pagename, "").format(title=app.config.html_title)
        or app.config.html_title
    )
    context["metatags"] = context.get("metatags", "") + (
        f'\n    <meta name="description" content="{html.escape(description, quote=True)}" />'
    )


# ---------------------------------------------------------------- setup


def _config_inited(app: Sphinx, config) -> None:
    templates = str(Path(app.confdir) / "book" / "_templates")
    if templates not in config.templates_path:
        config.templates_path.insert(0, templates)
    static = str(HERE / "static")  # site-menus.js
    if static not in config.html_static_path:
        config.html_static_path.append(static)
    app._site_tex = TexToSvg(Path(app.confdir) / "node_modules" / "mathjax")
    app._site_theme_digest = theme_digest()
    app._site_bundles = {}


def static_digests(app: Sphinx) -> dict[str, str]:
    """The content of every static source file (site.css, the extensions' scripts)."""
    digests = {}
    for folder in app.config.html_static_path:
        source = Path(app.confdir, folder)
        files = source.rglob("*") if source.is_dir() else []
        for path in sorted(p for p in files if p.is_file() and not p.name.endswith("_t")):  # _t: templates
            digests[str(path)] = hashlib.sha256(path.read_bytes()).hexdigest()
    return digests


def _static_record(app: Sphinx) -> Path:
    """The static sources as the last build copied them, kept beside the site: the site
    itself keeps no bundled stylesheet (book/_ext/offline removes what no page loads)."""
    outdir = Path(app.outdir)
    return outdir.parent / f"{outdir.name}-static-digests.json"


def _static_changed(app: Sphinx, env, added, changed, removed) -> list[str]:
    """Rebuild the root page when a static file (site.css, a script) changed alone.

    Sphinx copies static files only when some page is written: an edit to a stylesheet
    and nothing else would never reach the site (nor the bundle).
    """
    if app.builder.format != "html":
        return []
    record = _static_record(app)
    if record.exists() and json.loads(record.read_text()) == static_digests(app):
        return []
    return [app.config.root_doc]


def write_root_redirect(app: Sphinx) -> None:
    """The site's index.html: a small complete page that sends the reader to the book.

    sphinx-external-toc writes a bare ``<meta http-equiv="Refresh">`` there when the file
    is missing: no language and no title, and no icon, so Chromium asked the server for
    /favicon.ico (a 404). The icon here is empty and inline: the page is left at once,
    and a request it started would only be cut off by the move.
    """
    target = app.builder.get_target_uri(app.config.root_doc)
    title = html.escape(app.config.html_title or app.config.project)
    (Path(app.outdir) / "index.html").write_text(
        f"""<!DOCTYPE html>
<html lang="{app.config.language or 'en'}">
<head>
<meta charset="utf-8" />
<meta name="viewport" content="width=device-width, initial-scale=1" />
<title>{title}</title>
<link rel="icon" href="data:," />
<meta http-equiv="refresh" content="0; url={target}" />
</head>
<body><p><a href="{target}">{title}</a></p></body>
</html>
""",
        encoding="utf-8",
    )


def _build_finished(app: Sphinx, exception) -> None:
    app._site_tex.close()
    if exception is not None or app.builder.format != "html":
        return
    write_icon_font(app)
    # Rewrite every bundle any page links (also those of pages not written this time:
    # a stylesheet may have changed), listed between builds beside the site (bundle_registry).
    outdir = Path(app.outdir)
    registry = bundle_registry(outdir)
    bundles = json.loads(registry.read_text()) if registry.exists() else {}
    bundles.update(app._site_bundles)
    # a bundle no page links any more (an older build's) is dropped, file and all
    linked = linked_bundles(outdir)
    for name in sorted(set(bundles) - linked):
        (outdir / name).unlink(missing_ok=True)
        del bundles[name]
    # Sphinx copies the stylesheets only in a build that writes pages (book/_ext/offline then
    # removes them again, bundled): with nothing written, the bundles stand as they are.
    copied = all((outdir / sheet).exists() for sheets in bundles.values() for sheet in sheets)
    for name, stylesheets in bundles.items() if copied else ():
        write_bundle(outdir, name, stylesheets)
        # the bundle before pruning, beside the site (tests/test_css_pruning.py compares them)
        unpruned = unpruned_bundle(outdir, name)
        unpruned.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(outdir / name, unpruned)
    if copied:
        prune_bundles(app, outdir, sorted(bundles))
    minify_scripts(app, outdir)
    registry.write_text(json.dumps(bundles, indent=1, sort_keys=True))
    write_root_redirect(app)
    _static_record(app).write_text(json.dumps(static_digests(app), indent=1))
    (Path(app.outdir) / "robots.txt").write_text("User-agent: *\nAllow: /\n")
    if not app.config.html_use_index:  # an index page left by an older build is not the book's
        (outdir / "genindex.html").unlink(missing_ok=True)


def setup(app: Sphinx):
    app.add_html_math_renderer("svg", (visit_math, None), (visit_displaymath, None))
    app.connect("config-inited", _config_inited)
    app.add_js_file("site-menus.js")  # deferred, like every script (_page_context)
    app.connect("html-page-context", _page_context, priority=900)
    app.connect("env-get-outdated", _static_changed)
    app.connect("build-finished", _build_finished)
    return {"parallel_read_safe": True, "parallel_write_safe": False}
