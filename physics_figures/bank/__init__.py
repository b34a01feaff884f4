"""The question bank: one module per question type of the notes, each a list of templates.

Adding a question touches one file: write its ``build`` function and its ``Template`` in
the module of its type, and add it to that module's ``TEMPLATES``. Pages place a template
with the ``question`` directive by its key::

    ```{question} quick-check-1
    ```
"""

from __future__ import annotations

from ..questions import Question
from ..variants import QUESTION_TYPES, Template
from . import (
    definitions,
    drag,
    elastic,
    force_momentum,
    momentum_line,
    newton,
    two_d,
    worked_examples,
)

#: Every template of the book, by key, in the order of the notes' types.
TEMPLATES: dict[str, Template] = {}
for _module in (newton, drag, force_momentum, definitions, momentum_line, elastic, two_d,
                worked_examples):
    for _template in _module.TEMPLATES:
        if _template.key in TEMPLATES:
            raise ValueError(f"template key {_template.key!r} is used twice")
        TEMPLATES[_template.key] = _template


def by_type(question_type: str) -> list[Template]:
    """The bank's templates of one type (try-first parts of worked examples are not counted)."""
    if question_type not in QUESTION_TYPES:
        raise ValueError(f"question_type must be one of {QUESTION_TYPES} (got {question_type!r})")
    return [t for t in TEMPLATES.values() if t.type == question_type and not t.try_first]


#: The quick check's templates (book/exam/quick-check.md asks them first, in this order).
QUICK_CHECK = tuple(f"quick-check-{number}" for number in range(1, 6))


def all_questions() -> tuple[Question, ...]:
    """Every question of the quick check and the practice pages, with the printed numbers
    (variant 0), in book order: the quick check's five, then the practice pages, one a type
    in the notes' order (tests/test_questions.py checks the pages place them so)."""
    practice = [t for t in TEMPLATES.values() if not t.try_first and t.key not in QUICK_CHECK]
    return tuple(t.variant(0) for t in [TEMPLATES[key] for key in QUICK_CHECK] + practice)
