"""A question as the teachers' sheet builder prints it, in HTML: the sheet's body (text,
graph, each part with its working space or answer lines and its marks as [n]) and the key's
body (per part the answer with its unit and what is accepted, the working, the ecf note and
the common wrong answers; then the mark-scheme lines with their codes).

The same information as the PDF sheets and keys (:mod:`.latex`, whose plain-text helpers
this module shares), so a sheet made in the browser (book/_ext/questions/sheet_builder.py)
says what a sheet made by the command line says. No number is worked out here: every one
comes from the question (physics_figures.questions), written by notation.format_number.
"""

from __future__ import annotations

from html import escape
from types import SimpleNamespace

from .. import textformat
from ..notation import join_units
from ..questions import Question
from . import latex
from .latex import LINES_PER_MARK, WORKING_CM_PER_MARK

__all__ = ["KEEP_CLASS", "LINES_PER_MARK", "MARKS_CLASS", "WORKING_CM_PER_MARK", "key_body", "marks_html", "plain",
           "rich", "sheet_body"]

#: What a sheet's [n] and a key's lines are marked up with, for the builder's stylesheet
#: (sheet-builder.css) and its tests.
MARKS_CLASS = "sb-marks"
#: What holds a choice question's text, graph and options, which print on one page (each part
#: is one block too: sheet-builder.css).
KEEP_CLASS = "sb-keep"


def plain(text: str) -> str:
    """Plain text (a prompt, a mistake's name) as HTML, numbers tied to their units."""
    return escape(join_units(text), quote=False)


def rich(source: str) -> str:
    """Text in the text format as HTML, in one paragraph's worth (no <p>)."""
    return textformat.to_html(source, paragraphs=False)


def marks_html(count: int) -> str:
    """A part's marks, [n], as a sheet and a key print them."""
    return f'<span class="{MARKS_CLASS}">[{count}]</span>'


def writer() -> SimpleNamespace:
    """What a part kind writes its HTML sheet and key with (its ``html_sheet`` and ``html_key``
    hooks, physics_figures/parts/__init__.py): the text helpers, the sizes, and the key helpers
    the LaTeX key shares (:mod:`.latex`)."""
    return SimpleNamespace(plain=plain, rich=rich, marks_html=marks_html, WORKING_CM_PER_MARK=WORKING_CM_PER_MARK,
                           LINES_PER_MARK=LINES_PER_MARK, accept_note=latex.accept_note, ecf_note=latex.ecf_note,
                           working_text=latex.working_text, wrong_answers=latex.wrong_answers,
                           option_marks=latex.option_marks)


def sheet_body(question: Question, graph_svg: str = "") -> str:
    """The question on the sheet: its text (class sb-text), its graph (inline SVG, drawn for
    these numbers), then each part with room to answer and its marks."""
    figure = f'<figure class="sb-graph">{graph_svg}</figure>' if graph_svg else ""
    parts = [part.html_sheet(question, index, marks, writer())
             for index, (part, marks) in enumerate(zip(question.parts, question.part_marks(), strict=True))]
    start = f'<div class="sb-text">{question.text_html()}</div>{figure}'
    if question.parts[0].keeps_with_question_text:  # e.g. a choice question's text, graph and options: one page
        return f'<div class="{KEEP_CLASS}">{start}{parts[0]}</div>{"".join(parts[1:])}'
    return start + "".join(parts)


def key_body(question: Question) -> str:
    """The question in the key: its text, each part's answer, then the mark scheme."""
    parts = "".join(part.html_key(question, index, marks, writer())
                    for index, (part, marks) in enumerate(zip(question.parts, question.part_marks(), strict=True)))
    return (f'<div class="sb-key-text">{question.text_html()}</div>{parts}'
            f'<p><strong>Mark scheme</strong></p><div class="sb-scheme">{question.mark_scheme_html()}</div>')
