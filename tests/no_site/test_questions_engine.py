"""The browser's marking engine (book/_ext/questions/static/marking.js), run under Node.

1. `node --test tests/js` runs the engine's own tests (numbers, significant figures,
   units, direction, named mistakes).
2. Every variant of every template of the bank is marked by the engine with the data
   physics_figures computes: the key's own answer is correct, and each named mistake, the
   g = 9.8 slip and each part-way rounding is recognised as itself.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

from support.engine import mark_all, node
from support.templates import printed

from physics_figures import bank
from physics_figures import questions as q
from physics_figures.notation import format_number, plain_number

ROOT = Path(__file__).resolve().parents[2]
ENGINE = ROOT / "book" / "_ext" / "questions" / "static" / "marking.js"


def test_marking_engine_passes_its_node_tests():
    result = subprocess.run([node(), "--test", str(ROOT / "tests" / "js")], check=False, capture_output=True, text=True,
                            timeout=120, cwd=ROOT)
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-2000:]
    assert "# fail 0" in result.stdout


def _answer(part: q.Part, value: float, *, sig_figs: int, unit: str | None = None, direction: str | None = None,
            exact: bool = False):
    """An answer as a student types it (ASCII digits, no grouping). exact: its significant
    figures beyond doubt, for a value that must be told from the key (660 could be 2 s.f.)."""
    typed = plain_number(format_number(value, sig_figs))
    if exact and re.fullmatch(r"-?\d*[1-9]0+", typed):
        typed = f"{value:.{sig_figs - 1}e}"
    return {"value": typed, "unit": unit or part.unit, "direction": direction or part.answer_direction}


def _cases():
    for template in bank.TEMPLATES.values():
        for index, question in enumerate(template.variants):
            yield from _question_cases(question, f"{question.key}-{index}")


def _question_cases(question: q.Question, name: str):
    for part_id, part in zip(question.part_ids, question.parts, strict=True):
        data = part.browser_data(part_id)
        where = f"{name} ({part_id})"
        if part.kind == "mcq":  # the key's letter is right; each other letter is its named mistake
            for letter, option in zip("ABCD", part.options, strict=True):
                yield (where, letter, data, {"choice": letter},
                       ("mistake", option.mistake) if option.mistake else ("correct", None))
            continue
        if part.kind in ("explain", "text"):  # marked from words (tests/no_site/test_text_marking.py)
            continue
        if part.kind == "sketch":  # the model line earns every feature (each wrong line: test_sketches.py)
            yield where, "model line", data, {"line": [list(p) for p in part.model]}, ("correct", None)
            continue
        # The key as it prints, and the unrounded value, are both right.
        yield where, "key", data, _answer(part, part.value, sig_figs=part.shown_sig_figs), ("correct", None)
        yield where, "full", data, _answer(part, part.value, sig_figs=6), ("correct", None)
        for mistake in part.mistakes:
            typed = _answer(part, mistake.value, sig_figs=3, unit=mistake.unit, direction=mistake.direction,
                        exact=True)
            yield where, mistake.name, data, typed, ("mistake", mistake.name)
        # The slips computed from the working get their own message, and only they do.
        if part.g_nine_eight is not None:
            yield where, "g = 9.8", data, _answer(part, part.g_nine_eight, sig_figs=3, exact=True), ("g-9.8", None)
        for value, what in part.rounded_part_way:
            yield where, what, data, _answer(part, value, sig_figs=3, exact=True), ("rounded-part-way", None)


def test_every_question_marks_its_own_answer_right_and_names_each_mistake():
    # made here, not when the module is collected: every process that collects the suite (each
    # xdist worker, the site's runs) would make every variant's marking data for one test
    cases = list(_cases())
    results = mark_all([{"part": data, "answer": answer} for _, _, data, answer, _ in cases])
    wrong = [
        f"{where} {what}: typed {answer} -> {got['code']} {got.get('mistake')} ({got['message']})"
        for (where, what, _, answer, expected), got in zip(cases, results, strict=True)
        if (got["code"], got.get("mistake")) != expected
    ]
    assert not wrong, "\n".join(wrong)


def test_every_part_unit_is_read_as_si():
    """Each part's unit, as the data gives it, must read at scale 1 (answers are in SI). A ratio's
    unit is "" (none): the engine reads it as a pure number at scale 1 (tests/js/marking.test.js)."""
    units = sorted({part.unit for template in bank.TEMPLATES.values() for question in template.variants
                    for part in question.parts if part.kind == "numeric"} - {""})
    script = (f"const e = require({json.dumps(str(ENGINE))});"
              f"console.log(JSON.stringify({json.dumps(units)}.map(u => e.parseUnit(u))));")
    result = subprocess.run([node(), "-e", script], check=False, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    for unit, parsed in zip(units, json.loads(result.stdout), strict=True):
        assert parsed["ok"] and parsed["readings"][0]["scale"] == 1, unit


def test_the_issues_wrong_causes_are_no_longer_given():
    """Quick check 3(a): 700 N (g = 10) is not "right value"; 686.0 (g = 9.8) and practice 8(a)'s
    1.4 (a resistive force left out) are not "rounding"; practice 7(b)'s 14.7 N is; practice
    10(b) takes rad and degrees; quick check 2 takes the notes' own -1.0."""
    drag = printed("quick-check-3").parts[0].browser_data("a")
    towing = printed("practice-towing").parts[0].browser_data("a")
    rock = printed("practice-mars-rock").parts[1].browser_data("b")
    angle = printed("practice-pucks").parts[1].browser_data("b")
    recoil = printed("quick-check-2").parts[0].browser_data("a")
    results = mark_all([
        {"part": drag, "answer": {"value": "700", "unit": "N"}},
        {"part": drag, "answer": {"value": "7.0 x 10^2", "unit": "N"}},
        {"part": drag, "answer": {"value": "686.0", "unit": "N"}},
        {"part": towing, "answer": {"value": "1.4", "unit": "m s^-2"}},
        {"part": rock, "answer": {"value": "14.7", "unit": "N"}},
        {"part": angle, "answer": {"value": "35.5", "unit": "degrees"}},
        {"part": angle, "answer": {"value": "0.620", "unit": "rad"}},
        {"part": recoil, "answer": {"value": "-1.0", "unit": "m s^-1"}},
        {"part": recoil, "answer": {"value": "- 1.0", "unit": "metres per second"}},
    ])
    codes = [(r["code"], r.get("mistake")) for r in results]
    assert codes == [("mistake", "used g = 10 m s⁻²"), ("mistake", "used g = 10 m s⁻²"), ("g-9.8", None),
                     ("mistake", "trailer's resistance left out"), ("rounded-part-way", None),
                     ("correct", None), ("correct", None), ("correct", None), ("correct", None)]
    assert "mass to 1.5 kg" in results[4]["message"]


def test_sign_slip_and_prefix_slip_on_the_quick_check():
    """Notes, Answers 4: v1 = -2.0 m s^-1, so +2.0 is a sign slip; Answers 1: 15 N s, so 15 g m/s is a prefix slip."""
    v1 = printed("quick-check-4").parts[0].browser_data("a")
    p = printed("quick-check-1").parts[0].browser_data("a")
    sign, prefix = mark_all([
        {"part": v1, "answer": {"value": "2.0", "unit": "m/s"}},
        {"part": p, "answer": {"value": "15", "unit": "g m/s"}},
    ])
    assert sign["code"] == "sign" and "Positive is the direction the 1.0 kg ball moves at first" in sign["message"]
    assert prefix["code"] == "prefix"
