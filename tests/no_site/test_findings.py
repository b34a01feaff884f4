# ruff: noqa: RUF001, RUF003  (feedback and question text as typeset: true minus, times)
"""Issue 25, "the bank read as an examiner would": give-aways and missing real mistakes in the
templates that were already there. (The skydiver explorer's warning is checked with the
explorables: tests/no_site/test_explorables_models.py.)"""

from __future__ import annotations

import re

import pytest

from physics_figures import textformat
from physics_figures.bank import TEMPLATES
from physics_figures.parts import ChoicePart, ExplainPart

# ---- a direction part asks for the direction without giving it ----------------------------


def test_explosion_three_pieces_asks_for_the_direction_without_naming_it():
    # Issue 25: "(c) gives the direction away ('for example, south of west') in all 10 variants".
    template = TEMPLATES["explosion-three-pieces"]
    keys = set()
    for index, question in enumerate(template.variants):
        direction = question.parts[2]
        assert direction.direction == "choice"  # the direction is marked, from the four quadrants
        asked = textformat.to_plain(question.text) + " " + direction.prompt
        assert direction.answer_direction not in asked.lower(), f"variant {index} names its key"
        keys.add(direction.answer_direction)
    assert len(keys) > 1, "the third piece flies the same way in every variant"


# ---- an explain or conceptual answer follows the variant, or the template says why not -------

#: A multiple-choice option that is a value (Paper 1's numerical options): "1.5 m s⁻¹", "−2.0 N s".
_A_VALUE = re.compile(r"[−-]?\d")


def _answers(question) -> list[str]:
    """The model answer of each explain part and the key's text of each conceptual choice part."""
    found = []
    for part in question.parts:
        if isinstance(part, ExplainPart):
            found.append(textformat.to_plain(part.model_answer))
        elif isinstance(part, ChoicePart) and not all(_A_VALUE.match(textformat.to_plain(o.text))
                                                      for o in part.options):
            found.append(textformat.to_plain(part.options["ABCD".index(part.answer)].text))
    return found


#: The explain and conceptual templates that issue 25's reading found (and any added since).
CONCEPTUAL = sorted(key for key, template in TEMPLATES.items()
                    if not template.try_first and any(_answers(q) for q in template.variants))


def test_the_conceptual_templates_are_found():
    assert {"first-law-choice", "third-law-pair-choice", "terminal-velocity-choice", "mass-weight-choice",
            "elastic-or-not-choice", "constant-velocity-explained", "terminal-velocity-explained",
            "third-law-pair-explained", "deceleration-largest-explained", "mass-weight-explained",
            "collision-energy-explained"} <= set(CONCEPTUAL)
    assert "stick-choice" not in CONCEPTUAL  # numerical options follow their numbers anyway


@pytest.mark.parametrize("key", CONCEPTUAL)
def test_each_variant_answers_its_own_situation_or_the_template_says_why_not(key):
    # Issue 25: "An explain or conceptual answer changes with the variant, or the template says why
    # it cannot." Two variants with the same answer teach the wording, not the situation.
    template = TEMPLATES[key]
    if template.same_answer_because:
        return  # stated, and Template checks the reason is given in words
    seen: dict[str, int] = {}
    for index, question in enumerate(template.variants):
        for answer in _answers(question):
            assert answer not in seen, f"variants {seen[answer]} and {index} give the same answer: {answer!r}"
            seen[answer] = index


def test_a_template_states_why_its_answer_cannot_vary_in_words():
    template = TEMPLATES["mass-weight-explained"]
    fields = {"key": "x", "type": template.type, "title": "x", "build": template.build, "draws": template.draws,
              "variant_count": template.variant_count}
    with pytest.raises(ValueError, match="same_answer_because must say why"):
        type(template)(kinds=("explain",), same_answer_because="  ", **fields)
    with pytest.raises(ValueError, match="same_answer_because is only for an explain or multiple-choice"):
        type(template)(kinds=("numeric",), same_answer_because="One definition.", **fields)
    stated = type(template)(kinds=("explain",), same_answer_because="One definition, asked in four wordings.",
                            **fields)
    assert stated.same_answer_because.startswith("One definition")


# ---- real named mistakes, not strawmen -------------------------------------------------------

SIN_COS, SCALARS = "sin and cos swapped", "momentum added as scalars"
KE_KEPT, ONE_MASS = "kinetic energy conserved", "one body's mass used for both"

#: (template, part, mistake, its value in variant 0 worked by hand from the printed numbers). A part
#: is an index for a numerical part; None for a multiple-choice part, whose option prints the value.
REAL_MISTAKES = (
    # sin and cos swapped: A's components taken as p sin θ along and p cos θ across
    ("practice-pucks", 0, SIN_COS, 0.767),  # √((1.0 − 0.60 sin 40°)² + (0.60 cos 40°)²)
    ("oblique-wall-bounce", 0, SIN_COS, 0.919),  # 1.2 cos 40° (the angle is to the wall)
    ("oblique-wall-bounce", 1, SIN_COS, 1.84),  # 2 × 1.2 cos 40°
    ("glancing-speed-choice", None, SIN_COS, 1.6),  # √((0.60 − 0.30 sin 40°)² + (0.30 cos 40°)²) / 0.30
    # momentum added as scalars: sizes added (or subtracted) with no signs or angles
    ("practice-pucks", 0, SCALARS, 0.40),  # 1.0 − 0.60
    ("skaters-stick-right-angles", 0, SCALARS, 3.58),  # (70 × 4.0 + 50 × 3.0) / 120
    ("explosion-three-pieces", 0, SCALARS, 10.5),  # 0.20 × 30 + 0.30 × 15
    ("practice-trolleys-stick", 0, SCALARS, 2.5),  # (2.0 × 3.0 + 1.0 × 1.5) / 3.0
    ("stick-choice", None, SCALARS, 2.8),  # (3.0 × 4.0 + 2.0 × 1.0) / 5.0
    # the kinetic energy "conserved" in a collision that loses it, or an explosion that gains it
    ("sticking-energy-lost", 0, KE_KEPT, 1.90),  # ½ × 0.80 × 3.0² = ½ × 2.0 × v²
    ("sticking-energy-lost", 2, KE_KEPT, 0.0),
    ("practice-trolleys-stick", 1, KE_KEPT, 0.0),
    ("stick-energy-choice", None, KE_KEPT, 0.0),
    ("quick-check-2", 0, KE_KEPT, 20.0),  # ½ × 0.010 × 400² = ½ × 4.0 × v²
    ("example-4-try", 4, KE_KEPT, 0.90),  # ½ × 0.20 × 3.0², the kinetic energy before (notes, Example 4)
    # one body's mass used for both after they stick
    ("practice-trolleys-stick", 0, ONE_MASS, 2.25),  # (6.0 − 1.5) / 2.0
    ("stick-choice", None, ONE_MASS, 3.3),  # (12 − 2.0) / 3.0
    ("sticking-energy-lost", 0, ONE_MASS, 2.0),  # 0.80 × 3.0 / 1.2
    # the real mistakes that replace the strawmen
    ("quick-check-1", 0, "speed given as momentum", 7.5),  # 5.0 × 3.0 / 2.0
    ("quick-check-1", 1, "impulse taken as kinetic energy", 3.87),  # √(2 × 15 / 2.0)
    ("quick-check-1", 1, "distance given as speed", 11.25),  # ½ × 2.5 × 3.0²
    ("practice-stopping-time", 0, "stopping distance given as the time", 18.0),  # ½ × 900 × 12² / 3600
    ("graph-kick-force-time", 2, "impulse taken as kinetic energy", 5.96),  # √(2 × 8.0 / 0.45)
)

#: Mistakes no student makes (issue 25), which the real ones above replace.
STRAWMEN = ("mass over momentum", "momentum times mass", "force over momentum", "impulse × mass",
            "force times mass")


def _named(question) -> set[str]:
    return {m.name for p in question.parts for m in p.mistakes} | {
        o.mistake for p in question.parts if isinstance(p, ChoicePart) for o in p.options}


@pytest.mark.parametrize(("key", "part", "name", "value"), REAL_MISTAKES,
                         ids=[f"{key}-{part}-{name}" for key, part, name, _ in REAL_MISTAKES])
def test_the_real_mistakes_are_named_with_their_variant_0_values(key, part, name, value):
    question = TEMPLATES[key].variant(0)
    if part is None:  # multiple choice: the option standing for the mistake prints its value
        (option,) = [o for o in question.parts[0].options if o.mistake == name]
        assert re.match(r"[\d.]+", textformat.to_plain(option.text)).group() == f"{value:g}"
        assert option.see or question.parts[0].see, "the feedback sends the student to a section"
        return
    (mistake,) = [m for m in question.parts[part].mistakes if m.name == name]
    assert mistake.value == pytest.approx(value, rel=2e-3, abs=1e-12)
    assert mistake.see or question.parts[part].see, "the feedback sends the student to a section"


@pytest.mark.parametrize("key", TEMPLATES)
def test_no_strawman_mistake_remains(key):
    named = set().union(*(_named(q) for q in TEMPLATES[key].variants))
    assert not named & set(STRAWMEN)


# ---- a scheme's working gives its own answer -------------------------------------------------


def test_block_and_hanging_mass_tension_line_gives_the_printed_tension_in_every_variant():
    # Issue 25: "block-and-hanging-mass variant 9, whose own 3 s.f. working gives 6.6 N" (its
    # line "T − 1.7 = 2.3 × 2.11" for a key printed as 6.5 N). The reader of working lines
    # (tests/working_lines.py) reads "= result" lines, not this equation: read it here.
    for index, question in enumerate(TEMPLATES["block-and-hanging-mass"].variants):
        lines = [textformat.to_plain(mark.text) for mark in question.mark_scheme if mark.part == "b"]
        found = re.search(r"T − ([\d.]+) = ([\d.]+) × ([\d.]+)", lines[0])
        printed = re.search(r"T = ([\d.]+) N", lines[1])
        assert found and printed, lines
        friction, mass, acceleration = (float(x) for x in found.groups())
        place = 10 ** -len(printed.group(1).partition(".")[2])
        assert abs(friction + mass * acceleration - float(printed.group(1))) <= place / 2, (index, lines)
