"""One colour source: physics_figures/style/tokens.json (issue 24, item 3).

Every colour of the site, the figures, the PDF book and the web app manifest is written
there by role, and read from there: a colour written anywhere else is a second source
that drifts (the manifest's blue was not the blue the site shows).
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
from design_tokens import DARK, css, latex_name, rgb, sty
from offline import MANIFEST, THEME_COLOUR, write_manifest

from physics_figures.style import MODES, TOKENS, colour, names, tokens

ROOT = Path(__file__).resolve().parents[2]

#: Files the scan leaves out, and why.
SKIPPED = {
    # the one place colours are written
    TOKENS.relative_to(ROOT).as_posix(): "the tokens file itself",
    # npm's lock file: written by npm, names packages and hashes, never a colour of ours
    "package-lock.json": "written by npm",
    # this file: its examples are the forms of colour the scan must catch
    "tests/no_site/test_design_tokens.py": "the scan's own examples",
}
#: Images keep their colours in their pixels or paths: the pixel baselines of the figure
#: tests (tests/baseline/*.png) and the favicon (_static/favicon.svg), which a browser
#: draws without the page's stylesheets, so it could not read a CSS variable anyway.
IMAGE_SUFFIXES = (".png", ".svg", ".ico", ".jpg", ".woff", ".woff2", ".ttf")

#: Named colours, as CSS, matplotlib and xcolor spell them (not "transparent", "none",
#: "inherit" or "currentColor": they are no colour of their own).
NAMED = (
    "white|black|red|green|blue|yellow|orange|purple|pink|brown|gr[ae]y|silver|navy|teal|"
    "maroon|olive|lime|aqua|fuchsia|cyan|magenta|gold|violet|indigo|darkgr[ae]y|lightgr[ae]y"
)
COLOUR_LITERAL = re.compile(
    "|".join([
        # #rgb, #rgba, #rrggbb, #rrggbbaa, not in a word, an entity (&#123;) or a URL fragment
        r"(?<![\w&#/])#(?P<hex>[0-9a-fA-F]{8}|[0-9a-fA-F]{6}|[0-9a-fA-F]{3,4})(?![\w-])",
        # CSS colour functions with numbers in them
        r"\b(?:rgba?|hsla?|hwb|oklab|oklch|lab|lch)\(\s*[\d.]",
        # xcolor: \definecolor{name}{RGB}{...}
        r"\{(?:RGB|rgb|HTML|cmyk|gray)\}\s*\{",
        # a named colour given to a colour property: CSS, matplotlib keywords, tcolorbox keys
        (rf"(?:\b(?:colou?r|background(?:-color)?|border(?:-[a-z]+)?|outline|fill|stroke|"
         rf"box-shadow)\s*:[^;{{}}\n]*\b(?:{NAMED})\b)"),
        rf"""(?:\b(?:colou?r|[a-z]*facecolor|[a-z]*edgecolor|fc|ec)["']?\s*[=:]\s*["'](?:{NAMED}|[kwrgbcmy]|C\d)["'])""",
        rf"(?:\b(?:colback|colframe|coltitle|colbacktitle|colupper|collower)\s*=\s*(?:{NAMED})\b)",
        rf"\\(?:textcolor|color|colorbox|pagecolor)\{{(?:{NAMED})\}}",
    ])
)
#: An issue or pull request cited in prose ("pydata-sphinx-theme #2451", "issue #24"):
#: digits after a word and a space, not a colour.
ISSUE = re.compile(r"[A-Za-z)]\s#\d+$")


def colour_literals(text: str) -> list[tuple[int, str]]:
    """(line number, the literal) of every colour written in `text`."""
    found = []
    for match in COLOUR_LITERAL.finditer(text):
        start = match.start()
        if match["hex"] and match["hex"].isdigit() and ISSUE.search(text[max(0, start - 2):match.end()]):
            continue
        found.append((text.count("\n", 0, start) + 1, match[0]))
    return found


def tracked_text_files() -> list[Path]:
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
    files = []
    for name in listed.decode().split("\0"):
        path = ROOT / name
        if not name or name in SKIPPED or name.endswith(IMAGE_SUFFIXES) or not path.is_file():
            continue
        data = path.read_bytes()
        if b"\0" in data:  # any other binary file
            continue
        files.append(path)
    return files


def test_no_colour_is_written_outside_the_tokens_file():
    """Files skipped (SKIPPED, IMAGE_SUFFIXES): the tokens file; package-lock.json (npm
    writes it); this file (its examples of what the scan catches); images (the PNG pixel
    baselines, the SVG favicon: their colours are their content) and other binary files."""
    offending = [
        f"{path.relative_to(ROOT)}:{line}: {literal}"
        for path in tracked_text_files()
        for line, literal in colour_literals(path.read_text(encoding="utf-8", errors="replace"))
    ]
    assert not offending, "colours belong in physics_figures/style/tokens.json:\n" + "\n".join(offending)


@pytest.mark.parametrize(
    "text",
    ["color: #fff;", "background: #2f5d8aff", 'facecolor="white"', '"color": "k"', "rgba(0, 0, 0, .25)",
     r"\definecolor{x}{RGB}{1,2,3}", "colback=white,", "border: 1px solid gray;", 'THEME = "#176de8"'],
)
def test_the_scan_sees_a_colour(text):
    assert colour_literals(text), text


@pytest.mark.parametrize(
    "text",
    ["(pydata-sphinx-theme #2451, sphinx-book-theme #988)", "href='#fig-drag'", "&#8212;", "# a comment",
     "background: transparent;", "color: var(--q-right);", "page.fill('#q-quick-check-2-a-value')",
     "the WCAG contrast of two rgb()/rgba() colours", "a blue line"],
)
def test_the_scan_passes_what_is_no_colour(text):
    assert not colour_literals(text), text


VALUE = re.compile(r"#[0-9a-fA-F]{6}|rgba\(\s*\d+,\s*\d+,\s*\d+,\s*[\d.]+\)")


def test_every_role_has_a_colour_in_every_mode():
    for section, entries in tokens().items():
        if section == "about":
            continue
        for name in names(section):
            moded = isinstance(entries[name], dict)
            assert not moded or {"light", "dark"} <= set(entries[name]), f"{section}.{name}: light and dark"
            for mode in MODES:
                assert VALUE.fullmatch(colour(f"{section}.{name}", mode)), f"{section}.{name} ({mode})"


def test_the_site_colours_are_light_and_dark():
    assert all(isinstance(tokens()["site"][name], dict) for name in names("site"))


def test_tokens_css_declares_every_site_colour_light_and_dark():
    written = css()
    light, dark = written.split(DARK)
    for name in names("site"):
        assert f"--{name}: {colour(f'site.{name}').lower()};" in light
        if colour(f"site.{name}", "dark") != colour(f"site.{name}"):
            assert f"--{name}: {colour(f'site.{name}', 'dark').lower()};" in dark


def test_the_latex_colours_are_the_tokens():
    written = sty()
    for name in names("latex"):
        r, g, b = rgb(colour(f"latex.{name}"))
        assert rf"\definecolor{{{latex_name(name)}}}{{RGB}}{{{r},{g},{b}}}" in written
    print_style = (ROOT / "book/_latex/dynamics-print.sty").read_text(encoding="utf-8")
    assert r"\RequirePackage{dynamics-colours}" in print_style
    assert set(re.findall(r"\bdynamics[A-Z]\w*(?:Rule|Title|Back)\b", print_style)) <= {
        latex_name(name) for name in names("latex")}


def test_the_manifest_theme_colour_is_the_sites_blue(tmp_path):
    """The blue of the site's links and header (the theme's primary colour), not another."""
    write_manifest(tmp_path, "Dynamics")
    manifest = json.loads((tmp_path / MANIFEST).read_text(encoding="utf-8"))
    assert manifest["theme_color"] == THEME_COLOUR == colour("theme.link")
    assert manifest["background_color"] == colour("theme.background")



