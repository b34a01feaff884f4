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
- **One stylesheet, one script, none blocking.** Every screen stylesheet (the theme's and each
  extension's, root ``_static/*.css`` included) is joined into one bundle per set of
  stylesheets; every deferred script into one bundle per set of scripts, a kind of page's
  (scripts.py). A phone on a slow network paints sooner.
- **No dead weight or errors.** Thebe (live code via Binder: not used, and its script is
  added twice) is removed; the search index is loaded on the search page only; myst-nb's
  code toggles and the navigation's toggles get names that match what they show.
- **Menus that work.** ``static/site-menus.js`` binds the sidebar toggles a reader
  sees (the themes bind hidden duplicates); the search page loads Sphinx's search
  scripts deferred like the rest (``book/_templates/search.html``).
- **Findable.** Each page gets a meta description (its first paragraph), the site a
  ``robots.txt`` and a root ``index.html`` that is a real page leading to the book.

Needs ``node`` and ``npm ci`` (package.json at the repository root pins mathjax).

One module per job: maths.py, icons.py, stylesheets.py (bundles, pruning, minified
scripts), scripts.py (a script bundle per kind of page), page_context.py (what each page gets); this one wires them to the build.
"""

from __future__ import annotations

import hashlib
import html
import json
import shutil
from pathlib import Path

from sphinx.application import Sphinx
from svg_compact import is_compact, svg_file  # book/_ext: a figure in fewer bytes

from .icons import write_icon_font
from .maths import TexToSvg, visit_displaymath, visit_math
from .page_context import add_page_context, theme_digest
from .paths import HERE
from .scripts import page_scripts, write_script_bundles
from .stylesheets import (
    bundle_registry,
    linked_bundles,
    minify_scripts,
    prune_bundles,
    unpruned_bundle,
    write_bundle,
)

__all__ = ["bundle_registry", "page_scripts", "unpruned_bundle"]  # the tests read the bundles through these


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
    app._site_script_bundles = {}


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


def compact_images(outdir: Path) -> None:
    """The pages' own figures (matplotlib's SVG, as myst-nb saved them) in fewer bytes, drawn the
    same (svg_compact): a figure Sphinx copied this build is compacted, one compacted before is
    left as it is (a no-op build keeps the site's bytes, and the service worker's hashes)."""
    for image in sorted((outdir / "_images").glob("*.svg")):
        text = image.read_text(encoding="utf-8")
        if not is_compact(text):
            image.write_text(svg_file(text), encoding="utf-8")


def _build_finished(app: Sphinx, exception) -> None:
    app._site_tex.close()
    if exception is not None or app.builder.format != "html":
        return
    write_icon_font(app)
    compact_images(Path(app.outdir))
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
        # the bundle before pruning, beside the site (tests/browser/test_css_pruning.py compares them)
        unpruned = unpruned_bundle(outdir, name)
        unpruned.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(outdir / name, unpruned)
    # the scripts minified, then joined into each page's one bundle (scripts.py), before the
    # stylesheets are pruned to the rules the pages and their bundles use
    minify_scripts(app, outdir)
    write_script_bundles(outdir, app._site_script_bundles)
    if copied:
        prune_bundles(app, outdir, sorted(bundles))
    registry.write_text(json.dumps(bundles, indent=1, sort_keys=True))
    write_root_redirect(app)
    _static_record(app).write_text(json.dumps(static_digests(app), indent=1))
    (Path(app.outdir) / "robots.txt").write_text("User-agent: *\nAllow: /\n")
    if not app.config.html_use_index:  # an index page left by an older build is not the book's
        (outdir / "genindex.html").unlink(missing_ok=True)


def setup(app: Sphinx):
    app.add_html_math_renderer("svg", (visit_math, None), (visit_displaymath, None))
    app.connect("config-inited", _config_inited)
    app.add_js_file("site-menus.js")  # deferred, like every script (add_page_context)
    app.add_js_file("search-highlight.js")  # Sphinx's highlighter, for a page a search opened
    app.connect("html-page-context", add_page_context, priority=900)
    app.connect("env-get-outdated", _static_changed)
    app.connect("build-finished", _build_finished)
    return {"parallel_read_safe": True, "parallel_write_safe": False}
