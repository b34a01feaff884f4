"""The define and state questions (physics_figures.bank.statements): self-marked against the
published scheme's marking points, each point holding the words an examiner needs; one variant
where a definition has one wording (and the template says why), a situation per variant where
the statement can be set in several; on the practice pages, in Your practice, the worksheets
and their keys, and the Moodle export as essay questions."""

from __future__ import annotations

import dataclasses
import json
import re
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from moodle_format import check_file
from support.engine import mark_questions, node

from physics_figures import bank, textformat
from physics_figures.bank import statements
from physics_figures.questions import Question
from physics_figures.variants import MIN_SITUATIONS, Draw, Template
from physics_figures.worksheets import moodle as moodle_export
from physics_figures.worksheets import plan, select
from physics_figures.worksheets.latex import answer_key, question_sheet, rich

ROOT = Path(__file__).resolve().parents[2]

#: The words an examiner needs in each marking point, point by point (every variant). Each
#: row follows the scheme its template's docstring cites:
#: - define-momentum: "product of mass and velocity" (9702 syllabus 3.1.3), a vector (the notes);
#: - define-force: "rate of change of momentum" (9702/21/M/J/16 Q3(b)(i); notes, "Defining force
#:   as mass times acceleration ... examiner reports say this every year");
#: - mass-and-weight-defined: 8702/02/O/N/01 Q1, four B1: resists change in motion; constant OR
#:   scalar; effect of a gravitational field on a mass; variable OR vector (either half earns it);
#: - define-the-newton: 1 kg given 1 m s⁻² (the notes: the constant in F ∝ Δp/Δt is 1);
#: - state-first-law: at rest or constant velocity unless a resultant force acts (CIE booklet,
#:   Newton's laws mark scheme 1, Q1(a));
#: - state-third-law: "equal and opposite" and "on different bodies" (notes, How to get the
#:   marks; 9702/21/M/J/15 Q3(c)); no scheme asks for "the same type of force";
#: - state-second-law: "(resultant) force proportional/equal to rate of change of momentum"
#:   (9702/21/M/J/16 Q3(b)(i), 9702/21/M/J/23 Q3(a));
#: - state-momentum-conservation: "total momentum of a system remains constant" M1, "provided
#:   there are no resultant external forces / isolated system" A1 (9702/22/F/M/26, 9702/23/M/J/25;
#:   9702/23/M/J/13 Q3(a)(i) gave them B1 B1);
#: - state-elastic-collision: "total kinetic energy is conserved" (9702/23/M/J/13 Q3(a)(ii)),
#:   "relative speed of approach ... relative speed of separation" (9702/21/M/J/15 Q3(b));
#: - state-terminal-velocity: constant velocity with zero resultant force, and the forces named
#:   (notes, Common mistakes: "say the resultant force is zero ... naming them").
KEY_WORDS: dict[str, tuple[tuple[str, ...], ...]] = {
    "define-momentum": (("product of mass and velocity",), ("vector", "direction of the velocity")),
    "define-force": (("rate of change of momentum",),),
    "mass-and-weight-defined": (("mass", "resists a change", "motion"), ("either", "scalar", "or", "same wherever"),
                                ("weight", "force", "gravitational field"), ("either", "vector", "or", "changes")),
    "define-the-newton": (("1 kg", "acceleration of 1 m s"),),
    "state-first-law": (("at rest", "constant velocity", "unless a resultant force"),),
    "state-third-law": (("different bodies",),
                        ("equal and opposite", "equal in magnitude", "opposite in direction")),
    "state-second-law": (("resultant force", "proportional", "rate of change of momentum"),),
    "state-momentum-conservation": (("total momentum", "system", "constant"),
                                    ("no resultant external force", "isolated system")),
    "state-elastic-collision": (("total kinetic energy", "conserved"),
                                ("relative speed of approach", "relative speed of separation")),
    "state-terminal-velocity": (("constant velocity", "resultant force", "zero"), ("drag", "weight")),
}
#: Each statement on the practice page of the type that teaches it (notes, How to do it).
TYPES = {"define-momentum": "definitions", "define-force": "definitions",
         "mass-and-weight-defined": "definitions", "define-the-newton": "definitions",
         "state-first-law": "newton", "state-third-law": "newton", "state-second-law": "force-momentum",
         "state-momentum-conservation": "momentum-line", "state-elastic-collision": "elastic",
         "state-terminal-velocity": "drag"}
PAGES = {"definitions": "practice-definitions", "newton": "practice-newtons-laws",
         "force-momentum": "practice-force-momentum", "momentum-line": "practice-momentum-line",
         "elastic": "practice-collisions", "drag": "practice-drag"}
STATEMENTS = list(statements.TEMPLATES)


def missing_key_words(question: Question, words: tuple[tuple[str, ...], ...]) -> list[str]:
    """The key words a question's marking points lack, point by point ("" when none): each
    point must hold every word of its row, in the plain text a student ticks."""
    lines = [textformat.to_plain(mark.text).lower() for mark in question.mark_scheme if mark.code]
    if len(lines) != len(words):
        return [f"{question.key}: {len(lines)} marking points for {len(words)} rows of key words"]
    return [f"{question.key} point {index + 1}: {word!r}" for index, (line, row) in enumerate(zip(lines, words, strict=True))
            for word in row if word.lower() not in line]


def test_the_bank_asks_at_least_eight_define_and_state_questions_each_of_its_type():
    assert len(STATEMENTS) >= 8
    assert {t.key: t.type for t in STATEMENTS} == TYPES
    assert set(KEY_WORDS) == set(TYPES)
    for template in STATEMENTS:
        assert template.kinds == ("text",)
        assert bank.TEMPLATES[template.key] is template
        for question in template.variants:
            assert [part.kind for part in question.parts] == ["text"]
            # a B1 each, as schemes mark a definition; the conservation principle M1 A1, as the
            # newest schemes mark it (9702/22/F/M/26, 9702/23/M/J/25; CLARIFICATIONS, Papers)
            codes = [mark.code for mark in question.mark_scheme]
            assert codes == (["M1", "A1"] if template.key == "state-momentum-conservation" else ["B1"] * len(codes))
            assert question.marks == len(KEY_WORDS[template.key])


@pytest.mark.parametrize("template", STATEMENTS, ids=lambda t: t.key)
def test_every_marking_point_names_the_words_an_examiner_needs(template):
    for question in template.variants:
        assert missing_key_words(question, KEY_WORDS[template.key]) == []


@pytest.mark.parametrize("template", STATEMENTS, ids=lambda t: t.key)
def test_a_weakened_marking_point_is_caught(template):
    """Each key word taken out of its point ("resultant force" becoming "force", "no resultant
    external force" dropped) is reported: the check above can fail."""
    question = template.variant(0)
    for index, row in enumerate(KEY_WORDS[template.key]):
        for word in row:
            mark = question.mark_scheme[index]
            weakened = re.sub(re.escape(word), "it", textformat.to_plain(mark.text), flags=re.IGNORECASE)
            scheme = list(question.mark_scheme)
            scheme[index] = dataclasses.replace(mark, text=weakened)
            changed = dataclasses.replace(question, mark_scheme=tuple(scheme))
            assert f"point {index + 1}: {word!r}" in " ".join(missing_key_words(changed, KEY_WORDS[template.key]))


@pytest.mark.parametrize("template", STATEMENTS, ids=lambda t: t.key)
def test_one_wording_or_a_situation_per_variant_whose_answer_changes(template):
    """A definition: one variant, and the template says why (CLARIFICATIONS, Papers). A statement
    set in situations: at least MIN_SITUATIONS, each with its own text and its own model answer."""
    if template.one_wording:
        assert len(template.values) == 1 and not template.draws
        assert "word for word the same" in template.one_wording
        return
    questions = template.variants
    assert len(questions) >= MIN_SITUATIONS
    assert len({q.text for q in questions}) == len(questions)
    assert len({q.parts[0].model_answer for q in questions}) == len(questions)


def test_the_statements_page_places_every_statement_in_the_banks_order():
    """Every define and state question on one page (their marker loads there only; a type's
    page stays light), none on its type's page."""
    placed = re.findall(r"```\{question\} ([a-z0-9-]+)", (ROOT / "book" / "exam" / "practice-statements.md").read_text())
    assert placed == [t.key for t in STATEMENTS]
    for page in PAGES.values():
        on_page = re.findall(r"```\{question\} ([a-z0-9-]+)", (ROOT / "book" / "exam" / f"{page}.md").read_text())
        assert not set(on_page) & set(placed), page


# ---------------------------------------------------------------- the one-variant rule


def _template(**change) -> Template:
    fields = {"key": "define-x", "type": "definitions", "kinds": ("text",), "title": "Define x",
              "build": statements.define_force, "one_wording": statements._ONE_DEFINITION}
    return Template(**{**fields, **change})


@pytest.mark.parametrize(("change", "message"), [
    ({"kinds": ("mcq",)}, r"one_wording is for a define/state template, whose parts are answered in words"),
    ({"draws": {"situation": Draw(0, 0, 3, 1)}}, "one_wording means one variant, so define-x must have no draws"),
    ({"try_first": True}, "one_wording is for the bank's statements, not a worked example's try-first part"),
    ({"one_wording": "one wording"}, "one_wording must say in a sentence why the wording cannot change"),
    ({"one_wording": ""}, "draws must say how define-x's givens vary"),
])
def test_a_badly_declared_one_wording_template_is_refused_with_the_rule(change, message):
    with pytest.raises(ValueError, match=message):
        _template(**change)


def test_a_one_wording_template_has_one_variant_and_the_variant_rules_skip_it():
    template = _template()
    assert template.least_variants == 1 and len(template.values) == 1
    assert template.variant(0).key == "define-force"
    situated = bank.TEMPLATES["state-momentum-conservation"]
    assert situated.least_variants == MIN_SITUATIONS and not situated.one_wording


# ---------------------------------------------------------------- Your practice


def test_your_practice_counts_a_self_marked_statement_under_its_type():
    """The ticks are the attempt's marks (questions.js records marked.marks, as for any part);
    progress.js sums them by type: a statement ticked 1 of 2, then 2 of 2, shows under its type."""
    key = "define-momentum"
    question = bank.TEMPLATES[key].variant(0)
    data = question.browser_data()
    first, both = mark_questions([(data, {"a": {"text": "mass times velocity", "ticked": [0]}}),
                                  (data, {"a": {"text": "mass times velocity; a vector", "ticked": [0, 1]}})])
    assert (first["marks"]["earned"], first["marks"]["available"]) == (1, 2)
    assert (both["marks"]["earned"], both["marks"]["available"]) == (2, 2)
    kind = {"type": "definitions", "name": "Mass, weight and the definitions",
            "templates": [{"key": key, "title": "Define momentum", "marks": question.marks, "page": "p.html"}]}
    attempts = [{"question": key, "type": "definitions", "variant": 0, "earned": marked["marks"]["earned"],
                 "available": marked["marks"]["available"], "at": at, "mistakes": []}
                for at, marked in ((1, first), (2, both))]
    script = ("const P = require(process.argv[1]);"
              "const input = JSON.parse(require('fs').readFileSync(0, 'utf8'));"
              "const s = P.summarise(input.kind, input.attempts);"
              "process.stdout.write(JSON.stringify({tried: s.tried, earned: s.earned, available: s.available}));")
    progress = ROOT / "book" / "_ext" / "questions" / "static" / "progress.js"
    result = subprocess.run([node(), "-e", script, str(progress)], input=json.dumps({"kind": kind, "attempts": attempts}),
                            capture_output=True, text=True, check=True, timeout=60)
    assert json.loads(result.stdout) == {"tried": 1, "earned": 2, "available": 2}


# ---------------------------------------------------------------- worksheets and Moodle


def test_a_definitions_worksheet_prints_the_question_and_its_key_the_marking_points():
    sheet = plan("s", "Definitions", select(types=["definitions"]), versions=3, seed=5)
    assert {t.key for t in sheet.templates} >= {"define-momentum", "define-force", "define-the-newton"}
    for version in sheet.versions:  # a definition is the same in every version
        item = next(i for i in version.items if i.template.key == "define-momentum")
        assert item.variant == 0
    version = sheet.versions[1]
    question = bank.TEMPLATES["define-momentum"].variant(0)
    sheet_tex = question_sheet(sheet, version)
    assert rich(question.parts[0].prompt) in sheet_tex
    assert "product of mass and velocity" not in sheet_tex  # no answers on the question sheet
    key_tex = answer_key(sheet, version)
    for mark in question.mark_scheme:
        assert f"\\item {rich(mark.text)} \\textbf{{B1}}" in key_tex
    assert f"\\textbf{{Model answer}} \\hfill [2]\\par {rich(question.parts[0].model_answer)}" in key_tex
    assert "Answer }Model answer" not in key_tex  # a part alone is not labelled "Answer Model answer"


def test_a_situated_statement_prints_a_different_situation_in_each_version():
    sheet = plan("s", "Momentum", select(templates=["state-momentum-conservation"]), versions=3, seed=5)
    texts = {version.items[0].question.text for version in sheet.versions}
    assert len(texts) == 3
    for version in sheet.versions:
        key_tex = answer_key(sheet, version)
        assert "no resultant external force" in key_tex


def test_moodle_exports_a_statement_as_an_essay_with_its_marking_points_for_the_grader():
    keys = ["define-momentum", "state-momentum-conservation"]
    tree, count = moodle_export.export([bank.TEMPLATES[k] for k in keys])
    root = ET.fromstring(ET.tostring(tree.getroot(), encoding="unicode"))
    problems, _ = check_file(root)
    assert not problems, "\n".join(problems[:10])
    assert count == {"essay": 1 + len(bank.TEMPLATES["state-momentum-conservation"].values)}
    for key in keys:
        for index, question in enumerate(bank.TEMPLATES[key].variants):
            essay = next(q for q in root.iter("question") if q.findtext("idnumber") == f"{key}-v{index}-a")
            assert essay.get("type") == "essay"
            assert float(essay.findtext("defaultgrade")) == question.marks
            grader = essay.findtext("graderinfo/text")
            for mark in question.mark_scheme:
                assert f"{textformat.to_html(mark.text, paragraphs=False)} <strong>{mark.code}</strong>" in grader
            # the wordings accepted and rejected, for the grader (issue 38)
            assert "<li>Accept: " in grader and "<li>Reject: " in grader


def test_a_point_the_scheme_marks_either_way_takes_either_and_no_point_asks_more_than_its_scheme():
    """Issue 37. 8702/02/O/N/01 Q1 gives a B1 for "constant OR scalar" and one for "variable OR
    vector": the points say either earns it (they asked for both). 9702/21/M/J/15 Q3(c) marks the
    third law as "equal and opposite" on the two bodies: no point asks for "the same type"."""
    lines = [textformat.to_plain(m.text) for m in bank.TEMPLATES["mass-and-weight-defined"].variant(0).mark_scheme]
    for line, (one, other) in ((lines[1], ("scalar", "same wherever")), (lines[3], ("vector", "changes"))):
        assert re.fullmatch(rf"Either: [^;]*{one}[^;]*; or: [^;]*{other}[^;]*", line), line
    third = [textformat.to_plain(m.text) for m in bank.TEMPLATES["state-third-law"].variant(0).mark_scheme]
    assert not [line for line in third if "same type" in line.lower()], third
