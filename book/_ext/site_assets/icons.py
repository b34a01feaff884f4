"""The theme's icon font, cut down to the glyphs the theme uses (a few kB, not 150 kB)."""

from __future__ import annotations

import re
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.util import logging

logger = logging.getLogger(__name__)

from .paths import ASSETS, HERE


def theme_dirs() -> list[Path]:
    import pydata_sphinx_theme
    import sphinx_book_theme

    return [
        Path(pydata_sphinx_theme.__file__).parent / "theme" / "pydata_sphinx_theme",
        Path(sphinx_book_theme.__file__).parent / "theme" / "sphinx_book_theme",
    ]


def icon_code_points() -> set[int]:
    """Every Font Awesome glyph the themes' templates or stylesheets can show."""
    pydata, book = theme_dirs()
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
    source = theme_dirs()[0] / "static/vendor/fontawesome/webfonts/fa-solid-900.ttf"
    target = Path(app.outdir) / "_static" / ASSETS / "icons.woff"
    newest_input = max(source.stat().st_mtime, Path(__file__).stat().st_mtime)
    if target.exists() and target.stat().st_mtime >= newest_input:
        return target
    from fontTools import subset  # only when the font is made (a no-op build keeps it)
    from fontTools.ttLib import TTFont

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
