"""One stylesheet per set of stylesheets a page loads, pruned to the rules the pages use,
and the site's own scripts minified (node: prune-css.js, minify-js.js)."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.errors import ExtensionError
from sphinx.util import logging

logger = logging.getLogger(__name__)

from .paths import ASSETS, HERE

# The theme's own stylesheets, which its layout links by hand (book/_templates/layout.html
# leaves them to the bundle).
THEME_CSS = ["_static/basic.css", "_static/styles/pydata-sphinx-theme.css"]
URL = re.compile(r"""url\(\s*(['"]?)([^'")]+)\1\s*\)""")


def bundle_name(stylesheets: list[str]) -> str:
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
        cache = MinifiedCache(Path(app.confdir) / "node_modules")
        keys = {name: cache.key((outdir / name).read_bytes()) for name in todo}
        missing = [name for name in todo if not cache.fetch(keys[name], outdir / name)]
        if missing:
            run_node(app, "minify-js.js", [str(outdir), *missing], doing="minifying the scripts")
            for name in missing:
                cache.keep(keys[name], outdir / name)
        record.update({name: digest(name) for name in todo})
        record_path.write_text(json.dumps(record, indent=1, sort_keys=True))


class MinifiedCache:
    """Minified scripts by the digest of what made them (the source, minify-js.js and terser's
    version), in node_modules/.cache as other JS build tools keep theirs: a cold build (a fresh
    site, or a test's small book, whose node_modules is the project's) minifies only what
    terser has not minified before, and a changed source, script or terser is a new key."""

    def __init__(self, node_modules: Path):
        self.folder = node_modules / ".cache" / "minify-js"
        terser = node_modules / "terser" / "package.json"
        self.tool = (HERE / "minify-js.js").read_bytes() + (terser.read_bytes() if terser.exists() else b"")

    def key(self, source: bytes) -> str:
        return hashlib.sha256(self.tool + b"\0" + source).hexdigest()

    def fetch(self, key: str, target: Path) -> bool:
        cached = self.folder / f"{key}.js"
        if not cached.is_file():
            return False
        shutil.copyfile(cached, target)
        return True

    def keep(self, key: str, minified: Path) -> None:
        self.folder.mkdir(parents=True, exist_ok=True)
        partial = self.folder / f"{key}.{os.getpid()}.tmp"  # whole or not at all: builds run side by side
        shutil.copyfile(minified, partial)
        partial.replace(self.folder / f"{key}.js")
