"""Never serve a stale figure, and re-execute only the pages a physics_figures edit touches.

A page depends on the physics_figures modules its code cells import, and on those the
Sphinx directives it uses import while it is read ({question}, {explorable}, ...), each
with everything they import in turn. ``ImportGraph`` finds them statically (``ast`` over the
page's cells and the package's files, relative imports resolved; the package
``__init__`` files Python runs on the way count too), and a page's *digest* is the
SHA-256 of those files' paths and bytes. Two things follow from it:

* A page with code cells gets one more cell at source-read: hidden (``remove-cell``), it
  carries the digest of the modules its kernel imports. myst-nb's execution cache
  (jupyter-cache) matches a notebook on its cells' source, so the cached outputs are
  used exactly while those modules are unchanged; any change to them is a cache miss and
  the page executes again. Undoing the edit finds the old outputs in the cache again.
* Every page's modules (kernel and directives) are kept in the environment with their
  digest; at the next build, a page whose digest has changed is re-read (and so
  re-executed if its kernel modules changed). It is a comparison of contents, not of
  mtimes, so a checkout or a copy never leaves a page stale. The files are also Sphinx
  dependencies of the page (``env.note_dependency``), so a newer file re-reads it too.

Nothing else changes a page: an edit to ``figures/collisions.py`` re-runs the pages that
draw a collision and no other. Directives say what they use with :func:`uses_modules`.

A page's glued numbers are its own cells' outputs, so they are as fresh as its figures. A
value glued from another page (``{glue:text}`other/page::key```) would not be: that page
could execute again while this one is not re-read. No page does so, and a page that tries
fails the (strict) build with a warning saying so.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import re
from collections.abc import Iterable
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.util import logging

logger = logging.getLogger(__name__)

PACKAGE = "physics_figures"
#: Read by every page: the notation extension joins numbers and units on every page.
EVERY_PAGE = (f"{PACKAGE}.notation",)
#: The first line of the hidden cell that carries a page's digest.
CELL_MARK = "# fresh_figures: the physics_figures modules this page imports (sha256):"
ENV_ATTR = "fresh_figures_modules"  # {docname: {"modules": [...], "digest": "..."}}
PARSED_ATTR = "fresh_figures_parsed"  # ImportGraph.parsed, kept between builds
#: A glue role or directive that names another page (``path/to/page::key``).
CROSS_PAGE_GLUE = re.compile(r"\{glue(?::\w+)?\}[` ]\s*([^`\n]*::[^`\n]*)")


class ImportGraph:
    """Which modules of `package` a piece of code imports, directly or through others."""

    def __init__(self, package: str = PACKAGE, parsed: dict | None = None) -> None:
        """`parsed`: what an earlier graph found in each file, by content (kept between builds
        in the environment: a no-op build parses no module)."""
        spec = importlib.util.find_spec(package)
        if spec is None or not spec.submodule_search_locations:
            raise RuntimeError(f"cannot find the {package!r} package: is it installed (pip install -e .)?")
        self.package = package
        self.root = Path(next(iter(spec.submodule_search_locations)))
        self._direct: dict[str, frozenset[str]] = {}
        self._data: dict[str, list[Path]] = {}
        self._bytes: dict[Path, bytes] = {}
        self.parsed = {} if parsed is None else parsed  # {module: [path, sha256, imports, strings]}

    def path(self, module: str) -> Path | None:
        """The file Python runs for `module` (a package's ``__init__.py``), or None."""
        parts = module.split(".")
        if parts[0] != self.package:
            return None
        base = self.root.joinpath(*parts[1:])
        if (base / "__init__.py").is_file():
            return base / "__init__.py"
        if len(parts) > 1 and base.with_suffix(".py").is_file():
            return base.with_suffix(".py")
        return None

    def every_module(self) -> set[str]:
        found = set()
        for path in self.root.rglob("*.py"):
            if "__pycache__" in path.parts:
                continue
            parts = [self.package, *path.relative_to(self.root).with_suffix("").parts]
            found.add(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
        return found

    def imports(self, tree: ast.AST, module: str | None = None) -> set[str]:
        """Modules of the package that `tree` imports anywhere (at top level or inside a
        function: either may run), with their parent packages. `module` is the code's own
        module name, for relative imports (None: a page's cell, which has none)."""
        return {name for name in self._imported_names(tree, module) if self.path(name) is not None}

    def _imported_names(self, tree: ast.AST, module: str | None) -> set[str]:
        names: set[str] = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    names |= _with_parents(alias.name)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    if module is None:
                        continue
                    here = module.split(".")
                    if self.path(module).name != "__init__.py":
                        here = here[:-1]  # a plain module's relative imports start at its package
                    here = here[: len(here) - (node.level - 1)]
                    base = ".".join(here + ([node.module] if node.module else []))
                else:
                    base = node.module
                names |= _with_parents(base)
                for alias in node.names:  # `from package import module`
                    if alias.name != "*":
                        names.add(f"{base}.{alias.name}")
        return names

    def read(self, path: Path) -> bytes:
        """A file's bytes, read once a graph (once a build)."""
        if path not in self._bytes:
            self._bytes[path] = path.read_bytes()
        return self._bytes[path]

    def _parse(self, module: str) -> tuple[list[str], list[str]]:
        """The names `module` imports and the strings it holds that could name a data file,
        parsed again only when its file changed (checking which exist is left to the caller)."""
        path = self.path(module)
        source = self.read(path)
        key = [path.relative_to(self.root).as_posix(), hashlib.sha256(source).hexdigest()]
        known = self.parsed.get(module)
        if known is None or known[:2] != key:
            tree = ast.parse(source, filename=str(path))
            strings = {node.value for node in ast.walk(tree)
                       if isinstance(node, ast.Constant) and isinstance(node.value, str)
                       and re.fullmatch(r"[\w-]+\.\w+", node.value) and not node.value.endswith(".py")}
            known = self.parsed[module] = [*key, sorted(self._imported_names(tree, module)), sorted(strings)]
        return known[2], known[3]

    def direct(self, module: str) -> frozenset[str]:
        if module not in self._direct:
            names = self._parse(module)[0]
            self._direct[module] = frozenset(n for n in names if self.path(n) is not None) - {module}
        return self._direct[module]

    def closure(self, modules: Iterable[str]) -> set[str]:
        """`modules` (with their parent packages) and everything they import, transitively."""
        todo = {parent for module in modules for parent in _with_parents(module) if self.path(parent)}
        seen: set[str] = set()
        while todo:
            module = todo.pop()
            if module not in seen:
                seen.add(module)
                todo |= self.direct(module) - seen
        return seen

    def data_files(self, module: str) -> list[Path]:
        """The data files a module reads: those beside it that a string in its code names
        (``Path(__file__).with_name("marking_rules.json")``). Read once a build."""
        if module not in self._data:
            path = self.path(module)
            names = self._parse(module)[1]
            self._data[module] = sorted(path.with_name(name) for name in names if path.with_name(name).is_file())
        return self._data[module]

    def files(self, modules: Iterable[str]) -> list[Path]:
        """Every file of the closure of `modules`: the modules and the data files they read."""
        closure = self.closure(modules)
        found = {self.path(module) for module in closure}
        for module in closure:
            found.update(self.data_files(module))
        return sorted(found)

    def digest(self, modules: Iterable[str]) -> str:
        """SHA-256 over the relative path and bytes of every file of the closure of `modules`
        (data files included)."""
        digest = hashlib.sha256()
        for path in self.files(modules):
            digest.update(path.relative_to(self.root).as_posix().encode() + b"\0")
            digest.update(self.read(path) + b"\0")
        return digest.hexdigest()

    def imported_by_cells(self, sources: Iterable[str]) -> set[str]:
        """The package's modules that code cells import. A cell Python cannot parse (after
        dropping IPython's magics and shell lines) counts as importing every module."""
        found: set[str] = set()
        for source in sources:
            code = "\n".join("" if line.lstrip().startswith(("%", "!")) else line
                             for line in source.splitlines())
            try:
                found |= self.imports(ast.parse(code))
            except SyntaxError:
                return self.every_module()
        return found


def _with_parents(module: str) -> set[str]:
    parts = module.split(".")
    return {".".join(parts[: i + 1]) for i in range(len(parts))}


# ---------------------------------------------------------------- in the Sphinx build


def _graph(app: Sphinx) -> ImportGraph:
    """One graph a build (the files do not change while it runs)."""
    if getattr(app, "_fresh_figures_graph", None) is None:
        if not hasattr(app.env, PARSED_ATTR):
            setattr(app.env, PARSED_ATTR, {})
        app._fresh_figures_graph = ImportGraph(parsed=getattr(app.env, PARSED_ATTR))
    return app._fresh_figures_graph


def _records(env) -> dict[str, dict]:
    if not hasattr(env, ENV_ATTR):
        setattr(env, ENV_ATTR, {})
    return getattr(env, ENV_ATTR)


def _record(env, docname: str, modules: Iterable[str]) -> None:
    graph = _graph(env.app)
    record = _records(env).setdefault(docname, {"modules": set(EVERY_PAGE), "digest": ""})
    record["modules"] |= set(modules)
    record["digest"] = graph.digest(record["modules"])
    # Sphinx's own dependency list too (by mtime: a touched file re-reads the page, whose
    # unchanged digest then finds its outputs in the cache).
    for path in graph.files(modules):
        env.note_dependency(str(path))


def uses_modules(env, *modules: str) -> None:
    """A directive of the page being read calls this with the physics_figures modules its
    output comes from: the page is read again when any of them (or what they import) changes."""
    _record(env, env.docname, modules)


def modules_digest(app: Sphinx, modules: Iterable[str]) -> str:
    """SHA-256 of what `modules` run: the package's files they reach (ImportGraph.digest),
    and for a module outside the package (a topic of the tests) its own file and the
    package's files it reaches. For work done once a build that may be skipped when it is
    unchanged (the questions' variants)."""
    graph = _graph(app)
    digest = hashlib.sha256(graph.digest(modules).encode())
    for module in sorted(set(modules)):
        spec = None if graph.path(module) else importlib.util.find_spec(module)
        if spec is not None and spec.origin and Path(spec.origin).is_file():
            source = Path(spec.origin).read_bytes()
            digest.update(f"\0{module}\0".encode() + source)
            digest.update(graph.digest(graph.imports(ast.parse(source), None)).encode())
    return digest.hexdigest()


def _code_cells(docname: str, path: str, source: str) -> list[str] | None:
    """The code cells' sources of a MyST or ipynb notebook page; None if it is no notebook."""
    if path.endswith(".ipynb"):
        import nbformat

        return [cell.source for cell in nbformat.reads(source, as_version=4).cells if cell.cell_type == "code"]
    if "{code-cell}" not in source:
        return None
    from myst_nb.core.read import read_myst_markdown_notebook

    notebook = read_myst_markdown_notebook(source, path=path)
    return [cell.source for cell in notebook.cells if cell.cell_type == "code"]


def _with_digest_cell(path: str, source: str, digest: str) -> str:
    line = f"{CELL_MARK} {digest}"
    if path.endswith(".ipynb"):
        import nbformat

        notebook = nbformat.reads(source, as_version=4)
        notebook.cells.append(nbformat.v4.new_code_cell(line, metadata={"tags": ["remove-cell"]}))
        return nbformat.writes(notebook)
    return source.rstrip("\n") + f"\n\n```{{code-cell}} ipython3\n:tags: [remove-cell]\n\n{line}\n```\n"


def _source_read(app: Sphinx, docname: str, source: list[str]) -> None:
    """Record what the page's kernel imports; key its execution cache on their digest."""
    env = app.env
    _record(env, docname, ())
    for glued in CROSS_PAGE_GLUE.findall(source[0]):
        logger.warning("%s glues %r from another page: its value could go stale when that page "
                       "executes again; glue it on this page instead (book/_ext/fresh_figures.py)",
                       docname, glued.strip(), location=docname)
    path = env.doc2path(docname)
    cells = _code_cells(docname, str(path), source[0])
    if not cells:
        return
    graph = _graph(app)
    kernel = graph.imported_by_cells(cells)
    if not kernel:
        return
    _record(env, docname, kernel)
    source[0] = _with_digest_cell(str(path), source[0], graph.digest(kernel))


def _outdated(app: Sphinx, env, added, changed, removed) -> list[str]:
    """The pages whose modules' digest differs from the one they were read with."""
    graph = _graph(app)
    stale = []
    for docname, record in _records(env).items():
        unchanged = docname in env.found_docs and docname not in added | changed | removed
        if unchanged and graph.digest(record["modules"]) != record["digest"]:
            stale.append(docname)
    if stale:
        logger.info("physics_figures changed: re-reading %s", ", ".join(sorted(stale)))
    return sorted(stale)


def _purge(app: Sphinx, env, docname: str) -> None:
    _records(env).pop(docname, None)


def _merge(app: Sphinx, env, docnames, other) -> None:
    for docname in docnames:
        if docname in _records(other):
            _records(env)[docname] = _records(other)[docname]


def setup(app: Sphinx):
    app.connect("source-read", _source_read)
    app.connect("env-get-outdated", _outdated)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    # 2: the environment of the old whole-package scheme is read afresh, once.
    return {"parallel_read_safe": True, "parallel_write_safe": True, "env_version": 2}
