
"""The question bank as Moodle XML, for a school's learning platform.

One question category per type (the notes' seven), and inside it one category per
template and part, so a quiz can draw "a random question from this category": every
variant of the template (at least 10; a template with fewer situations gives all of them).

* A numeric part (or a reading from a graph) is a Moodle **numerical** question with the
  unit (every usual form, written without spaces, as Moodle strips them from a response)
  and the book's tolerance: half a unit in the second significant figure, so the answer at
  2, 3 or 4 s.f. is right; a reading from a graph is right within half a small square. The
  named mistakes come first in the file, each with its own feedback, matched as the book's
  marker matches them, at 3 significant figures, and never where a right rounding falls
  (Moodle takes the first answer whose range holds the response). A part asking for a direction is followed by a multichoice on the direction.
* A multiple-choice item is a **multichoice** question, options A to D in the printed
  order, each wrong option with the feedback of the mistake it stands for.
* A describe-and-explain part is an **essay** question, with the model answer and the
  marking points (with their codes) as information for the grader.
* A multi-part question becomes one question per part, each with the question's text.

Graphs are drawn for each variant and embedded as PNG images (``@@PLUGINFILE@@``). Text is the
bank's text format as HTML, escaped inside ``<text>`` by the XML library (xml.etree).
"""

from __future__ import annotations

import argparse
import base64
import html
import io
import math
import multiprocessing
import os
import sys
import xml.etree.ElementTree as ET
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from .. import textformat
from ..notation import format_number, round_number
from ..questions import OPTION_LETTERS, Question, unit_text
from ..variants import QUESTION_TYPES, Template
from . import TYPE_TITLES, bank_templates, part_marks
from .latex import MISTAKE_SIG_FIGS, ecf_note

#: Moodle's question bank is filled with this many variants of a template at least.
MOODLE_MIN_VARIANTS = 10
ROOT_CATEGORY = "$course$/top/Dynamics (9702)"
#: A right answer is taken at 2, 3 and 4 significant figures (the book's marking).
RIGHT_ROUNDINGS = (2, 3, 4)
#: The resolution of the graphs' images (a 5.6 in wide graph is 728 pixels).
GRAPH_DPI = 130


def tolerance(value: float) -> float:
    """Half a unit in the second significant figure: 11.6 -> 0.5, 0.57 -> 0.005."""
    if value == 0:
        return 0.0
    return 0.5 * 10 ** (math.floor(math.log10(abs(value))) - 1)


def _mistake_range(mistake: float, right: float) -> tuple[float, float] | None:
    """A named mistake is matched as the book's marker matches it: written to 3 significant
    figures. So its answer is the mistake at 3 s.f. and its tolerance half a unit in the
    third figure (two mistakes that differ at 3 s.f. never overlap). None when the right
    answer at 2, 3 or 4 s.f. would fall in that range (then the mistake is left out)."""
    if mistake == 0:
        width = 0.5 * 10 ** (math.floor(math.log10(abs(right))) - 2)
        centre = 0.0
    else:
        centre = float(round_number(mistake, MISTAKE_SIG_FIGS))
        width = 0.5 * 10 ** (math.floor(math.log10(abs(centre))) - MISTAKE_SIG_FIGS + 1)
    roundings = [float(round_number(right, sf)) for sf in RIGHT_ROUNDINGS] + [right]
    if any(abs(r - centre) <= width * (1 + 1e-9) for r in roundings):
        return None
    return centre, width


def _number(value: float) -> str:
    """A value for Moodle: plain digits, 10 significant figures, no grouping."""
    return format(value, ".10g")


def _text(parent: ET.Element, tag: str, html: str, *, fmt: str = "html") -> ET.Element:
    element = ET.SubElement(parent, tag, {"format": fmt} if fmt else {})
    ET.SubElement(element, "text").text = html
    return element


def _plain(parent: ET.Element, tag: str, text: str) -> ET.Element:
    element = ET.SubElement(parent, tag)
    element.text = text
    return element


def _units(unit: str, forms: str) -> list[str]:
    """Every usual form of the unit, without spaces: "m s^-2", "m s^-2 (m/s^2)" ->
    ["ms^-2", "ms⁻²", "m/s^2"]."""
    candidates = [unit]
    for chunk in forms.replace("(", " or ").replace(")", "").split(" or "):
        if chunk.strip():
            candidates.append(chunk.strip())
    out: list[str] = []
    for candidate in candidates:
        for form in (candidate, unit_text(candidate)):
            form = form.replace(" ", "")
            if form and form not in out:
                out.append(form)
    return out


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

    def numerical(self, name, idnumber, html, marks, general, files, part) -> None:
        question = self._question("numerical", name, idnumber, html, marks, general, files)
        right = part.value
        width = part.tolerance if part.kind == "graph" else tolerance(right)
        named: dict[float, object] = {}
        for mistake in part.mistakes:
            if mistake.unit is not None or mistake.direction is not None:
                continue  # another quantity or a direction: not a number to match
            value = mistake.value if part.direction == "signed" else abs(mistake.value)
            typed = round_number(value, MISTAKE_SIG_FIGS)
            if all(round_number(other, MISTAKE_SIG_FIGS) != typed for other in named):
                named[value] = mistake
        for value, mistake in named.items():
            found = _mistake_range(value, right)
            if found is None:
                continue
            self._answer(question, 0, *found,
                         f"<p><strong>{_escape(mistake.name)}.</strong> {_escape(mistake.feedback)}</p>")
        if part.direction == "signed" and right != 0:
            self._answer(question, 0, -right, width,
                         f"<p><strong>Sign slip.</strong> The size is right but the sign is wrong: "
                         f"positive is {_escape(part.positive)}.</p>")
        self._answer(question, 100, right, width,
                     f"<p>Right: {_escape(part.answer_text)}.</p>")
        units = ET.SubElement(question, "units")
        for form in _units(part.unit, part.units):
            unit = ET.SubElement(units, "unit")
            _plain(unit, "multiplier", "1")
            _plain(unit, "unit_name", form)
        _plain(question, "unitgradingtype", "1")  # a missing or wrong unit loses marks (as in the book)
        _plain(question, "unitpenalty", _number(1 / max(1, marks)))  # the A1's share
        _plain(question, "showunits", "0")  # the unit is typed after the number
        _plain(question, "unitsleft", "0")

    @staticmethod
    def _answer(question, fraction: int, value: float, width: float, feedback: str) -> None:
        answer = ET.SubElement(question, "answer", {"fraction": str(fraction), "format": "moodle_auto_format"})
        _plain(answer, "text", _number(value))
        _plain(answer, "tolerance", _number(width))
        _text(answer, "feedback", feedback)

    def multichoice(self, name, idnumber, html, marks, general, files,
                    options: list[tuple[str, bool, str]], *, numbering: str = "ABCD") -> None:
        question = self._question("multichoice", name, idnumber, html, marks, general, files)
        _plain(question, "single", "true")
        _plain(question, "shuffleanswers", "false")
        _plain(question, "answernumbering", numbering)
        _plain(question, "showstandardinstruction", "0")
        _text(question, "correctfeedback", "<p>Your answer is correct.</p>")
        _text(question, "partiallycorrectfeedback", "<p>Your answer is partially correct.</p>")
        _text(question, "incorrectfeedback", "<p>Your answer is incorrect.</p>")
        for html_option, right, feedback in options:
            answer = ET.SubElement(question, "answer", {"fraction": "100" if right else "0", "format": "html"})
            ET.SubElement(answer, "text").text = html_option
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


def _scheme_html(question: Question) -> str:
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
    """Every variant up to MOODLE_MIN_VARIANTS... all of them: at least 10 where the template
    has them, and every one of a template with fewer situations."""
    return range(len(template.values))


def export(templates: list[Template] | None = None) -> tuple[ET.ElementTree, dict[str, int]]:
    """The Moodle XML tree of the bank's templates, and how many questions of each kind."""
    templates = bank_templates() if templates is None else templates
    out = _Export()
    drawn = _draw_graphs(templates)
    for question_type in QUESTION_TYPES:
        chosen = [t for t in templates if t.type == question_type]
        if not chosen:
            continue
        type_path = f"{ROOT_CATEGORY}/{TYPE_TITLES[question_type]}"
        out.category(type_path, f"<p>{_escape(TYPE_TITLES[question_type])}: questions of the Dynamics "
                                "textbook, each in several variants with different numbers.</p>")
        for template in chosen:
            _template(out, template, type_path, drawn)
    return ET.ElementTree(out.quiz), out.count


def _drawn(job: tuple[str, int]) -> tuple[str, dict[str, bytes]]:
    from .. import bank

    key, index = job
    template = bank.TEMPLATES[key]
    return _graph_files(template, index, template.variant(index))


def _draw_graphs(templates: list[Template]) -> dict[tuple[str, int], tuple[str, dict[str, bytes]]]:
    """Every variant's graph, drawn once, on every core (matplotlib takes most of the time)."""
    jobs = [(t.key, index) for t in templates if "graph" in t.kinds for index in variant_indices(t)]
    if not jobs:
        return {}
    context = multiprocessing.get_context("fork") if sys.platform == "linux" else None
    with ProcessPoolExecutor(max_workers=os.cpu_count() or 1, mp_context=context) as pool:
        return dict(zip(jobs, pool.map(_drawn, jobs, chunksize=4), strict=True))


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
    note = ecf_note(question, part_index)
    general = _scheme_html(question) + (f"<p><em>{_escape(note)}</em></p>" if note else "")
    if part.kind == "mcq":
        options = [(textformat.to_html(option.text, paragraphs=False), letter == part.answer,
                    f"<p>{_escape(option.feedback)}</p>" if option.feedback
                    else f"<p>Right: {_escape(part.answer_text)}.</p>")
                   for letter, option in zip(OPTION_LETTERS, part.options, strict=True)]
        out.multichoice(name, idnumber, stem + ask + "</p>", marks, general, files, options)
    elif part.kind == "explain":
        grader = (f"<p><strong>Model answer</strong></p>{textformat.to_html(part.model_answer)}"
                  + _scheme_html(question))
        out.essay(name, idnumber, stem + ask + f" [{marks}]</p>", marks, general, files, grader)
    else:
        how = " (read from the graph)" if part.kind == "graph" else ""
        sign = f" Give a signed value: positive is {_escape(part.positive)}." if part.direction == "signed" else ""
        size = " Give its size here; the next question asks its direction." if part.direction == "choice" else ""
        value_marks = marks - 1 if part.direction == "choice" and marks > 1 else marks
        out.numerical(name, idnumber, stem + ask + f"{how}.{sign}{size} Type the number and its unit "
                      f"({_escape(unit_text(part.unit))}).</p>", value_marks, general, files, part)
        if part.direction == "choice":
            wrong = {m.direction: m.feedback for m in part.mistakes if m.direction}
            options = [(_escape(choice), choice == part.answer_direction,
                        f"<p>{_escape(wrong.get(choice) or part.direction_hint or part.revisit)}</p>")
                       for choice in part.choices]
            out.multichoice(f"{name} direction", f"{idnumber}-direction",
                            stem + f"<p><strong>{_escape(label)}</strong>What is the direction of the "
                            f"{_escape(part.prompt)}?</p>", 1, general, files, options, numbering="none")


def write(path: Path) -> dict[str, int]:
    """Write the bank's Moodle XML to ``path``; return the questions by kind."""
    tree, count = export()
    ET.indent(tree, space=" ")
    path.parent.mkdir(parents=True, exist_ok=True)
    tree.write(path, encoding="UTF-8", xml_declaration=True)
    return count


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m physics_figures.worksheets.moodle",
                                     description="Write the question bank as Moodle XML.")
    parser.add_argument("out", type=Path, help="the .xml file to write")
    args = parser.parse_args(argv)
    count = write(args.out)
    print(f"wrote {args.out}: {sum(count.values())} questions ({', '.join(f'{n} {k}' for k, n in sorted(count.items()))}), "
          f"{format_number(args.out.stat().st_size / 1e6, decimals=1)} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
