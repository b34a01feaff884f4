
"""The describe-and-explain part kind, self-marked against its marking points. Its browser
twin is book/_ext/questions/static/question-kinds/explain.js."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from .. import textformat
from .common import NoValue, _require
from .text import TextPoint, point_needs


@dataclass(frozen=True)
class ExplainPart(NoValue):
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

