"""The teacher's kit (physics_figures.worksheets): versions, marks, the command line and the
Moodle export. Fast tests here; tests/site/test_worksheets_pdf.py reads the typeset PDFs."""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from moodle_format import answers_inside_earlier, check_file, moodle_grade

from physics_figures import bank, worksheets
from physics_figures.notation import format_number, plain_number
from physics_figures.worksheets import (
    bank_templates,
    part_marks,
    plan,
    select,
    site_sheets,
    template_marks,
)
from physics_figures.worksheets import moodle as moodle_export
from physics_figures.worksheets.__main__ import main
from physics_figures.worksheets.latex import (
    answer_key,
    ecf_note,
    question_sheet,
    rich,
    tex,
    wrong_answers,
)

ROOT = Path(__file__).resolve().parents[2]
TEMPLATES = bank_templates()


def test_exam_weights_are_the_how_to_pages_table():
    """The end-of-topic test is weighted by the counts the book prints (from the notes)."""
    page = (ROOT / "book" / "exam" / "how-to.md").read_text()
    counts = [int(n) for n in re.findall(r"^\s+- (\d+)\s*$", page, re.MULTILINE)]
    assert counts == [t.exam_count for t in bank.TOPIC.types]
    assert [t.key for t in bank.TOPIC.types] == ["newton", "drag", "force-momentum", "definitions", "momentum-line",
                                                 "elastic", "two-d"]  # the notes' order


@pytest.mark.parametrize("template", TEMPLATES, ids=lambda t: t.key)
def test_every_variant_of_a_template_has_the_same_marks_per_part(template):
    """Versions agree in their marks only if a template's marks never depend on its numbers."""
    first = part_marks(template.variant(0))
    for question in template.variants:
        assert part_marks(question) == first
        assert sum(first) == question.marks == template_marks(template)


def test_versions_have_the_same_templates_and_different_variants():
    sheet = plan("s", "S", select(types=["drag", "force-momentum"]), versions=3, seed=7)
    keys = [tuple(i.template.key for i in v.items) for v in sheet.versions]
    assert len(set(keys)) == 1
    assert len({v.marks for v in sheet.versions}) == 1
    for position in range(len(sheet.templates)):
        variants = [v.items[position].variant for v in sheet.versions]
        assert len(set(variants)) == 3, "two versions share a variant"
        assert 0 not in variants, "a version uses the book's printed numbers"


def test_the_same_seed_gives_the_same_sheet_and_another_seed_another():
    def drawn(seed):
        sheet = plan("s", "S", TEMPLATES, versions=3, seed=seed, marks=30)
        return [[(i.template.key, i.variant) for i in v.items] for v in sheet.versions]

    assert drawn(2027) == drawn(2027)
    assert drawn(2027) != drawn(2028)


@pytest.mark.parametrize("marks", [10, 25, 40])
def test_chosen_templates_make_exactly_the_marks_and_follow_the_exam_weights(marks):
    chosen = plan("s", "S", TEMPLATES, versions=1, seed=1, marks=marks).templates
    assert sum(template_marks(t) for t in chosen) == marks
    if marks == 40:
        total = sum([t.exam_count for t in bank.TOPIC.types])
        for question_type, count in ((t.key, t.exam_count) for t in bank.TOPIC.types):
            got = sum(template_marks(t) for t in chosen if t.type == question_type)
            available = sum(template_marks(t) for t in TEMPLATES if t.type == question_type)
            # each type within a question's marks of its share (or all it has)
            assert abs(got - min(available, 40 * count / total)) <= 5, question_type


def test_site_sheets_are_one_per_type_and_the_40_mark_test():
    sheets = site_sheets()
    assert [s.name for s in sheets] == [f"worksheet-{t}" for t in bank.TOPIC.type_keys] + ["end-of-topic-test"]
    assert sheets[-1].marks == worksheets.END_OF_TOPIC_MARKS
    for sheet in sheets[:-1]:
        question_type = sheet.name.removeprefix("worksheet-")
        assert {t.key for t in sheet.templates} == {t.key for t in bank.by_type(question_type)}
    assert all([v.letter for v in s.versions] == ["A", "B", "C"] for s in sheets)


def test_site_sheets_use_only_variants_the_site_never_shows():
    """Issue 26: a sheet's numbers are never the site's New numbers (a shared template, of few
    situations, is the exception the "For teachers" page lists)."""
    for sheet in site_sheets():
        for version in sheet.versions:
            for item in version.items:
                assert item.variant in item.template.reserve_variants, (sheet.name, item)
                assert item.template.shares_variants or item.variant not in item.template.site_variants


def test_no_question_appears_twice_in_a_kit_of_the_same_letter():
    """Worksheet A and test A never share a template's variant: the test was a repeat of the
    worksheets when variants were drawn from the seed and the template only."""
    sheets = site_sheets()
    for index, letter in enumerate("ABC"):
        asked = [(item.template.key, item.variant) for sheet in sheets for item in sheet.versions[index].items]
        repeated = sorted({q for q in asked if asked.count(q) > 1})
        assert not repeated, f"kit {letter} asks twice: {repeated}"


def test_every_fresh_number_template_has_ten_site_and_ten_reserve_variants():
    for template in TEMPLATES:
        if template.fresh_numbers:
            assert len(template.site_variants) >= 10 and len(template.reserve_variants) >= 10, template.key
            assert 0 in template.site_variants  # the printed numbers are the book's


# ------------------------------------------------------------------ the LaTeX


def test_sheet_has_cover_marks_total_and_data_line_and_no_answers():
    sheet = plan("s", "A test", select(types=["drag"]), versions=1, seed=3)
    version = sheet.versions[0]
    tex = question_sheet(sheet, version).replace("~", " ")  # a tie prints as a space
    for field in ("Name", "Class", "Date"):
        assert f"{field} & \\answerline" in tex
    assert f"Total: {version.marks} marks" in tex
    assert "take g = 9.81 m s⁻²" in tex
    printed = [int(n) for n in re.findall(r"\\partmarks\{(\d+)\}", tex)]
    assert sum(printed) == version.marks
    assert "Multiple-choice answer grid" in tex  # drag has a multiple-choice item
    assert "C1" not in tex and "A1" not in tex


def test_key_gives_answers_mark_codes_ecf_and_wrong_answers():
    sheet = plan("s", "A test", select(templates=["quick-check-3"]), versions=1, seed=3)
    version = sheet.versions[0]
    tex = answer_key(sheet, version).replace("~", " ")
    question = version.items[0].question
    for part in question.parts:
        assert part.answer_text in tex
    for code in ("B1", "C1", "A1"):
        assert f"\\textbf{{{code}}}" in tex
    assert "ecf: a wrong answer to (a)" in tex
    rows = wrong_answers(question, 1)
    names = [row.name for row in rows]
    assert "used g = 10 m s⁻²" in names and "drag used as the resultant force" in names
    assert ecf_note(question, 0) == ""


def test_g_equals_ten_wrong_answer_is_the_models_value():
    """The issue's example: 70 kg, 1500 N gives 11.4 m s⁻² with g = 10."""
    question = bank.TEMPLATES["quick-check-3"].variant(0)
    rows = {row.name: row.written for row in wrong_answers(question, 1)}
    g_ten = next(m for m in question.parts[1].mistakes if m.name == "used g = 10 m s⁻²")
    assert rows["used g = 10 m s⁻²"] == f"{worksheets.latex.format_number(g_ten.value, 3)} m s⁻²"


# ---------------------------------------------------------------- the command line


def _run(capsys, *argv) -> tuple[int, str]:
    code = main(list(argv))
    return code, capsys.readouterr().err


#: One mark more than the elastic templates hold together: a sheet of them cannot make it.
TOO_MANY_ELASTIC = str(sum(worksheets.template_marks(t) for t in bank.by_type("elastic")) + 1)


@pytest.mark.parametrize(("argv", "names"), [
    (["--types", "drag,gravity"], ["types", "'gravity'", "newton"]),
    (["--templates", "quick-check-9"], ["templates", "'quick-check-9'", "--list"]),
    (["--templates", "graph-skydiver-termnal"], ["(did you mean graph-skydiver-terminal?)"]),
    (["--types", "elastic", "--marks", TOO_MANY_ELASTIC], ["marks", TOO_MANY_ELASTIC, "elastic"]),
    (["--types", "drag,two-d", "--marks", "400"], ["marks", "400"]),
    (["--templates", "terminal-velocity-explained", "--versions", "5"], ["versions", "terminal-velocity-explained has 4"]),
    (["--types", "drag", "--versions", "0"], ["versions", "1 to 26"]),
    ([], ["types or templates"]),
])
def test_cli_errors_name_what_is_wrong(capsys, tmp_path, argv, names):
    out = tmp_path / "never-written"
    code, err = _run(capsys, *argv, "--out", str(out))
    assert code == 2
    assert err.startswith("error: ")
    for name in names:
        assert name in err, err
    assert not out.exists()


def test_cli_lists_the_bank(capsys):
    assert main(["--list"]) == 0
    out = capsys.readouterr().out
    for template in TEMPLATES:
        assert template.key in out


def test_cli_runs_as_a_module():
    result = subprocess.run([sys.executable, "-m", "physics_figures.worksheets", "--types", "nope"],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2 and "nope" in result.stderr


# -------------------------------------------------------------------- Moodle


@pytest.fixture(scope="module")
def small_export():
    """A few templates, one of each kind: numbers, a direction, multiple choice, explain, a graph."""
    keys = ["quick-check-3", "parachute-opens-choice", "terminal-velocity-explained",
            "graph-skydiver-terminal", "quick-check-4", "practice-pucks"]
    tree, count = moodle_export.export([bank.TEMPLATES[k] for k in keys])
    text = ET.tostring(tree.getroot(), encoding="unicode")
    return ET.fromstring(text), count


def test_moodle_export_passes_the_structural_check(small_export):
    root, count = small_export
    problems, _categories = check_file(root)
    assert not problems, "\n".join(problems[:20])
    assert {"numerical", "multichoice", "essay"} <= set(count)


def test_moodle_has_a_category_per_type_and_every_variant_of_each_part(small_export):
    root, _ = small_export
    _, categories = check_file(root)
    root_path = moodle_export.root_category()
    assert f"{root_path}/{bank.TOPIC.type('drag').title}" in categories
    template = bank.TEMPLATES["quick-check-3"]
    first = template.variant(0)
    for index, part in enumerate(first.parts):
        path = f"{root_path}/{bank.TOPIC.type('drag').title}/{template.title} {first.label(index)}{part.prompt}"
        # a part that asks for a direction is one Cloze question (size and direction boxes)
        kind = "cloze" if part.direction == "choice" else "numerical"
        asked = [q for q in categories[path] if q.get("type") == kind]
        assert len(asked) == len(categories[path]) == len(template.reserve_variants) >= moodle_export.MOODLE_MIN_VARIANTS
    explain = bank.TEMPLATES["terminal-velocity-explained"]
    essays = [q for q in root.iter("question") if q.get("type") == "essay"]
    assert len(essays) == len(explain.values)  # fewer than 8 situations: every one, shared with the site


def _question(root, idnumber: str):
    return next(q for q in root.iter("question") if q.findtext("idnumber") == idnumber)


def _first_reserve(key: str) -> int:
    """Moodle holds only the reserve: the first of a template's (the site never shows it)."""
    return bank.TEMPLATES[key].reserve_variants[0]


def test_moodle_takes_the_books_written_forms_of_a_right_answer(small_export):
    """The key at 2 s.f. (that value only) and at 3 s.f. (half a unit in the 3rd figure), the
    key as it prints first; not half a unit in the 2nd s.f. (which took 2.88 for 2.85)."""
    root, _ = small_export
    index = _first_reserve("quick-check-3")
    key = bank.TEMPLATES["quick-check-3"].variant(index).parts[0].value  # a force of the order of 700 N
    question = _question(root, f"quick-check-3-v{index}-a")
    right = [(float(a.findtext("text")), float(a.findtext("tolerance")))
             for a in question.findall("answer") if a.get("fraction") == "100"]
    three, two = float(format_number(key, 3)), float(format_number(key, 2))
    assert right[0] == (three, 0.5)
    assert (two, pytest.approx(two * moodle_export.EXACT)) in right
    # a value that is the key at 2 s.f. but not at 3 s.f.: 5 units of the 3rd figure away
    stray = three + 5 if three + 5 < two + 5 else three - 5
    assert float(format_number(stray, 2)) == two
    assert not any(abs(stray - value) <= width for value, width in right)


def test_moodle_holds_only_the_reserve(small_export):
    """No variant the site shows is in the Moodle file (issue 26): its ids name reserve variants."""
    root, _ = small_export
    for question in root.iter("question"):
        idnumber = question.findtext("idnumber")
        if question.get("type") == "category" or not idnumber:
            continue
        key, index = re.fullmatch(r"(.+)-v(\d+)-[a-z]+", idnumber).groups()
        template = bank.TEMPLATES[key]
        assert int(index) in template.reserve_variants, idnumber
        assert template.shares_variants or int(index) not in template.site_variants, idnumber


def test_moodle_grades_each_mistake_by_the_lines_it_keeps(small_export):
    root, _ = small_export
    grades = {a.findtext("feedback/text")[:20]: float(a.get("fraction"))
              for a in _question(root, f"practice-pucks-v{_first_reserve('practice-pucks')}-a").findall("answer")}
    assert grades, "no answers"
    # quick check 3 (b) asks a direction: one Cloze question, g = 10 keeping the C1 of the size's two lines
    index = _first_reserve("quick-check-3")
    cloze = _question(root, f"quick-check-3-v{index}-b")
    assert cloze.get("type") == "cloze"
    text = cloze.findtext("questiontext/text")
    value = bank.TEMPLATES["quick-check-3"].variant(index).parts[1].value
    size = format_number(value, 3)

    def half(of: float) -> str:  # half a unit in the 3rd figure, as the export writes it
        return format(10 ** (math.floor(math.log10(abs(of))) - 2) / 2, ".10g")

    assert "{2:NUMERICAL:=" + size + f":{half(value)}#" in text
    assert "{1:MULTICHOICE:=" in text
    g_ten = bank.TEMPLATES["quick-check-3"].variant(index).parts[1].answer_for_g(10.0)
    assert f"%50%{format_number(g_ten, 3)}:{half(g_ten)}#" in text
    assert "~=-" + size + f":{half(value)}#Right: the minus sign is ignored" in text


def _book_unit_tables() -> dict:
    """The book's unit reader's tables (answer-reading.js), read under Node."""
    reader = ROOT / "book" / "_ext" / "questions" / "static" / "answer-reading.js"
    script = f"process.stdout.write(JSON.stringify(require({json.dumps(str(reader))}).tables))"
    return json.loads(subprocess.run(["node", "-e", script], capture_output=True, text=True, check=True).stdout)


def _numerical_parts(root):
    """(question element, the bank's part) of each numerical question with a unit."""
    for question in root.iter("question"):
        if question.get("type") != "numerical" or question.find("units") is None:
            continue
        key, index, part_id = re.fullmatch(r"(.+)-v(\d+)-([a-z]+)", question.findtext("idnumber")).groups()
        variant = bank.TEMPLATES[key].variant(int(index))
        yield question, variant.parts[variant.part_ids.index(part_id)]


def test_moodle_units_are_every_prefix_and_spelling_the_book_reads(small_export):
    """Each numerical question declares its unit in each prefix the book's unit reader takes
    (its own table) on the first symbol, powers written ^-2, -2 or ⁻², with and without a slash,
    and in words; without spaces (Moodle deletes them from a response); with the multiplier the
    reader's scales give. Before issue 37 only kN, g and kN s were there: 79.4 cm s^-2 scored 0."""
    root, _ = small_export
    tables = _book_unit_tables()
    sizes = {**{k: v[0] for k, v in tables["base"].items()}, **{k: v[0] for k, v in tables["unprefixed"].items()}}
    seen = set()
    for question, part in _numerical_parts(root):
        units = {u.findtext("unit_name"): float(u.findtext("multiplier")) for u in question.findall("units/unit")}
        assert not [name for name in units if " " in name], question.findtext("idnumber")
        factors = [(m[1], int(m[2] or 1)) for m in re.finditer(r"([^\s^]+)(?:\^(-?\d+))?", part.unit)]
        first, power = factors[0]
        seen.add(part.unit)
        if first in tables["unprefixed"]:  # ° takes no prefix
            assert {"°", "degrees", "deg"} <= set(units), sorted(units)
            continue
        base = first if first in tables["base"] else first[1:]
        own = sizes[base] * (tables["prefixes"].get(first[:1], 1) if base != first else 1)
        for prefix, size in [("", 1), *tables["prefixes"].items()]:
            symbol = prefix + base
            caret = symbol + "".join(s + (f"^{p}" if p != 1 else "") for s, p in factors[1:])
            superscript = caret.replace("^-1", "⁻¹").replace("^-2", "⁻²").replace("^2", "²")
            wanted = {caret, caret.replace("^", ""), superscript}
            if any(p < 0 for _, p in factors):
                bottom = "".join(s + (f"^{-p}" if p != -1 else "") for s, p in factors if p < 0)
                top = symbol + "".join(s + (f"^{p}" if p != 1 else "") for s, p in factors[1:] if p > 0)
                wanted |= {f"{top}/{bottom}", f"{top}/{bottom}".replace("^", "")}
            for name in wanted:
                assert name in units, (question.findtext("idnumber"), name, sorted(units))
                assert units[name] == pytest.approx(own / (sizes[base] * size) ** power, rel=1e-9), name
    assert {"N s", "m s^-1", "N", "kg m^-1"} <= seen
    pucks = _question(root, f"practice-pucks-v{_first_reserve('practice-pucks')}-a")
    units = {u.findtext("unit_name"): float(u.findtext("multiplier")) for u in pucks.findall("units/unit")}
    wanted = {"Ns": 1.0, "kgm/s": 1.0, "kgms^-1": 1.0, "kgms⁻¹": 1.0, "kNs": 0.001, "gm/s": 1000.0, "newtonseconds": 1.0}
    assert {name: units.get(name) for name in wanted} == wanted
    assert float(pucks.findtext("unitpenalty")) == 0.5  # the A1 of 2


def test_moodle_gives_full_marks_to_a_right_value_in_another_prefix(small_export):
    """Through Moodle's own unit matching (spaces deleted, the unit looked up exactly), the right
    value typed in another prefix or spelling scores what the book gives it, full marks; no unit
    or a wrong unit loses the A1."""
    root, _ = small_export
    typed = 0
    for question, part in _numerical_parts(root):
        value = float(question.find("answer").findtext("text"))
        penalty = float(question.findtext("unitpenalty"))
        rest = part.unit.split(" ", 1)[1] if " " in part.unit else ""
        if part.unit.startswith("m "):  # 79.4 cm s^-2 for 0.794 m s^-2
            for prefix, times in (("c", 100), ("k", 1e-3), ("m", 1e3), ("µ", 1e6)):
                response = f"{plain_number(format_number(value * times, 3))} {prefix}m {rest}"
                assert moodle_grade(question, response) == 1.0, (question.findtext("idnumber"), response)
                typed += 1
        if part.unit == "N s":
            assert moodle_grade(question, f"{value * 1000:.6g} g m/s") == 1.0
            assert moodle_grade(question, f"{value} newton seconds") == 1.0
            typed += 1
        assert moodle_grade(question, f"{value}") == pytest.approx(1 - penalty)
        assert moodle_grade(question, f"{value} J") == pytest.approx(1 - penalty)
    assert typed >= 10


def test_moodle_takes_either_rounding_of_a_key_on_a_tie_at_3_sf():
    """A key of 29.75 N s is right at 3 s.f. as 29.7 or 29.8 in the book (it compares at the
    student's last figure, a tie either way). Moodle took only 29.8, and so refused the right value
    in another prefix whenever the product rounded down (2.97e-5 MN s)."""
    template = bank.TEMPLATES["mass-from-momentum-change"]
    index = next(i for i in template.reserve_variants if template.variant(i).parts[0].value == 29.75)
    tree, _ = moodle_export.export([template])
    root = ET.fromstring(ET.tostring(tree.getroot(), encoding="unicode"))
    question = _question(root, f"mass-from-momentum-change-v{index}-a")
    for right in ("29.7 N s", "29.8 N s", "29.75 N s", "2.97e-5 MN s", "29700 g m/s"):
        assert moodle_grade(question, right) == 1.0, right
    for wrong in ("29.6 N s", "29.9 N s"):
        assert moodle_grade(question, wrong) < 1.0, wrong
    assert not check_file(root)[0]


def test_moodle_question_text_never_gives_the_method_away(small_export):
    """"How this part is marked: ecf … (b) = (a) x 400 + 80" is for the teacher and for after the
    attempt: in the general feedback (and an essay's grader information), not the question text."""
    root, _ = small_export
    problems = [p for p in check_file(root)[0] if "gives the method away" in p]
    assert not problems, problems[:3]
    for idnumber in (f"graph-skydiver-terminal-v{_first_reserve('graph-skydiver-terminal')}-c",
                     f"quick-check-3-v{_first_reserve('quick-check-3')}-b"):
        question = _question(root, idnumber)
        assert "How this part is marked" not in question.findtext("questiontext/text")
        assert "How this part is marked: ecf" in question.findtext("generalfeedback/text")


def test_no_moodle_answer_lies_inside_an_earlier_answers_range(small_export):
    """Moodle takes the first answer whose range (nominal tolerance, plus PHP's slack) holds a
    response, and its import warns of an answer inside an earlier one's range: a graph's band of
    readings after its key was one (62 warnings). Each answer of every numerical question and
    Cloze number box lies outside the ranges before it."""
    root, _ = small_export
    problems = [p for p in check_file(root)[0] if "inside the range" in p]
    assert not problems, problems[:5]
    graph = _question(root, f"graph-skydiver-terminal-v{_first_reserve('graph-skydiver-terminal')}-c")
    answers = [(float(a.findtext("text")), float(a.findtext("tolerance"))) for a in graph.findall("answer")]
    assert not answers_inside_earlier(answers)
    # the band of readings is still taken, around the key: pieces either side
    question = bank.TEMPLATES["graph-skydiver-terminal"].variant(_first_reserve("graph-skydiver-terminal"))
    low, high = question.parts[2].band
    for response in (low, high, (low + high) / 2, question.parts[2].value):
        assert moodle_grade(graph, f"{response} kg m^-1") == 1.0, response


def test_moodle_html_is_in_cdata():
    tree, _ = moodle_export.export([bank.TEMPLATES["quick-check-1"]])
    xml = moodle_export.to_xml(tree)
    assert "<![CDATA[<p>A resultant force of" in xml
    assert "&lt;p&gt;" not in xml
    assert ET.fromstring(xml.split("\n", 1)[1]).find("question") is not None


def test_moodle_check_catches_a_broken_file(small_export):
    """The structural check can fail: a mistake after the right answer, a missing image and
    an option without feedback are each found."""
    root, _ = small_export
    broken = ET.fromstring(ET.tostring(root))
    numerical = next(q for q in broken.iter("question") if q.get("type") == "numerical")
    answers = numerical.findall("answer")
    numerical.remove(answers[0])
    numerical.append(answers[0])
    graph = next(q for q in broken.iter("question") if q.find("questiontext/file") is not None)
    graph.find("questiontext").remove(graph.find("questiontext/file"))
    choice = next(q for q in broken.iter("question") if q.get("type") == "multichoice")
    choice.find("answer/feedback/text").text = ""
    problems = "\n".join(check_file(broken)[0])
    assert "the right answers do not come first" in problems
    assert "has no <file>" in problems
    assert "has no feedback" in problems


def test_a_sheet_never_breaks_a_line_between_a_number_and_its_unit():
    """"thrust of 11 | N" once broke across two lines of a sheet: numbers are tied (~) to
    their units in the question text (text format) and in plain text (mistakes, feedback)."""
    assert "thrust of 11~N. Calculate" in rich("thrust of 11 N. Calculate")
    assert r"at 1.5~m~s\textsuperscript{-2}" in rich("at 1.5 m s<sup>-2</sup>")
    assert "used g = 10~m~s⁻²" in tex("used g = 10 m s⁻²")
    assert r"100\% of 20~kg, \{a\}" in tex("100% of 20 kg, {a}")


def test_the_moodle_verdict_script_is_valid_php():
    """scripts/moodle_verdicts.php (the release check in a real Moodle) at least parses."""
    result = subprocess.run(["php", "-l", str(Path(__file__).resolve().parents[2] / "scripts" / "moodle_verdicts.php")],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0 and "No syntax errors" in result.stdout, result.stdout + result.stderr
