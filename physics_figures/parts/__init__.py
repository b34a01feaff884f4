"""The part kinds, one module each, found through ``KINDS``: a new kind is its class here
(with its registry line) and its marker in book/_ext/questions/static/question-kinds/."""

from __future__ import annotations

from .choice import OPTION_LETTERS, ChoicePart, Option, Sketch, choices_in_order
from .diagram import Arrow, Body, Diagram
from .explain import ExplainPart
from .graph import Graph, GraphPart, format_reading, reading_places
from .numeric import Alternative, Ecf, Mistake, Part, Reading, Step
from .text import Note, TextPart, TextPoint

#: Every part kind by its name: the data-kind of a question's part and the kind the browser's
#: engine looks its marker up by.
KINDS = {kind.kind: kind for kind in (Part, GraphPart, ChoicePart, ExplainPart, TextPart)}

__all__ = ["KINDS", "OPTION_LETTERS", "Alternative", "Arrow", "Body", "ChoicePart", "Diagram", "Ecf", "ExplainPart",
           "Graph", "GraphPart", "Mistake", "Note", "Option", "Part", "Reading", "Sketch", "Step", "TextPart", "TextPoint",
           "choices_in_order",
           "format_reading", "reading_places"]
