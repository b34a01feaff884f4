"""Question data (physics_figures.questions) and the {question} directive (book/_ext/questions).

The quick-check answers are asserted against the notes' "Answers" to the Quick check
(Notes, "Quick check" > "Answers", items 1-5).
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from physics_figures import bank
from physics_figures import questions as q

ROOT = Path(__file__).resolve().parents[1]
SPHINX_BUILD = Path(sys.executable).with_name("sphinx-build")


def shown(part: q.Part) -> str:
    return q.number(part.value, part.shown_sig_figs)


# ----------------------------------------------------------- the notes' answers


def test_quick_check_1_final_momentum_15_n_s_and_speed_7_5():
    """Notes, Answers 1: Δp = 5.0 x 3.0 = 15 N s; speed = 15 / 2.0 = 7.5 m s^-1."""
    momentum, speed = q.quick_check_1().parts
    assert (shown(momentum), momentum.unit) == ("15", "N s")
    assert momentum.value == pytest.approx(15.0)
    assert (shown(speed), speed.unit) == ("7.5", "m s^-1")
    assert speed.value == pytest.approx(7.5)


def test_quick_check_2_rifle_recoils_at_1_0_backwards():
    """Notes, Answers 2: 0 = 0.010 x 400 + 4.0v, v = -1.0 m s^-1: 1.0 m s^-1 backwards.
    The notes' own signed answer is accepted too (the part says what the minus sign means)."""
    (recoil,) = q.quick_check_2().parts
    assert (shown(recoil), recoil.unit, recoil.direction) == ("1.0", "m s^-1", "none")
    assert "backwards" in recoil.sign_means
    assert recoil.value == pytest.approx(1.0)
    assert "$v = -1.0$" in q.quick_check_2().mark_scheme_markdown()
    assert "backwards" in q.quick_check_2().mark_scheme_markdown()


def test_quick_check_3_drag_687_n_and_11_6_upwards():
    """Notes, Answers 3: drag = 70 x 9.81 = 687 N; a = (1500 - 687)/70 = 11.6 m s^-2 upwards."""
    drag, accel = q.quick_check_3().parts
    assert (shown(drag), drag.unit) == ("687", "N")
    assert (shown(accel), accel.unit, accel.answer_direction) == ("11.6", "m s^-2", "upwards")
    assert accel.direction == "choice"


def test_quick_check_4_velocities_minus_2_0_and_4_0():
    """Notes, Answers 4: v2 = 4.0 m s^-1 forwards, v1 = -2.0 m s^-1; kinetic energy 18 J both times."""
    first, second = q.quick_check_4().parts
    assert (shown(first), shown(second)) == ("-2.0", "4.0")
    assert first.direction == second.direction == "signed"
    assert "$2.0 + 16 = 18$ J after" in q.quick_check_4().mark_scheme_markdown()


def test_quick_check_5_mass_12_kg_and_weight_19_4_n():
    """Notes, Answers 5: mass 12 kg (unchanged); weight = 12 x 1.62 = 19.4 N."""
    mass, moon_weight = q.quick_check_5().parts
    assert (shown(mass), mass.unit) == ("12", "kg")
    assert (shown(moon_weight), moon_weight.unit) == ("19.4", "N")


# ------------------------------------------------------------ every question


ALL = q.all_questions()
PARTS = [(question.key, index, part) for question in ALL for index, part in enumerate(question.parts)]


def test_every_question_has_a_unique_key_and_practice_covers_each_direction_mode():
    assert len({question.key for question in ALL}) == len(ALL)
    practice = [part for make in q.PRACTICE for part in make().parts]
    assert 8 <= len(q.PRACTICE) <= 12
    assert {part.direction for part in practice} == set(q.DIRECTION_MODES)
    assert all(part.mistakes for part in practice)


@pytest.mark.parametrize(("key", "index", "part"), PARTS, ids=lambda v: v if isinstance(v, str) else None)
def test_every_named_mistake_differs_from_the_right_answer(key, index, part):
    """A mistake with the answer's unit and direction must differ from it at 2 s.f. (and at the
    part's own s.f. rule), or the student who is right would be told they made it."""
    assert part.mistakes, f"{key} part {index} names no mistake"
    for mistake in part.mistakes:
        same_kind = mistake.unit in (None, part.unit) and mistake.direction in (None, part.answer_direction)
        if same_kind:
            for sig_figs in {2, part.min_sig_figs}:
                assert q.number(mistake.value, sig_figs) != q.number(part.value, sig_figs), (key, mistake.name)
        else:
            assert mistake.unit != part.unit or mistake.direction != part.answer_direction


@pytest.mark.parametrize(("key", "index", "part"), PARTS, ids=lambda v: v if isinstance(v, str) else None)
def test_named_mistakes_of_a_part_differ_from_each_other(key, index, part):
    seen = {}
    for mistake in part.mistakes:
        kind = (q.number(mistake.value, 2), mistake.unit, mistake.direction)
        assert kind not in seen, f"{key}: '{mistake.name}' looks like '{seen.get(kind)}'"
        seen[kind] = mistake.name


@pytest.mark.parametrize("question", ALL, ids=lambda question: question.key)
def test_mark_scheme_prints_each_answer_and_awards_marks(question):
    scheme = question.mark_scheme_markdown()
    assert question.marks >= len(question.parts)
    for part in question.parts:
        assert re.search(rf"(?<![\d.]){re.escape(shown(part))}(?!\d)", scheme) or \
            re.search(rf"(?<![\d.]){re.escape(q.number(part.value, 3))}(?!\d)", scheme), \
            f"{question.key}: the mark scheme never states the answer {part.answer_text}"


def test_number_rounds_half_away_from_zero_and_keeps_significant_zeros():
    assert q.number(686.7, 3) == "687"
    assert q.number(-2.0, 2) == "-2.0"
    assert q.number(2.85, 2) == "2.9"
    assert q.number(10800, 3) == r"10\,800"  # grouped from five digits, a thin space in TeX
    assert q.unit_text("m s^-2") == "m s⁻²"
    assert q.unit_markdown("m s^-1") == "m s$^{-1}$"


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
        q.Question("q", (), (part,), (q.Mark("$F = ma$", "M1"), q.Mark("$= 1.0$ N", "A1")))
    explained = q.Part("force", 1.0, "N", "force", revisit="F = ma", asks="explain")
    assert q.Question("q", (), (explained,), (q.Mark("drag grows", "M1"), q.Mark("so a falls", "A1"))).marks == 2


def test_an_a1_with_no_mark_before_it_in_its_part_is_refused():
    first = q.Part("mass", 1.0, "kg", "mass", revisit="m = W / g")
    second = q.Part("weight", 9.81, "N", "weight", revisit="W = mg")
    with pytest.raises(ValueError, match="A1 needs a C1 or M1 before it in its part"):
        q.Question("q", (), (first, second), (q.Mark("$m = W/g$", "C1", "a"), q.Mark("$= 1.0$ kg", "A1", "a"),
                                             q.Mark("$W = 9.81$ N", "A1", "b")))
    with pytest.raises(ValueError, match="must name the part of each mark line"):
        q.Question("q", (), (first, second), (q.Mark("$m = W/g$", "C1"),))


def test_each_mark_line_names_its_part_in_the_scheme():
    scheme = q.quick_check_4().mark_scheme_markdown()
    assert scheme.startswith("- **(a, b)** ") and "- **(b)** " in scheme
    # a template's scheme is in the text format: the same labels, where the part changes
    labels = [label for label, _, _ in q.quick_check_1().mark_lines()]
    assert labels == ["(a)", "", "(b)", ""]


def test_the_answer_key_prints_the_number_its_mark_scheme_gives():
    """Practice 9 printed 6.8 J in the key and 6.75 J in its mark scheme: one number, not two."""
    for question in ALL:
        scheme = question.mark_scheme_markdown()
        for part in question.parts:
            assert re.search(rf"(?<![\d.]){re.escape(shown(part))}(?!\d)", scheme), (question.key, part.prompt)
    (_, lost) = q.practice_trolleys_stick().parts
    assert shown(lost) == "6.75"


# ------------------------------------------------------------ g and rounding

#: Every part whose answer depends on g = 9.81 m s^-2, with its answer at g = 10.
G_PARTS = {
    ("quick-check-3", 0): 70 * 10.0,  # drag = mg
    ("quick-check-3", 1): (1500 - 70 * 10.0) / 70,
    ("practice-lift", 0): 58 * (10.0 - 1.5),
    ("practice-mars-rock", 1): 5.4 / 3.7 * 10.0,
}


def test_every_part_that_depends_on_g_names_the_g_10_mistake_and_the_g_9_8_slip():
    for question in ALL:
        for index, part in enumerate(question.parts):
            g_ten = [m for m in part.mistakes if m.name == "used g = 10 m s⁻²"]
            if (question.key, index) in G_PARTS:
                assert len(g_ten) == 1 and g_ten[0].value == pytest.approx(G_PARTS[question.key, index])
                assert "A1" in g_ten[0].feedback
            else:
                assert not g_ten and part.answer_for_g is None, (question.key, index)
    drag = q.quick_check_3().parts[0]
    assert drag.g_nine_eight == pytest.approx(686.0)  # 70 x 9.8: its own message, not "rounding"
    assert q.quick_check_3().parts[1].g_nine_eight is None  # 11.63 is still 11.6: accepted


def test_rounded_part_way_is_what_the_working_gives_with_early_rounding():
    """Practice 7(b): the mass 5.4/3.7 = 1.459... kg rounded to 1.5 kg gives 14.7 N, not 14.3 N."""
    rock = q.practice_mars_rock().parts[1]
    assert [(round(value, 3), what) for value, what in rock.rounded_part_way] == [(14.715, "the mass to 1.5 kg")]
    # Nothing rounds part-way to the towing slips: 1.4 m s^-2 is a resistive force left out.
    towing = q.practice_towing().parts[0]
    assert towing.rounded_part_way == ()
    assert {m.name for m in towing.mistakes if q.number(m.value, 2) in ("1.4", "1.5")} == {
        "trailer's resistance left out", "car's resistance left out"}


def test_working_that_does_not_lead_to_the_answer_is_refused():
    with pytest.raises(ValueError, match="answer_from"):
        q.Part("weight", 14.3, "N", "weight", revisit="W = mg", working=(q.Step("mass", 1.46, "kg"),),
               answer_from=lambda m: m * 10)


def test_a_mark_must_be_a_cambridge_code():
    with pytest.raises(ValueError, match=r"code must be one of .* \(got code='X2'\)"):
        q.Mark("F = ma", "X2")


# ------------------------------------------------------------- the directive


def _sphinx_project(tmp_path: Path, body: str) -> Path:
    (tmp_path / "conf.py").write_text(textwrap.dedent(f"""\
        import sys
        sys.path.insert(0, {str(ROOT / "book" / "_ext")!r})
        extensions = ["myst_parser", "questions"]
        myst_enable_extensions = ["dollarmath"]
        root_doc = "index"
        latex_documents = [("index", "book.tex", "Book", "Author", "manual")]
        """))
    (tmp_path / "index.md").write_text("# Book\n\n```{toctree}\nplain\nasked\n```\n")
    (tmp_path / "plain.md").write_text("# A page without questions\n\nText.\n")
    (tmp_path / "asked.md").write_text("# Questions\n\n" + body + "\n## Key\n\n```{answer-key}\n```\n")
    return tmp_path


QUICK_CHECK_1 = """\
```{question} Quick check 1
:answer: physics_figures.questions:quick_check_1

A resultant force of 5.0 N acts on a 2.0 kg trolley, initially at rest, for 3.0 s.
Calculate its final momentum and speed.
```
"""


def _build(source: Path, builder: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(SPHINX_BUILD), "-W", "--keep-going", "-q", "-b", builder, str(source), str(source / "_out" / builder)],
        check=False, capture_output=True, text=True, timeout=300,
    )


@pytest.mark.build
def test_html_question_has_labelled_boxes_status_feedback_and_a_hidden_worked_answer(tmp_path):
    source = _sphinx_project(tmp_path, QUICK_CHECK_1)
    result = _build(source, "html")
    assert result.returncode == 0, result.stderr
    page = (source / "_out" / "html" / "asked.html").read_text()
    assert '<form class="q-form" hidden' in page  # shown by the script: no dead boxes without JavaScript
    assert page.count('role="status"') == 2
    assert '<label class="q-field" for="q-quick-check-1-a-value"><span>Value</span>' in page
    assert '<details class="q-worked" hidden>' in page
    assert "final momentum = " in page  # the answer line for print and no-JS
    key = page[page.index('<details class="q-key"'):]
    assert "final momentum: 15 N s" in key and "<strong>C1</strong>" in key
    assert 'href="#question-quick-check-1"' in key
    # The script and styles are added only where a question is asked.
    assert "_static/questions.js" in page and "_static/questions.css" in page
    plain = (source / "_out" / "html" / "plain.html").read_text()
    assert "questions.js" not in plain and "questions.css" not in plain


@pytest.mark.build
def test_print_builds_show_the_question_with_answer_lines_and_the_key(tmp_path):
    source = _sphinx_project(tmp_path, QUICK_CHECK_1)
    result = _build(source, "text")
    assert result.returncode == 0, result.stderr
    text = (source / "_out" / "text" / "asked.txt").read_text()
    question = text[:text.index("Answer key")]
    assert "(a) final momentum = ...." in question and "(b) speed = ...." in question
    assert "15 N s" not in question and "Check" not in question
    key = text[text.index("Answer key"):]
    assert "(a) final momentum: 15 N s" in key and "(b) speed: 7.5 m s⁻¹" in key
    assert "= 7.5 m s\u22121 **A1**" in key  # the mark scheme line (text format), with its mark


@pytest.mark.build
def test_latex_build_prints_the_question_and_its_key(tmp_path):
    source = _sphinx_project(tmp_path, QUICK_CHECK_1)
    result = _build(source, "latex")
    assert result.returncode == 0, result.stderr
    tex = (source / "_out" / "latex" / "book.tex").read_text()
    assert "initially at rest" in tex and "final momentum =" in tex
    assert "Answer key" in tex and r"\sphinxstylestrong{C1}" in tex


@pytest.mark.build
def test_text_that_disagrees_with_the_data_fails_the_strict_build(tmp_path):
    source = _sphinx_project(tmp_path, QUICK_CHECK_1.replace("5.0 N", "6.0 N"))
    result = _build(source, "html")
    assert result.returncode != 0
    assert "quick-check-1: the text does not state force = 5.0 N" in result.stderr


@pytest.mark.build
def test_an_answer_that_cannot_be_loaded_is_an_error(tmp_path):
    source = _sphinx_project(tmp_path, QUICK_CHECK_1.replace("quick_check_1", "quick_check_99"))
    result = _build(source, "html")
    assert result.returncode != 0
    assert "cannot load its answer" in result.stderr


def test_the_books_question_pages_name_real_questions_whose_givens_they_state():
    """Every {question} in book/exam names a Question and states the numbers it uses."""
    pattern = re.compile(r"```\{question\}[^\n]*\n:answer: ([\w.]+:\w+)\n(.*?)```", re.DOTALL)
    templated = re.compile(r"```\{question\} ([a-z0-9-]+)\n```")
    asked = []
    for page in ("quick-check.md", "practice.md"):
        source = (ROOT / "book" / "exam" / page).read_text()
        asked += [bank.TEMPLATES[key].variant(0).key for key in templated.findall(source)]
        for reference, text in pattern.findall(source):
            module, _, name = reference.partition(":")
            question = getattr(sys.modules[module], name)()
            asked.append(question.key)
            for given in question.givens:
                assert re.search(rf"(?<![\d.]){re.escape(given.text)}(?!\d)", text), (question.key, given)
    assert sorted(asked) == sorted(question.key for question in ALL)  # each asked once, none left out


@pytest.mark.build
def test_an_edit_to_the_question_module_re_reads_the_page(tmp_path):
    """The directive notes the answer's source files as dependencies, so an incremental
    build re-reads the page (here the new data no longer matches the text, so it warns)."""
    source = _sphinx_project(tmp_path, QUICK_CHECK_1.replace("physics_figures.questions:quick_check_1",
                                                             "asked_questions:ask"))
    module = source / "asked_questions.py"
    module.write_text("from physics_figures.questions import quick_check_1 as ask\n")
    conf = source / "conf.py"
    conf.write_text(conf.read_text() + f"sys.path.insert(0, {str(source)!r})\n")
    assert _build(source, "html").returncode == 0
    module.write_text("from physics_figures.questions import quick_check_5 as ask\n")
    result = _build(source, "html")
    assert result.returncode != 0
    assert "quick-check-5: the text does not state mass = 12 kg" in result.stderr
