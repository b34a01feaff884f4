"""The teachers' PDFs (`make pdf`): the book, the question sheet and the answer key.

The PDFs are read back the way a reader meets them, with poppler-utils: pdftotext
for the words, pdfimages for raster images, pdffonts for the fonts. The book is
compared with the built HTML site (titles, numbers, captions) and with the numbers
physics_figures computes (worked answers, question keys). `make test` builds the
site and the PDFs before pytest runs; PDF_DIR points these tests at PDFs built
elsewhere (e.g. `--path-output` builds), as SITE_DIR does for the site.
"""

from __future__ import annotations

import os
import re
import unicodedata
from functools import cache
from html import unescape
from html.parser import HTMLParser
from pathlib import Path

import pytest
import yaml
from support.pdf import poppler

from physics_figures import answers, textformat
from physics_figures.bank import all_questions
from physics_figures.questions import unit_text
from physics_figures.reproducible import SOURCE_DATE_EPOCH

pytestmark = [pytest.mark.site]

ROOT = Path(__file__).resolve().parents[2]
# the LaTeX build has its own folder (the Makefile's LATEX_BUILD), so its own Sphinx environment
PDF_DIR = Path(os.environ.get("PDF_DIR", ROOT / "_build" / "latex-build" / "_build" / "latex"))
BOOK, SHEET, KEY = "dynamics.pdf", "dynamics-questions.pdf", "dynamics-answers.pdf"
ALL_PDFS = (BOOK, SHEET, KEY)
MARK_CODE = re.compile(r"\b[CMAB]1\b")


# ----------------------------------------------------------------- reading PDFs


def pdf_path(name: str) -> Path:
    path = PDF_DIR / name
    if not path.exists():
        pytest.fail(f"no {name} in {PDF_DIR}: run `make pdf` (or `make test`, which builds it)")
    return path


@cache
def pdf_text(name: str) -> str:
    return poppler("pdftotext", "-enc", "UTF-8", str(pdf_path(name)), "-")


def squash(text: str) -> str:
    """Text reduced to what survives typesetting: NFKC (maths italic letters -> ASCII, ligatures),
    straight quotes and hyphens, no whitespace at all (line breaks and spacing differ)."""
    text = unicodedata.normalize("NFKC", text)
    text = text.translate(str.maketrans({
        "\N{RIGHT SINGLE QUOTATION MARK}": "'", "\N{LEFT SINGLE QUOTATION MARK}": "'",
        "\N{LEFT DOUBLE QUOTATION MARK}": '"', "\N{RIGHT DOUBLE QUOTATION MARK}": '"',
        "\N{HYPHEN}": "-", "\N{SOFT HYPHEN}": None}))
    return re.sub(r"\s+", "", text)


@cache
def squashed(name: str) -> str:
    return squash(pdf_text(name))


def page_count(name: str) -> int:
    return int(re.search(r"^Pages:\s+(\d+)", poppler("pdfinfo", str(pdf_path(name))), re.MULTILINE)[1])


# ------------------------------------------------------------ reading the site


def toc_pages() -> list[str]:
    """Every page of _toc.yml, in book order."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    pages = [toc["root"]]

    def visit(entries):
        for entry in entries or []:
            if "file" in entry:
                pages.append(entry["file"])
            visit(entry.get("sections"))
            visit(entry.get("chapters"))

    visit(toc.get("parts"))
    visit(toc.get("chapters"))
    return pages


class _PageNumbers(HTMLParser):
    """The headings (h1, h2), captions and equation numbers a built page shows."""

    def __init__(self):
        super().__init__()
        self.headings: list[str] = []
        self.captions: list[str] = []
        self.equation_numbers: list[str] = []
        self._open: list[str] = []  # what is being collected: heading / caption / eqno
        self._text: list[str] = []
        self._skip = 0  # inside a headerlink (its "#")
        # Inside an element marked hidden: controls a script reveals (the progress page's
        # file buttons), which print and the PDF never show.
        self._hidden_tag, self._hidden = "", 0

    def handle_starttag(self, tag, attrs):
        if self._hidden:
            self._hidden += tag == self._hidden_tag
            return
        if "hidden" in dict(attrs) and tag not in ("input", "img", "br"):
            self._hidden_tag, self._hidden = tag, 1
            return
        classes = (dict(attrs).get("class") or "").split()
        if self._skip or (tag == "a" and "headerlink" in classes):
            self._skip += 1
            return
        kind = None
        if tag in ("h1", "h2"):
            kind = "heading"
        elif tag in ("figcaption", "caption") or (tag == "p" and "caption" in classes):
            kind = "caption"
        elif tag == "span" and "eqno" in classes:
            kind = "eqno"
        if kind and not self._open:
            self._open.append(kind)
            self._text = []
        elif self._open:
            self._open.append("")

    def handle_endtag(self, tag):
        if self._hidden:
            self._hidden -= tag == self._hidden_tag
            return
        if self._skip:
            self._skip -= 1
            return
        if not self._open:
            return
        kind = self._open.pop()
        if kind:
            text = " ".join("".join(self._text).split())
            {"heading": self.headings, "caption": self.captions,
             "eqno": self.equation_numbers}[kind].append(text)

    def handle_data(self, data):
        if self._open and not self._skip and not self._hidden:
            self._text.append(data)


@cache
def page_numbers(site: Path, page: str) -> _PageNumbers:
    parser = _PageNumbers()
    parser.feed((site / f"{page}.html").read_text(encoding="utf-8"))
    return parser


def without_tex(text: str) -> str:
    """HTML keeps maths as TeX source for MathJax; the PDF typesets it. Keep what both share."""
    return re.sub(r"\\\(.*?\\\)|\$.*?\$", " ", text)


def as_printed(html_heading: str) -> str:
    """"5.1. In a lift" (HTML) is "5.1 In a lift" in the PDF's contents."""
    return re.sub(r"^(\d+(?:\.\d+)*)\.\s", r"\1 ", html_heading)


# ------------------------------------------------------------------------ tests


def test_book_lists_every_chapter_and_section_with_the_html_number(site_dir):
    book = squashed(BOOK)
    missing = []
    for page in toc_pages():
        for heading in page_numbers(site_dir, page).headings:
            printed = as_printed(heading)
            parts = [squash(piece) for piece in without_tex(printed).split(" ") if piece.strip()]
            if not all(part in book for part in parts) or (
                "\\(" not in printed and squash(printed) not in book
            ):
                missing.append(f"{page}: {printed!r}")
    assert not missing, "titles (with their HTML numbers) missing from the PDF:\n" + "\n".join(missing)


def test_book_numbers_figures_tables_and_equations_as_the_html_does(site_dir):
    book = squashed(BOOK)
    missing, captions = [], 0
    for page in toc_pages():
        numbers = page_numbers(site_dir, page)
        for caption in numbers.captions:
            match = re.match(r"((?:Fig\.|Table|Listing)\s+[\d.]+)\s+(.*)", caption)
            if not match:
                continue
            captions += 1
            label, words = match.groups()
            start = squash(without_tex(words).split("  ")[0])[:40]
            if squash(label) + ":" + start not in book:
                missing.append(f"{page}: {label}: {words[:50]}")
        for number in numbers.equation_numbers:
            if squash(number) not in book:
                missing.append(f"{page}: equation {number}")
    assert captions > 0, "the site shows no numbered figure or table: is it built?"
    assert not missing, "numbers or captions that differ from the HTML:\n" + "\n".join(missing)


def test_intro_keeps_its_heading_in_the_contents(site_dir):
    intro = toc_pages()[0]
    title = page_numbers(site_dir, intro).headings[0]
    contents = squash(pdf_text(BOOK).split("Contents", 1)[1][:400])
    assert contents.startswith(squash(title)), f"the contents should open with {title!r}"


@pytest.mark.parametrize("example", ["example_1", "example_2", "example_3", "example_4", "example_5"])
def test_worked_example_prints_every_answer(example):
    """Notes, "Worked examples": each value the solution states, as physics_figures prints it."""
    book = squashed(BOOK)
    values = getattr(answers, example)()
    missing = [f"{name} = {value}" for name, value in values.items() if squash(str(value)) not in book]
    assert not missing, f"{example}: answers missing from the PDF: {missing}"


def test_worked_solutions_print_open_with_their_mark_codes():
    text = pdf_text(BOOK)
    assert text.count("Solution to Example") >= 4 and "Exercise" not in text  # worked examples, not exercises
    assert len(MARK_CODE.findall(text)) >= 20


@pytest.mark.parametrize("question", all_questions(), ids=lambda q: q.key)
def test_book_and_answer_key_give_each_answer_with_its_unit(question):
    """Notes, "Quick check" and the practice questions: the key's answers come from the models."""
    for part in question.parts:
        for name in (BOOK, KEY):
            assert squash(part.answer_text) in squashed(name), (
                f"{question.key}: {part.prompt} = {part.answer_text} is not in {name}")
    key = pdf_text(KEY)
    assert len(MARK_CODE.findall(key)) >= sum(q.marks for q in all_questions())


@pytest.mark.parametrize("question", all_questions(), ids=lambda q: q.key)
def test_question_sheet_asks_each_question_with_space_to_answer(question):
    """Each part's answer space, as the part says it prints it (its kind's hooks, no kind's name)."""
    sheet = squashed(SHEET)
    for part in question.parts:
        if part.has_value:  # the prompt, then "=" and the line for the number
            assert squash(part.prompt) + "=" in sheet, f"{question.key}: no answer line for {part.prompt}"
        elif part.sketches:  # four drawings (TikZ) under A to D, then the box
            start = sheet.index(squash(part.prompt))
            assert sheet.index("Answer(A,B,CorD):", start) > start, question.key
        elif part.answer_grid:  # the options, then a box for the letter
            options = "".join(f"{letter}." + squash(textformat.to_plain(option.text))
                              for letter, option in zip("ABCD", part.options, strict=True))
            assert squash(part.prompt) + options + "Answer(A,B,CorD):" in sheet, question.key
        elif part.answered_in_words:  # the prompt, then lines to write on
            assert squash(part.prompt) + "." * 70 in sheet, question.key
        else:  # a sketch: the prompt, then blank axes (their tick numbers, then the time axis's label)
            start = sheet.index(squash(part.prompt)) + len(squash(part.prompt))
            assert squash("t / s") in sheet[start:start + 200], f"{question.key}: no axes for {part.prompt}"
            assert "=" not in sheet[start:start + 3], question.key


@pytest.mark.parametrize("question", [q for q in all_questions() if q.graph], ids=lambda q: q.key)
def test_question_sheet_draws_the_graph_a_question_reads_from(question):
    """The graph is in the sheet as a drawing (its axis labels are text in the vector PDF),
    right after the question's words, before its answer lines (a "which graph?" item: before
    its question and options)."""
    sheet = squashed(SHEET)
    start = sheet.index(squash(textformat.to_plain(question.text))[:60])
    first = question.parts[0]  # a number's prompt ends in its answer line's "="
    first_line = sheet.index(squash(first.prompt) + ("=" if first.has_value else ""), start)
    drawn = sheet[start:first_line]
    assert squash(f"{question.graph.quantity} / {question.graph.unit}") in drawn, question.key
    assert squash("time / s") in drawn, question.key


def test_question_sheet_gives_no_answer_or_mark_scheme():
    sheet, text = squashed(SHEET), pdf_text(SHEET)
    assert not MARK_CODE.findall(text), "the question sheet shows mark codes (a mark scheme)"
    # A number a question states (e.g. "3.0 s") may be another question's answer.
    stated = {squash(f"{given.text}{unit_text(given.unit)}")
              for question in all_questions() for given in question.givens}
    for question in all_questions():
        for part in question.parts:
            answer = squash(part.answer_text.split(" (positive")[0])
            # A whole number, not the end of another ("800N" is not in "11800N", 11 800 N); a
            # ratio, with no unit, is not the start of a quantity either ("0.25" in "k = 0.25 kg m^-1").
            after = r"(?![\w.])" if getattr(part, "unit", None) == "" else ""
            shown = re.search(r"(?<![\d.,])" + re.escape(answer) + after, sheet)
            assert answer in stated or not shown, (
                f"{question.key}: the sheet gives the answer {part.answer_text}")


def test_questions_are_numbered_in_the_same_order_on_the_sheet_and_in_the_key():
    numbered = [re.findall(r"^(\d+)\.\s", pdf_text(name), re.MULTILINE) for name in (SHEET, KEY)]
    count = len(all_questions())
    for found in numbered:
        assert [int(n) for n in found][:count] == list(range(1, count + 1))


@pytest.mark.parametrize("name", ALL_PDFS)
def test_pdf_has_no_code_html_or_raw_tex(name):
    text = pdf_text(name)
    for screen_only in ("IPython.core.display", "<div", "Click", "click to", "object at 0x",
                        "import ", "physics_figures", "glue(", "Show code"):
        assert screen_only not in text, f"{name} prints {screen_only!r}"
    assert "$" not in text, f"{name} prints raw $...$ TeX"
    raw = re.findall(r"\\[A-Za-z]{2,}", text)
    assert not raw, f"{name} prints raw TeX commands: {sorted(set(raw))[:10]}"


def test_book_figures_are_vectors_not_raster_images():
    listing = poppler("pdfimages", "-list", str(pdf_path(BOOK))).splitlines()
    images = listing[2:]  # two header lines
    assert not images, "raster images in the book (figures should be vector PDF):\n" + "\n".join(images)


@pytest.mark.parametrize("name", ALL_PDFS)
def test_every_font_is_embedded(name):
    rows = poppler("pdffonts", str(pdf_path(name))).splitlines()[2:]
    assert rows, f"{name} uses no font?"
    not_embedded = [row for row in rows if row.split()[-5] != "yes"]
    assert not not_embedded, f"{name}: fonts not embedded:\n" + "\n".join(not_embedded)


def test_page_counts_are_sane():
    chapters = len(toc_pages())
    assert chapters <= page_count(BOOK) <= 12 * chapters
    questions = len(all_questions())
    assert questions / 6 <= page_count(SHEET) <= questions
    assert 1 <= page_count(KEY) <= questions


def test_site_offers_the_pdfs_for_download(site_dir):
    for name in ALL_PDFS:
        copy = site_dir / "pdf" / name
        assert copy.exists(), f"{copy} is missing: `make pdf` copies the PDFs into the site"
        assert copy.read_bytes() == pdf_path(name).read_bytes(), f"{copy} is stale"


# ------------------------------------------- as a teacher hands them out (issue "reading")


def _part_marks(question) -> list[int]:
    """Each part's marks as the browser awards them: the lines its data gives that part."""
    lines = [line["part"] for line in question.browser_data()["marks"]]
    return [lines.count(part_id) for part_id in question.part_ids]


@pytest.mark.parametrize("number", range(1, len(all_questions()) + 1),
                         ids=[q.key for q in all_questions()])
def test_question_sheet_prints_each_parts_marks_and_the_total(number):
    """Cambridge's layout: [n] after each part's answer line, the total under the question."""
    from physics_figures.bank import TEMPLATES

    question = all_questions()[number - 1]
    sheet = squashed(SHEET)
    start = sheet.index(squash(f"{number}. {TEMPLATES[question.key].title}"))
    total = re.compile(r"Total:(\d+)marks?").search(sheet, start)
    assert total, f"{question.key}: no total on the sheet"
    assert int(total[1]) == question.marks == sum(_part_marks(question)), question.key
    printed = [int(n) for n in re.findall(r"\[(\d+)\]", sheet[start:total.start()])]
    assert printed == _part_marks(question), f"{question.key}: parts' marks {printed}"


def test_question_sheet_gives_the_data_the_questions_need():
    from physics_figures.constants import G_EARTH
    from physics_figures.notation import format_number

    line = f"take g = {format_number(G_EARTH, 3)} m s⁻²"
    assert squash(line) in squashed(SHEET), f"the sheet does not say {line!r}"
    assert squash("[2]") in squashed(SHEET)


def _version_and_date() -> tuple[str, str]:
    import sys

    sys.path.insert(0, str(ROOT / "book" / "_latex"))
    try:
        from latex_print import version_and_date
    finally:
        sys.path.pop(0)
    return version_and_date(ROOT)


@pytest.mark.parametrize("name", ALL_PDFS)
def test_every_pdf_shows_its_version_and_date_from_the_commit(name):
    version, date = _version_and_date()
    first_page = poppler("pdftotext", "-enc", "UTF-8", "-f", "1", "-l", "2", str(pdf_path(name)), "-")
    shown = squash(version.replace("version", "Version") if version.startswith("version") else "Unversioned")
    assert shown in squash(first_page), f"{name} does not show {version!r} on its first pages"
    assert date in first_page, f"{name} does not show the date {date} on its first pages"


def test_version_and_date_without_git_come_from_source_date_epoch(tmp_path):
    import sys

    sys.path.insert(0, str(ROOT / "book" / "_latex"))
    try:
        from latex_print import version_and_date
    finally:
        sys.path.pop(0)
    assert version_and_date(tmp_path, {"SOURCE_DATE_EPOCH": str(SOURCE_DATE_EPOCH)}) == ("unversioned", "2026-01-01")
    with pytest.raises(ValueError, match="SOURCE_DATE_EPOCH"):
        version_and_date(tmp_path, {})


@pytest.mark.parametrize("name", ALL_PDFS)
def test_pdf_author_names_an_open_textbook_not_cambridge(name):
    info = poppler("pdfinfo", str(pdf_path(name)))
    author = re.search(r"^Author:\s+(.*)$", info, re.MULTILINE)[1]
    assert "open textbook" in author and "9702" in author, author
    assert "not produced or endorsed by Cambridge" in author, author


def test_answer_key_leaves_no_heading_at_the_foot_of_a_page():
    """A page's name or a question's title is never the last line of a page of the key."""
    pages = page_count(KEY)
    titles = {squash(line) for line in pdf_text(SHEET).splitlines() if line.strip()}
    for number in range(1, pages):  # the last page may end anywhere
        text = poppler("pdftotext", "-enc", "UTF-8", "-layout", "-f", str(number), "-l", str(number),
                        str(pdf_path(KEY)), "-")
        lines = [line.strip() for line in text.splitlines() if line.strip() and not line.strip().isdigit()]
        last = lines[-1]
        assert not re.match(r"^\d+\.\s.*\[\d+ marks?\]$", last), f"page {number} ends with the title {last!r}"
        assert not (squash(last) in titles and len(last) < 60 and not re.search(r"[.:]$", last)), (
            f"page {number} ends with a heading: {last!r}")


WEB_ONLY = re.compile(r"\b(tap|taps|tapping|click|clicks|press|pressing|drag the|slider|explorer below|"
                      r"in the page|New numbers|this browser|Check button)\b", re.IGNORECASE)


def test_book_pdf_has_no_web_only_wording_and_says_where_each_explorable_is(site_dir):
    import sys

    text = pdf_text(BOOK).replace("Cambridge University Press", "Cambridge University")
    found = sorted({m[0] for m in WEB_ONLY.finditer(" ".join(text.split()))})
    assert not found, f"the book PDF says {found}"
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    try:
        from explorables import DESCRIPTIONS
    finally:
        sys.path.pop(0)
    book = squashed(BOOK)
    for name, (title, shows) in DESCRIPTIONS.items():
        pages = [p for p in toc_pages() if f'data-explorable="{name}"' in
                 (site_dir / f"{p}.html").read_text(encoding="utf-8")]
        assert len(pages) == 1, name
        heading = re.search(r"<h1>(.*?)<a", (site_dir / f"{pages[0]}.html").read_text(encoding="utf-8"))[1]
        page = re.sub(r"^[\d.]+\s*", "", unescape(re.sub(r"<[^>]+>", "", heading)))
        sentence = f"{title} (in the web version of this book, on the page “{page}”): {shows}."
        assert squash(sentence) in book, f"no sentence for the {name} explorable: {sentence}"
