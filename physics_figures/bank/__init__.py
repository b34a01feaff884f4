"""The Dynamics question bank, and the topic it belongs to (``TOPIC``): one module per
question type of the notes, each a list of templates, and ``statements``, the define and state
questions of the papers (each of the type whose practice page teaches it).

Adding a question touches one file: write its ``build`` function and its ``Template`` in
the module of its type (a definition or a stated law: in ``statements``), and add it to that
module's ``TEMPLATES``. Pages place a template with the ``question`` directive by its key::

    ```{question} quick-check-1
    ```
"""

from __future__ import annotations

from ..questions import Question
from ..topics import QuestionType, Topic
from ..variants import Template
from . import (
    definitions,
    drag,
    elastic,
    force_momentum,
    momentum_line,
    newton,
    sketches,
    statements,
    two_d,
    worked_examples,
)
from .sections import SECTIONS

#: Every template of the book, by key, in the order of the notes' types.
TEMPLATES: dict[str, Template] = {}
for _module in (newton, drag, force_momentum, definitions, momentum_line, elastic, two_d, sketches, statements,
                worked_examples):
    for _template in _module.TEMPLATES:
        if _template.key in TEMPLATES:
            raise ValueError(f"template key {_template.key!r} is used twice")
        TEMPLATES[_template.key] = _template


#: The topic, declared once: the site, the worksheets, Moodle and Your practice read it.
#: exam_count: how often each type came up in the Paper 1 and Paper 2 questions of 2021 to 2025
#: (the notes, "How to do it"; book/exam/how-to.md prints the same table, which a test compares).
TOPIC = Topic(
    key="dynamics",
    name="Dynamics",
    pages=(
        "book/understand/mass-and-first-law", "book/understand/momentum-and-second-law",
        "book/understand/momentum-time-graph", "book/understand/third-law", "book/understand/weight",
        "book/understand/friction-drag-terminal-velocity", "book/understand/conservation-of-momentum",
        "book/understand/elastic-and-inelastic", "book/understand/momentum-in-two-dimensions",
        "book/exam/method-newtons-laws", "book/exam/method-drag", "book/exam/method-force-momentum",
        "book/exam/method-definitions", "book/exam/method-momentum-line", "book/exam/method-collisions",
        "book/exam/method-two-dimensions", "book/exam/getting-the-marks",
    ),
    types=(
        QuestionType("newton", "Newton's laws, F = ma and third-law pairs", "book/exam/method-newtons-laws", 49),
        QuestionType("drag", "Drag, air resistance and terminal velocity", "book/exam/method-drag", 48),
        QuestionType("force-momentum", "Force as rate of change of momentum", "book/exam/method-force-momentum",
                     44),
        QuestionType("definitions", "Mass, weight and the definitions", "book/exam/method-definitions", 36),
        QuestionType("momentum-line", "Conservation of momentum in a straight line",
                     "book/exam/method-momentum-line", 23),
        QuestionType("elastic", "Elastic and inelastic collisions", "book/exam/method-collisions", 23),
        QuestionType("two-d", "Conservation of momentum in two dimensions", "book/exam/method-two-dimensions", 12),
    ),
    templates=tuple(TEMPLATES.values()),
    sections=SECTIONS,
)


def by_type(question_type: str) -> list[Template]:
    """The bank's templates of one type (try-first parts of worked examples are not counted)."""
    return TOPIC.by_type(question_type)


#: The quick check's templates (book/exam/quick-check.md asks them first, in this order).
QUICK_CHECK = tuple(f"quick-check-{number}" for number in range(1, 6))


def all_questions() -> tuple[Question, ...]:
    """Every question of the quick check and the practice pages, with the printed numbers
    (variant 0), in book order: the quick check's five, then each type's practice page in the
    notes' order, then the statements' page and the sketches' page (_toc.yml's order;
    tests/no_site/test_questions.py checks the pages place them so)."""
    # statements and sketches are asked on pages of their own, after every type's page
    apart = [*statements.TEMPLATES, *sketches.TEMPLATES]
    left_out = {*QUICK_CHECK, *(t.key for t in apart)}
    practice = [t for t in TOPIC.practice_templates() if t.key not in left_out]
    return tuple(t.variant(0) for t in [TEMPLATES[key] for key in QUICK_CHECK] + practice + apart)
