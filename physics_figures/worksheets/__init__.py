"""The teacher's kit: worksheets in several versions, each with its own answer key.

A teacher chooses question types or templates of the bank (physics_figures.bank), the
number of marks, the number of versions and a seed. :func:`plan` picks the templates (the
same in every version, so every version carries the same marks) and, for each version,
one variant of each template: different numbers from the same templates. Everything is
drawn from the seed, so the same seed gives the same sheets.

Sheets use only a template's reserve variants (Template.reserve_variants), which the site
never ships, so no student has met a sheet's numbers on the site; a template of a few
situations shares its variants with the site (Template.shares_variants). Within a kit (the
site's sheets), no variant of a template appears twice: each sheet takes the next unused
variants of each template (:func:`site_sheets`), and the end-of-topic test leaves out a template
whose reserve the worksheets used up.

The draw itself (the templates making the marks, each type's share, the variants' seeded order)
has one implementation, the teachers' sheet builder's question-draw.js, which :mod:`.draw` runs
under Node: the builder in the browser and this module give the same sheets.

:mod:`.latex` writes a version's question sheet and answer key as standalone LaTeX, and
:mod:`.build` typesets them with xelatex. :mod:`.moodle` exports the bank as Moodle XML.
``python -m physics_figures.worksheets --help`` is the command line.

A topic is read generically (physics_figures.topics: its types, their titles and exam
weights, its templates): a template added to a topic's bank, or a new topic, appears here
with nothing else to change. The Dynamics topic (physics_figures.bank) is the default.
"""

from __future__ import annotations

import difflib
import string
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

from .. import topics
from ..checks import require as _require
from ..questions import Question
from ..topics import Topic
from ..variants import Template
from .draw import draw_kit

#: The topic a sheet draws from unless told otherwise (--topic on the command line).
DEFAULT_TOPIC = "physics_figures.bank"
#: The seed of the worksheets on the site (`make worksheets`).
SITE_SEED = 2026
#: The site's mixed end-of-topic test.
END_OF_TOPIC_MARKS = 40
SITE_VERSIONS = 3
#: The one data line every sheet prints (the notes: g = 9.81 m s⁻²).
DATA_LINE = "Data: take g = 9.81 m s⁻²."
MAX_VERSIONS = len(string.ascii_uppercase)


def topic_of(topic: Topic | None) -> Topic:
    """The topic given, or the default one."""
    return topics.load(DEFAULT_TOPIC) if topic is None else topic


def bank_templates(topic: Topic | None = None) -> list[Template]:
    """Every template a worksheet or the Moodle file may use, in the bank's order (a worked
    example's try-first part is not one: its statement is the example's)."""
    return topic_of(topic).practice_templates()


def template_marks(template: Template) -> int:
    """The marks of a template (the same in every variant, which a test checks)."""
    return template.variant(0).marks


def part_marks(question: Question) -> list[int]:
    """The marks printed beside each part: the question's own count (Question.part_marks),
    the same number the site and Moodle give."""
    return question.part_marks()


@dataclass(frozen=True)
class Item:
    """One question of a version: the template and the variant it prints."""

    template: Template
    variant: int

    @cached_property
    def question(self) -> Question:
        return self.template.variant(self.variant)


@dataclass(frozen=True)
class Version:
    """One version of a sheet (A, B, C...): its questions in order."""

    letter: str
    items: tuple[Item, ...]

    @property
    def marks(self) -> int:
        return sum(item.question.marks for item in self.items)


@dataclass(frozen=True)
class Sheet:
    """A worksheet: its name (file names), title, seed and versions."""

    name: str
    title: str
    seed: int
    versions: tuple[Version, ...]

    @property
    def marks(self) -> int:
        return self.versions[0].marks

    @property
    def templates(self) -> tuple[Template, ...]:
        return tuple(item.template for item in self.versions[0].items)


def select(*, types: Sequence[str] = (), templates: Sequence[str] = (), topic: Topic | None = None
           ) -> list[Template]:
    """The templates named by type or by key (both may be given), in the bank's order.
    ValueError names a type or template that does not exist."""
    topic = topic_of(topic)
    _require(bool(types) or bool(templates), "types", list(types), "or templates must name something to ask")
    for question_type in types:
        _require(question_type in topic.type_keys, "types", question_type,
                 f"must name question types of the bank: {', '.join(topic.type_keys)}")
    known = {t.key: t for t in bank_templates(topic)}
    for key in templates:
        if key not in known:
            close = difflib.get_close_matches(key, known, n=3)  # a typing slip
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            raise ValueError(f"templates names {key!r}, which is no template of the bank{hint}; "
                             f"`python -m physics_figures.worksheets --list` lists them "
                             f"(got templates={list(templates)!r})")
    wanted = set(templates)
    chosen = [t for t in bank_templates(topic) if t.type in types or t.key in wanted]
    return chosen


def usable_versions(template: Template, topic: Topic | None = None) -> int:
    """How many versions a template can give in a fresh kit (the draw's rule): every version its
    own variant; a one-wording statement (a definition) has one variant, the same in every
    version (its answer is the same anyway)."""
    return draw_kit(topic_of(topic), [template], {"seed": 0, "versions": 1, "sheets": []})["left"][template.key]


def _sheet(name: str, title: str, seed: int, drawn: dict, templates: Sequence[Template]) -> Sheet:
    by_key = {t.key: t for t in templates}
    chosen = [by_key[key] for key in drawn["templates"]]
    return Sheet(name, title, seed, tuple(
        Version(letter, tuple(Item(t, variants[index]) for t, variants in zip(chosen, drawn["variants"], strict=True)))
        for index, letter in enumerate(string.ascii_uppercase[:len(drawn["variants"][0])])))


def plan(name: str, title: str, templates: Sequence[Template], *, versions: int, seed: int,
         marks: int | None = None, topic: Topic | None = None) -> Sheet:
    """A teacher's own sheet: the templates (all of them, or a set making ``marks``, shared
    among their types as the exam shares its questions), each version with its own reserve
    variant of each, taking the ready-made worksheets' variants only when it has no others
    (:func:`ready_made`). ValueError, naming the field, the value and the rule, when the
    request cannot be filled (for marks that cannot be made: the nearest totals that can)."""
    topic = topic_of(topic)
    sheet = {"templates": [t.key for t in templates], **({} if marks is None else {"marks": marks})}
    avoid = {key: {str(i): where for i, where in made.items()} for key, made in ready_made(topic).items()}
    drawn = draw_kit(topic, templates, {"seed": seed, "versions": versions, "avoid": avoid, "sheets": [sheet]})
    return _sheet(name, title, seed, drawn["sheets"][0], templates)


def site_sheets(*, seed: int = SITE_SEED, versions: int = SITE_VERSIONS, topic: Topic | None = None) -> list[Sheet]:
    """The site's sheets, one kit (no question, template and variant, appears twice in it): a
    worksheet of every template of each type, and the mixed 40-mark end-of-topic test weighted
    like the exam, from the templates with variants the worksheets have not used (a small
    topic's test: all it has)."""
    topic = topic_of(topic)
    templates = bank_templates(topic)
    every = list({t.key: t for t in [*templates, *(t for kind in topic.types for t in topic.by_type(kind.key))]}.values())
    worksheets = [(f"worksheet-{kind.key}", f"Worksheet: {kind.title}",
                   {"templates": [t.key for t in topic.by_type(kind.key)], "fitting": True}) for kind in topic.types]
    test = ("end-of-topic-test", f"{topic.name}: end-of-topic test",
            {"templates": [t.key for t in templates], "fitting": True, "marksAtMost": END_OF_TOPIC_MARKS})
    asked = [*worksheets, test]
    drawn = draw_kit(topic, every, {"seed": seed, "versions": versions,
                                    "sheets": [request for _, _, request in asked]})
    return [_sheet(name, title, seed, sheet, every)
            for (name, title, _), sheet in zip(asked, drawn["sheets"], strict=True) if sheet]


def ready_made(topic: Topic | None = None) -> dict[str, dict[int, str]]:
    """Per template key, the variants the ready-made worksheets (the site's kit, `make
    worksheets`) print, each with where: "Worksheet: Drag…, version B". A one-wording template
    (a definition, the same words in every sheet) has no numbers to repeat and is left out."""
    out: dict[str, dict[int, str]] = {}
    for sheet in site_sheets(topic=topic):
        for version in sheet.versions:
            for item in version.items:
                if not item.template.one_wording:
                    out.setdefault(item.template.key, {})[item.variant] = f"{sheet.title}, version {version.letter}"
    return out


def ready_made_repeats(sheet: Sheet, topic: Topic | None = None) -> list[str]:
    """Where a teacher's sheet repeats a ready-made worksheet's numbers (too many versions asked
    for the variants left), as "Version C, question 2: as in Worksheet: Drag…, version A"."""
    made = ready_made(topic)
    return [f"Version {version.letter}, question {number}: as in {made[item.template.key][item.variant]}"
            for version in sheet.versions for number, item in enumerate(version.items, start=1)
            if item.variant in made.get(item.template.key, {})]
