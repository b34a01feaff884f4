"""Never serve a stale figure: re-execute pages when physics_figures changes.

myst-nb's execution cache is keyed on a page's own code cells, so editing a model or
a figure function would leave the cached (old) outputs in place. This extension
hashes the source of the physics_figures package the kernel imports; when the hash
differs from the last successful build it drops the execution cache and marks every
page outdated, so each one is read and executed again.
"""

from __future__ import annotations

import hashlib
import importlib.util
import shutil
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.util import logging

logger = logging.getLogger(__name__)

STAMP_NAME = "physics_figures.sha256"


def package_digest(package: str = "physics_figures") -> str:
    """SHA-256 over the relative path and bytes of every source file of `package`."""
    spec = importlib.util.find_spec(package)
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError(f"cannot find the {package!r} package: is it installed (pip install -e .)?")
    root = Path(next(iter(spec.submodule_search_locations)))
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts:
            digest.update(path.relative_to(root).as_posix().encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()


def _stamp(app: Sphinx) -> Path:
    return Path(app.doctreedir) / STAMP_NAME


def _check_package(app: Sphinx, config) -> None:
    app._physics_figures_digest = package_digest()
    stamp = _stamp(app)
    previous = stamp.read_text().strip() if stamp.exists() else None
    app._physics_figures_changed = previous != app._physics_figures_digest
    if app._physics_figures_changed:
        cache = Path(config.nb_execution_cache_path or Path(app.outdir).parent / ".jupyter_cache")
        if cache.exists():
            logger.info("physics_figures changed: dropping the execution cache %s", cache)
            shutil.rmtree(cache)


def _outdate_everything(app: Sphinx, env, added, changed, removed):
    if getattr(app, "_physics_figures_changed", False):
        return sorted(env.found_docs - added - changed - removed)
    return []


def _save_stamp(app: Sphinx, exception) -> None:
    # Only a build that finished records the hash; a failed one is retried in full.
    if exception is None:
        _stamp(app).parent.mkdir(parents=True, exist_ok=True)
        _stamp(app).write_text(app._physics_figures_digest + "\n")


def setup(app: Sphinx):
    app.connect("config-inited", _check_package)
    app.connect("env-get-outdated", _outdate_everything)
    app.connect("build-finished", _save_stamp)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
