"""Help before the answer (book/_ext/questions/static/help-steps.js), run under Node on the whole
bank: every numeric part of every variant the site ships has a step to show, and no step holds
the part's answer as its key prints it. (tests/js/help-steps.test.js tests the selection's rules;
tests/browser/test_help_steps_browser.py the page.)"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

from support.engine import node

from physics_figures import bank
from physics_figures.notation import format_number

ROOT = Path(__file__).resolve().parents[2]
HELP = ROOT / "book" / "_ext" / "questions" / "static" / "help-steps.js"
STEPS = f"""
const help = require({json.dumps(str(HELP))});
let input = "";
process.stdin.on("data", (chunk) => (input += chunk));
process.stdin.on("end", () => {{
  const out = JSON.parse(input).map((data) => data.parts.map((part) => help.steps(data, part)));
  process.stdout.write(JSON.stringify(out));
}});
"""


def _text(step: dict) -> str:
    html = re.sub(r"<sup>(.*?)</sup>", r"^(\1)", step.get("html") or step.get("text") or "")  # 20.25² is not 20.252
    return re.sub(r"<[^>]+>", "", html)


def holds(text: str, printed: str) -> bool:
    """Does the text hold this number, not as part of a longer one (1.2 in 11.2 or 1.25)?"""
    return re.search(rf"(?<![\d.]){re.escape(printed)}(?!\.?\d)", text) is not None


def test_holds_finds_a_number_only_as_itself():
    assert holds("Δp of A = \u22121.2 N s", "1.2")  # the book's minus sign
    assert not holds("v = 11.2 + 1.25", "1.2")
    assert not holds("p = √(20.25^(2) + 2.5^(2))", "20")


def test_every_numeric_part_has_steps_and_none_gives_its_answer_away():
    questions = [bank.TEMPLATES[key].variant(index) for key in sorted(bank.TEMPLATES)
                 for index in bank.TEMPLATES[key].site_variants]
    data = [question.browser_data() for question in questions]
    result = subprocess.run([node(), "-e", STEPS], input=json.dumps(data), check=False, capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    shown, problems = 0, []
    for question, steps in zip(questions, json.loads(result.stdout), strict=True):
        for part_id, part, part_steps in zip(question.part_ids, question.parts, steps, strict=True):
            where = f"{question.key} ({part_id})"
            if part.kind not in ("numeric", "graph"):
                assert part_steps == [], where
                continue
            shown += 1
            if not part_steps:
                problems.append(f"{where}: no step to show")
            printed = format_number(abs(part.value), part.shown_sig_figs)
            problems += [f"{where}: a step holds the answer {printed}: {_text(s)}" for s in part_steps
                         if holds(_text(s), printed)]
            problems += _earlier_answers_given(question, part_id, part_steps)
    assert shown > 500  # the whole bank's numeric parts were seen
    assert not problems, "\n".join(problems[:30])


def _earlier_answers_given(question, part_id, part_steps) -> list[str]:
    """A later part's steps that print an earlier part's answer (the bounce graph's (c) gave
    both readings): help says "your answer to (a)" instead."""
    found = []
    for earlier_id, earlier in zip(question.part_ids, question.parts, strict=True):
        if earlier_id == part_id:
            break
        if earlier.kind not in ("numeric", "graph") or not earlier.value:
            continue
        printed = format_number(abs(earlier.value), earlier.shown_sig_figs)
        found += [f"{question.key} ({part_id}): a step holds ({earlier_id})'s answer {printed}: {_text(s)}"
                  for s in part_steps if _holds_as(_text(s), printed, earlier.unit)]
    return found


def _holds_as(text: str, printed: str, unit: str) -> bool:
    """Does the text hold this number as a value in this unit (not "0.40 J" for 0.40 m s⁻¹)?"""
    for found in re.finditer(rf"(?<![\d.]){re.escape(printed)}(?!\.?\d)", text):
        written = re.match(r"[\s\u00a0]*(kg|g|m|s|N|J|W|kW|Pa|cm|mm|km|ms|rad|°)(?![A-Za-z])", text[found.end():])
        if not written or written.group(1) == unit.split(" ")[0]:
            return True
    return False
