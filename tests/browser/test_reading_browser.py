
"""Reading the built site as a student does, in Debian's Chromium (issue 14, items 1-4).

* no value is split from its unit by a breakable space, on any page;
* every figure's text is drawn at least 11 CSS px high at 390 px (CLARIFICATIONS, Reading:
  SVG font-size x rendered width / viewBox width), book figures and question graphs alike;
* no page shows Python code or a "Show code cell source" toggle;
* a worked example's solution opens from its whole header, a button named
  "Show the solution to Example N", by keyboard.
"""

from __future__ import annotations

import re

import pytest
from browser import goto_page, serve_site, site_pages

from physics_figures.notation import UNIT_SYMBOLS

pytestmark = [pytest.mark.site, pytest.mark.browser]

PHONE = {"width": 390, "height": 844}
#: CLARIFICATIONS, Reading: figure text at least this high, inline, at 390 px.
SMALLEST_FIGURE_TEXT_PX = 11.0


def question_unit_symbols() -> list[str]:
    """Every unit symbol the questions use (their parts' units, split into symbols)."""
    from physics_figures.bank import TEMPLATES

    symbols = set()
    for template in TEMPLATES.values():
        for part in template.variant(0).parts:
            for symbol in re.split(r"[ /]", getattr(part, "unit", "") or ""):
                symbols.add(re.sub(r"\^-?\d+$", "", symbol))
    symbols -= {"", "degrees", "per", "%", "°"}
    assert symbols <= set(UNIT_SYMBOLS), "join_units must know every unit the questions use"
    return sorted(symbols, key=len, reverse=True)


# Each block of text (a paragraph, a list item, a table cell, a read-out...) as a reader's
# line breaker sees it: its text nodes in order, maths and code left out.
BLOCK_TEXTS = """() => {
  const skip = 'script, style, svg, math, code, pre, textarea, kbd, samp, .math-mathml, noscript, template';
  const blocks = new Map();
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!parent || parent.closest(skip)) continue;
    let block = parent;
    while (block !== document.body && /^(inline|contents)/.test(getComputedStyle(block).display)) block = block.parentElement;
    blocks.set(block, (blocks.get(block) || '') + node.data);
  }
  return [...blocks.values()].filter(t => /\\d/.test(t));
}"""


def split_values(texts: list[str], symbols: list[str]) -> list[str]:
    """The values with a unit in `texts` that a line may break inside (a plain space,
    tab or newline between the number, its unit or the unit's symbols)."""
    power = "(?:\u207b?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+)?"
    symbol = rf"(?:{'|'.join(map(re.escape, symbols))}){power}(?![A-Za-z0-9])"
    units = rf"{symbol}(?:(?:\s+|/){symbol})*"
    number = (r"(?<![\w.])\u2212?(?:\d{1,3}(?:[ \u202f]\d{3})+(?![\d.])|\d+(?:\.\d+)?)"
              r"(?:\s*\u00d7\s*10\u207b?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+)?")
    value = re.compile(rf"{number}\s+{units}")
    breakable = re.compile(r"[ \t\n\r]")
    return [m[0] for text in texts for m in value.finditer(text) if breakable.search(m[0])]


# (a figure's "Data and description" disclosure is a figure's output, not a code toggle)
SHOWN_CODE = """() => {
  const out = [];
  for (const el of document.querySelectorAll('.cell_input, .cell .highlight, details.hide, .toggle-details, summary:not(details.figure-data > summary)'))
    if (el.closest('.cell')) out.push(el.className || el.tagName);
  if (/Show code cell (source|content)/.test(document.body.innerText)) out.push('Show code cell source');
  return out;
}"""


@pytest.fixture(scope="module")
def readings(site_dir, browser) -> dict[str, dict]:
    """Every page read once on a 390 px phone: its blocks of text with digits (BLOCK_TEXTS),
    its figures' text sizes (FIGURE_TEXT) and any code shown (SHOWN_CODE)."""
    read = {}
    with serve_site(site_dir) as base:
        context = browser.new_context(viewport=PHONE)
        page = context.new_page()
        for path in site_pages(site_dir):
            goto_page(page, f"{base}/{path}")  # the root page redirects: the page it leads to
            read[path] = {"blocks": page.evaluate(BLOCK_TEXTS), "figures": page.evaluate(FIGURE_TEXT),
                          "code": page.evaluate(SHOWN_CODE)}
        context.close()
    return read


def test_split_values_finds_a_breakable_space_and_passes_a_joined_value():
    symbols = question_unit_symbols()
    assert split_values(["at 50 m s⁻¹ down"], symbols) == ["50 m s⁻¹"]
    assert split_values(["at 50\u00a0m s⁻¹ down"], symbols) == ["50\u00a0m s⁻¹"]
    assert split_values(["12 000\u00a0N s"], symbols) == ["12 000\u00a0N s"]
    assert split_values(["at 50\u00a0m\u00a0s⁻¹, 12\u202f000\u00a0N\u00a0s"], symbols) == []
    assert split_values(["Example 2 shows"], symbols) == []


def test_no_value_is_split_from_its_unit_on_any_page(readings):
    symbols = question_unit_symbols()
    found = {path: split[:8] for path, read in readings.items() if (split := split_values(read["blocks"], symbols))}
    assert not found, f"values a line can break inside (use U+00A0): {found}"


# Text size of every figure on the page: images of SVG (book figures, question graphs) by
# their file's font sizes, inline SVG (explorables) by their computed font size.
FIGURE_TEXT = """async () => {
  const out = [];
  const sizeOf = (t, base) => {
    const style = t.getAttribute('style') || '';
    const m = /font(?:-size)?:[^;]*?([\\d.]+)px/.exec(style);
    if (m) return parseFloat(m[1]);
    const holder = t.closest('[font-size]');
    return holder ? parseFloat(holder.getAttribute('font-size')) : base;
  };
  const images = [...document.querySelectorAll('article img, main img')].filter(i => /\\.svg(\\?|$)/.test(i.src));
  for (const img of images) {
    img.scrollIntoView();
    if (!img.complete) await new Promise(r => img.addEventListener('load', r, {once: true}));
    const box = img.getBoundingClientRect(), cs = getComputedStyle(img);
    const drawn = box.width - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight)
      - parseFloat(cs.borderLeftWidth) - parseFloat(cs.borderRightWidth);
    if (drawn <= 0) continue;  // not shown (a closed dropdown): measured where it is shown
    const doc = new DOMParser().parseFromString(await (await fetch(img.src)).text(), 'image/svg+xml');
    const viewBox = doc.documentElement.getAttribute('viewBox').split(/[\\s,]+/).map(Number);
    for (const t of doc.querySelectorAll('text')) {
      if (!t.textContent.trim()) continue;
      out.push({figure: img.getAttribute('src').split('/').pop(), text: t.textContent.trim(),
                px: sizeOf(t, 16) * drawn / viewBox[2]});
    }
  }
  for (const s of document.querySelectorAll('.explorable svg')) {
    const box = s.getBoundingClientRect(), vb = s.viewBox.baseVal;
    if (!box.width || !vb || !vb.width) continue;
    for (const t of s.querySelectorAll('text')) {
      if (!t.textContent.trim()) continue;
      out.push({figure: 'explorable ' + (s.getAttribute('aria-label') || ''), text: t.textContent.trim(),
                px: parseFloat(getComputedStyle(t).fontSize) * box.width / vb.width});
    }
  }
  return out;
}"""


def test_every_figure_s_text_is_at_least_11_css_px_on_a_390_px_phone(readings):
    small, measured = [], 0
    for path, read in readings.items():
        measured += len(read["figures"])
        small += [f"{path} {t['figure']}: {t['text']!r} at {t['px']:.1f} px"
                  for t in read["figures"] if t["px"] < SMALLEST_FIGURE_TEXT_PX]
    assert measured > 300, f"only {measured} figure texts measured: are the figures on the pages?"
    assert not small, f"{len(small)} figure texts below {SMALLEST_FIGURE_TEXT_PX} px at 390 px: {small[:12]}"


def test_question_graphs_are_measured_too(site_dir, browser):
    """img.q-graph (physics_figures/figures/question_graph.py) is among the figures above."""
    with serve_site(site_dir) as base:
        page = browser.new_page(viewport=PHONE)
        pages = [p for p in site_pages(site_dir) if 'class="q-graph' in (site_dir / p).read_text()]
        assert pages, "no page shows a question graph"
        page.goto(f"{base}/{pages[0]}", wait_until="load")
        texts = [t for t in page.evaluate(FIGURE_TEXT) if t["figure"].startswith("graph-")
                 or "q-graph" in t["figure"]]
        graphs = page.eval_on_selector_all("img.q-graph", "imgs => imgs.map(i => i.getAttribute('src').split('/').pop())")
        assert graphs and {t["figure"] for t in page.evaluate(FIGURE_TEXT)} >= set(graphs), texts[:3]


def test_no_page_shows_code_or_a_code_toggle(readings):
    shown = {path: read["code"] for path, read in readings.items() if read["code"]}
    assert not shown, f"pages that show code or its toggle to students: {shown}"


def example_pages(site_dir) -> list[tuple[str, str]]:
    pages = []
    for path in site_pages(site_dir):
        html = (site_dir / path).read_text()
        heading = re.search(r"<h1>(Example (\d+))", html)
        if heading and 'class="solution dropdown' in html:
            pages.append((path, heading[1]))
    assert len(pages) >= 5, pages
    return pages


def test_a_worked_solution_opens_from_its_whole_header_named_for_its_example(site_dir, browser):
    with serve_site(site_dir) as base:
        page = browser.new_page(viewport=PHONE)
        for path, example in example_pages(site_dir):
            page.goto(f"{base}/{path}", wait_until="load")
            toggle = page.get_by_role("button", name=f"Show the solution to {example}", exact=True)
            assert toggle.count() == 1, f"{path}: no button named 'Show the solution to {example}'"
            solution = page.locator(".solution.dropdown").first
            title = solution.locator(".admonition-title")
            assert title.locator("a").count() == 0, f"{path}: the header still holds a link"
            header, button = title.bounding_box(), toggle.bounding_box()
            assert button["width"] >= 0.95 * header["width"] and button["height"] >= 0.9 * header["height"], (
                f"{path}: the button covers {button} of the header {header}")
            body = solution.locator("section, p").nth(1)
            if "toggle-hidden" not in (solution.get_attribute("class") or ""):
                continue  # opened already (a try-first answer was checked): nothing to open
            assert not body.is_visible()
            toggle.focus()
            page.keyboard.press("Enter")
            opened = page.get_by_role("button", name=f"Hide the solution to {example}", exact=True)
            assert opened.get_attribute("aria-expanded") == "true", path
            assert body.is_visible(), f"{path}: Enter on the header did not show the solution"
            page.keyboard.press("Space")
            assert toggle.get_attribute("aria-expanded") == "false", path
