"""The part kinds, one module each, found through ``KINDS``; each kind has one browser twin
(book/_ext/questions/static/question-kinds/, registered in ``QuestionKinds``: see
book/_ext/questions/static/question-kinds.js). No code outside a kind's two modules and the two
registries branches on a kind's name: it asks the part (tests/no_site/test_kind_plugins.py checks).

A kind registers itself: ``register_kind(MyPart)`` when its module is imported (a topic's bank
that uses it imports it; the build then loads its browser twin, ``browser_script``).

What a kind's Python class provides (physics_figures.parts.common.PartKind has the defaults):

* ``kind``: its name (the data-kind of its fieldset, its key here and in QuestionKinds).
* Properties the outside code asks instead of the name (class attributes or properties):
  ``has_value`` (a number with a key value: bands, units, named mistakes, ecf),
  ``reads_graph`` (read off the question's graph), ``answer_grid`` (a letter in the sheet's
  multiple-choice grid), ``keeps_with_question_text`` (as a first part, printed on one page with
  the question's text), ``self_marked`` (its lines count when the student ticks them; a
  dependent A1 needs its M1), ``answered_in_words`` (a define/state template may ask it with one
  wording), ``sketches`` (its options are sketch graphs: the question shows its graph),
  ``mock_paper`` ("1", "2" or "": the mock test's paper that asks templates made of it),
  ``browser_script`` (the path of its JS twin; kinds may share one), ``uses_kinds`` (kinds whose
  twin its own calls: a page asking it loads them too), ``page_assets`` (scripts
  and styles under _static that only the pages asking such a part load), ``drawn_from_graph``
  (its question may print a graph that no part reads a value off: a sketch drawn from it).
* The part's data for the page, ``answer_text`` (plain text of its answer) and ``marks``-related
  attributes the bank's templates set (``prompt``, ``asks``, ``revisit``...).
* ``browser_data(part_id) -> dict``: what the page and its JS twin get (JSON-ready; has "id" and "kind").
* ``form_html(part: dict, question: dict, *, base, label, page) -> str`` (a classmethod: it gets
  the browser data): the part's form on the page, between its legend and the fieldset's end,
  ending with ``common.feedback_html(base)`` (and anything after the feedback). ``base`` is the
  prefix of its ids ("q-<question>-<part>"), ``label`` "(a) " or "", ``page`` a dict of
  once-a-page flags that the kinds share.
* ``print_lines(label, marks, paper) -> list`` of docutils nodes: the part in print (the PDF
  book, and the page without JavaScript), built with ``paper`` (book/_ext/questions/directive.py
  ``Paper``: ``line(text, **attributes)``, ``options(items)``, ``rich(text)``, ``sketch(sketch)``).
* ``latex_sheet(question, index, marks, sheet) -> str`` and ``latex_key(question, index, marks,
  sheet) -> list[str]``: the part on the LaTeX question sheet and in its key (paragraphs);
  ``html_sheet(question, index, marks, sheet) -> str`` and ``html_key(question, index, marks,
  sheet) -> str``: the same in the sheet builder's HTML. ``sheet`` holds the writer's helpers
  (a kind never imports the worksheets, a layer above it): physics_figures.worksheets.latex
  ``writer()`` (``tex``, ``rich``, ``WORKING_CM_PER_MARK``, ``LINES_PER_MARK``, ``sketch_row``,
  ``accept_note``, ``ecf_note``, ``working_text``, ``wrong_answers``, ``option_marks``) and
  .html ``writer()`` (``plain``, ``rich``, ``marks_html``, and the same sizes and key helpers).
* ``moodle(out, item, question, index)``: the part in the Moodle export, by one of ``out``'s
  question types (``numerical``, ``cloze``, ``multichoice``, ``essay``:
  physics_figures.worksheets.moodle) from ``item`` (``MoodleItem``: its name, idnumber, stem,
  ask, marks, general feedback, files, the mark scheme's HTML ``scheme`` and the ecf note
  ``how_marked``).
"""

from __future__ import annotations

from ..pictures import Arrow, Body, Diagram, Graph  # what a question prints: data the figures draw
from .choice import OPTION_LETTERS, ChoicePart, Option, Sketch, choices_in_order
from .common import PartKind
from .explain import ExplainPart
from .graph import GraphPart, format_reading, reading_places
from .numeric import Alternative, Ecf, Mistake, Part, Reading, Step
from .sketch import Feature, SketchAxes, SketchPart, SketchPoint, SketchTolerance, WrongSketch
from .text import Note, TextPart, TextPoint

#: Every part kind by its name: the data-kind of a question's part and the kind the browser's
#: engine looks its marker up by.
KINDS: dict[str, type[PartKind]] = {}


def register_kind(cls: type[PartKind]) -> type[PartKind]:
    """Add a part kind (its class) to KINDS, by its name; usable as a class decorator. A name
    taken by another class is refused."""
    name = getattr(cls, "kind", "")
    if not isinstance(name, str) or not name:
        raise ValueError(f"kind must name the part kind (got kind={name!r} on {cls.__name__})")
    if KINDS.get(name, cls) is not cls:
        raise ValueError(f"kind {name!r} is taken by {KINDS[name].__name__} (got kind={name!r} on {cls.__name__})")
    KINDS[name] = cls
    return cls


for _kind in (Part, GraphPart, ChoicePart, ExplainPart, SketchPart, TextPart):
    register_kind(_kind)

__all__ = [
    "KINDS",
    "OPTION_LETTERS",
    "Alternative",
    "Arrow",
    "Body",
    "ChoicePart",
    "Diagram",
    "Ecf",
    "ExplainPart",
    "Feature",
    "Graph",
    "GraphPart",
    "Mistake",
    "Note",
    "Option",
    "Part",
    "PartKind",
    "Reading",
    "Sketch",
    "SketchAxes",
    "SketchPart",
    "SketchPoint",
    "SketchTolerance",
    "Step",
    "TextPart",
    "TextPoint",
    "WrongSketch",
    "choices_in_order",
    "format_reading",
    "reading_places",
    "register_kind",
]
