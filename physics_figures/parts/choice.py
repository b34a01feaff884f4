
"""The multiple-choice part kind (Paper 1 style): options A to D, the wrong ones named
mistakes. Its browser twin is book/_ext/questions/static/question-kinds/choice.js."""

from __future__ import annotations

import html
import itertools
import math
import zlib
from dataclasses import dataclass, field
from typing import ClassVar

from .. import marking, textformat
from ..notation import format_number
from .common import SCRIPTS, NoValue, _require, feedback_html, prompt_html

OPTION_LETTERS = ("A", "B", "C", "D")


#: A piece of a sketch whose gradient is this small (in heights of the sketch per its
#: duration) is drawn and described as flat.
_FLAT = 0.03
#: A curved piece whose gradient changes by less than this factor is "steady".
_STEADY = 1.3
#: A value this close to zero (a share of the sketch's height) is drawn, and read, as zero.
_ZERO = 0.02


@dataclass(frozen=True)
class Sketch:
    """A small sketch graph for a "which graph?" option (Paper 1 draws four, A to D): a line
    through ``points`` (time, value) with no scale, only the shape. ``symbol`` labels the
    value axis ("F", "a"), ``quantity`` names it in words ("resultant force"). Two points at
    the same time draw a jump. The points come from the models, worked by the template;
    physics_figures.figures.sketches draws them (SVG for the site and Moodle, TikZ for the
    sheets), and ``describe`` puts the shape into words for the alt text, without saying
    whether it is right."""

    quantity: str
    symbol: str
    points: tuple[tuple[float, float], ...] = field(repr=False)

    def __post_init__(self):
        object.__setattr__(self, "points", tuple((float(t), float(y)) for t, y in self.points))
        _require(len(self.points) >= 2, "points", self.points, "must hold at least two points")
        _require(all(math.isfinite(t) and math.isfinite(y) for t, y in self.points), "points", self.points,
                 "must be finite numbers")
        times = [t for t, _ in self.points]
        _require(times[0] >= 0 and all(b >= a for a, b in itertools.pairwise(times)), "points",
                 times, "must start at a time of 0 or more and never go back in time")
        _require(times[-1] > times[0], "points", times, "must span some time")
        _require(bool(self.quantity.strip()) and bool(self.symbol.strip()), "quantity", self.quantity,
                 "and symbol must name the value axis")

    @property
    def size(self) -> float:
        """The largest size of a value (1 when the line lies on the time axis)."""
        return max(abs(y) for _, y in self.points) or 1.0

    def describe(self) -> str:
        """The shape in words: where it starts, then each piece (rises, falls, stays constant,
        jumps), how a curve bends, and each level's sign and size against the first."""
        levels = _Levels(self.size)
        words = [f"starts at {levels.word(self.points[0][1])}"]
        for trend, piece in _pieces(self.points, self.size):
            end = piece[-1][1]
            if trend == "flat":
                words.append("stays constant")
            elif trend == "jump":
                words.append(f"jumps to {levels.word(end)}")
            else:
                through = " through zero" if piece[0][1] * end < 0 and levels.word(end) != "zero" else ""
                verb = "rises" if trend == "up" else "falls"
                words.append(f"{verb} {_manner(piece)}{through} to {levels.word(end)}")
        shape = ", ".join([words[0], ", then ".join(words[1:])]) if len(words) > 1 else words[0]
        return f"{self.quantity[:1].upper()}{self.quantity[1:]} against time: {shape}."


class _Levels:
    """A value in words, its size told against the first non-zero value named."""

    def __init__(self, size: float):
        self.size, self.first = size, None

    def word(self, value: float) -> str:
        if abs(value) <= _ZERO * self.size:
            return "zero"
        sign = "positive" if value > 0 else "negative"
        if self.first is None:
            self.first = value
            return f"a {sign} value"
        ratio = abs(value) / abs(self.first)
        same_sign = (value > 0) == (self.first > 0)
        if math.isclose(ratio, 1, rel_tol=0.02):
            return f"the same {sign} value" if same_sign else f"a {sign} value of the same size"
        bigger = "larger" if ratio > 1 else "smaller"
        return f"a {bigger} {sign} value" if same_sign else f"a {sign} value of {bigger} size"


def _trend(a: tuple[float, float], b: tuple[float, float], size: float, duration: float) -> str:
    (t0, y0), (t1, y1) = a, b
    if t1 == t0:
        return "jump"
    if abs(y1 - y0) / (t1 - t0) * duration / size < _FLAT:
        return "flat"
    return "up" if y1 > y0 else "down"


def _pieces(points, size: float) -> list[tuple[str, list[tuple[float, float]]]]:
    """Runs of segments with the same trend, each with its points (a jump is its own piece)."""
    duration = points[-1][0] - points[0][0]
    pieces: list[tuple[str, list]] = []
    for a, b in itertools.pairwise(points):
        trend = _trend(a, b, size, duration)
        if pieces and pieces[-1][0] == trend and trend != "jump":
            pieces[-1][1].append(b)
        else:
            pieces.append((trend, [a, b]))
    return pieces


def _manner(piece: list[tuple[float, float]]) -> str:
    """How a rising or falling piece bends: steadily (straight), ever more quickly or slowly."""
    slopes = [abs((y1 - y0) / (t1 - t0)) for (t0, y0), (t1, y1) in itertools.pairwise(piece)]
    steepest = max(range(len(slopes)), key=slopes.__getitem__)
    quicker = slopes[steepest] > _STEADY * slopes[0]
    slower = slopes[steepest] > _STEADY * slopes[-1]
    if quicker and slower:
        return "ever more quickly, then ever more slowly"
    if quicker:
        return "ever more quickly"
    return "ever more slowly" if slower else "steadily"


@dataclass(frozen=True)
class Option:
    """One option of a multiple-choice part (text format). A wrong option names the mistake or
    misconception it stands for, with the feedback a student gets for choosing it. An option
    that is a sketch graph has ``sketch``; its text is then the sketch's shape in words (its
    alt text, and what the answer key and Your practice print)."""

    text: str
    mistake: str = ""
    feedback: str = ""
    #: The section that teaches the idea, where it is not the part's own (a bank section id).
    see: str | None = None
    sketch: Sketch | None = None

    def __post_init__(self):
        if self.sketch is not None:
            _require(not self.text, "text", self.text, "must be empty for a sketch: its words come from the shape")
            object.__setattr__(self, "text", self.sketch.describe())
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
    answer_grid: ClassVar[bool] = True
    keeps_with_question_text: ClassVar[bool] = True
    mock_paper: ClassVar[str] = "1"
    browser_script: ClassVar[str] = str(SCRIPTS / "choice.js")

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
        kinds = {o.sketch is None for o in self.options}
        _require(len(kinds) == 1, "options", texts, "must be all sketches or all words (none the odd one out)")
        _require(bool(self.revisit.strip()), "revisit", self.revisit, "must name the idea to revisit")

    @property
    def answer_text(self) -> str:
        return f"{self.answer}: {textformat.to_plain(self.options[OPTION_LETTERS.index(self.answer)].text)}"

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt, "answer": self.answer,
                "revisit": self.revisit, "see": self.see,
                "options": [{"letter": letter, "html": _option_html(o),
                             "mistake": o.mistake, "feedback": o.feedback, "see": o.see,
                             **({"sketch": True} if o.sketch else {}),
                             **({"loses": list(marking.mistake_losses("physics"))} if o.mistake else {})}
                            for letter, o in zip(OPTION_LETTERS, self.options, strict=True)]}

    @property
    def sketches(self) -> bool:
        """The options are sketch graphs (a "which graph?" item)."""
        return all(o.sketch is not None for o in self.options)

    # ------------------------------------------------------- the kind's hooks (parts/__init__.py)

    @classmethod
    def form_html(cls, part: dict, question: dict, *, base: str, label: str, page: dict) -> str:
        """Radio buttons A to D (values A-D: the interface outside tests use), and the feedback."""
        items = "".join(
            f'<label class="q-option" for="{base}-{o["letter"]}"><input type="radio" class="q-choice" '
            f'name="{base}" id="{base}-{o["letter"]}" value="{o["letter"]}" aria-describedby="{base}-feedback">'
            f'<span class="q-letter">{o["letter"]}</span> <span class="q-option-text">{o["html"]}</span></label>'
            for o in part["options"])
        # four sketch graphs sit side by side, two by two on a phone (questions.css)
        sketches = " q-sketches" if any(o.get("sketch") for o in part["options"]) else ""
        return f'<div class="q-options{sketches}">{items}</div>' + feedback_html(base)

    def print_lines(self, label: str, marks: int, paper) -> list:
        """The options, then a box for the letter."""
        options = paper.options([paper.sketch(o.sketch) if o.sketch else paper.rich(o.text) for o in self.options])
        return [paper.line(f"{label}{self.prompt}"), options,
                paper.line("Answer (A, B, C or D): " + "." * 8 + f" [{marks}]")]

    def latex_sheet(self, question, index: int, marks: int, sheet) -> str:
        rich, tex = sheet.rich, sheet.tex
        prompt = "\\par\\vspace{4pt}" + tex(f"{question.label(index)}{self.prompt}") + "\n"
        box = r"Answer (A, B, C or D): \gridbox \partmarks{" + str(marks) + "}\\par"
        if self.sketches:
            body = prompt + sheet.sketch_row(self) + box
        else:
            options = "\n".join(f"\\item {rich(option.text)}" for option in self.options)
            body = (prompt + "\\begin{enumerate}[label=\\textbf{\\Alph*}, itemsep=1pt, topsep=4pt]\n"
                    + options + "\n\\end{enumerate}\n" + box)
        # the first is kept with its question's text (latex.question_sheet); a later one on its own page
        return "\\begin{keeptogether}" + body + "\\end{keeptogether}" if index else body

    def latex_key(self, question, index: int, marks: int, sheet) -> list[str]:
        rich, tex = sheet.rich, sheet.tex
        label = question.label(index) or "Answer "
        right = self.options[OPTION_LETTERS.index(self.answer)]
        wrong = [(letter, option) for letter, option in zip(OPTION_LETTERS, self.options, strict=True)
                 if letter != self.answer]
        return [f"\\textbf{{{tex(label)}{self.answer}: {rich(right.text)}}} \\hfill [{marks}]",
                "\\begin{itemize}[leftmargin=1.5em,itemsep=0pt,topsep=2pt]\n" + "\n".join(
                    f"\\item {letter} ({rich(option.text)}): \\emph{{{tex(option.mistake)}}} "
                    f"(\\textbf{{{tex(sheet.option_marks(question, index))}}}). {tex(option.feedback)}"
                    for letter, option in wrong) + "\n\\end{itemize}"]

    def html_sheet(self, question, index: int, marks: int, sheet) -> str:
        from ..figures.sketches import sketch_svg  # SVG text only: no matplotlib
        marks_html = sheet.marks_html
        items = "".join(f'<li><span class="sb-letter">{letter}</span> '
                        f"{sketch_svg(option.sketch) if option.sketch else _inline_html(option.text)}</li>"
                        for letter, option in zip(OPTION_LETTERS, self.options, strict=True))
        sketches = " sb-sketches" if self.sketches else ""
        return (f'<div class="sb-part"><p>{prompt_html(question.label(index) + self.prompt)}</p>'
                f'<ol class="sb-options{sketches}">{items}</ol><p class="sb-answer">Answer (A, B, C or D): '
                f'<span class="sb-box"></span> {marks_html(marks)}</p></div>')

    def html_key(self, question, index: int, marks: int, sheet) -> str:
        marks_html = sheet.marks_html
        label = question.label(index) or "Answer "
        right = self.options[OPTION_LETTERS.index(self.answer)]
        wrong = "".join(f"<li>{letter} ({_inline_html(option.text)}): <em>{prompt_html(option.mistake)}</em> "
                        f'(<strong class="sb-kept">{prompt_html(sheet.option_marks(question, index))}</strong>). '
                        f"{prompt_html(option.feedback)}</li>"
                        for letter, option in zip(OPTION_LETTERS, self.options, strict=True)
                        if letter != self.answer)
        return (f'<p class="sb-key-answer"><strong>{prompt_html(label)}{self.answer}: {_inline_html(right.text)}'
                f"</strong> {marks_html(marks)}</p><ul>{wrong}</ul>")

    def moodle(self, out, item, question, index: int) -> None:
        """A multichoice question, options A to D in the printed order, each wrong one with the
        feedback of its mistake; a sketch option is a small SVG file shown by an image."""
        shown, option_files = self._moodle_options(item.idnumber)
        options = [(text, letter == self.answer,
                    f"<p>{_escape(option.feedback)}</p>" if option.feedback
                    else f"<p>Right: {_escape(self.answer_text)}.</p>")
                   for letter, option, text in zip(OPTION_LETTERS, self.options, shown, strict=True)]
        out.multichoice(item.name, item.idnumber, item.stem + item.ask + "</p>", item.marks, item.general,
                        item.files, options, option_files=option_files)

    def _moodle_options(self, idnumber: str) -> tuple[list[str], list[dict[str, bytes]]]:
        """Each option's HTML, and its files: a sketch graph is a small SVG file shown by an <img>
        whose alt text is its shape in words (Moodle's HTML filter drops inline SVG)."""
        if not self.sketches:
            return [textformat.to_html(o.text, paragraphs=False) for o in self.options], []
        from ..figures.sketches import HEIGHT, WIDTH, sketch_svg  # SVG text only: no matplotlib

        texts, files = [], []
        for letter, option in zip(OPTION_LETTERS, self.options, strict=True):
            filename = f"{idnumber}-{letter}.svg"
            texts.append(f'<img src="@@PLUGINFILE@@/{filename}" alt="{html.escape(option.text)}" '
                         f'width="{WIDTH}" height="{HEIGHT}">')
            files.append({filename: sketch_svg(option.sketch).encode()})
        return texts, files


def _inline_html(source: str) -> str:
    """Text in the text format as HTML, in one paragraph's worth (no <p>)."""
    return textformat.to_html(source, paragraphs=False)


def _escape(text: str) -> str:
    return html.escape(text, quote=False)


def _option_html(option: Option) -> str:
    """An option's words, or its sketch as a small inline SVG named by its shape in words."""
    if option.sketch is None:
        return textformat.to_html(option.text, paragraphs=False)
    from ..figures.sketches import sketch_svg  # drawn only where a sketch is asked for

    return sketch_svg(option.sketch)


def choices_in_order(key: float, wrong: dict[str, tuple], *, sig_figs: int, unit: str, seed: int = 0
                     ) -> tuple[tuple[Option, ...], str]:
    """Options for a numerical multiple-choice part, in increasing order as Paper 1 prints them:
    the key and three named mistakes {name: (value, feedback)} worked from the same givens, or
    (value, feedback, see) for a mistake taught in another section than the part's.

    Given a pool of more than three mistakes (some above the key, some below), three are chosen
    so that the key's letter moves from variant to variant (issue 25, no give-aways): the letter
    comes from the key's printed value, never from random state, so a variant always prints the
    same options. ``seed`` is the template's own fixed number mixed into that choice: a template
    picks the one that spreads its variants' keys over the letters (tests/no_site/test_choice_letters.py
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
