# ruff: noqa: RUF001  (the typed answers and wordings use the times sign, as students type it)
"""The text part kind (physics_figures/parts/text.py, its marker question-kinds/text.js): the define
and state templates marked from the typed words, by rules that are data citing the published 9702
schemes. The corpus, tests/fixtures/text_answers.json, holds typed answers with the marks an
examiner gives each and why; the marker, under Node, must agree on at least 95 % of them, and no
answer that uses a wording a scheme rejects may earn full marks (issue 38, Done when). The same
answers are typed into the built site in Chromium by tests/browser/test_text_marking_browser.py."""

from __future__ import annotations

import collections
import json
import subprocess
from pathlib import Path

import pytest
from support.engine import node

from physics_figures import bank
from physics_figures.bank import statements
from physics_figures.parts.text import Note, TextPart, TextPoint, print_wording

ROOT = Path(__file__).resolve().parents[2]
CORPUS = json.loads((ROOT / "tests" / "fixtures" / "text_answers.json").read_text())["answers"]
STATEMENT_KEYS = [t.key for t in statements.TEMPLATES]


def mark_texts(items: list[dict]) -> list[dict]:
    """Each {part, answer} marked by the browser's text marker (tests/js/mark_text.js)."""
    result = subprocess.run([node(), str(ROOT / "tests" / "js" / "mark_text.js")], input=json.dumps(items),
                            capture_output=True, text=True, check=True, timeout=120)
    return json.loads(result.stdout)


def corpus_part(row: dict) -> dict:
    return bank.TEMPLATES[row["template"]].variant(row["variant"]).parts[0].browser_data("a")


def marks_of(result: dict) -> int:
    return sum(result.get("earned", []))


@pytest.fixture(scope="module")
def corpus_marked() -> list[dict]:
    return mark_texts([{"part": corpus_part(row), "answer": {"text": row["answer"]}} for row in CORPUS])


def test_the_corpus_holds_150_answers_at_least_12_per_define_and_state_template():
    counts = collections.Counter(row["template"] for row in CORPUS)
    assert len(CORPUS) >= 150
    assert set(counts) == set(STATEMENT_KEYS)
    assert min(counts.values()) >= 12, counts
    for row in CORPUS:
        question = bank.TEMPLATES[row["template"]].variant(row["variant"])
        assert 0 <= row["marks"] <= question.marks, row
        assert row["why"].strip(), row
    # each wording the issue names as one a scheme rejects is in it
    rejected = " ".join(row["answer"].lower() for row in CORPUS if row["rejected_wording"])
    for wording in ("mass × speed", "mass x speed", "kinetic energy is conserved", "equal and opposite reaction",
                    "no resultant force"):
        assert wording in rejected, wording


def test_the_marker_agrees_with_the_examiner_on_95_percent_and_per_template(corpus_marked):
    agree = collections.Counter()
    total = collections.Counter()
    for row, result in zip(CORPUS, corpus_marked, strict=True):
        total[row["template"]] += 1
        agree[row["template"]] += marks_of(result) == row["marks"]
    assert sum(agree.values()) >= 0.95 * len(CORPUS), {k: f"{agree[k]}/{total[k]}" for k in total}
    for key in total:  # no template far below the rest
        assert agree[key] >= 0.85 * total[key], (key, agree[key], total[key])


def test_no_answer_with_a_wording_a_scheme_rejects_earns_full_marks(corpus_marked):
    full = [row["answer"] for row, result in zip(CORPUS, corpus_marked, strict=True)
            if row["rejected_wording"] and marks_of(result) == len(result["earned"])]
    assert full == []


def test_the_feedback_names_each_point_made_and_each_missing(corpus_marked):
    for row, result in zip(CORPUS, corpus_marked, strict=True):
        part = corpus_part(row)
        for point, judged in zip(part["points"], result["points"], strict=True):
            assert point["text"] in result["message"], (row["answer"], point["text"])
            word = {"made": "Made", "missing": "Missing", "undecided": "Cannot tell"}.get(judged["state"], "Not credited")
            assert f"{word}" in result["message"]


# ---------------------------------------------------------------- departure 4: M1 A1


def conservation_marks(answer: str) -> int:
    part = bank.TEMPLATES["state-momentum-conservation"].variant(0).parts[0].browser_data("a")
    return marks_of(mark_texts([{"part": part, "answer": {"text": answer}}])[0])


def test_the_conservation_principle_is_m1_a1_as_the_newest_schemes_mark_it():
    """9702/22/F/M/26 and 9702/23/M/J/25 mark it M1 A1 and accept "isolated system" or "no
    external force" for the A1 (CLARIFICATIONS, Papers). Today's code coded it B1 B1, self-marked,
    with "no resultant external force" the point's words: "isolated system" alone earned nothing."""
    for question in bank.TEMPLATES["state-momentum-conservation"].variants:
        assert [mark.code for mark in question.mark_scheme] == ["M1", "A1"]
        assert question.parts[0].kind == "text"
        assert question.parts[0].browser_data("a")["points"][1]["needs"] == 0
    assert conservation_marks("The total momentum of an isolated system remains constant.") == 2
    assert conservation_marks("Total momentum is conserved if there is no external force.") == 2
    assert conservation_marks("The total momentum of a system stays the same.") == 1
    # the A1 depends on the M1
    assert conservation_marks("It is an isolated system.") == 0
    assert conservation_marks("Momentum before equals momentum after, in an isolated system.") == 0


# ---------------------------------------------------------------- the rules as data


def test_every_point_and_every_note_cites_its_source():
    for key in STATEMENT_KEYS:
        for question in bank.TEMPLATES[key].variants:
            part = question.parts[0]
            assert isinstance(part, TextPart)
            assert [(p.code, p.text) for p in part.points] == [(m.code, m.text) for m in question.mark_scheme]
            for point in part.points:
                assert point.source.strip()
                assert all(note.source.strip() and note.why.strip() for note in point.reject)


def test_the_key_lines_print_the_accepted_and_rejected_wordings():
    part = bank.TEMPLATES["define-momentum"].variant(0).parts[0]
    lines = part.key_lines()
    assert ("accept", "“mass × / product velocity”") in lines
    assert any(kind == "reject" and "mass × / product speed" in text and "speed is a scalar" in text
               for kind, text in lines)
    assert print_wording("speed_of_approach|closing") == "speed of approach / closing"


@pytest.mark.parametrize(("make", "message"), [
    (lambda: TextPoint("x", "C1", ("a",), "9702/22/M/J/24"), "code must be one of"),
    (lambda: TextPoint("x", "B1", (), "9702/22/M/J/24"), "accept must list"),
    (lambda: TextPoint("x", "B1", ("(only optional)",), "9702/22/M/J/24"), "at least one word"),
    (lambda: TextPoint("x", "B1", ("a",), " "), "source must cite"),
    (lambda: Note("a", "", "9702/22/M/J/24"), "why must say"),
    (lambda: TextPart("p", "m", (TextPoint("x", "A1", ("a",), "s"),)), "an A1 must follow the M1"),
])
def test_a_bad_rule_is_refused_by_name(make, message):
    with pytest.raises(ValueError, match=message):
        make()
