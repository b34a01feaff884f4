
"""The multiple-choice part kind (Paper 1 style): options A to D, the wrong ones named
mistakes. Its browser twin is book/_ext/questions/static/question-kinds/choice.js."""

from __future__ import annotations

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


def choices_in_order(key: float, wrong: dict[str, tuple], *, sig_figs: int, unit: str
                     ) -> tuple[tuple[Option, ...], str]:
    """Options for a numerical multiple-choice part, in increasing order as Paper 1 prints them:
    the key and three named mistakes {name: (value, feedback)} worked from the same givens, or
    (value, feedback, see) for a mistake taught in another section than the part's.
    Returns (options, the key's letter)."""
    _require(len(wrong) == len(OPTION_LETTERS) - 1, "wrong", sorted(wrong),
             f"must hold {len(OPTION_LETTERS) - 1} named mistakes")
    space = "" if unit == "°" else " "
    rows = sorted([(key, "", "", None)] + [(value, name, feedback, *see) for name, (value, feedback, *see)
                                           in wrong.items()], key=lambda row: row[:3])
    texts = [f"{format_number(value, sig_figs)}{space}{unit}" for value, *_ in rows]
    _require(len(set(texts)) == len(texts), "wrong", texts,
             f"must print differently from the key and each other at {sig_figs} s.f.")
    options = tuple(Option(text, name, feedback, *see) for text, (_, name, feedback, *see) in zip(texts, rows, strict=True))
    answer = OPTION_LETTERS[[name for _, name, *_ in rows].index("")]
    return options, answer
