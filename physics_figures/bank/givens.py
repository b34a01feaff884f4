"""The givens a teacher or a paper may pass to a template, checked before any physics is worked.

A template's build function takes its givens by name. Its draws say what each given is: a
whole-number choice (its printed value is an int: which situation, which story) or a size (a
mass, a speed, a time; a direction is stated in words, never by a sign). A given that is
neither is refused here with its name, its value and the rule (issue 38: a negative speed
reached a model and was reported as another given's fault, and a situation of -1 silently gave
the last situation).

Givens that keep these rules may still make a question that cannot be posed: a template's or a
model's rule refuses them, or a check of the question itself does (two named mistakes that
give one answer, a line off its axes). Every such refusal names the givens passed, and a check
of the question is told in plain words, never as the bank's internal working.
"""

from __future__ import annotations

import functools
import math
import traceback
from dataclasses import replace

from ..variants import Draw, Template


def _refusal(name: str, value: object, draw: Draw) -> str | None:
    """Why a given breaks its draw's rule, or None when it keeps it."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return f"{name} must be a number (got {name}={value!r})"
    if not math.isfinite(value):
        return f"{name} must be a finite number (got {name}={value!r})"
    if isinstance(draw.printed, int):  # a choice among the template's situations
        if value != int(value) or not draw.low <= value <= draw.high:
            return (f"{name} must be a whole number from {draw.low:g} to {draw.high:g}, one of the question's "
                    f"choices (got {name}={value!r})")
    elif draw.low >= 0 and value < 0:
        return (f"{name} must not be negative: it is a size, and the question states each direction in "
                f"words (got {name}={value!r})")
    return None


#: A check of the built question, found by its words, and what it means for the givens, in plain words.
_QUESTION_CHECKS = (
    (("could not tell them apart", "could not tell it from", "three mistakes that print differently",
      "must all differ"),
     ("two of the question's named mistakes (or a mistake and the key) give the same answer, so the marker "
     "could not tell them apart: choose other numbers")),
    (("must lie within", "strictly increasing", "must span some time", "whole divisions", "positive top"),
     ("the graph's line does not fit the axes the question draws (its times must increase and its values "
     "stay on the axes)")),
    (("must be a size", "must be a finite number"),
     "an answer comes out negative or not finite, which the question as worded cannot ask"),
    (("ecf must give",), "the question's working does not reach its key with these numbers"),
    (("math domain error",), "they have no real answer (a square root or a logarithm of a negative number)"),
)


def _own_rule(error: ValueError) -> bool:
    """Whether a template's or a model's own rule raised the error (it names its given and says
    why), not a check of the built question or a library."""
    frames = traceback.extract_tb(error.__traceback__)
    origin = frames[-1].filename.replace("\\", "/") if frames else ""
    return "/physics_figures/bank/" in origin or "/physics_figures/models/" in origin


def _why(error: ValueError) -> str:
    """The refusal's reason in plain words."""
    text = str(error)
    for signs, words in _QUESTION_CHECKS:
        if any(sign in text for sign in signs) and (not _own_rule(error) or "math domain" in text):
            return words
    return text


def checked(template: Template) -> Template:
    """The template with its givens checked against their draws before it builds."""
    if not template.draws:
        return template
    build, draws = template.build, template.draws

    @functools.wraps(build)
    def build_checked(*args: float, **givens: float):
        for name, value in givens.items():
            refused = _refusal(name, value, draws[name]) if name in draws else None
            if refused:
                raise ValueError(f"{template.key}: {refused}")
        try:
            return build(*args, **givens)
        except (ValueError, ZeroDivisionError) as error:
            passed = ", ".join(f"{name}={value!r}" for name, value in givens.items()) or "its printed givens"
            why = "they divide by zero" if isinstance(error, ZeroDivisionError) else _why(error)
            raise ValueError(f"{template.key} cannot be posed with {passed}: {why}") from error

    return replace(template, build=build_checked)


def checked_givens(*templates: Template) -> tuple[Template, ...]:
    """A module's templates, each with its givens checked (see :func:`checked`)."""
    return tuple(checked(template) for template in templates)
