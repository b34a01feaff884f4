
"""The describe-and-explain part kind, self-marked against its marking points. Its browser
twin is book/_ext/questions/static/question-kinds/explain.js."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from .. import textformat
from .common import SCRIPTS, _require, feedback_html, prompt_html
from .text import TextPoint, WrittenInWords, point_needs


@dataclass(frozen=True)
class ExplainPart(WrittenInWords):
    """A describe-and-explain part. The student writes an answer, then ticks the marking points
    of its mark-scheme lines that they made, and scores themselves against them. points: the rules
    of the text kind for its lines, in their order (optional): the marker finds the points the words
    make, and the page ticks them for the student to confirm (issue 38)."""

    prompt: str
    model_answer: str
    points: tuple[TextPoint, ...] = ()
    kind: ClassVar[str] = "explain"
    asks: ClassVar[str] = "explain"
    revisit: ClassVar[str] = ""
    self_marked: ClassVar[bool] = True
    answered_in_words: ClassVar[bool] = True
    browser_script: ClassVar[str] = str(SCRIPTS / "explain.js")
    uses_kinds: ClassVar[tuple[str, ...]] = ("text",)  # its points' pre-ticks are the text marker's

    def __post_init__(self):
        textformat.parse(self.model_answer)
        for index, point in enumerate(self.points):
            _require(point.code != "A1" or any(p.code == "M1" for p in self.points[:index]), "points",
                     point.text, "an A1 must follow the M1 it depends on (9702's M1 A1)")

    @property
    def answer_text(self) -> str:
        return textformat.to_plain(self.model_answer)

    def browser_data(self, part_id: str) -> dict:
        data = {"id": part_id, "kind": self.kind, "prompt": self.prompt,
                "model": textformat.to_html(self.model_answer)}
        if self.points:
            data["points"] = [p.data(point_needs(self.points, i)) for i, p in enumerate(self.points)]
        return data

    # ------------------------------------------------------- the kind's hooks (parts/__init__.py)

    @classmethod
    def form_html(cls, part: dict, question: dict, *, base: str, label: str, page: dict) -> str:
        """A box for the student's own words; after Check, the marking points to tick."""
        points = "".join(
            f'<label class="q-point"><input type="checkbox" class="q-tick" value="{i}"> '
            f'<span class="q-point-text">{mark["html"]}</span> <strong>{mark["code"]}</strong></label>'
            for i, mark in enumerate(question["marks"]) if mark["part"] == part["id"])
        return (f'<label class="q-field q-field-wide" for="{base}-text"><span>Your answer</span>'
                f'<textarea class="q-explain" id="{base}-text" rows="4" aria-describedby="{base}-feedback">'
                f'</textarea></label>'
                f'<div class="q-points" hidden><p>Tick each marking point your answer makes:</p>{points}'
                f'<div class="q-model"><p><strong>A full answer:</strong></p>'
                f'<div class="q-model-text">{part["model"]}</div></div></div>' + feedback_html(base))

    def latex_key(self, question, index: int, marks: int, sheet) -> list[str]:
        rich, tex = sheet.rich, sheet.tex
        # "Model answer", not "Answer Model answer", for a part alone
        return [(f"\\textbf{{{tex(question.label(index))}Model answer}} \\hfill [{marks}]\\par "
                 f"{rich(self.model_answer)}")]

    def html_sheet(self, question, index: int, marks: int, sheet) -> str:
        marks_html = sheet.marks_html
        lines = '<span class="sb-line"></span>' * (sheet.LINES_PER_MARK * marks)
        return (f'<div class="sb-part"><p>{prompt_html(question.label(index) + self.prompt)}</p>'
                f'<div class="sb-lines">{lines}</div><p class="sb-answer">{marks_html(marks)}</p></div>')

    def html_key(self, question, index: int, marks: int, sheet) -> str:
        marks_html = sheet.marks_html
        return (f'<p class="sb-key-answer"><strong>{prompt_html(question.label(index))}Model answer</strong> '
                f"{marks_html(marks)}</p><p>{textformat.to_html(self.model_answer, paragraphs=False)}</p>")

    def moodle(self, out, item, question, index: int) -> None:
        """An essay, with the model answer and the marking points for the grader."""
        grader = (f"<p><strong>Model answer</strong></p>{textformat.to_html(self.model_answer)}"
                  + item.scheme + item.how_marked)
        out.essay(item.name, item.idnumber, item.stem + item.ask + f" [{item.marks}]</p>", item.marks, item.general,
                  item.files, grader)
