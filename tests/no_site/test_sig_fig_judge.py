"""One judge of significant figures (issue 39): the shared case table
(tests/fixtures/sig_fig_cases.json, each judgement worked by hand from the rule table's
"sig_figs") runs through physics_figures.marking.judge_sig_figs and through the browser's
engine under Node, and they agree on every case, down to the feedback's words."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from test_questions_engine import node

from physics_figures import marking

ROOT = Path(__file__).resolve().parents[2]
TABLE = json.loads((ROOT / "tests" / "fixtures" / "sig_fig_cases.json").read_text(encoding="utf-8"))
CASES = TABLE["cases"]


def python_judgement(row: dict) -> marking.SigFigJudgement | None:
    """The Python judge's judgement of a case (None: it is no number, a ValueError)."""
    try:
        return marking.judge_sig_figs(row["written"], row["key"], min_sf=row.get("min_sf"),
                                      check_sf=row.get("check_sf"))
    except ValueError:
        return None


def test_the_table_covers_the_rule():
    """At least 40 cases, with each part of the rule: zeros after a point, 1 s.f., powers of
    ten, leading zeros, a whole number's trailing zeros, and each judgement."""
    written = [row["written"] for row in CASES]
    assert len(CASES) >= 40
    for needed in ("0.300", "4.40", "0.3", "0.0045", "4500", "4.5 × 10³"):  # noqa: RUF001 (the times sign students type)
        assert needed in written, needed
    assert {row["judgement"] for row in CASES} == {"correct", "too-few-sf", "wrong", "unreadable"}


@pytest.mark.parametrize("row", CASES, ids=lambda row: f"{row['written']} for {row['key']}")
def test_the_python_judge_gives_the_table_s_judgement(row):
    judged = python_judgement(row)
    if row["judgement"] == "unreadable":
        assert judged is None, judged
        return
    assert judged is not None and judged.code == row["judgement"], judged
    if row["judgement"] == "too-few-sf":
        assert (judged.few, judged.padded) == (row["few"], row["padded"])


def test_the_browser_s_engine_and_the_python_judge_agree_on_every_case():
    result = subprocess.run([node(), str(ROOT / "tests" / "js" / "sig_fig_cases.js")], input=json.dumps(CASES),
                            check=False, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    disagree = []
    for row, browser in zip(CASES, json.loads(result.stdout), strict=True):
        judged = python_judgement(row)
        python = ("unreadable-number", "") if judged is None else (judged.code, judged.feedback)
        said = browser["message"] if browser["code"] in ("too-few-sf",) else ""
        if (browser["code"], said) != (python[0], python[1] if judged is not None else ""):
            disagree.append((row["written"], row["key"], browser, python))
    assert not disagree, disagree


def test_the_judge_refuses_a_band_it_cannot_judge():
    with pytest.raises(ValueError, match=r"min_sf must be between 1 and check_sf=3 \(got min_sf=4\)"):
        marking.judge_sig_figs("4.4", 4.4, min_sf=4)
    with pytest.raises(ValueError, match=r"written must be a number .* \(got written='1,500'\)"):
        marking.judge_sig_figs("1,500", 1500)
