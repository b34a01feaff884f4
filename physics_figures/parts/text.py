# ruff: noqa: RUF002  (the rules name the symbols students type: times, delta)
"""The text part kind: a define or state part marked from the typed words, by rules that are data
(CLARIFICATIONS, Papers: "rules as data, in the template, readable by a teacher in the key").
Its browser twin, the marker, is book/_ext/questions/static/question-kinds/text.js.

A part has marking points (``TextPoint``), one a mark line: its code (B1, or M1 with a dependent
A1), the wordings an examiner accepts, the wordings the schemes reject with why, and the
published 9702 scheme each note comes from.

The rule syntax of a wording, as a teacher reads it in the key:
- words separated by spaces, each a term that must be in the answer, in any order, together in
  one clause ("total momentum constant");
- ``a|b``: either word ("constant|conserved"); the key prints it "constant / conserved";
- ``(word)``: optional, printed as the scheme prints it and not needed ("(resultant) force");
- ``a_b``: words that come together, in this order ("speed_of_approach").
Case, punctuation, the stop words (the, of, is, ...) and symbols the marker knows ("×", "=",
"Δp/Δt", "p = mv") need no spelling out.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from html import escape
from typing import ClassVar

from .. import textformat
from .common import SCRIPTS, NoValue, _require, feedback_html, prompt_html

#: The codes a text point carries: an independent B1, or an M1 and the A1 that depends on it.
TEXT_CODES = ("B1", "M1", "A1")


def _check_wording(name: str, wording: str) -> None:
    _require(bool(wording.strip()) and wording.count("(") == wording.count(")"), name, wording,
             "must be words with balanced (optional) parts")
    _require(bool(re.sub(r"\([^()]*\)", " ", wording).strip()), name, wording,
             "must have at least one word outside its (optional) parts")


def print_wording(wording: str) -> str:
    """A wording as the key prints it: "constant|conserved" -> "constant / conserved",
    "speed_of_approach" -> "speed of approach"."""
    return wording.replace("|", " / ").replace("_", " ")


class WrittenInWords(NoValue):
    """A part answered in words (a text part, an explain part): on the printed page, dotted lines
    or a sheet's writing lines to write on, the marks after the last."""

    def print_lines(self, label: str, marks: int, paper) -> list:
        """Dotted lines to write on, the marks after the last."""
        return [paper.line(f"{label}{self.prompt}")] + [
            paper.line("." * 70 + (f" [{marks}]" if last else "")) for last in (False, False, False, True)]

    def latex_sheet(self, question, index: int, marks: int, sheet) -> str:
        tex = sheet.tex
        return (f"\\par\\vspace{{4pt}}\\needspace{{4\\baselineskip}}{tex(question.label(index) + self.prompt)}"
                f"\\writinglines{{{sheet.LINES_PER_MARK * marks}}}\\vspace{{2pt}}\\partmarks{{{marks}}}\\par")


@dataclass(frozen=True)
class Note:
    """A scheme's note on a wording it does not credit: the wording (the rule syntax), why, and
    the published paper the note is from. ``contradicts``: the wording loses the point even
    beside an accepted one (the schemes' "a contradiction loses the mark"); otherwise it only
    earns nothing, and the feedback says why."""

    wording: str
    why: str
    source: str
    contradicts: bool = False

    def __post_init__(self):
        _check_wording("wording", self.wording)
        _require(bool(self.why.strip()), "why", self.why, "must say why the scheme does not credit it")
        _require(bool(self.source.strip()), "source", self.source, "must cite the paper the note is from")


@dataclass(frozen=True)
class TextPoint:
    """One marking point (one mark line): what the key prints (``text``), its code, the wordings
    an examiner accepts, those the schemes reject (``Note``), what the schemes ignore (printed in
    the key, no effect on the mark), and the scheme the point follows (``source``). An A1
    depends on the M1 before it in the part (``TextPart`` sets it)."""

    text: str
    code: str
    accept: tuple[str, ...]
    source: str
    reject: tuple[Note, ...] = ()
    ignore: tuple[str, ...] = ()

    def __post_init__(self):
        _require(self.code in TEXT_CODES, "code", self.code, f"must be one of {TEXT_CODES}")
        _require(bool(self.accept), "accept", self.accept, "must list at least one accepted wording")
        for wording in self.accept:
            _check_wording("accept", wording)
        _require(bool(self.source.strip()), "source", self.source, "must cite the scheme the point follows")
        textformat.parse(self.text)

    def data(self, needs: int | None) -> dict:
        # the page shows the point's words (text.py form_html, text.js): a value keeps its unit
        return {"text": textformat.to_plain(self.text, joined=True), "code": self.code, "needs": needs,
                "accept": list(self.accept), "source": self.source,
                "reject": [{"wording": n.wording, "why": n.why, "source": n.source, "contradicts": n.contradicts}
                           for n in self.reject]}


def point_needs(points: tuple[TextPoint, ...], index: int) -> int | None:
    """The point an A1 depends on: the last M1 before it (9702's M1 A1); None for the rest."""
    if points[index].code != "A1":
        return None
    return max(i for i in range(index) if points[i].code == "M1")


@dataclass(frozen=True)
class TextPart(WrittenInWords):
    """A define or state part, marked from the typed words by its points' rules."""

    prompt: str
    model_answer: str
    points: tuple[TextPoint, ...]
    kind: ClassVar[str] = "text"
    asks: ClassVar[str] = "state"
    revisit: ClassVar[str] = ""
    #: Its lines count when ticked: by the marker (the points it finds), or by the student where
    #: the marker could not decide (text.js; a dependent A1 needs its M1).
    self_marked: ClassVar[bool] = True
    answered_in_words: ClassVar[bool] = True
    browser_script: ClassVar[str] = str(SCRIPTS / "text.js")

    def __post_init__(self):
        textformat.parse(self.model_answer)
        _require(bool(self.points), "points", self.points, "must list at least one marking point")
        for index, point in enumerate(self.points):
            _require(point.code != "A1" or any(p.code == "M1" for p in self.points[:index]), "points",
                     point.text, "an A1 must follow the M1 it depends on (9702's M1 A1)")

    def needs(self, index: int) -> int | None:
        return point_needs(self.points, index)

    @property
    def answer_text(self) -> str:
        return textformat.to_plain(self.model_answer)

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt,
                "model": textformat.to_html(self.model_answer),
                "points": [p.data(self.needs(i)) for i, p in enumerate(self.points)]}

    def key_html(self) -> str:
        """The rules as the HTML key and Moodle's grader information print them: per point, the
        wordings accepted, those rejected (why, and the paper), those ignored."""
        out, words = [], {"accept": "Accept", "reject": "Reject", "ignore": "Ignore"}
        for kind, text in self.key_lines():
            if kind == "point":
                out.append(("</ul>" if out else "") + f"<p><strong>{escape(text)}</strong></p><ul>")
            else:
                out.append(f"<li>{words[kind]}: {escape(text)}</li>")
        return "".join(out) + "</ul>"

    def key_lines(self) -> list[tuple[str, str]]:
        """What the key prints under each point: ("accept", "…"), ("reject", "… (why; paper)"),
        ("ignore", "…"), in plain text (the sheets and Moodle write it each their way)."""
        lines = []
        for point in self.points:
            lines.append(("point", f"{textformat.to_plain(point.text)} {point.code} ({point.source})"))
            lines.append(("accept", "; ".join(f"“{print_wording(w)}”" for w in point.accept)))
            lines.extend(("reject", f"“{print_wording(n.wording)}”: {n.why} ({n.source})") for n in point.reject)
            lines.extend(("ignore", note) for note in point.ignore)
        return lines

    # ------------------------------------------------------- the kind's hooks (parts/__init__.py)

    @classmethod
    def form_html(cls, part: dict, question: dict, *, base: str, label: str, page: dict) -> str:
        """The one textarea for the student's words; after Check, each marking point with what the
        marker found (text.js, show), a box to tick only where it could not decide. A tick's value
        is its line's index in the question's marks, as an explain part's."""
        lines = [i for i, mark in enumerate(question["marks"]) if mark["part"] == part["id"]]
        points = "".join(
            f'<label class="q-point"><input type="checkbox" class="q-tick" value="{line}" disabled> '
            f'<span class="q-point-text">{escape(point["text"])}</span> <strong>{point["code"]}</strong></label>'
            for line, point in zip(lines, part["points"], strict=True))
        return (f'<label class="q-field q-field-wide" for="{base}-text"><span>Your answer</span>'
                f'<textarea class="q-explain" id="{base}-text" rows="4" aria-describedby="{base}-feedback">'
                f'</textarea></label>'
                f'<div class="q-points" hidden><p>The marking points (tick one only where the marker could not '
                f'decide and your answer makes it):</p>{points}'
                f'<div class="q-model"><p><strong>A full answer:</strong></p>'
                f'<div class="q-model-text">{part["model"]}</div></div></div>' + feedback_html(base))

    def latex_key(self, question, index: int, marks: int, sheet) -> list[str]:
        """The model answer, then per point what an examiner accepts, rejects (why, the paper) and ignores."""
        rich, tex = sheet.rich, sheet.tex
        words = {"accept": "Accept", "reject": "Reject", "ignore": "Ignore"}
        items = [f"\\item[] \\textbf{{{tex(text)}}}" if kind == "point" else f"\\item {words[kind]}: {tex(text)}"
                 for kind, text in self.key_lines()]
        return [(f"\\textbf{{{tex(question.label(index))}Model answer}} \\hfill [{marks}]\\par "
                 f"{rich(self.model_answer)}"),
                "\\begin{itemize}[leftmargin=1.5em,itemsep=0pt,topsep=2pt]\n" + "\n".join(items) + "\n\\end{itemize}"]

    def html_sheet(self, question, index: int, marks: int, sheet) -> str:
        lines = '<span class="sb-line"></span>' * (sheet.LINES_PER_MARK * marks)
        return (f'<div class="sb-part"><p>{prompt_html(question.label(index) + self.prompt)}</p>'
                f'<div class="sb-lines">{lines}</div><p class="sb-answer">{sheet.marks_html(marks)}</p></div>')

    def html_key(self, question, index: int, marks: int, sheet) -> str:
        return (f'<p class="sb-key-answer"><strong>{prompt_html(question.label(index))}Model answer</strong> '
                f"{sheet.marks_html(marks)}</p><p>{textformat.to_html(self.model_answer, paragraphs=False)}</p>"
                + self.key_html())

    def moodle(self, out, item, question, index: int) -> None:
        """An essay (Moodle has no core type that reads the words: CLARIFICATIONS, Papers), with the
        model answer, the mark scheme and the points' accepted and rejected wordings for the grader."""
        grader = (f"<p><strong>Model answer</strong></p>{textformat.to_html(self.model_answer)}" + item.scheme
                  + "<p><strong>The marking points</strong></p>" + self.key_html() + item.how_marked)
        out.essay(item.name, item.idnumber, item.stem + item.ask + f" [{item.marks}]</p>", item.marks, item.general,
                  item.files, grader)
