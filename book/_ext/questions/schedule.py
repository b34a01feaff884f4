"""Spaced review's scripts: ts-fsrs (npm, the FSRS scheduler Anki uses) vendored into the site
at build time as ``_static/ts-fsrs.js``, and what a page that plans reviews loads.

A page that records attempts loads the store (static/progress-store.js) only; a page that
works out what is due (Your practice) calls :func:`add_plan_scripts` and gets ts-fsrs and
static/schedule.js as well, so no other page carries the scheduler's weight.
"""

from __future__ import annotations

import json
import shutil
from html import escape
from pathlib import Path

from sphinx.errors import ExtensionError

from . import store

#: ts-fsrs's browser build, as `npm ci` installs it (package.json pins the version).
TS_FSRS = Path(__file__).resolve().parents[3] / "node_modules" / "ts-fsrs" / "dist" / "index.umd.js"


def vendor_ts_fsrs(app, config) -> None:
    """Copy ts-fsrs into a static folder of the build's own (beside the site, so the site's
    scripts are minified with it), unchanged files left alone so a no-op build stays one."""
    if not TS_FSRS.exists():
        raise ExtensionError(f"questions: ts-fsrs is missing at {TS_FSRS}: run `npm ci` at the repository root")
    folder = Path(app.outdir).parent / "vendor"
    folder.mkdir(parents=True, exist_ok=True)
    target = folder / "ts-fsrs.js"
    if not target.exists() or target.read_bytes() != TS_FSRS.read_bytes():
        shutil.copyfile(TS_FSRS, target)
    if str(folder) not in config.html_static_path:
        config.html_static_path.append(str(folder))


def add_store_script(app) -> None:
    """The student's record (before the scripts that write or read it)."""
    app.add_js_file("progress-store.js", loading_method="defer", priority=430)


def add_plan_scripts(app) -> None:
    """The store, ts-fsrs and the schedule: for a page that works out what is due."""
    add_store_script(app)
    app.add_js_file("ts-fsrs.js", loading_method="defer", priority=431)
    app.add_js_file("schedule.js", loading_method="defer", priority=432)


#: The meta tag that names the book's storage keys in every page (progress-store.js reads it, and
#: book/_ext/offline names the service worker's caches by it).
STORAGE_META = "book-storage"


def add_storage_meta(app, pagename, templatename, context, doctree) -> None:
    """Every page names the keys the book keeps its records under (physics_figures.topics
    storage_keys of the book's id), so a book of another topic keeps its own with no script edited."""
    from physics_figures.topics import storage_keys

    keys = json.dumps(storage_keys(store.book_id(app.config)), separators=(",", ":"))
    context["metatags"] = context.get("metatags", "") + f'\n<meta name="{STORAGE_META}" content="{escape(keys)}">'


def setup(app) -> None:
    app.connect("config-inited", vendor_ts_fsrs)
    app.connect("html-page-context", add_storage_meta)
