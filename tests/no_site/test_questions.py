# ruff: noqa: RUF001  (mark schemes are typeset text: true minus, times)
"""Question data (physics_figures.questions) and the {question} directive (book/_ext/questions).

The quick-check answers are asserted against the notes' "Answers" to the Quick check
(Notes, "Quick check" > "Answers", items 1-5). Every question is a template of the bank
(physics_figures/bank); its printed version (variant 0) keeps the numbers the book printed
before, and every variant is checked as the fixed questions were.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import yaml
from conftest import variant_param
from support.templates import PRINTED, printed

from physics_figures import bank, textformat
from physics_figures import questions as q
from physics_figures.bank import sketches as sketch_bank
from physics_figures.bank import statements as statement_bank
from physics_figures.notation import round_number
from physics_figures.parts.numeric import G_TEN_SLIP

ROOT = Path(__file__).resolve().parents[2]


def shown(part: q.Part) -> str:
    return q.number(part.value, part.shown_sig_figs)


def numeric(question: q.Question) -> list[q.Part]:
    """The parts that ask for a number (not a choice or an explanation)."""
    return [part for part in question.parts if part.kind == "numeric"]


def scheme_text(question: q.Question) -> str:
    """The mark scheme as its words, one line each (labels and codes as the page prints them)."""
    return "\n".join(f"{label} {textformat.to_plain(text)} {code}".strip()
                      for label, text, code in question.mark_lines())


# ----------------------------------------------------------- the notes' answers


def test_quick_check_1_final_momentum_15_n_s_and_speed_7_5():
    """Notes, Answers 1: Δp = 5.0 x 3.0 = 15 N s; speed = 15 / 2.0 = 7.5 m s^-1."""
    momentum, speed = printed("quick-check-1").parts
    assert (shown(momentum), momentum.unit) == ("15", "N s")
    assert momentum.value == pytest.approx(15.0)
    assert (shown(speed), speed.unit) == ("7.5", "m s^-1")
    assert speed.value == pytest.approx(7.5)


def test_quick_check_2_rifle_recoils_at_1_0_backwards():
    """Notes, Answers 2: 0 = 0.010 x 400 + 4.0v, v = -1.0 m s^-1: 1.0 m s^-1 backwards.
    The notes' own signed answer is accepted too (the part says what the minus sign means)."""
    (recoil,) = printed("quick-check-2").parts
    assert (shown(recoil), recoil.unit, recoil.direction) == ("1.0", "m s^-1", "none")
    assert "backwards" in recoil.sign_means
    assert recoil.value == pytest.approx(1.0)
    scheme = scheme_text(printed("quick-check-2"))
    assert "0 = 0.010 × 400 + 4.0v C1" in scheme
    assert "v = −1.0 m s−1: the recoil speed is 1.0 m s−1, backwards A1" in scheme


def test_quick_check_3_drag_687_n_and_11_6_upwards():
    """Notes, Answers 3: drag = 70 x 9.81 = 687 N; a = (1500 - 687)/70 = 11.6 m s^-2 upwards."""
    drag, accel = printed("quick-check-3").parts
    assert (shown(drag), drag.unit) == ("687", "N")
    assert (shown(accel), accel.unit, accel.answer_direction) == ("11.6", "m s^-2", "upwards")
    assert accel.direction == "choice"
    scheme = scheme_text(printed("quick-check-3"))
    assert "drag = mg = 70 × 9.81 = 687 N B1" in scheme and "a = (1500 − 687) / 70 C1" in scheme


def test_quick_check_4_velocities_minus_2_0_and_4_0():
    """Notes, Answers 4: 6.0 = v1 + 2.0v2, 6.0 = v2 - v1, 12 = 3v2; v2 = 4.0 m s^-1 forwards,
    v1 = -2.0 m s^-1; kinetic energy 18 J both times."""
    question = printed("quick-check-4")
    first, second = question.parts
    assert (shown(first), shown(second)) == ("−2.0", "4.0")
    assert first.direction == second.direction == "signed"
    scheme = scheme_text(question)
    for line in ("Momentum: 6.0 = v1 + 2.0v2", "relative speeds: 6.0 = v2 − v1", "Adding: 12 = 3v2",
                 "2.0 + 16 = 18 J after"):
        assert line in scheme, line


def test_quick_check_5_mass_12_kg_and_weight_19_4_n():
    """Notes, Answers 5: mass 12 kg (unchanged); weight = 12 x 1.62 = 19.4 N."""
    mass, moon_weight = printed("quick-check-5").parts
    assert (shown(mass), mass.unit) == ("12", "kg")
    assert (shown(moon_weight), moon_weight.unit) == ("19.4", "N")
    assert "Weight = mg = 12 × 1.62 C1" in scheme_text(printed("quick-check-5"))


@pytest.mark.parametrize("key", sorted(PRINTED))
def test_a_first_visit_shows_the_numbers_the_book_printed_before(key):
    """Variant 0 of each converted question states the same givens and prints the same key as
    the fixed question did, so saved answers and the printed book still match."""
    question = printed(key)
    givens, keys = PRINTED[key]
    assert tuple((g.name, g.value, g.unit, g.sig_figs) for g in question.givens) == givens
    assert tuple(part.answer_text for part in question.parts) == keys
    text = textformat.to_plain(question.text)
    for given in question.givens:
        assert re.search(rf"(?<![\d.]){re.escape(given.text)}(?!\d)", text), (key, given.name)


def test_every_question_of_the_book_is_a_template_and_none_is_left_out():
    assert set(PRINTED) <= {question.key for question in ALL}  # the 15 the book asked before
    assert all(question.text for question in ALL)


# ------------------------------------------------------------ every question


ALL = bank.all_questions()
#: Every variant of every question the book asks (the printed one is variant 0).
VARIANTS = [variant_param(t, i, question)
            for t in (bank.TEMPLATES[q_.key] for q_ in ALL) for i, question in enumerate(t.variants)]


def test_every_question_has_a_unique_key_and_practice_covers_each_direction_mode():
    assert len({question.key for question in ALL}) == len(ALL)
    practice = [part for question in ALL if not question.key.startswith("quick-check")
                for part in question.parts if part.kind == "numeric"]
    assert {part.direction for part in practice} == set(q.DIRECTION_MODES)
    assert all(part.mistakes for part in practice)


@pytest.mark.parametrize("question", VARIANTS)
def test_every_named_mistake_differs_from_the_right_answer(question):
    """A mistake with the answer's unit and direction must differ from it at 2 s.f. (and at the
    part's own s.f. rule), or the student who is right would be told they made it. The g = 10
    slip, 2 % off, may round to the key at 2 s.f. (issue 38: a scheme's A1 then takes it, and the
    key is read first): it differs at the figures the key is trusted to."""
    for part in numeric(question):
        assert part.mistakes, f"{question.key}: {part.prompt} names no mistake"
        for mistake in part.mistakes:
            same_kind = mistake.unit in (None, part.unit) and mistake.direction in (None, part.answer_direction)
            if same_kind:
                figures = {part.check_sig_figs} if mistake.name == G_TEN_SLIP else {2, part.min_sig_figs}
                for sig_figs in figures:
                    assert q.number(mistake.value, sig_figs) != q.number(part.value, sig_figs), mistake.name
            else:
                assert mistake.unit != part.unit or mistake.direction != part.answer_direction


@pytest.mark.parametrize("question", VARIANTS)
def test_named_mistakes_of_a_part_differ_from_each_other(question):
    for part in question.parts:
        seen = {}
        for mistake in part.mistakes:
            kind = (q.number(mistake.value, 3), mistake.unit, mistake.direction)
            assert kind not in seen, f"{question.key}: '{mistake.name}' looks like '{seen.get(kind)}'"
            seen[kind] = mistake.name


@pytest.mark.parametrize("question", VARIANTS)
def test_mark_scheme_prints_each_answer_as_the_key_does_and_awards_marks(question):
    """Practice 9 once printed 6.8 J in the key and 6.75 J in its mark scheme: one number, not two."""
    scheme = scheme_text(question)
    assert "$" not in scheme  # the text format, no TeX
    assert question.marks >= len(question.parts)
    for part in question.parts:
        if part.kind == "mcq":  # the scheme names the right letter
            assert scheme.startswith(f"{part.answer}:"), question.key
    for part in numeric(question):
        assert re.search(rf"(?<![\d.]){re.escape(shown(part))}(?!\d)", scheme), \
            f"{question.key}: the mark scheme never states the answer {part.answer_text}"


@pytest.mark.parametrize("question", VARIANTS)
def test_feedback_names_the_variants_own_numbers(question):
    """A number in a mistake's feedback, a hint or a prompt is one the variant states or
    computes, never the printed version's (e.g. "You divided by 20 instead of 0.020")."""
    stated = {given.text for given in question.givens}
    # a number the variant works out itself may print like a given of the printed version (B's
    # 0.40 N s in collision-third-law's variant 12 is the printed version's 0.40 kg): its scheme has it
    scheme = scheme_text(question)
    printed_only = {g.text for g in printed(question.key).givens} - stated
    printed_only = {number for number in printed_only
                    if not re.search(rf"(?<![\d.]){re.escape(number)}(?![\d.])", scheme)}
    for part in numeric(question):
        words = [part.prompt, part.positive, part.direction_hint, part.revisit,
                 *(m.feedback for m in part.mistakes)]
        for text in words:
            for number in printed_only:
                assert not re.search(rf"(?<![\d.]){re.escape(number)}(?![\d.])", text), (question.key, number, text)


def test_a_question_that_names_its_objects_by_mass_gives_them_different_masses():
    """"The 2.0 kg trolley" must say which trolley: the generator never draws equal masses,
    and a build with them is refused (ValueError naming both)."""
    template = bank.TEMPLATES["quick-check-4"]
    assert all(values["m1"] != values["m2"] for values in template.values)
    with pytest.raises(ValueError, match=r"m2 must .* \(got m1=2\.0, m2=2\.0"):
        template.build(m1=2.0, m2=2.0)


def test_trolleys_of_equal_mass_are_named_first_and_second_not_by_their_mass():
    """9702/12/M/J/14 Q7's two 5000 kg carriages: "the 5000 kg trolley" would not say which."""
    question = bank.TEMPLATES["practice-trolleys-stick"].build(m1=5000.0, u1=2.0, m2=5000.0, speed2=1.0)
    words = " ".join([question.text, *(mark.text for mark in question.mark_scheme),
                      *(m.feedback for part in question.parts for m in part.mistakes)])
    assert "the first trolley" in words and "5000 kg trolley's" not in words
    assert "kg trolley's" in " ".join(mark.text for mark in bank.TEMPLATES["practice-trolleys-stick"]
                                      .build(m1=2.0, u1=3.0, m2=1.0, speed2=1.5).mark_scheme)


def test_the_key_prints_the_notes_values_in_the_mark_scheme():
    (_, lost) = printed("practice-trolleys-stick").parts
    assert shown(lost) == "6.75"
    assert "Transferred = 10.125 − 3.375 = 6.75 J A1" in scheme_text(printed("practice-trolleys-stick"))


#: The parts that use an earlier part's answer, and so carry an error forward. Quick check
#: 4 solves both velocities from the same two equations: neither uses the other. Quick check
#: 5(b) and the pucks' angle can be done without (a), but an examiner follows the student's
#: own working (issue 37): the weight from their own mass, the angle by sin or cos from (a).
ECF_PARTS = {("quick-check-1", "b"), ("quick-check-3", "b"), ("quick-check-5", "b"), ("practice-pucks", "b"),
             ("practice-wall-bounce", "b"),
             ("practice-mars-rock", "b"), ("practice-towing", "b"), ("practice-trolleys-stick", "b"),
             ("elastic-both-moving", "b"), ("elastic-both-moving", "c"),
             ("sticking-energy-lost", "b"), ("sticking-energy-lost", "c"),
             ("explosion-three-pieces", "b"), ("skaters-stick-right-angles", "c"),
             ("oblique-wall-bounce", "b"), ("oblique-wall-bounce", "c"),
             ("block-and-hanging-mass", "b"), ("rocket-lift-off", "b"),
             ("falling-with-drag-constant", "b"), ("sphere-in-liquid", "b"), ("sphere-in-liquid", "c"),
             # read from a graph, then worked from the readings
             ("graph-kick-force-time", "b"), ("graph-kick-force-time", "c"),
             ("graph-cyclist-momentum-time", "c"), ("graph-bounce-momentum-time", "c"),
             ("graph-skydiver-terminal", "c"), ("graph-ball-acceleration", "c"),
             ("graph-trolley-collision", "c"), ("practice-spring-apart", "b"),
             # the papers' gaps (issue 25): worked on from an earlier part
             ("stopping-force-distance", "b"), ("mass-from-momentum-change", "b"),
             ("collision-third-law", "b"), ("collision-third-law", "c"),
             ("sticking-fraction-lost", "b"), ("bounce-energy-ratio", "b"),
             # a drag law given in the question; components and an explosion in two dimensions
             ("drag-law-constant", "b"), ("stokes-terminal-speed", "b"), ("puck-components", "c"),
             ("puck-components", "d"),
             ("explosion-two-pieces", "c"), ("explosion-two-pieces", "d"),
             ("graph-lorry-speed-momentum-time", "c"), ("graph-lorry-speed-momentum-time", "d"),
             # a bounce's surface force from its resultant; a drop's acceleration from its drag
             ("bounce-contact-force", "d"), ("stokes-drag-acceleration", "b")}


def test_every_part_that_uses_an_earlier_answer_carries_it_forward():
    found = {(question.key, pid) for question in ALL
             for pid, part in zip(question.part_ids, question.parts, strict=True) if part.ecf}
    assert found == ECF_PARTS
    # (a) wrong by the named mistake, (b) worked from it: the formula gives (b) from that (a)
    towing = printed("practice-towing")
    (a_wrong,) = [m.value for m in towing.parts[0].mistakes if m.name == "car's mass only"]
    assert towing.parts[1].ecf.evaluate({"a": a_wrong}) == pytest.approx(150 + 500 * a_wrong)
def test_number_rounds_half_away_from_zero_and_keeps_significant_zeros():
    assert q.number(686.7, 3) == "687"
    assert q.number(-2.0, 2) == "−2.0"
    assert q.number(2.85, 2) == "2.9"
    assert q.number(10800, 3) == "10\u202f800"  # grouped from five digits (notation.format_number)
    assert q.unit_text("m s^-2") == "m s⁻²"


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"direction": "sideways"}, "direction must be one of"),
        ({"value": -1.0}, "value must be a size (>= 0) unless direction is 'signed'"),
        ({"direction": "signed", "value": -1.0}, "positive must say which way is positive"),
        ({"direction": "choice", "choices": ("up", "down"), "answer_direction": "left"},
         "answer_direction must be one of"),
        ({"min_sig_figs": 4}, "min_sig_figs must be between 1 and check_sig_figs=3"),
        ({"revisit": " "}, "revisit must name the idea to revisit"),
        ({"value": math.nan}, "value must be a finite number"),
    ],
)
def test_a_badly_made_part_is_refused_with_the_rule(change, message):
    arguments = {"value": 1.0, "revisit": "F = ma"} | change
    with pytest.raises(ValueError, match=re.escape(message)):
        q.Part("p", arguments.pop("value"), "N", "force", **arguments)


# ------------------------------------------------------- 9702's mark codes


def test_no_question_uses_m1_on_a_calculation_and_every_a1_follows_its_own_c1_or_m1():
    """9702: calculation steps are C1; M1 (with a dependent A1) only where a part asks to
    show that, explain or state a principle; an A1 depends on a mark before it in its part."""
    for question in ALL:
        earned = set()
        for mark in question.mark_scheme:
            parts = question.parts_of(mark) if mark.code else ()
            for part_id in parts:
                part = question.parts[question.part_ids.index(part_id)]
                if mark.code == "M1":
                    assert part.asks in ("show that", "explain", "state"), (question.key, mark.text)
                if mark.code == "A1":
                    assert part_id in earned, (question.key, part_id, mark.text)
            if mark.code in ("C1", "M1"):
                earned.update(parts)
        assert {code for mark in question.mark_scheme for code in [mark.code] if code} <= {"C1", "M1", "A1", "B1"}


def test_m1_on_a_calculation_step_is_refused():
    part = q.Part("force", 1.0, "N", "force", revisit="F = ma")
    with pytest.raises(ValueError, match="M1 is for show that, explain or state, not for a calculation step"):
        q.Question("q", (), (part,), (q.Mark("F = ma", "M1"), q.Mark("= 1.0 N", "A1")))
    explained = q.Part("force", 1.0, "N", "force", revisit="F = ma", asks="explain")
    assert q.Question("q", (), (explained,), (q.Mark("drag grows", "M1"), q.Mark("so a falls", "A1"))).marks == 2


def test_an_a1_with_no_mark_before_it_in_its_part_is_refused():
    first = q.Part("mass", 1.0, "kg", "mass", revisit="m = W / g")
    second = q.Part("weight", 9.81, "N", "weight", revisit="W = mg")
    with pytest.raises(ValueError, match="A1 needs a C1 or M1 before it in its part"):
        q.Question("q", (), (first, second), (q.Mark("m = W / g", "C1", "a"), q.Mark("= 1.0 kg", "A1", "a"),
                                             q.Mark("W = 9.81 N", "A1", "b")))
    with pytest.raises(ValueError, match="must name the part of each mark line"):
        q.Question("q", (), (first, second), (q.Mark("m = W / g", "C1"),))


def test_each_mark_line_names_its_part_in_the_scheme():
    labels = [label for label, _, _ in printed("quick-check-4").mark_lines()]
    assert labels == ["(a, b)", "", "(b)", "(a)", ""]
    labels = [label for label, _, _ in printed("quick-check-1").mark_lines()]
    assert labels == ["(a)", "", "(b)", ""]


def test_a_mark_line_is_in_the_text_format():
    with pytest.raises(ValueError, match=r"text must be in the text format .* not \$\.\.\.\$ maths"):
        q.Mark("$F = ma$", "C1")
    with pytest.raises(ValueError, match=r"tag <b>"):
        q.Mark("m s<b>−1</b>", "A1")


def test_two_named_mistakes_the_marker_cannot_tell_apart_are_refused():
    """The marker names the first mistake a typed value matches to 3 s.f.; the generator
    drops a draw whose mistakes collide (ValueError from build)."""
    same = (q.Mistake("one", 2.501, "first"), q.Mistake("two", 2.499, "second"))
    with pytest.raises(ValueError, match=r"mistakes gives 2.50, as 'one' does"):
        q.Part("force", 1.0, "N", "force", revisit="F = ma", mistakes=same)
    sign = (q.Mistake("backwards", 1.0, "the sign slip, named"),)
    with pytest.raises(ValueError, match="from a sign slip"):
        q.Part("velocity", -1.0, "m s^-1", "velocity", revisit="p = mv", direction="signed",
               positive="right", mistakes=sign)


def test_an_ecf_given_named_like_a_part_is_refused():
    import sympy

    a, g = sympy.symbols("a g")
    with pytest.raises(ValueError, match=r"values names \['g'\], which are part ids"):
        q.Ecf(a * g, {"g": 9.81})


# ------------------------------------------------------------ g and rounding

#: Every part whose answer depends on g = 9.81 m s^-2, with its answer at g = 10 from the
#: variant's givens (the printed ones: 70 x 10 = 700 N, (1500 - 700) / 70, 58 x (10 - 1.5), 5.4 / 3.7 x 10).
G_PARTS = {
    ("quick-check-3", 0): lambda v: v["mass"] * 10.0,  # drag = mg
    ("quick-check-3", 1): lambda v: (v["open_drag"] - v["mass"] * 10.0) / v["mass"],
    ("practice-lift", 0): lambda v: v["mass"] * (10.0 - v["a_down"]),
    ("practice-mars-rock", 1): lambda v: v["mars_weight"] / 3.7 * 10.0,
}


@pytest.mark.parametrize("key", sorted(PRINTED))
def test_every_part_that_depends_on_g_names_the_g_10_mistake_in_every_variant(key):
    template = bank.TEMPLATES[key]
    for values, question in zip(template.values, template.variants, strict=True):
        for index, part in enumerate(question.parts):
            g_ten = [m for m in part.mistakes if m.name == "used g = 10 m s⁻²"]
            if (key, index) in G_PARTS:
                assert len(g_ten) == 1 and g_ten[0].value == pytest.approx(G_PARTS[key, index](values))
                assert "A1" in g_ten[0].feedback
            else:
                assert not g_ten and part.answer_for_g is None, (key, index)


def test_the_g_9_8_slip_is_its_own_message_where_the_key_would_not_take_it():
    drag, accel = printed("quick-check-3").parts
    assert drag.g_nine_eight == pytest.approx(686.0)  # 70 x 9.8: its own message, not "rounding"
    assert accel.g_nine_eight is None  # 11.63 is still 11.6: accepted


def test_rounded_part_way_is_what_the_working_gives_with_early_rounding():
    """Practice 7(b): the mass 5.4/3.7 = 1.459... kg rounded to 1.5 kg gives 14.7 N, not 14.3 N."""
    rock = printed("practice-mars-rock").parts[1]
    assert [(round(value, 3), what) for value, what in rock.rounded_part_way] == [(14.715, "the mass to 1.5 kg")]
    # issue 25: "the unrounded mass: 1.5 kg" read as if 1.5 kg were the unrounded value
    assert "= 1.459 × 9.81 (the unrounded mass; the mass rounded to 1.5 kg would give 14.7 N)" in scheme_text(
        printed("practice-mars-rock"))
    # Nothing rounds part-way to the towing slips: 1.4 m s^-2 is a resistive force left out.
    towing = printed("practice-towing").parts[0]
    assert towing.rounded_part_way == ()
    assert {m.name for m in towing.mistakes if q.number(m.value, 2) in ("1.4", "1.5")} == {
        "trailer's resistance left out", "car's resistance left out"}
    # A later part worked from an earlier answer rounded to 2 s.f. is "rounded part-way" in
    # every variant where that changes it (the wall's force from a rounded change in momentum).
    for question in bank.TEMPLATES["practice-wall-bounce"].variants:
        force = question.parts[1]
        early = force.answer_from(float(round_number(question.parts[0].value, 2)))
        if q.number(early, 3) != q.number(force.value, 3):
            assert any(q.number(value, 3) == q.number(early, 3) for value, _ in force.rounded_part_way)


def test_working_that_does_not_lead_to_the_answer_is_refused():
    with pytest.raises(ValueError, match="answer_from"):
        q.Part("weight", 14.3, "N", "weight", revisit="W = mg", working=(q.Step("mass", 1.46, "kg"),),
               answer_from=lambda m: m * 10)


def test_a_mark_must_be_a_cambridge_code():
    with pytest.raises(ValueError, match=r"code must be one of .* \(got code='X2'\)"):
        q.Mark("F = ma", "X2")


# ------------------------------------------------------------- the directive


# ------------------------------------------------------------------ the pages

#: The practice pages, one a question type (book/exam/practice-<name>.md). A type without a
#: practice question of its own yet has no page: the index says which questions cover it.
PRACTICE_PAGES = {"newton": "practice-newtons-laws", "drag": "practice-drag",
                  "force-momentum": "practice-force-momentum",
                  "definitions": "practice-definitions", "momentum-line": "practice-momentum-line",
                  "elastic": "practice-collisions",
                  "two-d": "practice-two-dimensions"}
SKETCH_PAGE = "practice-sketches"
STATEMENT_PAGE = "practice-statements"
PLACED = re.compile(r"```\{question\}[ ]*([^\n]*)\n(.*?)```", re.DOTALL)


def _placed(page: str) -> list[str]:
    keys = []
    for key, body in PLACED.findall((ROOT / "book" / "exam" / f"{page}.md").read_text()):
        assert not body.strip(), f"{page}: the question {key} has text on the page; a template writes its own"
        keys.append(key.strip())
    return keys


def test_the_books_question_pages_place_every_question_once_in_book_order():
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    exam = next(part for part in toc["parts"] if part["caption"] == "Exam skills")["chapters"]
    practice = next(chapter for chapter in exam if chapter["file"] == "book/exam/practice")
    pages = [section["file"].rpartition("/")[2] for section in practice["sections"]]
    # the notes' order of the types, then the statements and the sketches of every type on a
    # page each (their markers would push a type's page past its first-visit budget)
    assert pages == [*PRACTICE_PAGES.values(), STATEMENT_PAGE, SKETCH_PAGE]
    assert _placed("quick-check") == list(bank.QUICK_CHECK)
    assert _placed("practice") == []  # the index only
    asked = _placed("quick-check") + [key for page in pages for key in _placed(page)]
    assert asked == [question.key for question in ALL]  # each once, in book order
    sketches = [t.key for t in sketch_bank.TEMPLATES]
    stated = [t.key for t in statement_bank.TEMPLATES]
    assert _placed(SKETCH_PAGE) == sketches
    assert _placed(STATEMENT_PAGE) == stated
    for kind, page in PRACTICE_PAGES.items():  # in book order
        assert _placed(page) == [t.key for t in bank.by_type(kind)
                                 if t.key not in {*bank.QUICK_CHECK, *sketches, *stated}]
    index = (ROOT / "book" / "exam" / "practice.md").read_text()
    for kind in bank.TOPIC.type_keys:
        if kind in PRACTICE_PAGES:
            assert f"{{ref}}`{PRACTICE_PAGES[kind]}`" in index, kind
        else:  # no page yet: its questions are elsewhere, and the index says where
            assert bank.by_type(kind), f"no question of type {kind} at all"
            number = next(t.title for t in bank.by_type(kind)).rpartition(" ")[2]
            assert f"Quick check {number} <quick-check>" in index, kind


# ------------------------------------------------------------------ graphs to read

def _graph(**change) -> q.Graph:
    fields = {"name": "momentum–time", "quantity": "momentum", "unit": "N s",
              "points": ((0.0, 1.0), (1.0, 1.0), (1.5, 0.5), (3.0, 0.5)),
              "time_division": 0.1, "value_division": 0.05, "time_max": 3.0, "value_max": 1.5}
    return q.Graph(**{**fields, **change})


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"points": ((0.0, 1.0),)}, "points must hold at least two points"),
        ({"points": ((0.0, 1.0), (2.0, 1.0), (1.0, 0.5))}, "points must be in increasing time"),
        ({"points": ((0.0, 1.0), (4.0, 1.0))}, "points must lie within 0 to time_max=3.0 s"),
        ({"points": ((0.0, 1.0), (1.0, 2.0))}, "points must lie within value_min=0.0 to value_max=1.5"),
        ({"time_max": 3.05}, "time_max must be 2 to 60 whole small squares of 0.1"),
        ({"value_division": 0.01}, "value_max must be 2 to 60 whole small squares of 0.01"),
        ({"value_min": 2.0}, "value_min must be below value_max=1.5"),
    ],
)
def test_a_graph_that_cannot_be_drawn_or_read_is_refused_by_name(change, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        _graph(**change)


def test_a_graph_reads_the_value_its_line_passes_through():
    assert _graph().value_at(1.25) == pytest.approx(0.75)
    with pytest.raises(ValueError, match="time must lie on the drawn line"):
        _graph().value_at(3.5)


def _reading(**change) -> q.GraphPart:
    fields = {"prompt": "momentum before", "value": 1.0, "unit": "N s", "quantity": "momentum",
              "tolerance": 0.025, "revisit": "Read the flat part."}
    return q.GraphPart(**{**fields, **change})


def test_a_reading_prints_to_the_places_of_a_small_square_and_is_right_within_half_of_one():
    part = _reading(value=1.15)
    assert part.answer_text == "1.15 N s" and part.kind == "graph"
    assert part.band == pytest.approx((1.125, 1.175))
    assert _reading(value=240.0, tolerance=10.0).answer_text == "240 N s"
    assert _reading().browser_data("a")["tolerance"] == 0.025


def test_a_reading_refuses_no_tolerance_and_a_mistake_the_marker_would_take_as_right():
    with pytest.raises(ValueError, match="tolerance must be positive"):
        _reading(tolerance=0.0)
    with pytest.raises(ValueError, match="within the reading's tolerance"):
        _reading(mistakes=(q.Mistake("misread", 1.02, "Read again."),))


def _graph_question(**change) -> q.Question:
    fields = {"key": "graph-test", "givens": (), "parts": (_reading(),), "graph": _graph(),
              "mark_scheme": (q.Mark("1.00 N s", "B1"),)}
    return q.Question(**{**fields, **change})


def test_a_graph_goes_with_a_part_read_from_it_at_half_a_small_square():
    assert _graph_question().graph.points[0] == (0.0, 1.0)
    with pytest.raises(ValueError, match="graph goes with a part read from it"):
        _graph_question(graph=None)
    with pytest.raises(ValueError, match="tolerance must be half a small square of the graph"):
        _graph_question(parts=(_reading(tolerance=0.1),))


def test_every_feedback_names_a_declared_section():
    """Feedback links are named in the data (Part.see, Mistake.see, Option.see), never guessed
    from the words: each id is a section of physics_figures.bank.sections, and every part a
    student can get wrong by a value or a choice names one."""
    from physics_figures.bank.sections import SECTIONS

    named = 0
    for template in bank.TEMPLATES.values():
        for variant in template.variants:
            for part in variant.parts:
                if part.kind in ("explain", "text"):
                    continue
                ids = [part.see, *(m.see for m in getattr(part, "mistakes", ())),
                       *(o.see for o in getattr(part, "options", ()))]
                assert all(i is None or i in SECTIONS for i in ids), (template.key, ids)
                named += sum(i is not None for i in ids)
    assert named > 1000
