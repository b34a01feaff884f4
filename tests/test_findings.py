# ruff: noqa: RUF001, RUF003  (feedback and question text as typeset: true minus, times)
"""Issue 25, "the bank read as an examiner would": give-aways and missing real mistakes in the
templates that were already there. (The skydiver explorer's warning is checked with the
explorables: tests/test_explorables_models.py.)"""

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
