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
variants of each template (:class:`Kit`), and the end-of-topic test leaves out a template
whose reserve the worksheets used up.

The order of templates and variants is drawn with :func:`seeded_order`, a 32-bit FNV-1a
hash of the seed and the key, which the teachers' sheet builder (book/_ext/questions/sheet_builder.py,
static/sheet-builder.js) computes the same way: the builder and this module give the same sheets.

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
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from functools import cached_property

from .. import topics
from ..checks import require as _require
from ..questions import Question
from ..topics import Topic
from ..variants import Template

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


def fnv1a(text: str) -> int:
    """The 32-bit FNV-1a hash of a text's UTF-8 bytes: a draw any language repeats exactly
    (Python's random cannot be repeated in the browser's sheet builder)."""
    value = 0x811C9DC5
    for byte in text.encode():
        value = ((value ^ byte) * 0x01000193) & 0xFFFFFFFF
    return value


def seeded_order(items: Sequence, label: str, seed: int, name=str) -> list:
    """The items in the order a seed draws: by the hash of "label:seed:name(item)", ties in the
    given order."""
    return sorted(items, key=lambda item: fnv1a(f"{label}:{seed}:{name(item)}"))


def _subset_sums(templates: Sequence[Template], most: int) -> dict[int, tuple[Template, ...]]:
    """For each total up to ``most``, one set of templates that makes it (the first found
    in the given order, which the seed has shuffled)."""
    sums: dict[int, tuple[Template, ...]] = {0: ()}
    for template in templates:
        marks = template_marks(template)
        for total, chosen in sorted(sums.items(), reverse=True):
            if total + marks <= most and total + marks not in sums:
                sums[total + marks] = (*chosen, template)
    return sums


def choose_templates(templates: Sequence[Template], marks: int, seed: int, topic: Topic | None = None
                     ) -> list[Template]:
    """Templates making exactly ``marks``, shared among their types as the exam shares its
    questions (each type's exam_count in the topic), drawn by ``seed``. ValueError when no
    set of them makes that many marks, naming the nearest totals that can be made."""
    topic = topic_of(topic)
    by_type: dict[str, list[Template]] = {}
    for template in templates:
        by_type.setdefault(template.type, []).append(template)
    by_type = {t: seeded_order(group, "worksheet-templates", seed, lambda template: template.key)
               for t, group in by_type.items()}
    available = sum(template_marks(t) for t in templates)
    _require(marks <= available, "marks", marks,
             f"is more than the {available} marks the bank holds for "
             f"{', '.join(sorted(by_type))} ({len(templates)} templates)")
    counts = {t: topic.type(t).exam_count for t in by_type}
    weight = sum(counts.values()) or 1
    targets = {t: marks * counts[t] / weight for t in by_type}
    # Per type: the totals it can make; then over the types: the exact total that strays
    # least from each type's share.
    options = {t: _subset_sums(group, marks) for t, group in by_type.items()}
    best: dict[int, tuple[float, tuple[tuple[str, int], ...]]] = {0: (0.0, ())}
    for question_type, sums in options.items():
        following: dict[int, tuple[float, tuple[tuple[str, int], ...]]] = {}
        for total, (cost, picks) in best.items():
            for amount in sums:
                if total + amount > marks:
                    continue
                entry = (cost + abs(amount - targets[question_type]), (*picks, (question_type, amount)))
                if total + amount not in following or entry[0] < following[total + amount][0] - 1e-9:
                    following[total + amount] = entry
        best = following
    if marks not in best:
        below = max((total for total in best if total < marks), default=0)
        above = _subset_sums(templates, available)
        above = min((total for total in above if total > marks), default=available)
        raise ValueError(f"marks cannot be made exactly from the questions of these templates "
                         f"({', '.join(f'{t.key}: {template_marks(t)}' for t in templates)}); "
                         f"the nearest totals that can are {below} and {above} (got marks={marks!r})")
    chosen = [t for question_type, amount in best[marks][1] for t in options[question_type][amount]]
    order = {template.key: index for index, template in enumerate(bank_templates(topic))}
    return sorted(chosen, key=lambda t: order.get(t.key, len(order)))


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


def variant_order(template: Template, seed: int, avoid: Collection[int] = ()) -> list[int]:
    """A template's reserve variants in the order a seed draws them; the printed variant (0, in
    the book and its key), when the reserve holds it, comes last; before it, the variants in
    ``avoid`` (a ready-made worksheet's) after all the others, in the same order."""
    drawn = seeded_order([i for i in template.reserve_variants if i], f"worksheet-variants:{template.key}", seed)
    return [*(i for i in drawn if i not in avoid), *(i for i in drawn if i in avoid),
            *(i for i in template.reserve_variants if not i)]


def usable_versions(template: Template, used: int = 0) -> int:
    """How many versions a template can still give after ``used`` of its variants went to other
    sheets: every version its own variant; a one-wording statement (a definition) has one
    variant, the same in every version (its answer is the same anyway), once in a kit."""
    if template.one_wording:
        return MAX_VERSIONS if not used else 0
    return len(template.reserve_variants) - used


@dataclass
class Kit:
    """The sheets of one kit draw their variants from here: each template's next unused
    variants, so no question (template and variant) appears twice in the kit."""

    seed: int
    used: dict[str, int] | None = None
    #: Per template key, the variants to take only when no other is left (the ready-made
    #: worksheets' numbers, for a teacher's own sheet: :func:`ready_made`).
    avoid: dict[str, dict[int, str]] | None = None

    def __post_init__(self):
        self.used = {} if self.used is None else self.used
        self.avoid = {} if self.avoid is None else self.avoid

    def left(self, template: Template) -> int:
        return usable_versions(template, self.used.get(template.key, 0))

    def take(self, template: Template, count: int) -> list[int]:
        if template.one_wording:
            self.used[template.key] = 1
            return [0] * count
        start = self.used.get(template.key, 0)
        self.used[template.key] = start + count
        return variant_order(template, self.seed, self.avoid.get(template.key, {}))[start:start + count]


def plan(name: str, title: str, templates: Sequence[Template], *, versions: int, seed: int,
         marks: int | None = None, topic: Topic | None = None, kit: Kit | None = None) -> Sheet:
    """A sheet's versions: the templates (all of them, or a set making ``marks``), each
    version with its own reserve variant of each (the next unused ones of ``kit``, when the
    sheet is one of a kit; else a teacher's own sheet, which takes the ready-made worksheets'
    variants only when it has no others: :func:`ready_made`). ValueError when the request
    cannot be filled."""
    _require(isinstance(versions, int) and 1 <= versions <= MAX_VERSIONS, "versions", versions,
             f"must be a whole number from 1 to {MAX_VERSIONS} (A to Z)")
    _require(isinstance(seed, int) and seed >= 0, "seed", seed, "must be a whole number, 0 or more")
    _require(bool(templates), "templates", list(templates), "must hold at least one template")
    kit = Kit(seed, avoid=ready_made(topic)) if kit is None else kit
    short = [t for t in templates if kit.left(t) < versions]
    _require(not short, "versions", versions,
             "needs that many different variants of every template, but "
             + ", ".join(f"{t.key} has {kit.left(t)} the site does not show" for t in short)
             + ": ask for fewer versions or leave those templates out")
    if marks is not None:
        _require(isinstance(marks, int) and marks >= 1, "marks", marks, "must be a whole number, 1 or more")
        templates = choose_templates(templates, marks, seed, topic)
    chosen_variants = {t.key: kit.take(t, versions) for t in templates}
    return Sheet(name, title, seed, tuple(
        Version(string.ascii_uppercase[index],
                tuple(Item(t, chosen_variants[t.key][index]) for t in templates))
        for index in range(versions)))


def site_sheets(*, seed: int = SITE_SEED, versions: int = SITE_VERSIONS, topic: Topic | None = None) -> list[Sheet]:
    """The site's sheets: a worksheet of every template of each type, and the mixed 40-mark
    end-of-topic test weighted like the exam."""
    topic = topic_of(topic)
    kit = Kit(seed)
    sheets = []
    for question_type in topic.types:
        usable = [t for t in topic.by_type(question_type.key) if kit.left(t) >= versions]
        if usable:
            sheets.append(plan(f"worksheet-{question_type.key}", f"Worksheet: {question_type.title}",
                               usable, versions=versions, seed=seed, topic=topic, kit=kit))
    # the test: the templates with variants the worksheets have not used
    usable = [t for t in bank_templates(topic) if kit.left(t) >= versions]
    marks = min(END_OF_TOPIC_MARKS, sum(template_marks(t) for t in usable))  # a small topic: all it has
    sheets.append(plan("end-of-topic-test", f"{topic.name}: end-of-topic test", usable, versions=versions,
                       seed=seed, marks=marks, topic=topic, kit=kit))
    return sheets


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
