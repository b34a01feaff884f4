
"""The multiple-choice part kind (Paper 1 style): options A to D, the wrong ones named
mistakes. Its browser twin is book/_ext/questions/static/question-kinds/choice.js."""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from typing import ClassVar

from .. import marking, textformat
from ..notation import format_number
from .common import NoValue, _require

OPTION_LETTERS = ("A", "B", "C", "D")


@dataclass(frozen=True)
class Option:
    """One option of a multiple-choice part (text format). A wrong option names the mistake or
    misconception it stands for, with the feedback a student gets for choosing it."""

    text: str
    mistake: str = ""
    feedback: str = ""
    #: The section that teaches the idea, where it is not the part's own (a bank section id).
    see: str | None = None

    def __post_init__(self):
        textformat.parse(self.text)
        _require(bool(self.mistake) == bool(self.feedback), "feedback", self.feedback,
                 "goes with a named mistake: a wrong option has both, the key has neither")


@dataclass(frozen=True)
class ChoicePart(NoValue):
    """A Paper 1-style multiple-choice part: options A to D, one of them right (``answer``).
    The wrong options are named mistakes worked from the same givens, or named misconceptions."""

    prompt: str
    options: tuple[Option, ...]
    answer: str
    revisit: str
    #: The section of the book a wrong choice sends the student to (an id of the bank's sections).
    see: str | None = None
    kind: ClassVar[str] = "mcq"
    asks: ClassVar[str] = "state"

    def __post_init__(self):
        _require(len(self.options) == len(OPTION_LETTERS), "options", len(self.options),
                 f"must be {len(OPTION_LETTERS)}, one per letter {OPTION_LETTERS}")
        _require(self.answer in OPTION_LETTERS, "answer", self.answer, f"must be one of {OPTION_LETTERS}")
        for letter, option in zip(OPTION_LETTERS, self.options, strict=True):
            right = letter == self.answer
            _require(right != bool(option.mistake), "options", letter,
                     "must name a mistake for each wrong option and none for the key")
        texts = [textformat.to_plain(o.text) for o in self.options]
        _require(len(set(texts)) == len(texts), "options", texts, "must all differ")
        _require(bool(self.revisit.strip()), "revisit", self.revisit, "must name the idea to revisit")

    @property
    def answer_text(self) -> str:
        return f"{self.answer}: {textformat.to_plain(self.options[OPTION_LETTERS.index(self.answer)].text)}"

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt, "answer": self.answer,
                "revisit": self.revisit, "see": self.see,
                "options": [{"letter": letter, "html": textformat.to_html(o.text, paragraphs=False),
                             "mistake": o.mistake, "feedback": o.feedback, "see": o.see,
                             **({"loses": list(marking.mistake_losses("physics"))} if o.mistake else {})}
                            for letter, o in zip(OPTION_LETTERS, self.options, strict=True)]}


def choices_in_order(key: float, wrong: dict[str, tuple], *, sig_figs: int, unit: str, seed: int = 0
                     ) -> tuple[tuple[Option, ...], str]:
    """Options for a numerical multiple-choice part, in increasing order as Paper 1 prints them:
    the key and three named mistakes {name: (value, feedback)} worked from the same givens, or
    (value, feedback, see) for a mistake taught in another section than the part's.

    Given a pool of more than three mistakes (some above the key, some below), three are chosen
    so that the key's letter moves from variant to variant (issue 25, no give-aways): the letter
    comes from the key's printed value, never from random state, so a variant always prints the
    same options. ``seed`` is the template's own fixed number mixed into that choice: a template
    picks the one that spreads its variants' keys over the letters (tests/test_choice_letters.py
    checks no letter is the key in more than 40 % of them). Returns (options, the key's letter)."""
    _require(len(wrong) >= len(OPTION_LETTERS) - 1, "wrong", sorted(wrong),
             f"must hold at least {len(OPTION_LETTERS) - 1} named mistakes")
    space = "" if unit == "°" else " "

    def text(value: float) -> str:
        return f"{format_number(value, sig_figs)}{space}{unit}"

    wrong = _three_mistakes(key, wrong, text, seed)
    rows = sorted([(key, "", "", None)] + [(value, name, feedback, *see) for name, (value, feedback, *see)
                                           in wrong.items()], key=lambda row: row[:3])
    texts = [text(value) for value, *_ in rows]
    _require(len(set(texts)) == len(texts), "wrong", texts,
             f"must print differently from the key and each other at {sig_figs} s.f.")
    options = tuple(Option(text, name, feedback, *see) for text, (_, name, feedback, *see) in zip(texts, rows, strict=True))
    answer = OPTION_LETTERS[[name for _, name, *_ in rows].index("")]
    return options, answer


def _three_mistakes(key: float, wrong: dict[str, tuple], text, seed: int) -> dict[str, tuple]:
    """Three of a pool of named mistakes, in the pool's order of preference within each side of
    the key, chosen so the key takes a letter drawn from its printed value: of the letters the
    pool can give (enough mistakes below and above the key, each printing differently), the one
    at crc32(seed and the key's text) mod how many there are."""
    wanted = len(OPTION_LETTERS) - 1
    if len(wrong) == wanted:
        return wrong
    seen = {text(key)}
    below, above = [], []
    for name, row in wrong.items():
        printed = text(row[0])
        if printed in seen:
            continue  # prints the same as the key or a mistake before it in the pool
        seen.add(printed)
        (below if row[0] < key else above).append(name)
    places = [p for p in range(len(OPTION_LETTERS)) if len(below) >= p and len(above) >= wanted - p]
    _require(bool(places), "wrong", sorted(wrong), "must hold three mistakes that print differently")
    place = places[zlib.crc32(f"{seed}:{text(key)}".encode()) % len(places)]
    # the nearest mistakes below the key first go furthest from it in the printed order, so
    # keep the pool's preference: the first named on each side
    chosen = below[:place] + above[:wanted - place]
    return {name: wrong[name] for name in wrong if name in chosen}
