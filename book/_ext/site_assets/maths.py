"""Maths at build time: TeX to SVG by MathJax 3 under node (tex2svg.js), with the MathML
beside it for screen readers. No maths JavaScript or fonts reach the reader."""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
import threading
from pathlib import Path

from docutils import nodes
from sphinx.errors import ExtensionError
from sphinx.locale import _
from sphinx.util import logging
from sphinx.util.math import get_node_equation_number

logger = logging.getLogger(__name__)

from .paths import HERE


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
