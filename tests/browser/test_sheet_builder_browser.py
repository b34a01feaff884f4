"""The teachers' sheet builder ("For teachers", Make your own) as a teacher meets it, in Chromium.

For a chosen set of types, 30 marks, 3 versions and seed 2027 (issue 26's "Done when"):
- printed to PDF, the pages are A4, each version's sheet and key start their own pages (A's
  sheet, A's key, B's sheet...), each sheet's text holds every part's marks [n] in order and
  the total, and each key the total;
- the questions are the command line's: version by version, the templates and variants and
  the text on the page are physics_figures.worksheets.plan()'s, and version A's numbers are
  those of the LaTeX sheet the command line writes;
- it works offline after one visit that made sheets (the service worker keeps the data), and
  from the built folder opened as files;
- a keyboard alone makes the sheets; axe finds nothing, light or dark.
Issue 37: sheets made at once on a first visit are made again offline; the Versions field says
and allows what the types ticked allow; a refusal says what to change on the form, in its words
(no template ids); a Date line; sheets only or keys only; the status says where a ready-made
worksheet's numbers repeat; a key's "[6 marks]" never wraps; printed, a choice question's
options stay on its stem's page.
Everything expected is computed here from physics_figures."""

from __future__ import annotations

import re
import subprocess

import pytest
from browser import axe_violations, serve_site
from sheet_pages import split_choices
from support.pages import words
from support.pdf import pdf_pages

from physics_figures import topics
from physics_figures.worksheets import plan, ready_made_repeats, select, usable_versions
from physics_figures.worksheets.latex import question_sheet

pytestmark = [pytest.mark.site, pytest.mark.browser]

PAGE = "book/teachers.html"
TYPES = ["drag", "momentum-line", "two-d"]
MARKS, VERSIONS, SEED = 30, 3, 2027
TOPIC = topics.load("physics_figures.bank")


@pytest.fixture(scope="module")
def expected():
    """The command line's sheet for the same choices."""
    templates = select(types=TYPES, topic=TOPIC)
    title = "Worksheet: " + "; ".join(TOPIC.type(t).title for t in TYPES)
    return plan("worksheet", title, templates, versions=VERSIONS, seed=SEED, marks=MARKS, topic=TOPIC)


@pytest.fixture(scope="module")
def base_url(site_dir):
    with serve_site(site_dir, cache_control="no-store") as url:
        yield url


def make_sheets(page, *, types=TYPES, marks=MARKS, versions=VERSIONS, seed=SEED, wait=True):
    page.locator(".sb-form").wait_for()
    for box in page.locator('.sb-form input[name="types"]').all():
        box.set_checked(box.get_attribute("value") in types)
    page.fill("#sb-marks", str(marks))
    page.fill("#sb-versions", str(versions))
    page.fill("#sb-seed", str(seed))
    page.click(".sb-make")
    if wait:
        page.locator(".sb-sheet").nth(versions - 1).wait_for(timeout=60_000)


def html_text(html: str) -> str:
    return words(re.sub(r"<[^>]+>", "", html).replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"))


def builder_questions(page) -> list[list[dict]]:
    return page.evaluate("""() => [...document.querySelectorAll('.sb-sheet')].map(sheet =>
        [...sheet.querySelectorAll('.sb-question')].map(q => ({
            key: q.dataset.question, variant: Number(q.dataset.variant),
            text: q.querySelector('.sb-text').innerText})))""")


def test_the_builder_gives_the_command_line_s_questions(browser, base_url, expected):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    make_sheets(page)
    shown = builder_questions(page)
    assert len(shown) == VERSIONS
    for version, questions in zip(expected.versions, shown, strict=True):
        assert [(q["key"], q["variant"]) for q in questions] == [(i.template.key, i.variant) for i in version.items]
        for item, question in zip(version.items, questions, strict=True):
            assert words(question["text"]) == html_text(item.question.text_html()), item.template.key
    # version A against the LaTeX the command line writes: the same numbers, question by question
    latex = question_sheet(expected, expected.versions[0])
    printed = re.split(r"\\question\{\d+\}", latex)[1:]
    number = re.compile(r"\d+(?:[.,]\d+)?")
    for question, tex in zip(shown[0], printed, strict=True):
        stated = tex.split("\\par", 1)[0]
        assert number.findall(words(question["text"]).replace(" ", "")) == \
            number.findall(re.sub(r"\\[a-z]+|[{}~\s]", "", stated)), question["key"]
    assert page.locator(".sb-sheet .sb-title").first.inner_text() == expected.title
    page.close()


def test_printed_a4_one_sheet_or_key_per_version_with_every_mark_and_total(browser, base_url, expected, tmp_path):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    make_sheets(page)
    pdf = tmp_path / "sheets.pdf"
    page.pdf(path=str(pdf), format="A4")
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True).stdout
    assert re.search(r"Page size:\s+59[5-6](\.\d+)? x 84[1-3](\.\d+)? pts \(A4\)", info), info
    pages = pdf_pages(pdf, "-layout")
    # which section each page belongs to: a section starts at the top of a page, in order
    starts = [f"{kind} {v.letter}" for v in expected.versions for kind in ("sheet", "key")]
    sections: dict[str, str] = {}
    current = None
    for text in pages:
        top = words(" ".join(text.strip().splitlines()[:4]))
        started = [s for s in starts if (f"Version {s[-1]} ·" if s.startswith("sheet") else
                                         f"Answer key, version {s[-1]}") in top]
        if started:
            assert len(started) == 1 and started[0] not in sections, top
            current = started[0]
        assert current is not None, f"a page before the first sheet: {top}"
        sections[current] = sections.get(current, "") + text
    assert list(sections) == starts  # A's sheet, A's key, B's sheet... each on its own pages
    for version in expected.versions:
        sheet, key = sections[f"sheet {version.letter}"], sections[f"key {version.letter}"]
        marks = [m for item in version.items for m in item.question.part_marks()]
        assert [int(n) for n in re.findall(r"\[(\d+)\]", sheet)] == marks
        assert f"Total: {version.marks} marks" in sheet and f"Total: {version.marks} marks" in key
        assert "Data: take g = 9.81 m s⁻²." in words(sheet)
        assert "Make the sheets" not in sheet + key and "For teachers" not in sheet + key  # the sheets alone
    page.close()


def test_offline_after_one_visit_that_made_sheets(browser, base_url, expected):
    context = browser.new_context(service_workers="allow")
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.wait_for_function("navigator.serviceWorker.controller !== null", timeout=60_000)
    make_sheets(page)  # the page keeps the data before it makes the sheets
    context.set_offline(True)
    page.reload()
    make_sheets(page)
    assert [(q["key"], q["variant"]) for q in builder_questions(page)[2]] == \
        [(i.template.key, i.variant) for i in expected.versions[2].items]
    context.close()


def test_from_the_built_folder_opened_as_files(browser, site_dir, expected):
    page = browser.new_page()
    page.goto((site_dir / PAGE).as_uri())
    make_sheets(page)  # the data comes by a <script> element, which file:// allows
    assert [(q["key"], q["variant"]) for q in builder_questions(page)[0]] == \
        [(i.template.key, i.variant) for i in expected.versions[0].items]
    page.close()


def test_a_keyboard_alone_makes_the_sheets(browser, base_url, expected):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.locator(".sb-form").wait_for()
    boxes = page.locator('.sb-form input[name="types"]')
    boxes.first.focus()  # the form's first control (Tab from the page's top passes the site's menus)

    def focused() -> str:
        return page.evaluate("document.activeElement.id || document.activeElement.value || "
                             "document.activeElement.textContent")

    for index in range(boxes.count()):
        value = boxes.nth(index).get_attribute("value")
        assert focused() == value
        if value not in TYPES:
            page.keyboard.press("Space")  # every type starts checked: uncheck the others
        page.keyboard.press("Tab")
    for field, value in (("sb-marks", MARKS), ("sb-versions", VERSIONS), ("sb-seed", SEED)):
        assert focused() == field
        page.keyboard.press("Control+A")
        page.keyboard.type(str(value))
        page.keyboard.press("Tab")
    assert focused() == "both"  # Make: sheets and their keys (a radio group is one stop)
    page.keyboard.press("Tab")
    assert focused() == "Make the sheets"
    page.keyboard.press("Enter")
    page.locator(".sb-sheet").nth(VERSIONS - 1).wait_for(timeout=60_000)
    assert [(q["key"], q["variant"]) for q in builder_questions(page)[1]] == \
        [(i.template.key, i.variant) for i in expected.versions[1].items]
    page.keyboard.press("Tab")
    assert focused() == "Print"
    # Space on the button makes them again (a second press, the same sheets)
    page.keyboard.press("Shift+Tab")
    page.keyboard.press("Space")
    page.wait_for_function("document.querySelector('.sb-status').textContent.startsWith('Made')")
    assert page.locator(".sb-sheet").count() == VERSIONS
    page.close()


@pytest.mark.parametrize("mode", ["light", "dark"])
def test_no_axe_violations_with_sheets_made(browser, base_url, mode):
    context = browser.new_context(color_scheme=mode)
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.evaluate(f"document.documentElement.dataset.theme = '{mode}'")
    make_sheets(page)
    assert axe_violations(page, context_selector=".sb") == []
    context.close()


# ------------------------------------------------------------ issue 37: what a teacher met


def made(page) -> str:
    """The status once the sheets are made or refused (either ends the wait)."""
    page.wait_for_function("(s => s.textContent.startsWith('Made') || s.classList.contains('sb-error'))"
                           "(document.querySelector('.sb-status'))", timeout=60_000)
    return words(page.locator(".sb-status").inner_text())


def test_sheets_made_at_once_on_a_first_visit_are_made_again_offline(browser, base_url):
    """The first sheets, made before the service worker takes the page, keep the data: the next
    day, offline, with the browser's HTTP cache emptied, the builder makes them again. The form's
    defaults: every type, 30 marks, 3 versions, seed 2027."""
    every = [kind.key for kind in TOPIC.types]
    want = plan("w", "", select(types=every, topic=TOPIC), versions=3, seed=2027, marks=30, topic=TOPIC)
    context = browser.new_context(service_workers="allow")
    page = context.new_page()
    page.goto(f"{base_url}/{PAGE}")
    # at once, with the form as it opens: within 1 s of the page's load, by the page's own clock
    assert page.evaluate("""() => { document.querySelector('.sb-make').click();
        return performance.now() - performance.getEntriesByType('navigation')[0].loadEventEnd; }""") < 1000
    assert page.evaluate("navigator.serviceWorker.controller") is None  # before the worker took the page
    assert made(page).startswith("Made")
    page.wait_for_function("navigator.serviceWorker.controller !== null", timeout=120_000)  # its precache is done
    context.new_cdp_session(page).send("Network.clearBrowserCache")
    context.set_offline(True)
    page.reload()
    page.click(".sb-make")
    assert made(page).startswith("Made")
    assert [(q["key"], q["variant"]) for q in builder_questions(page)[2]] == \
        [(i.template.key, i.variant) for i in want.versions[2].items]
    context.close()


def _versions_allowed(types: list[str]) -> int:
    return min(26, *(usable_versions(t) for t in select(types=types, topic=TOPIC)))


def test_the_versions_field_says_and_allows_what_the_types_ticked_allow(browser, base_url):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.locator(".sb-form").wait_for()
    every = [kind.key for kind in TOPIC.types]
    for types in (every, ["two-d"], ["drag", "two-d"], every):
        for box in page.locator('.sb-form input[name="types"]').all():
            box.set_checked(box.get_attribute("value") in types)
        most = _versions_allowed(types)
        plan("w", "", select(types=types, topic=TOPIC), versions=most, seed=SEED, topic=TOPIC)  # allowed
        with pytest.raises(ValueError, match="versions"):
            plan("w", "", select(types=types, topic=TOPIC), versions=most + 1, seed=SEED, topic=TOPIC)
        label = words(page.locator('label[for="sb-versions"]').inner_text())
        assert label == f"Versions (1 to {most})", types
        assert page.locator("#sb-versions").get_attribute("max") == str(most)
        assert f"allow up to {most} versions" in page.locator("#sb-versions-why").inner_text()
    page.close()


def _no_template_keys(text: str) -> None:
    keys = [t.key for t in select(types=[kind.key for kind in TOPIC.types], topic=TOPIC)]
    assert not [key for key in keys if key in text], text
    assert "template" not in text.lower() and "got " not in text, text


def test_refusals_speak_of_the_form_not_of_templates(browser, base_url):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    # marks that cannot be made: the nearest totals, from Python's own draw
    make_sheets(page, types=["two-d"], marks=2, wait=False)
    with pytest.raises(ValueError) as error:
        plan("w", "", select(types=["two-d"], topic=TOPIC), versions=VERSIONS, seed=SEED, marks=2, topic=TOPIC)
    below, above = re.search(r"the nearest totals that can are (\d+) and (\d+)", str(error.value)).groups()
    text = made(page)
    assert text == (f"The sheets cannot be made. No set of questions of the types ticked adds up to exactly 2 "
                    f"marks: the nearest totals are {below} and {above}. Change Total marks to one of those, "
                    "or tick other types.")
    _no_template_keys(text)
    # more versions than the types ticked allow: how many, which types, what to change
    most = _versions_allowed(TYPES)
    limiting = [TOPIC.type(t).title for t in TYPES if _versions_allowed([t]) == most]
    make_sheets(page, versions=most + 1, wait=False)
    text = made(page)
    assert text.startswith(f"The sheets cannot be made. The types ticked allow at most {most} versions"), text
    assert all(title in text for title in limiting) and f"Ask for {most} or fewer, or untick" in text, text
    _no_template_keys(text)
    # more marks than the types hold
    held = sum(t.variant(0).marks for t in select(types=["drag"], topic=TOPIC))
    make_sheets(page, types=["drag"], marks=held + 1, versions=1, wait=False)
    text = made(page)
    assert f"The types ticked hold {held} marks of questions in all" in text, text
    _no_template_keys(text)
    make_sheets(page, types=[], wait=False)
    assert made(page) == "The sheets cannot be made. Tick at least one question type."
    page.close()


def test_a_date_line_beside_name_and_class(browser, base_url):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    make_sheets(page)
    for fields in page.locator(".sb-sheet .sb-fields").all():
        assert words(fields.inner_text()).split() == ["Name", "Class", "Date"]
    page.close()


@pytest.mark.parametrize(("make", "sheets", "keys"), [("sheets", VERSIONS, 0), ("keys", 0, VERSIONS)])
def test_sheets_only_or_keys_only(browser, base_url, make, sheets, keys, tmp_path):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.locator(".sb-form").wait_for()
    page.check(f'input[name="make"][value="{make}"]')
    make_sheets(page, wait=False)
    assert made(page).startswith("Made")
    assert page.locator(".sb-sheet").count() == sheets and page.locator(".sb-key").count() == keys
    pdf = tmp_path / "printed.pdf"
    page.pdf(path=str(pdf), format="A4")
    printed = words(" ".join(pdf_pages(pdf, "-layout")))
    assert ("Answer key, version A" in printed) == bool(keys) and ("Version A ·" in printed) == bool(sheets)
    page.close()


def test_the_status_says_where_a_ready_made_worksheet_s_numbers_repeat(browser, base_url):
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    for versions in (1, _versions_allowed(["drag"])):
        sheet = plan("w", "", select(types=["drag"], topic=TOPIC), versions=versions, seed=SEED, marks=MARKS,
                     topic=TOPIC)
        repeats = ready_made_repeats(sheet, TOPIC)
        make_sheets(page, types=["drag"], versions=versions, wait=False)
        text = made(page)
        if not repeats:
            assert "No question repeats the numbers of a ready-made worksheet" in text
        else:
            listed = "; ".join(r.replace("Version", "version", 1).replace(": as in", " is as in") for r in repeats)
            assert f"the ready-made worksheets' numbers everywhere: {words(listed)}. Fewer versions avoid them." in text
    assert repeats  # the second request needed them
    page.close()


def test_a_key_s_marks_never_wrap(browser, base_url, tmp_path):
    """"[6 marks]" stays on one line in every key header, on a phone and printed."""
    page = browser.new_page(viewport={"width": 390, "height": 844})
    page.goto(f"{base_url}/{PAGE}")
    make_sheets(page)
    lines = page.evaluate("""() => [...document.querySelectorAll('.sb-key-question h4 .sb-marks')].map(m => {
        const range = document.createRange(); range.selectNodeContents(m);
        return [m.textContent, new Set([...range.getClientRects()].map(r => Math.round(r.top))).size]; })""")
    assert lines and all(count == 1 for _, count in lines), [text for text, count in lines if count != 1]
    pdf = tmp_path / "keys.pdf"
    page.pdf(path=str(pdf), format="A4")
    printed = "\n".join(pdf_pages(pdf, "-layout"))
    assert not re.search(r"\[\d+\s*$", printed, re.MULTILINE) and re.search(r"\[\d+ marks\]", printed)
    page.close()


@pytest.mark.parametrize("types", [[kind.key for kind in TOPIC.types], ["drag", "elastic", "two-d", "definitions"]],
                         ids=["every-type", "four-types"])
def test_printed_choice_questions_keep_their_options_with_the_stem(browser, base_url, tmp_path, types):
    """Seed 2027, 30 marks: without the keeping together, a stem ends a page and its options
    start the next (falling-graph-choice, stick-energy-choice)."""
    marks = 30
    sheet = plan("w", "", select(types=types, topic=TOPIC), versions=VERSIONS, seed=SEED, marks=marks, topic=TOPIC)
    page = browser.new_page()
    page.goto(f"{base_url}/{PAGE}")
    page.locator(".sb-form").wait_for()
    page.check('input[name="make"][value="sheets"]')
    make_sheets(page, types=types, marks=marks)
    pdf = tmp_path / "sheets.pdf"
    page.pdf(path=str(pdf), format="A4")
    assert split_choices(pdf_pages(pdf, "-enc", "UTF-8"), list(sheet.versions)) == []
    page.close()
