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

from .. import textformat
from ..notation import join_units
from ..questions import OPTION_LETTERS, Question, unit_text
from .latex import (
    LINES_PER_MARK,
    WORKING_CM_PER_MARK,
    accept_note,
    ecf_note,
    option_marks,
    working_text,
    wrong_answers,
)

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


def _marks(count: int) -> str:
    return f'<span class="{MARKS_CLASS}">[{count}]</span>'


def _options(part) -> str:
    from ..figures.sketches import sketch_svg  # SVG text only: no matplotlib

    items = []
    for letter, option in zip(OPTION_LETTERS, part.options, strict=True):
        body = sketch_svg(option.sketch) if option.sketch else rich(option.text)
        items.append(f'<li><span class="sb-letter">{letter}</span> {body}</li>')
    sketches = " sb-sketches" if part.sketches else ""
    return f'<ol class="sb-options{sketches}">{"".join(items)}</ol>'


def _sheet_part(question: Question, index: int, marks: int) -> str:
    part, label = question.parts[index], question.label(index)
    prompt = plain(label + part.prompt)
    if part.kind == "mcq":
        return (f'<div class="sb-part"><p>{prompt}</p>{_options(part)}<p class="sb-answer">Answer (A, B, C or D): '
                f'<span class="sb-box"></span> {_marks(marks)}</p></div>')
    if part.kind in ("explain", "text"):
        lines = '<span class="sb-line"></span>' * (LINES_PER_MARK * marks)
        return (f'<div class="sb-part"><p>{prompt}</p><div class="sb-lines">{lines}</div>'
                f'<p class="sb-answer">{_marks(marks)}</p></div>')
    space = 0.6 if part.kind == "graph" else WORKING_CM_PER_MARK * marks  # as the PDF sheet
    unit = plain(unit_text(part.unit))
    direction = ('<p class="sb-answer">direction: <span class="sb-blank"></span></p>'
                 if part.direction == "choice" else "")
    return (f'<div class="sb-part"><div class="sb-working" style="height: {space:g}cm"></div>'
            f'<p class="sb-answer">{prompt} = <span class="sb-blank"></span> {unit} {_marks(marks)}</p>'
            f"{direction}</div>")


def sheet_body(question: Question, graph_svg: str = "") -> str:
    """The question on the sheet: its text (class sb-text), its graph (inline SVG, drawn for
    these numbers), then each part with room to answer and its marks."""
    figure = f'<figure class="sb-graph">{graph_svg}</figure>' if graph_svg else ""
    parts = [_sheet_part(question, index, marks) for index, marks in enumerate(question.part_marks())]
    start = f'<div class="sb-text">{question.text_html()}</div>{figure}'
    if question.parts[0].kind == "mcq":  # a choice question's text, graph and options print on one page
        return f'<div class="{KEEP_CLASS}">{start}{parts[0]}</div>{"".join(parts[1:])}'
    return start + "".join(parts)


def _key_part(question: Question, index: int, marks: int) -> str:
    part, label = question.parts[index], question.label(index) or "Answer "
    if part.kind == "mcq":
        right = part.options[OPTION_LETTERS.index(part.answer)]
        wrong = "".join(f"<li>{letter} ({rich(option.text)}): <em>{plain(option.mistake)}</em> "
                        f'(<strong class="sb-kept">{plain(option_marks(question, index))}</strong>). '
                        f"{plain(option.feedback)}</li>"
                        for letter, option in zip(OPTION_LETTERS, part.options, strict=True)
                        if letter != part.answer)
        return (f'<p class="sb-key-answer"><strong>{plain(label)}{part.answer}: {rich(right.text)}</strong> '
                f"{_marks(marks)}</p><ul>{wrong}</ul>")
    if part.kind in ("explain", "text"):
        rules = part.key_html() if part.kind == "text" else ""  # the wordings accepted and rejected
        return (f'<p class="sb-key-answer"><strong>{plain(question.label(index))}Model answer</strong> '
                f"{_marks(marks)}</p><p>{rich(part.model_answer)}</p>{rules}")
    out = [(f'<p class="sb-key-answer"><strong>{plain(label + part.prompt)} = {plain(part.answer_text)}</strong>'
           f"{plain(accept_note(part))} {_marks(marks)}</p>")]
    if part.working:
        out.append(f"<p>{plain(working_text(part))}</p>")
    note = ecf_note(question, index)
    if note:
        out.append(f"<p><em>{plain(note)}</em></p>")
    rows = wrong_answers(question, index)
    if rows:
        items = "".join(f"<li><strong>{plain(row.written)}</strong>: <em>{plain(row.name)}</em> "
                        f'(<strong class="sb-kept">{plain(row.marks)}</strong>). {plain(row.feedback)}</li>'
                        for row in rows)
        out.append("<p><strong>Common wrong answers</strong> (the mistake each shows, and what it scores)</p>"
                   f'<ul class="sb-wrong">{items}</ul>')
    return "".join(out)


def key_body(question: Question) -> str:
    """The question in the key: its text, each part's answer, then the mark scheme."""
    parts = "".join(_key_part(question, index, marks) for index, marks in enumerate(question.part_marks()))
    return (f'<div class="sb-key-text">{question.text_html()}</div>{parts}'
            f'<p><strong>Mark scheme</strong></p><div class="sb-scheme">{question.mark_scheme_html()}</div>')
