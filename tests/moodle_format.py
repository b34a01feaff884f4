# ruff: noqa: RUF001, RUF002  (typeset text and Moodle's own pattern: times and divide signs)
"""A structural check of a Moodle XML question file against Moodle's documented format
(docs.moodle.org/en/Moodle_XML_format, and what qformat_xml reads), plus the marking rules
the book gives the export. Returns a list of problems (empty: the file is sound).

What it checks, question by question:
- every question has a type Moodle knows, a name, a question text and a default grade;
- category entries come before their questions and every question sits in a category;
- every <text> holding HTML parses as HTML with balanced tags, holds no raw TeX ($, \\frac,
  ^{...}) and no tag outside the book's text format plus the few the export adds;
- numerical: each answer has a fraction among Moodle's grades, a number, a tolerance and
  feedback; the right answers (100 %) come first, the key as it prints first of all; each
  right form, and the key written to 4 s.f., reaches a right answer (Moodle takes the first
  range that holds a response, and adds its own tiny slack); each other answer reaches
  itself first; ×10, ÷10 and a sign slip are not right; units are
  written without spaces;
- cloze: each embedded NUMERICAL and MULTICHOICE answer is well formed with a grade among
  Moodle's, one right option per MULTICHOICE, and the weights add up to the default grade;
- multichoice: single answer, one 100 % option, feedback on every option;
- essay: grader information with the mark codes;
- images: every @@PLUGINFILE@@ file named in a text is embedded in that text's <file> (an
  option's in its <answer>), base64 that decodes to a PNG or SVG, and every image has alt text.
"""

from __future__ import annotations

import base64
import math
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

#: Moodle's allowed grades (question/engine/bank.php, fraction_options_full), in per cent.
MOODLE_GRADES = {100, 90, 83.33333, 80, 75, 70, 66.66667, 60, 50, 40, 33.33333, 30, 25, 20,
                 16.66667, 14.28571, 12.5, 11.11111, 10, 5, 0}
QUESTION_TYPES = {"category", "numerical", "multichoice", "essay", "cloze", "shortanswer",
                  "truefalse", "description", "matching"}
#: The book's text format (physics_figures.textformat) and what the export wraps it in.
ALLOWED_TAGS = {"p", "sup", "sub", "em", "strong", "ul", "li", "img"}
VOID_TAGS = {"img"}
RAW_TEX = re.compile(r"\$|\\frac|\\times|\^\{|_\{")
#: How a part is marked by error carried forward: never in what the student reads first.
METHOD = re.compile(r"How this part is marked|carried forward|\becf\b", re.IGNORECASE)


class _Html(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.problems: list[str] = []
        self.images: list[dict] = []

    def handle_starttag(self, tag, attrs):
        if tag not in ALLOWED_TAGS:
            self.problems.append(f"tag <{tag}>")
        if tag == "img":
            self.images.append(dict(attrs))
        elif tag not in VOID_TAGS:
            self.stack.append(tag)

    def handle_endtag(self, tag):
        if not self.stack or self.stack[-1] != tag:
            self.problems.append(f"unbalanced </{tag}>")
        else:
            self.stack.pop()


def check_html(text: str) -> tuple[list[str], list[dict]]:
    parser = _Html()
    parser.feed(text)
    parser.close()
    problems = parser.problems + [f"<{tag}> left open" for tag in parser.stack]
    if RAW_TEX.search(text):
        problems.append("raw TeX in the text")
    return problems, parser.images


def _text(element: ET.Element | None, tag: str) -> str | None:
    if element is None:
        return None
    found = element.find(f"{tag}/text")
    return None if found is None else (found.text or "")


def _ranges(question: ET.Element) -> list[tuple[float, float, float, str]]:
    out = []
    for answer in question.findall("answer"):
        value = float(answer.findtext("text"))
        width = float(answer.findtext("tolerance") or 0)
        out.append((float(answer.get("fraction")), value - width, value + width, answer.findtext("text")))
    return out


def _first_match(ranges, response: float):
    """Moodle: the first answer whose range (plus its slack of 1e-14 relative) holds the response."""
    for fraction, low, high, text in ranges:
        slack = 1e-14 * max(abs(low), abs(high), 1e-14)
        if low - slack <= response <= high + slack:
            return fraction, text
    return None


def moodle_interval(value: float, tolerance: float) -> tuple[float, float]:
    """The responses a numerical answer takes. A numerical question's answers have Moodle's
    "nominal" tolerance (qtype_numerical_answer::$tolerancetype = 2; relative and geometric are the
    calculated types'), widened by PHP's precision: value ± (tolerance + 1e-14 max(|tolerance|,
    |value|, 1e-14)) (get_tolerance_interval)."""
    tolerance = abs(tolerance)
    slack = tolerance + 1e-14 * max(tolerance, abs(value), 1e-14)
    return value - slack, value + slack


def answers_inside_earlier(answers: list[tuple[float, float]]) -> list[str]:
    """Each answer (value, tolerance) whose value lies inside the range of one listed before it:
    Moodle never reaches it, and its import warns (what ../shared/moodle's harness reports)."""
    found = []
    for i, (value, _) in enumerate(answers):
        for earlier, tolerance in answers[:i]:
            low, high = moodle_interval(earlier, tolerance)
            if low <= value <= high:
                found.append(f"answer {value:.10g} lies inside the range of answer {earlier:.10g} listed before it")
    return found


_MOODLE_NUMBER = re.compile(r"^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[-+]?\d+)?")


def moodle_grade(question: ET.Element, response: str) -> float:
    """The fraction Moodle gives a response to an imported numerical question, as its question
    engine computes it (qtype_numerical_answer_processor::apply_units, then
    qtype_numerical_question::grade_response): spaces deleted, the unit the text after the
    number, looked up exactly; the first answer whose range holds the value in the question's
    unit (or the number as typed) wins; a unit that is missing, unknown or gives another value
    loses the unit penalty."""
    text = re.sub(r"(?:e|E|(?:x|\*|×)10(?:\^|\*\*))([+-]?\d+)", r"e\1", response.replace(" ", ""))
    number = _MOODLE_NUMBER.match(text)
    if not number:
        return 0.0
    value, unit = float(number[0]), text[len(number[0]):]
    units = {}
    for element in question.findall("units/unit"):  # Moodle keeps the first of a name
        units.setdefault(element.findtext("unit_name"), float(element.findtext("multiplier")))
    multiplier = 1 / units[unit] if unit in units else None
    scaled = value * multiplier if multiplier is not None else value
    for answer in question.findall("answer"):
        low, high = moodle_interval(float(answer.findtext("text")), float(answer.findtext("tolerance")))
        if low <= scaled <= high or low <= value <= high:
            fraction = float(answer.get("fraction")) / 100
            unit_right = multiplier is not None and low <= multiplier * value <= high
            if not unit_right and question.findtext("unitgradingtype") == "1":
                fraction -= float(question.findtext("unitpenalty")) * fraction
            return max(fraction, 0.0)
    return 0.0


def _round(value: float, sig_figs: int) -> float:
    return float(format(value, f".{sig_figs}g"))


def check_question(question: ET.Element, where: str) -> list[str]:
    kind = question.get("type")
    problems = []
    say = problems.append
    if kind not in QUESTION_TYPES:
        return [f"{where}: type {kind!r} is not a Moodle question type"]
    name = _text(question, "name")
    if not name:
        say(f"{where}: no name")
    where = f"{where} {name!r}"
    text_element = question.find("questiontext")
    text = _text(question, "questiontext")
    if not text:
        say(f"{where}: no question text")
        return problems
    if question.findtext("defaultgrade") is None or float(question.findtext("defaultgrade")) <= 0:
        say(f"{where}: no positive defaultgrade")
    html_problems, images = check_html(text)
    problems += [f"{where}: question text: {p}" for p in html_problems]
    if METHOD.search(text):
        say(f"{where}: the question text gives the method away (how the part is marked belongs in "
            "the general feedback and the grader's information)")
    problems += _check_images(images, text_element, f"{where}: question text")
    general = _text(question, "generalfeedback")
    if general:
        problems += [f"{where}: general feedback: {p}" for p in check_html(general)[0]]
    if kind == "numerical":
        problems += _check_numerical(question, where)
    elif kind == "multichoice":
        problems += _check_multichoice(question, where)
    elif kind == "cloze":
        problems += _check_cloze(question, where)
    elif kind == "essay":
        grader = _text(question, "graderinfo")
        if not grader or not re.search(r"\b[ABCM]1\b", grader):
            say(f"{where}: essay without grader information with the mark codes")
    return problems


def _check_images(images: list[dict], holder: ET.Element, where: str) -> list[str]:
    """Each image has alt text and its @@PLUGINFILE@@ file among ``holder``'s <file>s (the
    question text's, or an answer's own), a PNG or an SVG."""
    problems = []
    files = {f.get("name"): f.text or "" for f in holder.findall("file")}
    for image in images:
        source = image.get("src", "")
        if not image.get("alt"):
            problems.append(f"{where}: an image without alt text")
        if not source.startswith("@@PLUGINFILE@@/"):
            problems.append(f"{where}: image {source!r} is not embedded (@@PLUGINFILE@@)")
            continue
        data = files.get(source.removeprefix("@@PLUGINFILE@@/"))
        if data is None:
            problems.append(f"{where}: image {source!r} has no <file> beside it")
            continue
        raw = base64.b64decode(data, validate=True)
        if not (raw.startswith(b"\x89PNG\r\n\x1a\n") or b"<svg" in raw[:400]):
            problems.append(f"{where}: image {source!r} is neither PNG nor SVG")
    return problems


def _check_answers_feedback(question, where) -> list[str]:
    problems = []
    answers = question.findall("answer")
    if not answers:
        problems.append(f"{where}: no answers")
    for answer in answers:
        fraction = float(answer.get("fraction", "nan"))
        if not any(math.isclose(fraction, grade, abs_tol=1e-5) for grade in MOODLE_GRADES):
            problems.append(f"{where}: grade {fraction} is not one of Moodle's")
        if not _text(answer, "feedback"):
            problems.append(f"{where}: answer {answer.findtext('text')!r} has no feedback")
        else:
            problems += [f"{where}: feedback: {p}" for p in check_html(_text(answer, "feedback"))[0]]
    return problems


def _check_numerical(question, where) -> list[str]:
    problems = _check_answers_feedback(question, where)
    ranges = _ranges(question)
    right = [r for r in ranges if r[0] == 100]
    if not right:
        return [*problems, f"{where}: no right answer"]
    if ranges[:len(right)] != right:
        problems.append(f"{where}: the right answers do not come first")
    value = float(right[0][3])
    # each right form (the key at 2 and at 3 s.f.: the export writes both) and the key as
    # printed, written to 4 s.f., are right
    for typed in [float(r[3]) for r in right] + [_round(value, 4)]:
        if (_first_match(ranges, typed) or (0, ""))[0] != 100:
            problems.append(f"{where}: the right answer {value:g} written {typed:g} is not marked right")
    for slip in (value * 10, value / 10, -value):  # a signed part names its sign slip
        if slip != value and (_first_match(ranges, slip) or (0, ""))[0] == 100:
            problems.append(f"{where}: the slip {slip:g} is marked right")
    problems += [f"{where}: {p}" for p in answers_inside_earlier(
        [(float(a.findtext("text")), float(a.findtext("tolerance") or 0)) for a in question.findall("answer")])]
    for fraction, low, high, other in ranges[len(right):]:
        if _first_match(ranges, float(other)) != (fraction, other):
            problems.append(f"{where}: the answer {other} ({fraction} %) is never reached")
        if high < low:
            problems.append(f"{where}: the answer {other} has a negative tolerance")
    units = [u.findtext("unit_name") for u in question.findall("units/unit")]
    if not units and question.findtext("showunits") != "3":  # 3: no units, for a ratio
        problems.append(f"{where}: no unit")
    problems += [f"{where}: unit {u!r} has a space" for u in units if u is None or " " in u]
    return problems


CLOZE = re.compile(r"\{(\d+):(NUMERICAL|MULTICHOICE):((?:\\.|[^}])*)\}")


def _check_cloze(question, where) -> list[str]:
    problems, weights = [], 0
    for weight, kind, body in CLOZE.findall(_text(question, "questiontext") or ""):
        weights += int(weight)
        answers = re.split(r"(?<!\\)~", body)
        if kind == "NUMERICAL":
            numbers = [re.match(r"(?:=|%[-\d.]+%)?(-?[\d.]+):([\d.]+)", a) for a in answers]
            problems += [f"{where}: NUMERICAL box: {p}"
                         for p in answers_inside_earlier([(float(n[1]), float(n[2])) for n in numbers if n])]
        for answer in answers:
            found = re.fullmatch(r"(=|%(-?[\d.]+)%)?((?:\\.|[^#])*)#((?:\\.|[^#])*)", answer)
            if not found:
                problems.append(f"{where}: {kind} answer {answer!r} is not well formed")
                continue
            if found[2] is not None and not any(math.isclose(float(found[2]), g, abs_tol=1e-5) for g in MOODLE_GRADES):
                problems.append(f"{where}: grade {found[2]} is not one of Moodle's")
            if kind == "NUMERICAL" and not re.fullmatch(r"-?\d+(\.\d+)?:\d+(\.\d+)?", found[3]):
                problems.append(f"{where}: NUMERICAL answer {found[3]!r} is not number:tolerance")
        if kind == "MULTICHOICE" and sum(a.startswith("=") for a in answers) != 1:
            problems.append(f"{where}: a MULTICHOICE box without exactly one right option")
    if not weights:
        problems.append(f"{where}: a cloze question with no box")
    elif weights != float(question.findtext("defaultgrade")):
        problems.append(f"{where}: the boxes weigh {weights}, the question {question.findtext('defaultgrade')}")
    return problems


def _check_multichoice(question, where) -> list[str]:
    problems = _check_answers_feedback(question, where)
    if question.findtext("single") != "true":
        problems.append(f"{where}: not a single-answer multichoice")
    fractions = [float(a.get("fraction")) for a in question.findall("answer")]
    if fractions.count(100) != 1:
        problems.append(f"{where}: {fractions.count(100)} options at 100 %, not 1")
    for answer in question.findall("answer"):
        html_problems, images = check_html(answer.findtext("text") or "")
        problems += [f"{where}: option: {p}" for p in html_problems]
        problems += _check_images(images, answer, f"{where}: option")  # a sketch graph's own file
    return problems


def check_file(root: ET.Element) -> tuple[list[str], dict[str, list[ET.Element]]]:
    """Problems, and the questions of each category path."""
    problems = []
    if root.tag != "quiz":
        return [f"the root element is <{root.tag}>, not <quiz>"], {}
    categories: dict[str, list[ET.Element]] = {}
    current = None
    for number, question in enumerate(root.findall("question"), start=1):
        if question.get("type") == "category":
            current = question.findtext("category/text")
            if not current or not current.startswith("$course$/top/"):
                problems.append(f"question {number}: category {current!r} is not under $course$/top/")
            categories.setdefault(current, [])
            continue
        if current is None:
            problems.append(f"question {number}: before any category")
        problems += check_question(question, f"question {number}")
        categories.setdefault(current, []).append(question)
    return problems, categories
