"""The topic registry names the storage keys (issue 39, "A house for the tests"): the names a book
keeps a student's records under (localStorage, the export's file name, the service worker's
caches) come from physics_figures.topics.storage_keys of the book's id; the build writes them
into every page and sw.js, and no script types them. Dynamics's keep the names its students'
saved progress is under."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from physics_figures import bank
from physics_figures.topics import storage_keys

ROOT = Path(__file__).resolve().parents[2]
#: A string literal or a comment of JavaScript, as a tokenizer meets them left to right (a
#: comment's quoted example is no string).
TOKEN = re.compile(r"//[^\n]*|/\*.*?\*/|\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*'|`(?:\\.|[^`\\])*`", re.DOTALL)


def typed_keys(source: str, book: str) -> list[str]:
    """The string literals of a script that name one of `book`'s storage keys ("BOOK-...")."""
    return [token for token in TOKEN.findall(source) if token[0] in "\"'`" and f"{book}-" in token]


def scripts() -> list[Path]:
    """The book's own scripts (the vendored ones aside)."""
    return sorted(path for path in (ROOT / "book" / "_ext").rglob("*.js") if "vendor" not in path.parts)


def test_no_script_types_a_storage_key_of_the_book():
    found = {path.relative_to(ROOT).as_posix(): typed_keys(path.read_text(encoding="utf-8"), bank.TOPIC.key)
             for path in scripts()}
    found = {name: keys for name, keys in found.items() if keys}
    assert len(scripts()) > 30
    assert not found, f"scripts type the book's storage keys (read ProgressStore.KEYS instead): {found}"


@pytest.mark.parametrize(("source", "typed"), [
    ('  var STORE = "dynamics-progress-v2";', ['"dynamics-progress-v2"']),
    ("localStorage.getItem('dynamics-review-v1')", ["'dynamics-review-v1'"]),
    ("var CACHE = `dynamics-${VERSION}`;", ["`dynamics-${VERSION}`"]),
    ('/* under localStorage "dynamics-progress-v2" */ var STORE = KEYS.progress;', []),
    ('// "dynamics-progress-v1" is upgraded\nvar OLD = KEYS.oldProgress;', []),
    ('var PDF = "dynamics.pdf";', []),  # the book's files are no storage key
])
def test_the_scan_finds_a_typed_key_and_passes_a_comment(source, typed):
    assert typed_keys(source, "dynamics") == typed


def test_dynamics_keeps_the_names_its_students_progress_is_under():
    assert storage_keys(bank.TOPIC.key) == {
        "book": "dynamics", "progress": "dynamics-progress-v2", "oldProgress": "dynamics-progress-v1",
        "answers": "dynamics-questions:", "review": "dynamics-review-v1", "mock": "dynamics-mock-v1",
        "exports": "dynamics-progress", "cache": "dynamics-"}


@pytest.mark.parametrize("book", ["", "Dynamics", "two topics"])
def test_a_book_id_that_cannot_name_keys_is_refused(book):
    with pytest.raises(ValueError, match="book"):
        storage_keys(book)
