
"""What every part kind shares: the constants of marking, the ids of parts, and the helpers
that write a number and a unit and refuse an impossible value."""

from __future__ import annotations

import re
from html import escape
from pathlib import Path
from typing import ClassVar

from .. import marking
from ..checks import require as _require  # noqa: F401 (the kinds and questions.py take it from here)
from ..notation import format_number, join_units

#: How a part treats direction: a size only, a signed value along a stated positive
#: direction, or a size plus a direction chosen from a list.
DIRECTION_MODES = ("none", "signed", "choice")
#: Cambridge 9702 accepts 2 or more significant figures unless a question says otherwise;
#: the key is trusted to 3 s.f., so an answer worked with intermediates rounded to 3 s.f.
#: still agrees with it (the rule table, marking_rules.json).
DEFAULT_MIN_SIG_FIGS = marking.rules()["sig_figs"]["min"]
DEFAULT_CHECK_SIG_FIGS = marking.rules()["sig_figs"]["check"]
MARK_CODES = ("C1", "M1", "A1", "B1", "")
#: What a part asks for. M1 (with its dependent A1) belongs only to the last three: a plain
#: calculation earns C1 for its steps and A1 for its answer.
ASKS = ("calculate", "show that", "explain", "state")
#: Rounding an intermediate value to these significant figures is "rounding part-way" (the rule table's).
PART_WAY_SIG_FIGS = tuple(marking.sig_figs()["part_way"])
#: The values of g students use instead of the data's 9.81 m s^-2.
G_TEN, G_NINE_EIGHT = 10.0, 9.8

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


#: A question's parts are (a), (b), ...; an ecf formula names earlier answers by these ids.
PART_IDS = tuple("abcdefghij")


def number(value: float, sig_figs: int) -> str:
    """A value as the book writes it, e.g. number(686.7, 3) -> "687" (notation.format_number)."""
    return format_number(value, sig_figs)


def unit_text(unit: str) -> str:
    """A unit for plain text: "m s^-1" -> "m s⁻¹"."""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


#: Where the product kinds' browser twins live (the questions extension's static folder).
SCRIPTS = Path(__file__).resolve().parents[2] / "book" / "_ext" / "questions" / "static" / "question-kinds"
#: Under the first unit box of a page: how to type units and powers, before any mistake.
UNIT_HINT = ("Type a unit with its symbols, a space between them and ^ for a power: N s, "
             "kg m s^-1 or kg m/s, m s^-2. Units are case-sensitive: kg, not Kg.")


def field_label(label: str, name: str) -> str:
    """A field's name: "(a) value" for part (a) of several, "Value" for a question of one part."""
    return f"{label.strip()} {name.lower()}" if label.strip() else name


def input_html(cls: str, ident: str, label: str, described_by: str) -> str:
    """A labelled text box of a part's form."""
    return (f'<label class="q-field" for="{ident}"><span>{label}</span>'
            f'<input class="{cls}" id="{ident}" type="text" autocomplete="off" autocapitalize="off" '
            f'spellcheck="false" aria-describedby="{described_by}"></label>')


def feedback_html(base: str) -> str:
    """Where the page writes a part's feedback and marks after Check (every kind's form has it)."""
    return f'<p class="q-feedback" id="{base}-feedback" role="status"></p><p class="q-part-marks"></p>'


def prompt_html(text: str) -> str:
    """A prompt or other plain text for a page or a sheet, a number never parted from its unit."""
    return escape(join_units(text), quote=False)


class PartKind:
    """The hooks every part kind provides (the plug-in API, parts/__init__.py): what the
    outside code asks a part instead of testing its kind's name. The defaults are those of a
    part that asks for no number; a kind overrides what differs."""

    #: The kind's name: the data-kind of its fieldset, and its key in KINDS and QuestionKinds.
    kind: ClassVar[str]
    #: Its answer is a number with a key value (a band, a unit, named mistakes, ecf).
    has_value: ClassVar[bool] = False
    #: Its value is read off the question's graph (the graph is printed and drawn for it).
    reads_graph: ClassVar[bool] = False
    #: Its answer is a letter in the sheet's multiple-choice grid.
    answer_grid: ClassVar[bool] = False
    #: As a question's first part, it prints on one page with the question's text and graph.
    keeps_with_question_text: ClassVar[bool] = False
    #: The student marks it by ticking its marking points (each line counts when ticked).
    self_marked: ClassVar[bool] = False
    #: Its answer is written in words (a define/state template may ask it with one wording).
    answered_in_words: ClassVar[bool] = False
    #: Its options are sketch graphs (a "which graph?" item shows the question's graph).
    sketches: ClassVar[bool] = False
    #: The mock test's paper that asks a template made only of such parts ("1", "2"), or "".
    mock_paper: ClassVar[str] = ""
    #: Its browser twin (a script that registers itself in QuestionKinds), a path the build
    #: copies and loads; several kinds may share one script.
    browser_script: ClassVar[str] = ""
    #: Other kinds whose browser twin this kind's calls (a page that asks it loads them too).
    uses_kinds: ClassVar[tuple[str, ...]] = ()
    #: Scripts and styles (paths under _static) that only the pages asking such a part load,
    #: after its browser_script: a sketch's drawing pad and its CSS.
    page_assets: ClassVar[tuple[str, ...]] = ()
    #: Its question may print a graph it is drawn from, though no part reads a value off it
    #: (a sketch of force X from a momentum-time graph, 9702/21/M/J/23 Q3(c)).
    drawn_from_graph: ClassVar[bool] = False


class NoValue(PartKind):
    """What a part that asks for no number (a choice, an explanation) answers when the marker,
    the sheets or Moodle ask it numeric questions: no value, no named mistakes of its own, no
    direction and nothing carried forward."""

    value: ClassVar[None] = None
    mistakes: ClassVar[tuple] = ()
    direction: ClassVar[str] = "none"
    ecf: ClassVar[None] = None
    ecf_methods: ClassVar[tuple] = ()
