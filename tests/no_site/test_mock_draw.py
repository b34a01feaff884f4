"""The mock test's draw (book/_ext/questions/static/mock-draw.js), under Node, on the book's own
index (questions/mock_test.py, index_of, from the bank as the pages place it):

- a test takes 9702's pace: Paper 1, 1.875 minutes a question; Paper 2, 1.25 minutes a mark;
- Paper 1 asks the multiple-choice templates only, its size in questions; Paper 2 the templates
  whose parts are all values (numeric, graph readings), its size in marks, exactly;
- the types are weighted by their exam counts (CLARIFICATIONS, Plan): of the totals each type's
  templates can make, the draw's are the ones that stray least from each type's share, as the
  worksheets share marks (computed here, in Python, by a search of its own);
- no question comes twice: a template comes again only with other numbers, and only when its type
  has no other template left; the variants are the site's, never the teachers' reserve;
- a seed gives the same test again; seeds give different tests.
And the clock: its text, and the warnings a screen reader hears once each."""

from __future__ import annotations

import functools
import json
import re
import sys
from collections import Counter
from pathlib import Path

import pytest

from physics_figures import topics

ROOT = Path(__file__).resolve().parents[2]
RUNNER = ROOT / "tests" / "js" / "mock_draw.js"
sys.path.insert(0, str(ROOT / "book" / "_ext"))
from questions.mock_test import index_of
from support.engine import node_json

TOPIC = topics.load("physics_figures.bank")
#: Every template the practice pages place (tests/no_site/test_questions.py checks they place them all).
INDEX = index_of([TOPIC], {t.key for t in TOPIC.templates})
SIZES = {"1": (10, 20), "2": (15, 20, 30)}
SEEDS = range(40)
PACE = {"1": 1.875, "2": 1.25}  # minutes a question (Paper 1) or a mark (Paper 2): 9702's 75-minute papers


run = functools.partial(node_json, RUNNER)  # run(request): what the runner answers


@pytest.fixture(scope="module")
def drawn() -> list[dict]:
    cases = [{"paper": paper, "size": size, "seed": seed} for paper, sizes in SIZES.items() for size in sizes
             for seed in SEEDS]
    tests = run({"index": INDEX, "cases": cases})["tests"]
    assert not [t for t in tests if "error" in t], [t["error"] for t in tests if "error" in t][:3]
    return tests


def asked(paper: str) -> list[dict]:
    """The templates a paper asks, by their kinds (the bank's, not the index's)."""
    if paper == "1":
        return [t for t in INDEX["templates"] if TOPIC.by_key[t["key"]].kinds == ("mcq",)]
    return [t for t in INDEX["templates"] if set(TOPIC.by_key[t["key"]].kinds) <= {"numeric", "graph"}]


def weight(paper: str, template: dict) -> int:
    return 1 if paper == "1" else template["marks"]


def test_the_index_holds_the_site_variants_of_every_template_the_papers_ask():
    by_key = {t["key"]: t for t in INDEX["templates"]}
    assert len(asked("1")) >= 10 and len(asked("2")) >= 20
    for entry in asked("1") + asked("2"):
        template = TOPIC.by_key[entry["key"]]
        assert entry["variants"] == len(template.site_variants)  # the data file's: the reserve is never there
        assert by_key[entry["key"]]["marks"] == template.variant(0).marks
    # the explanations are self-marked: Paper 2 leaves them out
    assert not [t for t in asked("2") if "explain" in t["kinds"]]


def test_a_test_takes_the_papers_pace(drawn):
    for test in drawn:
        assert test["minutes"] == pytest.approx(PACE[test["paper"]] * test["size"])
    assert {(t["paper"], t["size"], t["minutes"]) for t in drawn} >= {("1", 10, 18.75), ("1", 20, 37.5),
                                                                       ("2", 20, 25)}


#: 9702's papers (the syllabus, "Assessment overview"): Paper 1, 40 multiple-choice questions in
#: 1 hour 15 minutes; Paper 2, 60 marks of structured questions in 1 hour 15 minutes.
PAPERS = {"1": (40, "questions", 75), "2": (60, "marks", 75)}
FRACTIONS = {"": 0, "¼": 0.25, "½": 0.5, "¾": 0.75}


def _minutes(text: str) -> float:
    """ "18¾" as 18.75."""
    whole, part = re.fullmatch(r"(\d*)([¼½¾]?)", text).groups()
    return int(whole or 0) + FRACTIONS[part]


def test_the_page_states_each_papers_pace_as_the_test_takes_it(drawn):
    """The mock page's pace sentence says the real paper's timing and the pace it gives, a
    question or a mark, and each length the setup offers with the minutes the draw allows."""
    text = " ".join((ROOT / "book" / "exam" / "mock-test.md").read_text().split())
    allowed = {(t["paper"], t["size"]): t["minutes"] for t in drawn}
    for paper, (count, unit, minutes) in PAPERS.items():
        assert PACE[paper] == minutes / count
        bullet = re.search(rf"\*\*Paper {paper} style\*\*: (.*?)(?: - \*\*|```)", text).group(1)
        assert f"Paper {paper} has {count} {unit}" in bullet, bullet
        seconds = PACE[paper] * 60
        pace = (f"{int(seconds // 60)} minute {int(seconds % 60)}½ seconds a question" if paper == "1"
                else "1¼ minutes a mark")
        assert pace in bullet and (seconds % 60 == 52.5 if paper == "1" else seconds == 75), bullet
        stated = {int(size): _minutes(m) for size, m in re.findall(r"(\d+)(?: \w+)? in (\d*[¼½¾]?) minutes", bullet)}
        assert stated == {size: allowed[(paper, size)] for size in SIZES[paper]}, stated
    assert "Each 9702 paper gives you 1 hour 15 minutes" in text


def test_a_test_asks_its_papers_templates_to_its_size_exactly(drawn):
    for test in drawn:
        templates = {t["key"]: t for t in asked(test["paper"])}
        keys = [q["question"] for q in test["questions"]]
        assert set(keys) <= set(templates), set(keys) - set(templates)
        assert sum(weight(test["paper"], templates[key]) for key in keys) == test["size"]
        for q in test["questions"]:
            assert q["type"] == templates[q["question"]]["type"]
            # a site variant: an index into the template's data file, never the reserve
            assert 0 <= q["variant"] < templates[q["question"]]["variants"]


def makeable(paper: str, size: int, times: int) -> bool:
    """Whether the paper's templates, each at most `times` times, make the size exactly."""
    sums = {0}
    for template in asked(paper):
        for _ in range(min(times, template["variants"])):
            sums |= {s + weight(paper, template) for s in sums if s + weight(paper, template) <= size}
    return size in sums


def test_no_question_comes_twice_and_a_template_again_only_when_the_test_needs_it(drawn):
    repeated = 0
    for test in drawn:
        pairs = [(q["question"], q["variant"]) for q in test["questions"]]
        assert len(pairs) == len(set(pairs)), f"a question twice: {test}"
        times = Counter(q["question"] for q in test["questions"])
        most = max(times.values())
        if most > 1:
            repeated += 1
            assert not makeable(test["paper"], test["size"], most - 1), f"{test}: a template {most} times"
            for key, count in times.items():  # and its type had no other left
                kind = TOPIC.by_key[key].type
                unused = [t["key"] for t in asked(test["paper"]) if t["type"] == kind and t["key"] not in times]
                assert count == 1 or not unused, f"{key} comes {count} times while {unused} of its type do not"
    # Paper 1 of 20 questions needs repeats: the bank has fewer multiple-choice templates
    assert repeated >= len(SEEDS) and not makeable("1", 20, 1)


def least_straying(paper: str, size: int) -> float:
    """The least total by which the types' shares can be missed: each type's |total - size x
    exam count / all counts|, over the totals its templates can make that add up to the size
    exactly, each template asked as few times as the size needs (once, if it can)."""
    times = next(t for t in range(1, 11) if makeable(paper, size, t))
    counts = {kind["key"]: kind["examCount"] for kind in INDEX["types"]}
    best = {0: 0.0}
    for kind, count in counts.items():
        sums = {0}
        for template in [t for t in asked(paper) if t["type"] == kind]:
            for _ in range(min(times, template["variants"])):
                sums |= {s + weight(paper, template) for s in sums if s + weight(paper, template) <= size}
        share = size * count / sum(counts.values())
        following: dict[int, float] = {}
        for total, cost in best.items():
            for amount in sums:
                if total + amount <= size:
                    following[total + amount] = min(following.get(total + amount, float("inf")),
                                                    cost + abs(amount - share))
        best = following
    return best[size]


def test_the_types_are_weighted_by_their_exam_counts(drawn):
    counts = {kind["key"]: kind["examCount"] for kind in INDEX["types"]}
    templates = {t["key"]: t for t in INDEX["templates"]}
    least = {(paper, size): least_straying(paper, size) for paper, sizes in SIZES.items() for size in sizes}
    for test in drawn:
        paper, size = test["paper"], test["size"]
        totals = Counter()
        for q in test["questions"]:
            totals[q["type"]] += weight(paper, templates[q["question"]])
        straying = sum(abs(totals[kind] - size * count / sum(counts.values())) for kind, count in counts.items())
        assert straying == pytest.approx(least[(paper, size)]), (test, dict(totals))
    # Paper 1, 20 questions: each type within one question of its share (Newton's laws, 49 of 235:
    # 4.2), or all its templates can give when each comes twice at most (the definitions' one: 2)
    for twenty in [t for t in drawn if t["paper"] == "1" and t["size"] == 20]:
        by_type = Counter(q["type"] for q in twenty["questions"])
        for kind, count in counts.items():
            most = sum(min(2, t["variants"]) for t in asked("1") if t["type"] == kind)
            assert abs(by_type[kind] - 20 * count / sum(counts.values())) < 1 or by_type[kind] == most, (kind, by_type)


def test_a_seed_gives_the_same_test_and_seeds_give_different_ones(drawn):
    again = run({"index": INDEX, "cases": [{"paper": "2", "size": 20, "seed": 7}] * 2})["tests"]
    assert again[0] == again[1] == next(t for t in drawn if (t["paper"], t["size"], t["seed"]) == ("2", 20, 7))
    tests = {json.dumps(t["questions"]) for t in drawn if (t["paper"], t["size"]) == ("1", 10)}
    assert len(tests) > len(SEEDS) * 0.9
    # and fresh numbers: a template's variant changes with the seed
    numbers: dict[str, set[int]] = {}
    for test in drawn:
        for q in test["questions"]:
            numbers.setdefault(q["question"], set()).add(q["variant"])
    assert all(len(seen) > 1 for seen in numbers.values()), numbers


def test_a_size_the_paper_does_not_offer_is_refused_with_what_it_offers():
    out = run({"index": INDEX, "cases": [{"paper": "2", "size": 17, "seed": 1}, {"paper": "3", "size": 10,
                                                                                   "seed": 1}]})["tests"]
    assert out[0] == {"error": "size must be one of 15, 20, 30 marks (got size=17)"}
    assert out[1] == {"error": "paper must be \"1\" or \"2\" (got paper='3')"}


def test_the_clock_reads_minutes_and_seconds_and_warns_once_at_5_and_1_minute_left():
    out = run({"index": INDEX, "cases": [], "clock": [1_125_000, 1_124_001, 60_000, 999, 0],
               "warnings": [{"ms": 300_001, "given": []}, {"ms": 300_000, "given": []},
                            {"ms": 299_000, "given": [300_000]}, {"ms": 59_000, "given": [300_000]},
                            {"ms": 30_000, "given": []}, {"ms": 30_000, "given": [300_000, 60_000]}]})
    assert out["clock"] == ["18:45", "18:45", "1:00", "0:01", "0:00"]
    texts = [w and w["text"] for w in out["warnings"]]
    assert texts == [None, "5 minutes left.", None, "1 minute left.", "1 minute left.", None]
