
"""The real-paper suite: published 9702 Paper 1 and Paper 2 Dynamics parts (every *.json case file of
tests/no_site/real_papers/, cases.json and more_papers.json, read as one list; each case cites its paper,
question and part), posed by the bank's templates with the papers' own numbers and marked by the
browser's engine (book/_ext/questions/static/marking.js) under Node, in one run.

A case that cannot be posed stays in the file with its blocker; the test checks that each blocker
still holds, so a case never drops out silently, and one that becomes posable is named."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from support.engine import mark_questions

from physics_figures import bank, variants

#: Every case file of the folder (cases.json, more_papers.json, ...), read as one list.
CASE_FILES = sorted(Path(__file__).parent.glob("*.json"))
CASES = [case for path in CASE_FILES for case in json.loads(path.read_text(encoding="utf-8"))["cases"]]
POSED = [case for case in CASES if "cannot_pose" not in case]
PAPER = re.compile(r"^9702/(1[1-3]|2[1-3])/(F/M|M/J|O/N)/\d\d$")


def _question(case: dict):
    return bank.TEMPLATES[case["template"]].build(**case["givens"])


def _still_blocked(case: dict) -> bool:
    """Whether what the case names as its blocker still stands in the code."""
    blocker = case["cannot_pose"]["blocker"]
    if blocker == "text-kind":  # a define/state part waits for the text kind (k38-text)
        question = bank.TEMPLATES[case["template"]].variant(0)
        return all(part.kind != "text" for part in question.parts)
    if blocker == "sketch-kind":  # a sketch part waits for the sketch kind (k38-sketch) and a template of it
        return "sketch" not in variants.KINDS or case["template"] is None
    if blocker == "refused":  # the template refuses the paper's numbers
        try:
            _question(case)
        except ValueError:
            return True
        return False
    assert blocker == "no-template", f"{case['id']}: unknown blocker {blocker!r}"
    return case["template"] is None


def test_every_case_cites_a_published_paper_question_and_part():
    for case in CASES:
        assert PAPER.match(case["paper"]), case["id"]
        assert case["question"].isdigit() and re.fullmatch(r"(\([a-z]+\))*(\([ivx]+\))?\d?", case["part"]), case["id"]
        assert case["sources"] and all(url.startswith("https://") for url in case["sources"].values()), case["id"]
    assert len({case["id"] for case in CASES}) == len(CASES), "a part is in the case files twice"


def test_every_case_file_of_the_folder_is_in_the_suite():
    """A case file added to the folder (more_papers.json beside cases.json) is read, whole."""
    ids = [case["id"] for case in CASES]
    for path in Path(__file__).parent.glob("*.json"):
        data = json.loads(path.read_text(encoding="utf-8"))
        assert data["about"] and data["cases"], path.name
        assert all(case["id"] in ids for case in data["cases"]), f"{path.name} is not read"


def test_the_suite_holds_the_parts_of_at_least_fifteen_papers():
    assert len({case["paper"] for case in CASES}) >= 15
    assert len(CASES) >= 60


def test_the_parts_that_cannot_be_posed_are_exactly_those_the_file_declares():
    """Each declared blocker still holds (so a part that becomes posable is named, not lost)."""
    declared = [case["id"] for case in CASES if "cannot_pose" in case]
    lifted = [case["id"] for case in CASES if "cannot_pose" in case and not _still_blocked(case)]
    assert not lifted, f"these parts can now be posed: move them to the posed cases: {lifted}"
    assert len(declared) + len(POSED) == len(CASES)


@pytest.mark.parametrize("case", POSED, ids=[case["id"] for case in POSED])
def test_each_posed_part_is_built_from_the_papers_own_numbers(case):
    question = _question(case)
    for name, value in case["givens"].items():
        if isinstance(value, float) and name not in {"body", "side", "turns", "force_on", "figures"}:
            assert any(abs(given.value - value) < 1e-12 for given in question.givens), (case["id"], name)
    part_index = question.part_ids.index(case["template_part"])
    assert question.part_marks()[part_index] == case["template_marks"], case["id"]


def _what_was_typed(typed: dict) -> str:
    """A numeric part's value, a text part's words (question-kinds/text.js marks those), a sketch's line named."""
    return typed.get("text") or typed.get("drawn") or typed["value"]


def _answer(part, typed: dict) -> dict:
    """What the page sends: a sketch's line is the template's model or one of its named wrong lines
    (computed by physics_figures), drawn on the axes; the other kinds as typed."""
    if "drawn" not in typed:
        return typed
    lines = {"the model line": part.model, **{wrong.name: wrong.line for wrong in part.wrong}}
    return {"line": [list(point) for point in lines[typed["drawn"]]]}


def test_the_schemes_answers_and_partial_credit_earn_the_schemes_marks():
    """One Node run marks every answer of every posed case as the site does: the numeric parts by
    the engine's rules, the define/state parts by the text kind's marker (question-kinds/text.js),
    the sketches by the sketch kind's (question-kinds/sketch.js)."""
    runs, expected = [], []
    for case in POSED:
        question = _question(case)
        data, part = question.browser_data(), question.parts[question.part_ids.index(case["template_part"])]
        for answer in case["answers"]:
            runs.append((data, {case["template_part"]: _answer(part, answer["typed"])}))
            earns = case["template_marks"] if answer["earns"] == "all" else answer["earns"]
            expected.append((case["id"], _what_was_typed(answer["typed"]), [earns, case["template_marks"]]))
    marked = mark_questions(runs)
    got = [(case_id, typed, result["marks"]["byPart"][part])
           for (case_id, typed, _), result, (_, answers) in zip(expected, marked, runs, strict=True)
           for part in answers]
    assert got == expected
