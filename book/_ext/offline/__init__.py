"""Offline after one visit (a local Sphinx extension): a service worker, generated when the
HTML build finishes, precaches every page and every file a page uses, listed with their
content hashes, so a new build (any changed byte) is a new cache.

* ``sw.js`` (site root): cache first from the precache, the network for anything else. A
  download (a PDF of the book or of the teacher's kit, the Moodle file) is fetched network
  first and kept once opened, so it opens again offline without weighing on the first visit.
  A new version installs beside the old one and waits; static/offline.js then shows a
  notice with a Reload button that activates it and reloads the page.
* ``manifest.webmanifest`` and two icons: a phone can install the book to its home screen.
* Registration is skipped on ``file://`` (a copy opened from disk has no service worker).
* ``_static/search-texts.js``: each page's words, for a copy opened from disk. Sphinx's
  search fetches a page to show a snippet of it, and a browser refuses fetch() of a local
  file; static/file-search.js (search page only, file:// only) answers those fetches from
  this script, which a <script> element may load.

What is precached is what the pages reference (``href``/``src``, a stylesheet's ``url()``),
the question variants and graphs loaded on New numbers, and the search index: not the PDFs
(downloads, not pages: sw.js keeps each once opened) nor the TrueType fonts (every browser
with service workers reads WOFF2).
"""

from __future__ import annotations

import gzip
import hashlib
import json
import posixpath
import re
from html import escape, unescape
from html.parser import HTMLParser
from pathlib import Path

from sphinx.application import Sphinx

from physics_figures.style import TOKENS, colour

__version__ = "1.0"
HERE = Path(__file__).parent
SERVICE_WORKER = "sw.js"
MANIFEST = "manifest.webmanifest"
ICONS = {192: "_static/offline/icon-192.png", 512: "_static/offline/icon-512.png"}
#: The site's blue (the theme's links and header) and page (physics_figures/style/tokens.json).
THEME_COLOUR = colour("manifest.theme")
BACKGROUND = colour("manifest.background")
#: Downloads and fallbacks no page needs offline.
# (and the theme's Font Awesome fonts, 300 kB: its stylesheet names them, but the site's own subset,
# site_assets/icons.woff, declared after it, is the one every page loads)
# (and _static/search-texts.js, 62 kB: the search's snippets for a copy opened from disk, where no
# service worker runs; a page served over HTTP never asks for it)
NOT_PRECACHED = re.compile(
    r"^pdf/|^teachers/|\.ttf$|\.map$|\.zip$|^_static/vendor/fontawesome/webfonts/|^_static/search-texts\.js$")
#: Loaded by script on demand: New numbers' variants and graphs, the search index.
ON_DEMAND = ("_static/questions/", "searchindex.js")
_REFERENCE = re.compile(r'(?:src|href)="([^"#?]+)')
_CSS_URL = re.compile(r"""url\(\s*["']?([^"')#?]+)""")
# (not a require("./x.js"): the scripts that node's tests also load name each other so, and a
# browser never runs it; each of them comes in the page's script bundle, site_assets/scripts.py)
_NAMED = re.compile(r"""(?<!require\()["']([\w@./-]+\.[a-z0-9]{2,5})["']""")


def _pages(site: Path) -> list[str]:
    return sorted(p.relative_to(site).as_posix() for p in site.rglob("*.html")
                  if not {"_static", "_sources", "_images"} & set(p.relative_to(site).parts))


def _resolve(site: Path, base: str, link: str) -> str | None:
    if "://" in link or link.startswith(("data:", "mailto:", "javascript:")):
        return None
    target = posixpath.normpath(posixpath.join(posixpath.dirname(base), link))
    if target.endswith("/") or (site / target).is_dir():
        target = posixpath.join(target, "index.html")
    return target if (site / target).is_file() else None


def referenced_files(site: Path) -> set[str]:
    """Every file of the site a page names (href, src), a stylesheet names (url()), or a
    script loads by name (ON_DEMAND), relative to the site's root."""
    found = set(_pages(site))
    stylesheets = []
    for page in list(found):
        for link in _REFERENCE.findall((site / page).read_text(encoding="utf-8")):
            target = _resolve(site, page, link)
            if target:
                found.add(target)
                if target.endswith(".css"):
                    stylesheets.append(target)
    for stylesheet in stylesheets:
        for link in _CSS_URL.findall((site / stylesheet).read_text(encoding="utf-8", errors="replace")):
            target = _resolve(site, stylesheet, link)
            if target:
                found.add(target)
    for name in ON_DEMAND:
        path = site / name
        found.update(p.relative_to(site).as_posix() for p in (path.rglob("*") if path.is_dir() else [path])
                     if p.is_file())
    # a script (or the web app manifest) that names a file in a string loads it
    every = {p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file()}
    for named_by in [f for f in found if f.endswith((".js", ".webmanifest"))]:
        for name in _NAMED.findall((site / named_by).read_text(encoding="utf-8", errors="replace")):
            name = re.sub(r"^(\.{0,2}/)+", "", name)
            found.update(f for f in every if f == name or f.endswith("/" + name))
    # the licence that comes with a script goes where the script goes
    found.update(f for f in every if f.endswith(".LICENSE.txt") and f.removesuffix(".LICENSE.txt") in found)
    return found


#: Always kept: what a server or a crawler asks for by name, and the offline machinery.
ENTRY_POINTS = ("index.html", "robots.txt", "objects.inv", ".buildinfo", SERVICE_WORKER, MANIFEST,
                *ICONS.values(), "download/dynamics.zip")


def unreferenced_files(site: Path) -> list[str]:
    """Files of the site that nothing names (see referenced_files) and no server asks for."""
    keep = referenced_files(site) | set(ENTRY_POINTS)
    return sorted(f for p in site.rglob("*") if p.is_file() and (f := p.relative_to(site).as_posix()) not in keep)


def remove_unreferenced(site: Path) -> list[str]:
    """Delete every file nothing names: source maps, unused locales and theme images,
    fontawesome.js (the icons come from a subset font), stylesheets already bundled,
    figures of an older build. Sphinx copies its static files again on the next build."""
    removed = unreferenced_files(site)
    for name in removed:
        (site / name).unlink()
    for folder in sorted((p for p in site.rglob("*") if p.is_dir()), key=lambda p: -len(p.parts)):
        if not any(folder.iterdir()):
            folder.rmdir()
    return removed


def precache_list(site: Path) -> list[tuple[str, str]]:
    """(path, content hash) of every file the service worker keeps, sorted."""
    files = sorted(f for f in referenced_files(site) if not NOT_PRECACHED.search(f) and f != SERVICE_WORKER)
    return [(f, hashlib.sha256((site / f).read_bytes()).hexdigest()[:16]) for f in files]


def precache_size(site: Path) -> int:
    """Bytes of the precache as a server sends it gzipped (make bench reports it)."""
    return sum(len(gzip.compress((site / f).read_bytes(), mtime=0)) for f, _ in precache_list(site))


def book_storage(site: Path) -> dict[str, str]:
    """The names the book keeps its records and caches under, as the questions extension wrote
    them into its pages (<meta name="book-storage">, physics_figures/topics.py storage_keys)."""
    for page in sorted(site.rglob("*.html")):  # the first page that has it (index.html may be a redirect)
        found = re.search(r'<meta name="book-storage" content="([^"]+)"', page.read_text(encoding="utf-8"))
        if found:
            return json.loads(unescape(found[1]))
    raise ValueError(f"site {site} has no page with <meta name=\"book-storage\">: the questions extension writes it")


def write_service_worker(site: Path) -> str:
    """Write sw.js for the site as it is now; returns its version (a hash of the list)."""
    files = precache_list(site)
    version = hashlib.sha256(json.dumps(files).encode()).hexdigest()[:16]
    script = (HERE / "sw_template.js").read_text(encoding="utf-8")
    script = script.replace("__VERSION__", version).replace("__BOOK_CACHES__", book_storage(site)["cache"]).replace(
        "__PRECACHE__", json.dumps([f for f, _ in files], indent=0))
    (site / SERVICE_WORKER).write_text(script, encoding="utf-8")
    return version


def write_manifest(site: Path, title: str) -> None:
    manifest = {
        "name": title, "short_name": "Dynamics", "start_url": "./index.html", "scope": "./",
        "display": "standalone", "background_color": BACKGROUND, "theme_color": THEME_COLOUR,
        "icons": [{"src": path, "sizes": f"{size}x{size}", "type": "image/png", "purpose": "any"}
                  for size, path in ICONS.items()],
    }
    (site / MANIFEST).write_text(json.dumps(manifest, indent=1, ensure_ascii=False), encoding="utf-8")


def write_icons(site: Path) -> None:
    """The home-screen icons, drawn again only when the colours change: "Δp" in white on
    the site's blue."""
    for size, path in ICONS.items():
        target = site / path
        if target.exists() and target.stat().st_mtime >= TOKENS.stat().st_mtime:
            continue
        from matplotlib.figure import Figure  # only to draw one (importing it takes a second)

        target.parent.mkdir(parents=True, exist_ok=True)
        figure = Figure(figsize=(1, 1), dpi=size)
        figure.patch.set_facecolor(THEME_COLOUR)
        figure.text(0.5, 0.5, "Δp", color=colour("manifest.icon-text"), fontsize=34, ha="center",
                    va="center", family="DejaVu Sans", weight="bold")
        figure.savefig(target, dpi=size, facecolor=THEME_COLOUR, metadata={"Software": None})


SEARCH_TEXTS = "_static/search-texts.js"


#: Elements whose content is no words of the page: maths drawings, scripts, buttons.
SKIPPED = frozenset({"script", "style", "svg", "button"})
VOID = frozenset({"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
                  "track", "wbr"})


class _MainText(HTMLParser):
    """A page's main content as search snippets need it: its words, and the sections (with
    their ids, for a result that points into a page); no maths drawings, scripts or styles."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.depth = 0  # how deep inside the main content (0: outside it)
        self.skip_from: int | None = None  # the depth of the element being left out
        self.out: list[str] = []

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        if self.depth == 0:
            self.depth = int(tag == "main" or attributes.get("role") == "main")
            return
        if tag in VOID:
            return
        self.depth += 1
        if self.skip_from is None and (tag in SKIPPED or "headerlink" in (attributes.get("class") or "")):
            self.skip_from = self.depth
        elif tag == "section" and self.skip_from is None:
            self.out.append(f'<section id="{escape(attributes.get("id", ""))}">')

    def handle_endtag(self, tag):
        if self.depth == 0 or tag in VOID:
            return
        if self.skip_from == self.depth:
            self.skip_from = None
        elif tag == "section" and self.skip_from is None:
            self.out.append("</section>")
        self.depth -= 1

    def handle_data(self, data):
        if self.depth and self.skip_from is None and data.strip():
            self.out.append(escape(" ".join(data.split())) + " ")


def page_text(html: str) -> str:
    """A page's main content, reduced to its words in its sections (see _MainText)."""
    parser = _MainText()
    parser.feed(html)
    return '<div role="main">' + "".join(parser.out) + "</div>"


def write_search_texts(site: Path) -> None:
    texts = {page: page_text((site / page).read_text(encoding="utf-8")) for page in _pages(site)}
    payload = json.dumps(texts, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    (site / SEARCH_TEXTS).write_text(f"window.SearchTexts = {payload};\n", encoding="utf-8")


def _page_context(app: Sphinx, pagename, templatename, context, doctree) -> None:
    root = "../" * pagename.count("/")
    context["metatags"] = context.get("metatags", "") + (
        f'\n    <link rel="manifest" href="{root}{MANIFEST}" />'
        f'\n    <meta name="theme-color" content="{THEME_COLOUR}" />')


def _record(site: Path) -> Path:
    """The site as this extension last left it, beside the site (no page loads it)."""
    return site.parent / f"{site.name}-offline.json"


def _state(site: Path, title: str) -> dict:
    """What this extension's work depends on: every file of the site, by content, the title
    and this extension's code (what writes the service worker, and its template)."""
    code = hashlib.sha256(title.encode())
    for path in (Path(__file__), HERE / "sw_template.js"):
        code.update(path.read_bytes())
    files = {p.relative_to(site).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
             for p in sorted(site.rglob("*")) if p.is_file()}
    return {"code": code.hexdigest(), "files": files}


def _build_finished(app: Sphinx, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    site = Path(app.outdir)
    title = app.config.html_title or app.config.project
    # Reading every page for its words and every file for its hash takes seconds: a site
    # byte for byte as this left it last time (a no-op build) needs none of it. Extensions
    # write their stylesheets again at every build (sphinx-exercise's, myst-nb's: bundled,
    # so removed here); those alone, unchanged, are removed again.
    state, record = _state(site, title), _record(site)
    last = json.loads(record.read_text()) if record.exists() else {}
    if last.get("code") == state["code"] and _as_left(state["files"], last):
        for name in set(state["files"]) - set(last["files"]):
            (site / name).unlink()
        return
    write_icons(site)
    write_manifest(site, title)
    write_search_texts(site)
    removed = remove_unreferenced(site)
    write_service_worker(site)  # last: it hashes everything the other steps wrote
    record.write_text(json.dumps({**_state(site, title), "removed": {name: state["files"].get(name)
                                                                      for name in removed}},
                                 indent=0, sort_keys=True))


def _as_left(files: dict[str, str], last: dict) -> bool:
    """`files` are those this left last time, and maybe some it removed, all unchanged."""
    left, removed = last.get("files", {}), last.get("removed", {})
    return all(files.get(name) == sha for name, sha in left.items()) and all(
        removed.get(name) == sha for name, sha in files.items() if name not in left)


def _add_static(app: Sphinx, config) -> None:
    static = str(HERE / "static")
    if static not in config.html_static_path:
        config.html_static_path.append(static)


def setup(app: Sphinx):
    app.connect("config-inited", _add_static)
    app.add_js_file("offline.js")  # deferred, like every script (site_assets)
    app.add_css_file("offline.css")
    app.connect("html-page-context", _page_context)
    app.connect("build-finished", _build_finished, priority=900)  # after every other writer
    return {"version": __version__, "parallel_read_safe": True, "parallel_write_safe": True}
