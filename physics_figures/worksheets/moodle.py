
"""The question bank as Moodle XML, for a school's learning platform.

One question category per type (the notes' seven), and inside it one category per
template and part, so a quiz can draw "a random question from this category": every
variant of the template (at least 10; a template with fewer situations gives all of them).

Moodle grades as the book grades wherever its core question types can: the same rule table
(physics_figures/marking_rules.json) and the same mark lines of each part.

* A numeric part (or a reading from a graph) is a **numerical** question. A right answer is
  one 100 % answer per written form the book accepts: the key at 2 s.f. (that value only)
  and at 3 s.f. (half a unit in its 3rd figure), the key as it prints first, so Moodle shows
  it as the key does; a reading from a graph is right within half a small square. Then, each
  with the grade of the lines it keeps: the named mistakes, the g = 9.8 slip, the part-way
  roundings, the sign slip and the key to 1 s.f. A missing or wrong unit costs what it costs
  in the book (Moodle's unit grading), and a unit may be typed in each prefix and spelling the
  book's unit reader accepts (cm s^-2, m/s², kN, g, newtons), each with its multiplier and
  without spaces (moodle_units). No answer lies inside the range of one before it (moodle_answers).
* A part that asks for a direction is one **Cloze** (multianswer) question: a NUMERICAL box
  for the size and a MULTICHOICE box for the direction, weighted as the part's lines split
  (the direction's own B1, or the A1 that carries the direction). A minus sign on the size
  is ignored, as the schemes do.
* A multiple-choice item is a **multichoice** question, options A to D in the printed
  order, each wrong option with the feedback of the mistake it stands for. A "which graph?"
  item's options are its sketch graphs, each a small SVG file inside its answer, shown by an
  image whose alt text is the shape in words.
* A describe-and-explain part is an **essay** question, with the model answer and the
  marking points (with their codes) as information for the grader.
* A multi-part question becomes one question per part, each with the question's text. How a
  part is marked by error carried forward (Moodle cannot carry an answer from one question to
  another) is for the teacher: it is in the general feedback (and an essay's grader
  information), never in the question text, where it would give the method away.

Graphs are drawn for each variant and embedded as PNG images (``@@PLUGINFILE@@``). Text is the
bank's text format as HTML, in CDATA (Moodle drops the space before each tag of escaped HTML).
"""

from __future__ import annotations

import argparse
import base64
import html
import io
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import NamedTuple

import numpy

from .. import marking, topics
from ..cores import on_every_core
from ..notation import format_number, plain_number
from ..questions import KINDS, Question, unit_text
from ..topics import Topic
from ..variants import Template
from . import DEFAULT_TOPIC, bank_templates, part_marks, topic_of
from .latex import ecf_note
from .moodle_answers import EXACT, MOODLE_GRADES, RIGHT_SIG_FIGS, grade, graded_answers, right_forms
from .moodle_units import forms as unit_forms

__all__ = ["EXACT", "MOODLE_GRADES", "MOODLE_MIN_VARIANTS", "RIGHT_SIG_FIGS", "export", "grade", "graded_answers",
           "right_forms", "root_category", "to_xml", "unit_forms", "variant_indices", "write"]

#: Moodle's question bank is filled with this many variants of a template at least.
MOODLE_MIN_VARIANTS = 10


def root_category(topic: Topic | None = None) -> str:
    """The topic's category in Moodle's question bank: "$course$/top/Dynamics (9702)"."""
    return f"$course$/top/{topic_of(topic).name} (9702)"

#: The resolution of the graphs' images (a 5.6 in wide graph is 728 pixels).
GRAPH_DPI = 130


def _number(value: float) -> str:
    """A value for Moodle: plain digits, 15 significant figures (a band's ends exactly), no grouping."""
    return format(value, ".15g")


def _text(parent: ET.Element, tag: str, html: str, *, fmt: str = "html") -> ET.Element:
    element = ET.SubElement(parent, tag, {"format": fmt} if fmt else {})
    ET.SubElement(element, "text").text = html
    return element


def _plain(parent: ET.Element, tag: str, text: str) -> ET.Element:
    element = ET.SubElement(parent, tag)
    element.text = text
    return element


class _Export:
    def __init__(self):
        self.quiz = ET.Element("quiz")
        self.count: dict[str, int] = {}

    def category(self, path: str, info: str = "") -> None:
        question = ET.SubElement(self.quiz, "question", {"type": "category"})
        category = ET.SubElement(question, "category")
        ET.SubElement(category, "text").text = path
        if info:
            _text(question, "info", info)

    def _question(self, kind: str, name: str, idnumber: str, html: str, marks: int,
                  general: str, files: dict[str, bytes]) -> ET.Element:
        self.count[kind] = self.count.get(kind, 0) + 1
        question = ET.SubElement(self.quiz, "question", {"type": kind})
        ET.SubElement(ET.SubElement(question, "name"), "text").text = name
        text = _text(question, "questiontext", html)
        for filename, data in files.items():
            file = ET.SubElement(text, "file", {"name": filename, "path": "/", "encoding": "base64"})
            file.text = base64.b64encode(data).decode("ascii")
        _text(question, "generalfeedback", general)
        _plain(question, "defaultgrade", str(marks))
        _plain(question, "penalty", "0.3333333" if kind != "essay" else "0")
        _plain(question, "hidden", "0")
        _plain(question, "idnumber", idnumber)
        return question

    def numerical(self, name, idnumber, html, marks, general, files, question: Question, index: int) -> None:
        part = question.parts[index]
        lines = question.part_lines(question.part_ids[index])
        element = self._question("numerical", name, idnumber, html, marks, general, files)
        printed = plain_number(format_number(part.value, part.shown_sig_figs))
        for points, value, width, feedback in graded_answers(question, index):
            # the key as it prints ("-1.0", not "-1"): Moodle shows it as the right answer
            text = printed if float(printed) == value else _number(value)
            self._answer(element, points, value, width, f"<p>{_escape(feedback)}</p>", text=text)
        if not part.unit:  # a ratio: a pure number, with no unit to type or to grade
            _plain(element, "unitgradingtype", "0")
            _plain(element, "unitpenalty", "0")
            _plain(element, "showunits", "3")  # Moodle's "no units" (qtype_numerical::UNITNONE)
            _plain(element, "unitsleft", "0")
            return
        units = ET.SubElement(element, "units")
        # every prefix and spelling the book's unit reader accepts, without spaces (moodle_units)
        for _typed, form, multiplier in unit_forms(part.unit, part.units):
            unit = ET.SubElement(units, "unit")
            _plain(unit, "multiplier", format(multiplier, ".12g"))
            _plain(unit, "unit_name", form)
        # a missing or wrong unit loses what the rule table says (the A1; on a one-mark part, all)
        kept = marking.lines_kept(lines, marking.outcome_losses()["missing-unit"])
        _plain(element, "unitgradingtype", "1")
        _plain(element, "unitpenalty", _number(1 - kept / len(lines)))
        _plain(element, "showunits", "0")  # the unit is typed after the number
        _plain(element, "unitsleft", "0")

    def cloze(self, name, idnumber, html, marks, general, files, question: Question, index: int) -> None:
        """A size and a direction in one question: a NUMERICAL box weighted by the part's
        lines that are not the direction's, a MULTICHOICE box by those that are."""
        part = question.parts[index]
        lines = question.part_lines(question.part_ids[index])
        size_lines = [line for line in lines if "direction" not in line[1]]
        way_lines = [line for line in lines if "direction" in line[1]]
        if not size_lines or not way_lines:
            raise ValueError(f"{question.key} ({question.part_ids[index]}): a direction part needs a line "
                             f"for the size and one for the direction (got {lines})")
        answers = graded_answers(question, index, direction_box=len(way_lines))
        # "ignore sign": the size with a minus sign is right too, the direction asked apart
        right = right_forms(question, index)
        answers[len(right):len(right)] = [
            (100.0, -value, width, "Right: the minus sign is ignored, as the direction is given separately.")
            for value, width in right]
        size = "~".join(f"{'=' if points == 100 else f'%{_number(points)}%'}{_decimal(value)}:{_decimal(width)}"
                        f"#{_cloze_escape(feedback)}" for points, value, width, feedback in answers)
        wrong = {m.direction: m.feedback for m in part.mistakes if m.direction}
        way = "~".join(f"{'=' if choice == part.answer_direction else ''}{_cloze_escape(choice)}"
                       f"#{_cloze_escape(wrong.get(choice) or part.direction_hint or part.revisit)}"
                       for choice in part.choices)
        boxes = (f"<p>Size: {{{len(size_lines)}:NUMERICAL:{size}}} {_escape(unit_text(part.unit))} "
                 f"Direction: {{{len(way_lines)}:MULTICHOICE:{way}}}</p>")
        self._question("cloze", name, idnumber, html + boxes, marks, general, files)

    @staticmethod
    def _answer(question, fraction: float, value: float, width: float, feedback: str, *, text: str = "") -> None:
        answer = ET.SubElement(question, "answer", {"fraction": _number(fraction), "format": "moodle_auto_format"})
        _plain(answer, "text", text or _number(value))
        _plain(answer, "tolerance", _number(width))
        _text(answer, "feedback", feedback)

    def multichoice(self, name, idnumber, html, marks, general, files,
                    options: list[tuple[str, bool, str]], *, numbering: str = "ABCD",
                    option_files: list[dict[str, bytes]] | None = None) -> None:
        question = self._question("multichoice", name, idnumber, html, marks, general, files)
        _plain(question, "single", "true")
        _plain(question, "shuffleanswers", "false")
        _plain(question, "answernumbering", numbering)
        _plain(question, "showstandardinstruction", "0")
        _text(question, "correctfeedback", "<p>Your answer is correct.</p>")
        _text(question, "partiallycorrectfeedback", "<p>Your answer is partially correct.</p>")
        _text(question, "incorrectfeedback", "<p>Your answer is incorrect.</p>")
        for index, (html_option, right, feedback) in enumerate(options):
            answer = ET.SubElement(question, "answer", {"fraction": "100" if right else "0", "format": "html"})
            ET.SubElement(answer, "text").text = html_option
            # an answer's own files sit inside <answer> (qformat_xml: import_answer with files)
            for filename, data in (option_files[index] if option_files else {}).items():
                file = ET.SubElement(answer, "file", {"name": filename, "path": "/", "encoding": "base64"})
                file.text = base64.b64encode(data).decode("ascii")
            _text(answer, "feedback", feedback)

    def essay(self, name, idnumber, html, marks, general, files, grader: str) -> None:
        question = self._question("essay", name, idnumber, html, marks, general, files)
        _plain(question, "responseformat", "editor")
        _plain(question, "responserequired", "1")
        _plain(question, "responsefieldlines", str(5 + 3 * marks))
        _plain(question, "attachments", "0")
        _plain(question, "attachmentsrequired", "0")
        _text(question, "graderinfo", grader)
        _text(question, "responsetemplate", "")


def _escape(text: str) -> str:
    return html.escape(text, quote=False)


class MoodleItem(NamedTuple):
    """What a part kind's ``moodle`` hook writes its question from: its name and idnumber, the
    question's text with its graph (stem), the part's own prompt ("<p><strong>(a) </strong>Find
    ...", its </p> left to the kind), its marks, the general feedback, the files, the mark scheme (HTML) and how the
    part is marked by error carried forward (HTML, or "")."""

    name: str
    idnumber: str
    stem: str
    ask: str
    marks: int
    general: str
    files: dict[str, bytes]
    scheme: str
    how_marked: str


def scheme_html(question: Question) -> str:
    return "<p><strong>Mark scheme</strong></p>" + question.mark_scheme_html()


def _graph_files(template: Template, index: int, question: Question) -> tuple[str, dict[str, bytes]]:
    if question.graph is None:
        return "", {}
    from ..figures.question_graph import question_graph

    drawn = question_graph(question.graph)
    filename = f"{template.key}-{index}.png"
    width, height = (round(size * GRAPH_DPI) for size in drawn.figure.get_size_inches())
    image = (f'<p><img src="@@PLUGINFILE@@/{filename}" alt="{html.escape(drawn.alt)}" '
             f'width="{width}" height="{height}"></p>')
    return image, {filename: _png(drawn.figure)}


def _png(figure) -> bytes:
    """The graph as a small PNG (a palette of 64 colours: lines and grid on white), the same
    bytes on every run. PNG, not SVG: a graph is embedded once in each part's question, and
    SVG would make the file about 13 MB, more than many schools' upload limit."""
    from PIL import Image

    from ..figures.style import book_style

    buffer = io.BytesIO()
    with book_style():
        figure.savefig(buffer, format="png", dpi=GRAPH_DPI, metadata={"Software": None})
    image = Image.open(io.BytesIO(buffer.getvalue())).convert("RGB").quantize(colors=64)
    out = io.BytesIO()
    image.save(out, format="PNG", optimize=True)
    return out.getvalue()


def variant_indices(template: Template) -> range:
    """The template's reserve variants, which the site never shows (at least MOODLE_MIN_VARIANTS
    of fresh numbers), or all the situations of a template that shares them with the site."""
    return template.reserve_variants


def export(templates: list[Template] | None = None, topic: Topic | None = None
           ) -> tuple[ET.ElementTree, dict[str, int]]:
    """The Moodle XML tree of the topic's templates (all of them, or those given), in one
    category per question type, and how many questions of each kind."""
    topic = topic_of(topic)
    templates = bank_templates(topic) if templates is None else templates
    out = _Export()
    drawn = _draw_graphs(templates)
    for question_type in topic.types:
        chosen = [t for t in templates if t.type == question_type.key]
        if not chosen:
            continue
        type_path = f"{root_category(topic)}/{question_type.title}"
        out.category(type_path, f"<p>{_escape(question_type.title)}: questions of the {_escape(topic.name)} "
                                "textbook, each in several variants with different numbers.</p>")
        for template in chosen:
            _template(out, template, type_path, drawn)
    return ET.ElementTree(out.quiz), out.count


def _draw_graphs(templates: list[Template]) -> dict[tuple[str, int], tuple[str, dict[str, bytes]]]:
    """Every variant's graph, drawn once, on every core (matplotlib takes most of the time)."""
    by_key = {t.key: t for t in templates}
    jobs = [(t.key, index) for t in templates if any(KINDS[kind].reads_graph for kind in t.kinds)
            for index in variant_indices(t)]

    def draw(job: tuple[str, int]) -> tuple[str, dict[str, bytes]]:
        template = by_key[job[0]]
        return _graph_files(template, job[1], template.variant(job[1]))

    return dict(zip(jobs, on_every_core(draw, jobs), strict=True))


def _template(out: _Export, template: Template, type_path: str, drawn: dict) -> None:
    # each variant built and its graph drawn once, then one category per part
    variants = [(index, template.variant(index)) for index in variant_indices(template)]
    graphs = [drawn.get((template.key, index)) or _graph_files(template, index, question)
              for index, question in variants]
    first = variants[0][1]
    for part_index, part in enumerate(first.parts):
        # a "/" inside a category's name is written "//" (Moodle's escape)
        name = f"{template.title} {first.label(part_index)}{part.prompt}".replace("/", "//")
        out.category(f"{type_path}/{name}")
        for (index, question), (image, files) in zip(variants, graphs, strict=True):
            _part(out, template, index, question, part_index, image, files)


def _part(out: _Export, template: Template, index: int, question: Question, part_index: int,
          image: str, files: dict[str, bytes]) -> None:
    part, label = question.parts[part_index], question.label(part_index)
    marks = part_marks(question)[part_index]
    name = f"{template.title} {label}(variant {index + 1})".replace("  ", " ")
    idnumber = f"{template.key}-v{index}-{question.part_ids[part_index]}"
    stem = question.text_html() + image
    ask = f"<p><strong>{_escape(label)}</strong>{_escape(part.prompt[:1].upper() + part.prompt[1:])}"
    # how the part is marked by error carried forward: for the teacher and, after the attempt,
    # the student (the general feedback; an essay's grader information), never in the question
    note = ecf_note(question, part_index)
    how_marked = f"<p><em>How this part is marked: {_escape(note)}</em></p>" if note else ""
    general = scheme_html(question) + how_marked
    item = MoodleItem(name, idnumber, stem, ask, marks, general, files, scheme_html(question), how_marked)
    part.moodle(out, item, question, part_index)


def _decimal(value: float) -> str:
    """A number for a Cloze answer: its shortest plain decimals (the syntax takes no exponent)."""
    text = numpy.format_float_positional(float(value), trim="-")
    return "0" if float(text) == 0 else text


def _cloze_escape(text: str) -> str:
    """Plain text inside a Cloze answer: HTML-escaped, and its own marks (} # ~ / " \\) escaped."""
    return re.sub(r'([}#~/"\\])', r"\\\1", _escape(text))


def to_xml(tree: ET.ElementTree) -> str:
    """The file's text: every HTML <text> in CDATA, as Moodle needs it."""
    blocks: dict[str, str] = {}
    for element in tree.iter():
        if element.get("format") == "html":
            text = element.find("text")
            if text is not None and text.text:
                token = f"@@cdata-{len(blocks)}@@"
                blocks[token], text.text = text.text, token
    xml = ET.tostring(tree.getroot(), encoding="unicode")
    # one pass over the text (a replace per block copied the 5 MB file thousands of times: 50 s)
    xml = _CDATA_TOKEN.sub(
        lambda token: "<![CDATA[" + blocks[token[0]].replace("]]>", "]]]]><![CDATA[>") + "]]>", xml)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + xml + "\n"


_CDATA_TOKEN = re.compile(r"@@cdata-\d+@@")


def write(path: Path, topic: Topic | None = None) -> dict[str, int]:
    """Write the topic's Moodle XML to ``path``; return the questions by kind."""
    tree, count = export(topic=topic)
    ET.indent(tree, space=" ")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(to_xml(tree), encoding="utf-8")
    return count


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m physics_figures.worksheets.moodle",
                                     description="Write the question bank as Moodle XML.")
    parser.add_argument("out", type=Path, help="the .xml file to write")
    parser.add_argument("--topic", default=DEFAULT_TOPIC, help=f"the topic's module (default {DEFAULT_TOPIC})")
    args = parser.parse_args(argv)
    try:
        topic = topics.load(args.topic)
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    count = write(args.out, topic)
    print(f"wrote {args.out}: {sum(count.values())} questions ({', '.join(f'{n} {k}' for k, n in sorted(count.items()))}), "
          f"{format_number(args.out.stat().st_size / 1e6, decimals=1)} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
