"""The worked examples to try first (issue "Practice at volume", item 5): every numeric part
of every worked example has a self-marked box above the example's solution, with the notes'
numbers as keys, named mistakes and error carried forward; the solution opens after a Check.

A part is numeric when its solution marks it as a calculation or a single point (C1/A1 or
B1). A part that earns M1 (show that, explain, state a principle) is read in the solution,
as tests/site/test_content.py's METHOD_MARKED_PARTS lists them.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from support.templates import printed

from physics_figures import answers, bank
from physics_figures.bank import worked_examples
from physics_figures.notation import format_number

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = range(1, 6)
KEYS = [f"example-{n}-try" for n in EXAMPLES]

# Each box: the glued value the notes print for it, and where the notes print it.
# (Example 5 is not in the notes: the physics issue added it; tests/no_site/test_answers.py
# checks its numbers by hand.)
NOTES_VALUES = {
    "example-1-try": [
        ("ex1_acceleration", "1.5", "Worked examples > Example 1 (a): a = 2400/1600 = 1.5 m s^-2"),
        ("ex1_tension", "800", "Example 1 (b): T - 200 = 400 x 1.5, so T = 800 N"),
        ("ex1_force_on_car", "800", "Example 1 (c): 800 N, backwards"),
    ],
    "example-2-try": [
        ("ex2_momentum_change", "2.44", "Worked examples > Example 2 (a): 0.058 x 42 = 2.44 N s"),
        ("ex2_force_on_ball", "203", "Example 2 (b): 2.436/0.012 = 203 N"),
        ("ex2_force_on_wall", "203", "Example 2 (d): 203 N towards the wall"),
    ],
    "example-3-try": [
        ("ex3_velocity_b", "3.0", "Worked examples > Example 3 (b): v = 3.0 m s^-1"),
        ("ex3_force_on_b", "24", "Example 3 (d): F = 1.2/0.050 = 24 N"),
    ],
    "example-4-try": [
        ("ex4_y_along", "0.42", "Worked examples > Example 4 (a): p_along = 0.42 N s"),
        ("ex4_y_across", "0.312", "Example 4 (a): p_across = 0.312 N s"),
        ("ex4_y_speed", "1.74", "Example 4 (b): v_Y = 0.523/0.30 = 1.74 m s^-1"),
        ("ex4_y_angle", "36.6", "Example 4 (b): tan^-1 (0.312/0.42) = 36.6 degrees"),
        ("ex4_kinetic_energy_after", "0.78", "Example 4 (c): after = 0.324 + 0.456 = 0.78 J"),
    ],
    "example-5-try": [
        ("ex5_upthrust", "0.0135", "Example 5 (b): rho g V (the physics issue's drag example)"),
        ("ex5_drag", "0.104", "Example 5 (c): W - U"),
        ("ex5_initial_acceleration", "8.68", "Example 5 (d): (W - U)/m"),
    ],
}

# A later part that uses an earlier answer is marked with error carried forward from it.
ECF_USES = {
    "example-1-try": {"b": ("a",), "c": ("b",)},
    "example-2-try": {"b": ("a",), "c": ("b",)},
    "example-3-try": {"b": ("a",)},
    "example-4-try": {"c": ("a", "b"), "d": ("a", "b"), "e": ("c",)},
    "example-5-try": {"b": ("a",), "c": ("a",)},
}

TYPES = {"example-1-try": "newton", "example-2-try": "force-momentum", "example-3-try": "momentum-line",
         "example-4-try": "two-d", "example-5-try": "drag"}


def _page(number: int) -> str:
    return (ROOT / "book" / "exam" / f"example-{number}.md").read_text(encoding="utf-8")


def _block(source: str, directive: str) -> str:
    return re.search(rf"(`{{3,}})\{{{directive}\}}.*?\n(.*?)\n\1(?!`)", source, re.DOTALL).group(2)


def _parts(block: str) -> dict[str, str]:
    """{part letter: text} of an exercise or solution block."""
    pieces = re.split(r"(?:^|\n)\**\(([a-z])\)\**", block)
    return dict(zip(pieces[1::2], pieces[2::2], strict=True))


def _numeric_parts(number: int) -> dict[str, list[str]]:
    """{part: its mark codes} for each part of the example whose solution earns no M1."""
    solution = _parts(_block(_page(number), "solution"))
    codes = {part: re.findall(r"\*\*([CMAB]1)\*\*", text) for part, text in solution.items()}
    return {part: found for part, found in codes.items() if "M1" not in found}


# ------------------------------------------------------------------- the content


@pytest.mark.parametrize("number", EXAMPLES)
def test_every_numeric_part_of_every_worked_example_has_a_try_first_box(number):
    key = f"example-{number}-try"
    numeric = _numeric_parts(number)
    assert numeric, f"example {number} has no numeric part?"
    answered = worked_examples.EXAMPLE_PARTS[key]
    assert set(answered) == set(numeric), f"{key} answers {answered}; the numeric parts are {sorted(numeric)}"
    assert list(answered) == sorted(answered), "boxes follow the example's order"
    assert len(answered) == len(printed(key).parts)
    # each box's glued value is printed in the solution of the part it answers
    solution = _parts(_block(_page(number), "solution"))
    for part, (glue, _, _) in zip(answered, NOTES_VALUES[key], strict=True):
        assert f"{{glue:text}}`{glue}`" in solution[part], (key, part, glue)


def test_the_try_first_boxes_count_what_the_pages_and_the_answers_module_give():
    """Example 1: 3 parts; 2: 3; 3: 2; 4: 3 (with 5 boxes: two components, speed and angle,
    the energy after); 5: 3. Each box's value is one the example's answers function glues."""
    boxes = {key: len(printed(key).parts) for key in KEYS}
    assert boxes == {"example-1-try": 3, "example-2-try": 3, "example-3-try": 2, "example-4-try": 5,
                     "example-5-try": 3}
    assert sum(len(_numeric_parts(n)) for n in EXAMPLES) == 14
    for number, key in zip(EXAMPLES, KEYS, strict=True):
        glued = answers.ALL[f"example_{number}"]()
        assert all(glue in glued for glue, _, _ in NOTES_VALUES[key])


@pytest.mark.parametrize("key", KEYS)
def test_each_key_is_the_value_the_notes_print(key):
    number = int(key.split("-")[1])
    glued = answers.ALL[f"example_{number}"]()
    question = printed(key)
    for part, (glue, in_the_notes, where) in zip(question.parts, NOTES_VALUES[key], strict=True):
        assert part.value == pytest.approx(glued[glue].value, rel=1e-12), where
        assert glued[glue].text == in_the_notes, where
        assert format_number(part.value, part.shown_sig_figs) == in_the_notes, where


@pytest.mark.parametrize("key", KEYS)
def test_mark_lines_carry_the_codes_of_the_examples_solution(key):
    number = int(key.split("-")[1])
    numeric = _numeric_parts(number)
    question = printed(key)
    answered = worked_examples.EXAMPLE_PARTS[key]
    for part, codes in numeric.items():
        boxes = {box for box, of in zip(question.part_ids, answered, strict=True) if of == part}
        lines = [m.code for m in question.mark_scheme if m.code and set(question.parts_of(m)) <= boxes]
        assert lines == codes, f"{key}: the example's ({part}) is marked {codes}, the boxes {lines}"
    assert question.marks == sum(len(codes) for codes in numeric.values())


@pytest.mark.parametrize("key", KEYS)
def test_later_parts_carry_an_earlier_error_forward(key):
    question = printed(key)
    uses = {pid: part.ecf.uses for pid, part in zip(question.part_ids, question.parts, strict=True) if part.ecf}
    assert uses == ECF_USES[key]
    values = {pid: part.value for pid, part in zip(question.part_ids, question.parts, strict=True)}
    for part in question.parts:
        if part.ecf:  # a wrong earlier answer gives another, consistent, later one
            wrong = {earlier: (1.3 + 0.2 * i) * values[earlier] for i, earlier in enumerate(part.ecf.uses)}
            assert part.ecf.evaluate({**values, **wrong}) != pytest.approx(part.value)


@pytest.mark.parametrize("key", KEYS)
def test_every_box_names_the_classic_mistakes_with_what_to_revisit(key):
    for part in printed(key).parts:
        assert part.mistakes, f"{key}: {part.prompt} names no mistake"
        feedback = [mistake.feedback for mistake in part.mistakes]
        assert len(set(feedback)) == len(feedback), f"{key}: {part.prompt} says the same twice"
        assert all(len(text.split()) >= 8 for text in feedback), "feedback names the mistake and the fix"
        assert part.revisit


def test_the_text_says_which_part_of_the_example_each_box_answers():
    texts = {key: printed(key).text for key in KEYS}
    assert "Here" not in texts["example-1-try"]  # (a), (b), (c) are the example's own
    assert "Here (c) answers the example's (d)." in texts["example-2-try"]
    assert "Here (a) answers the example's (b) and (b) its (d)." in texts["example-3-try"]
    assert "(a) and (b) answer the example's (a), (c) and (d) its (b) and (e) its (c)." in texts["example-4-try"]


# ------------------------------------------------------------------ the bank


def test_try_first_parts_keep_the_printed_numbers_and_are_not_counted_in_the_bank():
    for key in KEYS:
        template = bank.TEMPLATES[key]
        assert template.try_first and not template.draws and len(template.values) == 1
        assert template.type == TYPES[key] and template.kinds == ("numeric",)
    counted = [t.key for kind in bank.TOPIC.type_keys for t in bank.by_type(kind)]
    assert not set(KEYS) & set(counted)
    assert len(counted) == len(bank.TEMPLATES) - len(KEYS)


@pytest.mark.parametrize("number", EXAMPLES)
def test_each_page_places_its_try_first_question_just_above_the_solution(number):
    source = _page(number)
    exercise = source.index("{exercise}")
    question = source.index(f"```{{question}} example-{number}-try\n```")
    solution = source.index("{solution}")
    assert exercise < question < solution
    assert re.search(r"\{solution\} [^\n]+\n:class: dropdown try-first\n", source)
    between = source[question:solution]
    assert between.count("```") == 3  # the empty directive, then the solution's fence opens


# ------------------------------------------------------------------- the site


# ------------------------------------------------------------- in Chromium
