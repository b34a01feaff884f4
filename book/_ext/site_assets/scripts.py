"""One script per kind of page: the scripts a page runs after parsing (the theme's, the
extensions', the book's own), joined in their order into one file, shared by every page that
runs the same scripts (a practice page, the mock test, a teachers' page, a plain page).

Twenty small scripts cost a phone a request each (about 200 bytes of headers apiece, and
gzip starts afresh in each file); one file costs one, and compresses better. The bundle is
written when the build finishes, from the copies in the site (the book's own minified first,
stylesheets.minify_scripts), and kept, with the scripts that make it, in a registry beside the
site, as the stylesheets' bundles are.
"""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path
from typing import Any

from .paths import ASSETS

#: The theme's own script, which its layout loads last (book/_templates/layout.html leaves it
#: to the bundle).
THEME_SCRIPT = "_static/scripts/pydata-sphinx-theme.js"
#: Runs before the page is parsed (inline scripts in the head read it): stays on its own.
SYNCHRONOUS = "documentation_options.js"
#: A minified script's pointer to its source map: the bundle has none.
SOURCE_MAP = re.compile(r"^//# sourceMappingURL=.*$", re.MULTILINE)
BUNDLE_LINK = re.compile(rf"_static/{ASSETS}/scripts-[0-9a-f]{{12}}\.js")


def script_bundle_name(scripts: list[str]) -> str:
    digest = hashlib.sha256("\n".join(scripts).encode()).hexdigest()[:12]
    return f"_static/{ASSETS}/scripts-{digest}.js"


def _bundled(js) -> bool:
    """A deferred script of the site's own (not inline, not another host's, not async)."""
    name = js.filename or ""
    return bool(name) and "://" not in name and not name.startswith("data:") and SYNCHRONOUS not in name \
        and "async" not in js.attributes and js.attributes.get("defer")


def bundle_page_scripts(app, context: dict[str, Any]) -> None:
    """Take the page's deferred scripts out of its script tags and name the bundle that holds
    them, then the theme's (context["site_js_bundle"], linked by layout.html)."""
    # in the order Sphinx writes the tags (by priority, then as added), which is the order they ran in
    scripts = sorted(context.get("script_files", []), key=lambda js: js.priority)
    bundled = [js for js in scripts if _bundled(js)]
    names = [*dict.fromkeys(js.filename.split("?")[0] for js in bundled), THEME_SCRIPT]
    name = script_bundle_name(names)
    app._site_script_bundles[name] = names
    context["script_files"] = [js for js in scripts if js not in bundled]
    context["site_js_bundle"] = name


def script_registry(outdir: Path) -> Path:
    """Which scripts make each bundle, kept between builds beside the site."""
    return outdir.parent / f"{outdir.name}-js-bundles.json"


def write_script_bundles(outdir: Path, built: dict[str, list[str]]) -> None:
    """Write every bundle a page links from the scripts' copies in the site: this build's
    bundles and the last builds' still linked. Sphinx copies the scripts only in a build that
    writes pages (book/_ext/offline then removes them, bundled): with none copied, the bundles
    stand as they are. A bundle no page links any more is dropped."""
    registry = script_registry(outdir)
    bundles = json.loads(registry.read_text()) if registry.exists() else {}
    bundles.update(built)
    linked = set()
    for page in outdir.rglob("*.html"):
        linked.update(BUNDLE_LINK.findall(page.read_text(encoding="utf-8")))
    for name in sorted(set(bundles) - linked):
        (outdir / name).unlink(missing_ok=True)
        del bundles[name]
    for name, scripts in bundles.items():
        if all((outdir / script).is_file() for script in scripts):
            target = outdir / name
            target.parent.mkdir(parents=True, exist_ok=True)
            # A statement first, so that no script's "use strict" becomes the whole bundle's;
            # each script ends with a line break and a semicolon, so none runs into the next.
            parts = [f"/* {script} */\n{SOURCE_MAP.sub('', (outdir / script).read_text(encoding='utf-8')).rstrip()}\n;"
                     for script in scripts]
            text = ";\n" + "\n".join(parts) + "\n"
            if not target.is_file() or target.read_text(encoding="utf-8") != text:
                target.write_text(text, encoding="utf-8")
    registry.write_text(json.dumps(bundles, indent=1, sort_keys=True))


def page_scripts(outdir: Path, page: str) -> list[str]:
    """The scripts (paths in the site, in order) that a written page's bundle holds: what the page
    runs after parsing. `page` is the page's HTML."""
    found = BUNDLE_LINK.search(page)
    return json.loads(script_registry(outdir).read_text())[found[0]] if found else []
