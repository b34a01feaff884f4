"""A key says what each common wrong answer scores, and the book's engine agrees.

Issue 37: "The book and Moodle give 'volume left in cm³' 1/2, while the line above it gets
0/2; the key prints both alike." Each wrong answer of a worksheet key now prints its marks
("keeps the C1: 1/2", CLARIFICATIONS "What a wrong answer keeps"). Here every wrong answer of
every template's key is typed into the browser's engine (marking.js, under Node) as a student
would write it, and the engine must award exactly the marks the key prints.
"""

from __future__ import annotations

import re

from support.engine import mark_questions
from support.templates import typed

from physics_figures import bank
from physics_figures.notation import format_number
from physics_figures.worksheets.html import key_body
from physics_figures.worksheets.latex import marks_kept, option_marks, wrong_answers

SCORE = re.compile(r"(\d+)/(\d+)$")


def _typed(part, row) -> dict:
    """What a student who made this row's mistake types into the part."""
    right = {"value": typed(part.value, part.shown_sig_figs), "unit": part.unit, "direction": part.answer_direction}
    if row.name == "sign slip":
        return {**right, "value": typed(-part.value, part.shown_sig_figs)}
    mistake = next((m for m in part.mistakes if m.name == row.name), None)
    if mistake is not None and mistake.direction is not None:
        return {**right, "direction": mistake.direction}
    if mistake is not None:
        value = mistake.value if part.direction == "signed" else abs(mistake.value)
        return {**right, "value": typed(value, 3), "unit": mistake.unit or part.unit}
    if row.name == "used g = 9.8 m s⁻²":
        return {**right, "value": typed(part.g_nine_eight, 3)}
    values = [value for value, _ in part.rounded_part_way if row.written.startswith(_written(value))]
    return {**right, "value": typed(values[0], 3)}


def _written(value: float) -> str:
    return format_number(abs(value), 3)


def _numeric_cases(key: str, question):
    data = question.browser_data()
    for index, (part_id, part) in enumerate(zip(question.part_ids, question.parts, strict=True)):
        if part.kind != "numeric":
            continue
        for row in wrong_answers(question, index):
            yield (key, part_id, row), (data, {part_id: _typed(part, row)})


def test_each_wrong_answer_in_a_key_scores_what_the_engine_gives_it():
    cases = [case for key, template in sorted(bank.TEMPLATES.items())
             for case in _numeric_cases(key, template.variant(0))]
    marked = mark_questions([case for _, case in cases])  # one Node process for the whole bank
    wrong = []
    for ((key, part_id, row), case), result in zip(cases, marked, strict=True):
        earned, available = (int(n) for n in SCORE.search(row.marks).groups())
        if result["marks"]["byPart"][part_id] != [earned, available]:
            wrong.append(f"{key} ({part_id}) {row.written} [{row.name}]: key says {row.marks}, "
                         f"engine gives {result['marks']['byPart'][part_id]} for {case[1]}")
    assert len(cases) > 100 and not wrong, "\n".join(wrong)


def test_the_issues_two_rows_print_different_marks():
    """A slip that keeps the method lines and a wrong method that keeps nothing read differently."""
    assert marks_kept([("C1", ("method",)), ("A1", ("answer",))], ("answer",)) == "keeps the C1: 1/2"
    assert marks_kept([("C1", ("method",)), ("A1", ("answer",))], ("method", "answer")) == "scores 0/2"
    lines = [("C1", ("method",)), ("C1", ("method",)), ("A1", ("answer",))]
    assert marks_kept(lines, ("answer",)) == "keeps both C1 marks: 2/3"
    assert marks_kept([*lines, ("B1", ("direction",))], ("direction",)) == "keeps both C1 marks and the A1: 3/4"


def test_the_key_prints_each_wrong_answers_marks_and_each_wrong_options():
    for key, template in bank.TEMPLATES.items():
        question = template.variant(0)
        html = key_body(question)
        for index, part in enumerate(question.parts):
            if part.kind == "numeric":
                for row in wrong_answers(question, index):
                    assert row.marks in html, (key, row)
            if part.kind == "mcq":
                assert html.count(option_marks(question, index)) >= len(part.options) - 1, key


def test_a_rounded_part_way_value_says_why_its_two_sf_form_is_right():
    """"Why 0.32 is right where 0.320 is not": a part-way value whose 2 s.f. form is the key's own
    rounding says so, and what it scores."""
    found = 0
    for template in bank.TEMPLATES.values():
        question = template.variant(0)
        for index, part in enumerate(question.parts):
            if part.kind != "numeric":
                continue
            for row in wrong_answers(question, index):
                if row.name == "rounded part-way" and "earns full marks: it is the key's" in row.feedback:
                    found += 1
                    assert row.marks.endswith(f"/{len(question.part_lines(question.part_ids[index]))}")
    assert found, "no rounded-part-way value in the bank whose 2 s.f. form is the key's"
