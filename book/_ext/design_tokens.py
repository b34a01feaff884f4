"""The book's colours from one file, physics_figures/style/tokens.json (a local Sphinx
extension).

* **HTML.** The "site" colours become CSS custom properties in ``_static/tokens.css``
  (``--q-right``): light values under ``:root``, dark ones under
  ``html[data-theme="dark"]`` (the theme's dark mode), only where they differ. Every
  stylesheet of the site uses them by ``var()`` and writes no colour of its own. The file
  is linked before the extensions' stylesheets, so book/_ext/site_assets puts it at the
  head of the page's one bundle (precached with it by book/_ext/offline); its pruning
  keeps a property while a kept rule reads it.
* **LaTeX.** The "latex" colours become xcolor colours ``dynamicsNAME`` (red, green and
  blue 0-255) in ``dynamics-colours.sty`` beside the .tex files, which
  book/_latex/dynamics-print.sty loads.
"""

from __future__ import annotations

import re
from pathlib import Path

from sphinx.application import Sphinx

from physics_figures.style import colour, names

STYLESHEET = "tokens.css"
LATEX_COLOURS = "dynamics-colours.sty"
DARK = 'html[data-theme="dark"]'


def css() -> str:
    """tokens.css: each site colour as a custom property, light then dark."""
    site = names("site")
    light = {name: colour(f"site.{name}").lower() for name in site}
    dark = {name: colour(f"site.{name}", "dark").lower() for name in site}
    block = "\n".join  # one declaration a line
    return (
        "/* Written by book/_ext/design_tokens.py from physics_figures/style/tokens.json:"
        " edit that file. */\n"
        f":root {{\n{block(f'  --{n}: {v};' for n, v in light.items())}\n}}\n"
        f"{DARK} {{\n{block(f'  --{n}: {v};' for n, v in dark.items() if v != light[n])}\n}}\n"
    )


def rgb(hex_colour: str) -> tuple[int, int, int]:
    """(r, g, b), 0-255, of a #rrggbb colour."""
    match = re.fullmatch(r"#([0-9a-fA-F]{2})([0-9a-fA-F]{2})([0-9a-fA-F]{2})", hex_colour)
    if match is None:
        raise ValueError(f"not a #rrggbb colour: {hex_colour!r}")
    return tuple(int(channel, 16) for channel in match.groups())


def latex_name(name: str) -> str:
    """definition-rule -> dynamicsDefinitionRule."""
    return "dynamics" + "".join(word.capitalize() for word in name.split("-"))


def sty() -> str:
    """dynamics-colours.sty: a \\definecolor for each LaTeX colour."""
    lines = [
        r"% Written by book/_ext/design_tokens.py from physics_figures/style/tokens.json: edit that file.",
        r"\NeedsTeXFormat{LaTeX2e}",
        r"\ProvidesPackage{dynamics-colours}",
        r"\RequirePackage{xcolor}",
    ]
    for name in names("latex"):
        lines.append(rf"\definecolor{{{latex_name(name)}}}{{RGB}}{{{','.join(map(str, rgb(colour(f'latex.{name}'))))}}}")
    return "\n".join(lines) + "\n"


def _write(path: Path, text: str) -> None:
    """Write only a change: an unchanged file keeps its date (no-op builds stay no-ops)."""
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def static_folder(app: Sphinx) -> Path:
    """Where tokens.css is written, beside the site (Sphinx copies it into _static/)."""
    outdir = Path(app.outdir)
    return outdir.parent / f"{outdir.name}-tokens"


def _config_inited(app: Sphinx, config) -> None:
    # Written at once, as a static file: book/_ext/site_assets sees a change to it as a
    # change to the site's stylesheets (and rebuilds the bundle).
    folder = static_folder(app)
    _write(folder / STYLESHEET, css())
    if str(folder) not in config.html_static_path:
        config.html_static_path.append(str(folder))


def _builder_inited(app: Sphinx) -> None:
    if app.builder.format == "latex":
        _write(Path(app.outdir) / LATEX_COLOURS, sty())


def setup(app: Sphinx):
    app.connect("config-inited", _config_inited)
    app.connect("builder-inited", _builder_inited)
    # before every extension's stylesheet (default priority 500)
    app.add_css_file(STYLESHEET, priority=200)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
