
"""The describe-and-explain part kind, self-marked against its marking points. Its browser
twin is book/_ext/questions/static/question-kinds/explain.js."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from .. import textformat
from .common import NoValue


@dataclass(frozen=True)
class ExplainPart(NoValue):
    """A describe-and-explain part. The student writes an answer, then ticks the marking points
    of its mark-scheme lines that they made, and scores themselves against them."""

    prompt: str
    model_answer: str
    kind: ClassVar[str] = "explain"
    asks: ClassVar[str] = "explain"
    revisit: ClassVar[str] = ""

    def __post_init__(self):
        textformat.parse(self.model_answer)

    @property
    def answer_text(self) -> str:
        return textformat.to_plain(self.model_answer)

    def browser_data(self, part_id: str) -> dict:
        return {"id": part_id, "kind": self.kind, "prompt": self.prompt,
                "model": textformat.to_html(self.model_answer)}

