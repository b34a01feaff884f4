"""A topic of the syllabus, declared once: its name, its pages, its question types (each with
its title, its exam weight and the page teaching its method), its templates and the
sections its feedback sends a student back to.

Everything that lists questions reads a topic, never a global list: the site (the modules
named by ``question_topics`` in _config.yml), Your practice, the landing page's map, the
worksheets and the Moodle export (``--topic MODULE``). A topic is a module with a ``TOPIC``:
the Dynamics one is :mod:`physics_figures.bank`. A new topic is a new module and its pages;
no shared code changes (the tests build a second topic so).
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property

from .checks import require as _require
from .variants import Template


@dataclass(frozen=True)
class QuestionType:
    """A kind of exam question of the topic (the notes' "How to do it").

    key: the stable id (the pages' data-type); title: its name wherever it is listed;
    method: the page teaching its method; exam_count: how often it came up in past papers,
    the weight an end-of-topic test gives it.
    """

    key: str
    title: str
    method: str
    exam_count: int

    def __post_init__(self):
        _require(bool(self.key) and self.key == self.key.strip().lower() and " " not in self.key, "key",
                 self.key, "must be a lower-case id without spaces, e.g. 'momentum-line'")
        _require(bool(self.title.strip()), "title", self.title, "must not be empty")
        _require(isinstance(self.exam_count, int) and self.exam_count >= 0, "exam_count", self.exam_count,
                 "must be a whole number, 0 or more")


@dataclass(frozen=True)
class Topic:
    """One topic: key (file names, storage), name (titles, Moodle's category), pages (its
    docnames), types (in the order they are taught), templates (its question bank) and
    sections (id -> (page, section title or "" for the top)) that feedback links to."""

    key: str
    name: str
    pages: tuple[str, ...]
    types: tuple[QuestionType, ...]
    templates: tuple[Template, ...] = field(repr=False)
    sections: Mapping[str, tuple[str, str]] = field(default_factory=dict, repr=False)

    def __post_init__(self):
        keys = [t.key for t in self.types]
        _require(bool(keys) and len(set(keys)) == len(keys), "types", keys, "must be one or more, each key once")
        pages = set(self.pages)
        for question_type in self.types:
            _require(question_type.method in pages, "types", question_type.method,
                     f"must name method pages among the topic's pages {sorted(pages)}")
        for ident, (page, _) in self.sections.items():
            _require(page in pages, "sections", f"{ident}: {page}", "must point at the topic's pages")
        seen = set()
        for template in self.templates:
            _require(template.type in keys, "templates", template.key, f"must be of the topic's types {keys}")
            _require(template.key not in seen, "templates", template.key, "must each have their own key")
            seen.add(template.key)

    @property
    def type_keys(self) -> tuple[str, ...]:
        return tuple(t.key for t in self.types)

    def type(self, key: str) -> QuestionType:
        for question_type in self.types:
            if question_type.key == key:
                return question_type
        raise ValueError(f"question_type must be one of {self.type_keys} (got {key!r})")

    @cached_property
    def by_key(self) -> dict[str, Template]:
        return {t.key: t for t in self.templates}

    def by_type(self, key: str) -> list[Template]:
        """The topic's templates of one type (a worked example's try-first part is not one:
        its statement is the example's)."""
        self.type(key)
        return [t for t in self.templates if t.type == key and not t.try_first]

    def practice_templates(self) -> list[Template]:
        """Every template a worksheet, a test or the Moodle file may use, type by type."""
        return [t for question_type in self.types for t in self.by_type(question_type.key)]


def load(module: str) -> Topic:
    """The TOPIC of a module (e.g. "physics_figures.bank"); ValueError if it has none."""
    try:
        found = getattr(importlib.import_module(module), "TOPIC", None)
    except ImportError as error:
        raise ValueError(f"topic {module!r} cannot be imported: {error}") from error
    _require(isinstance(found, Topic), "topic", module, "must be a module whose TOPIC is a physics_figures.topics.Topic")
    return found


def storage_keys(book: str) -> dict[str, str]:
    """The names a book keeps a student's records under in the browser, from its id (the keys of
    its topics, book/_ext/questions/store.py book_id): its localStorage keys (progress, the
    format 1 store it upgrades, a question's saved answers by prefix, Start's review queue, the
    mock test in progress), the export's file name before "-NAME-DATE.json", and the service
    worker's caches by prefix. The build writes them into every page (a meta tag) and sw.js,
    and the scripts read them there, so a book of another topic keeps its own. Dynamics's are
    the names its students' saved progress is under: they never change."""
    _require(bool(book) and book == book.strip().lower() and " " not in book, "book", book,
             "must be a lower-case id without spaces (the topics' keys), e.g. 'dynamics'")
    return {"book": book, "progress": f"{book}-progress-v2", "oldProgress": f"{book}-progress-v1",
            "answers": f"{book}-questions:", "review": f"{book}-review-v1", "mock": f"{book}-mock-v1",
            "exports": f"{book}-progress", "cache": f"{book}-"}
