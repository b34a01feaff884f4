# ruff: noqa: RUF001, RUF002  (typeset text: true minus, times, superscripts)
"""A version's question sheet and answer key as standalone LaTeX documents (for xelatex).

The sheet: a cover (name, class, date, the data line, the total, a table of the marks and,
when there are multiple-choice items, their answer grid), then each question with its
graph drawn for this version's numbers, working space and answer lines sized to each
part's marks, and the marks as [n]. The key: for each part the working, the answer to the
significant figures the book prints with its unit, the mark-scheme lines with their codes
and ecf notes, and the common wrong answers with the mistake each shows.

All text comes from the bank in the text format (physics_figures.textformat) and every
number from physics_figures, written by physics_figures.notation.format_number.
"""

from __future__ import annotations

import math
import re
from types import SimpleNamespace
from typing import NamedTuple

import sympy

from .. import marking, textformat
from ..notation import format_number, join_units, round_number, working_number
from ..questions import OPTION_LETTERS, Question, unit_text
from . import DATA_LINE, Sheet, Version, part_marks

#: Working space per mark of a calculation, and ruled lines per mark of an explanation.
WORKING_CM_PER_MARK = 1.5
LINES_PER_MARK = 2
#: The key prints a wrong answer to the figures the marker tells it apart at (the rule table's check).
MISTAKE_SIG_FIGS = marking.sig_figs()["check"]

#: What a key says of its codes (the PDF key's and the sheet builder's), as 9702 mark schemes use
#: them: a calculation step C1 then the answer A1 (9702/21/O/N/16 Q2(b)(ii): "E = V / d … C1 … A1
#: [2]"; 9702/21/M/J/16 Q3(b)(ii): Δp C1, then F = Δp / Δt A1).
KEY_CODES = ("Mark codes as in Cambridge mark schemes: C1 a calculation step (given when the final answer "
             "is right), M1 method, A1 accuracy (the answer, to 2 or more significant figures), B1 an "
             "independent mark; ecf: error carried forward (a later part worked correctly from the student's "
             "own wrong earlier answer earns its marks; only the first error is penalised).")

PREAMBLE = r"""\documentclass[11pt,a4paper]{article}
% Written by physics_figures.worksheets: do not edit (run the command again).
\usepackage[a4paper,hmargin=2.2cm,top=2.2cm,bottom=2.4cm]{geometry}
\usepackage{fontspec}
\setmainfont{FreeSerif}[Extension=.otf,UprightFont=*,BoldFont=*Bold,ItalicFont=*Italic,BoldItalicFont=*BoldItalic]
\setsansfont{FreeSans}[Extension=.otf,UprightFont=*,BoldFont=*Bold,ItalicFont=*Oblique,BoldItalicFont=*BoldOblique]
\usepackage{graphicx}
\usepackage{array}
\usepackage{needspace}
\usepackage{enumitem}
\usepackage{fancyhdr}
\usepackage{xcolor}
\usepackage{tikz} % the sketch graphs of a "which graph?" item
\usepackage[hidelinks,pdfcreator={physics_figures.worksheets}]{hyperref}
\tracinglostchars=3 % a character the font lacks is an error, not a silent gap
\setlength{\parindent}{0pt}
\setlength{\parskip}{4pt}
\pagestyle{fancy}
\fancyhf{}
\renewcommand{\headrulewidth}{0pt}
\fancyfoot[L]{\small\sffamily @FOOTER@}
\fancyfoot[R]{\small\sffamily Page \thepage}
\hypersetup{pdftitle={@TITLE@},pdfauthor={},pdfsubject={},pdfkeywords={}}
\newcommand{\answerline}[1]{\leavevmode\hbox to #1{\dotfill}}
\newcommand{\partmarks}[1]{\hfill\mbox{\textbf{[#1]}}}
\newcount\writinglinecount
\newcommand{\writinglines}[1]{\par\writinglinecount=#1\relax
  \loop\ifnum\writinglinecount>0\relax\vspace{0.95cm}\hrule height 0.3pt\relax
  \advance\writinglinecount by -1\repeat\par}
\newcommand{\question}[1]{\par\needspace{6\baselineskip}\vspace{10pt}{\sffamily\bfseries\large #1}\quad}
\newcommand{\gridbox}{\framebox[1.1cm]{\rule{0pt}{0.5cm}}}
% A choice question's stem, options and answer box on one page: a box no page break enters.
\newenvironment{keeptogether}{\par\noindent\begin{minipage}{\linewidth}\setlength{\parskip}{4pt}}%
  {\end{minipage}\par}
"""

#: A cover's marks table keeps its roomy rows up to this many questions.
COVER_ROOMY_ROWS = 15


#: Unicode subscript letters that FreeSerif lacks (vₜ in feedback), as \textsubscript.
_SUBSCRIPTS = {chr(code): letter for code, letter in zip(range(0x2090, 0x209D), "aeoxəhklmnpst", strict=True)}


def _subscripts(text: str) -> str:
    return "".join(f"\\textsubscript{{{_SUBSCRIPTS[c]}}}" if c in _SUBSCRIPTS else c for c in text)


def _marks(count: int) -> str:
    """"6 marks", tied (~): a line never ends between the number and its word."""
    return f"{count}~mark" if count == 1 else f"{count}~marks"


def tex(plain: str) -> str:
    """Plain text (a prompt, a mistake's name, feedback) for LaTeX; Unicode stays Unicode,
    and numbers are tied to their units."""
    return _subscripts(textformat.latex_escape(join_units(plain)))


def rich(source: str) -> str:
    """Text in the text format (question text, options, mark lines) for LaTeX."""
    return _subscripts(textformat.to_latex(source))


def _value_with_unit(value: float, sig_figs: int, unit: str) -> str:
    space = "" if unit in ("°", "") else " "  # a ratio ("") has no unit
    return f"{format_number(value, sig_figs)}{space}{unit_text(unit)}"


def _document(body: str, *, footer: str, title: str) -> str:
    return (PREAMBLE.replace("@FOOTER@", tex(footer)).replace("@TITLE@", tex(title))
            + "\\begin{document}\n" + body + "\n\\end{document}\n")


def _graph_file(index: int) -> str:
    return f"graph-{index}.pdf"


def graphs(version: Version) -> dict[str, bytes]:
    """The vector PDFs of this version's graphs and diagrams (a question prints one or the
    other), by file name (drawn from its numbers)."""
    # matplotlib only when a sheet has a figure
    from ..figures.question_diagram import question_diagram
    from ..figures.question_graph import question_graph

    return {_graph_file(number): (question_graph(item.question.graph) if item.question.graph is not None
                                  else question_diagram(item.question.diagram)).pdf()
            for number, item in enumerate(version.items, start=1)
            if item.question.graph is not None or item.question.diagram is not None}


# ----------------------------------------------------------------- the question sheet


def _cover(sheet: Sheet, version: Version) -> str:
    numbers = range(1, len(version.items) + 1)
    choices = [(number, item) for number, item in zip(numbers, version.items, strict=True)
               if any(part.answer_grid for part in item.question.parts)]
    rows = "\n".join(f"{number} & {item.question.marks} & \\\\ \\hline"
                     for number, item in zip(numbers, version.items, strict=True))
    out = [
        r"\thispagestyle{fancy}",
        r"{\raggedright\sffamily\bfseries\LARGE " + tex(sheet.title) + r"\par}",
        r"\vspace{4pt}{\sffamily\Large Version " + version.letter + r"\par}",
        r"\vspace{18pt}",
        r"\renewcommand{\arraystretch}{1.9}",
        r"\begin{tabular}{@{}l p{11cm}@{}}",
        r"Name & \answerline{11cm} \\",
        r"Class & \answerline{11cm} \\",
        r"Date & \answerline{11cm} \\",
        r"\end{tabular}",
        r"\renewcommand{\arraystretch}{1}",
        r"\vspace{14pt}",
        r"\begin{itemize}[leftmargin=1.2em,itemsep=2pt]",
        r"\item Answer \textbf{all} questions in the spaces provided.",
        r"\item Show your working: marks are given for the method as well as the answer.",
        r"\item Give each numerical answer to an appropriate number of significant figures, with its unit.",
        r"\item The number of marks is given in brackets [\,] at the end of each part.",
        (r"\item For each multiple-choice question, write the letter of your answer in the grid below."
         if choices else ""),
        r"\end{itemize}",
        r"\vspace{6pt}",
        r"\textbf{" + tex(DATA_LINE) + r"}\par",
        r"\vspace{10pt}",
        r"{\sffamily\bfseries\Large Total: " + str(version.marks) + r" marks\par}",
        r"\vspace{12pt}",
    ]
    # A worksheet of every template of a type runs to 17 questions: rows closer together keep
    # its table (and the grid beside it) on the cover.
    stretch = "1.5" if len(version.items) <= COVER_ROOMY_ROWS else "1.2"
    marks_table = [
        r"\renewcommand{\arraystretch}{" + stretch + "}",
        r"\begin{tabular}{|c|c|c|}\hline",
        r"\textbf{Question} & \textbf{Marks available} & \textbf{Marks awarded} \\ \hline",
        rows,
        r"\textbf{Total} & \textbf{" + str(version.marks) + r"} & \\ \hline",
        r"\end{tabular}",
    ]
    if not choices:
        out += [r"\begin{center}", *marks_table, r"\end{center}"]
    else:
        header = " & ".join(["\\textbf{Question}", *(f"\\textbf{{{letter}}}" for letter in OPTION_LETTERS),
                             "\\textbf{Answer}"])
        grid = "\n".join(f"{number} & " + " & ".join("$\\bigcirc$" for _ in OPTION_LETTERS)
                         + r" & \gridbox \\ \hline" for number, _ in choices)
        # Side by side, tops aligned (\vspace{0pt}), so a long test's cover stays on one page
        # and the grid never leaves its heading at the foot of one.
        out += [
            r"\begin{center}\begin{minipage}[t]{0.49\linewidth}\vspace{0pt}\centering",
            *marks_table,
            r"\end{minipage}\hfill\begin{minipage}[t]{0.49\linewidth}\vspace{0pt}\centering",
            r"{\sffamily\bfseries Multiple-choice answer grid}\par\vspace{4pt}",
            r"Shade one circle for each question, and write the letter in the box.\par\vspace{4pt}",
            r"\renewcommand{\arraystretch}{1.6}",
            r"\begin{tabular}{|c|c|c|c|c|c|}\hline",
            header + r" \\ \hline",
            grid,
            r"\end{tabular}\end{minipage}\end{center}",
        ]
    out.append(r"\newpage")
    return "\n".join(line for line in out if line)


def _part(question: Question, index: int, marks: int) -> str:
    """The part on the sheet, as its kind prints it (parts/__init__.py)."""
    return question.parts[index].latex_sheet(question, index, marks, writer())


def sketch_row(part) -> str:
    """The four sketch graphs of a "which graph?" item side by side, each under its letter."""
    from ..figures.sketches import sketch_tikz  # TikZ text only: no matplotlib

    cells = "\\hfill".join(f"\\begin{{minipage}}[t]{{0.24\\linewidth}}\\centering\\textbf{{{letter}}}\\par"
                          f"{sketch_tikz(option.sketch)}\\end{{minipage}}"
                          for letter, option in zip(OPTION_LETTERS, part.options, strict=True))
    return "\\par\\needspace{4cm}\\noindent" + cells + "\\par\\vspace{6pt}\n"


def question_sheet(sheet: Sheet, version: Version) -> str:
    """The LaTeX of one version's question sheet."""
    body = [_cover(sheet, version)]
    for number, item in enumerate(version.items, start=1):
        question = item.question
        # a choice question: its text, graph and first part (the options) on one page
        keep = question.parts[0].keeps_with_question_text
        start = [f"\\question{{{number}}}{rich(question.text)}"]
        if question.graph is not None or question.diagram is not None:
            # a graph to read is wide; a diagram (Before above After) needs less than half the line
            size = "0.78" if question.graph is not None else "0.42"
            start.append(f"\\par\\begin{{center}}\\includegraphics[width={size}\\linewidth]{{"
                         + _graph_file(number) + "}\\end{center}")
        parts = [_part(question, index, marks) for index, marks in enumerate(part_marks(question))]
        if keep:
            body.append("\\begin{keeptogether}" + "\n\n".join([*start, parts.pop(0)]) + "\\end{keeptogether}")
        else:
            body += start
        body += parts
        body.append(f"\\par\\vspace{{2pt}}\\hfill{{\\small\\itshape [Total for question {number}: "
                    f"{_marks(question.marks)}]}}\\par")
    body.append(r"\vspace{16pt}\begin{center}\textbf{End of the questions.}\end{center}")
    return _document("\n\n".join(body), footer=f"Version {version.letter}", title=f"{sheet.title} (version {version.letter})")


# ----------------------------------------------------------------------- the key


_POWERS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def ecf_note(question: Question, index: int) -> str:
    """"ecf: a wrong answer to (a) carried forward earns these marks: (b) = (1200 − (a)) / 62,
    worked with the student's own (a)" (plain text): the part's Ecf formula with the
    givens' numbers in it."""
    part = question.parts[index]
    if part.ecf is None:
        return ""
    names = {sympy.Symbol(name): sympy.Symbol(working_number(value))
             for name, value in part.ecf.values.items()}
    names.update({sympy.Symbol(used): sympy.Symbol(f"({used})") for used in part.ecf.uses})
    text = sympy.sstr(part.ecf.formula.xreplace(names))
    text = re.sub(r"\*\*(\d+)", lambda m: m[1].translate(_POWERS), text)
    text = text.replace("*", " × ").replace("/", " / ").replace("-", "−")
    uses = ", ".join(f"({u})" for u in part.ecf.uses)
    # a named mistake of this part that follows from the same mistake earlier is such an answer
    carried = "".join(f" {name} in {', '.join(f'({u})' for u in shown)} carried forward earns these marks too."
                      for name, shown in question.carried_mistakes(index).items())
    return (f"ecf: a wrong answer to {uses} carried forward earns these marks: "
            f"({question.part_ids[index]}) = {text}, worked with the student's own {uses}.{carried}")


class WrongAnswer(NamedTuple):
    """A common wrong answer in a key: what the student wrote, the mistake it shows, what to
    say, and what it scores ("keeps the C1: 1/2"), as the book and Moodle mark it."""

    written: str
    name: str
    feedback: str
    marks: str


def _codes(codes: list[str]) -> str:
    """"the C1", "the C1 and M1", "both C1 marks": the codes of the lines kept."""
    counts = {code: codes.count(code) for code in codes}
    names = [f"the {code}" if n == 1 else f"{'both' if n == 2 else f'all {n}'} {code} marks"
             for code, n in counts.items()]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def marks_kept(lines: list[tuple[str, tuple[str, ...]]], lost) -> str:
    """What an answer that loses these roles scores, as a key says it (CLARIFICATIONS, Trust:
    "keeps the C1: 1/2"; nothing kept: "0/2"): the lines it keeps, by the rule table."""
    kept = [code for code, roles in lines if not set(roles) & set(lost)]
    score = f"{len(kept)}/{len(lines)}"
    return f"keeps {_codes(kept)}: {score}" if kept else f"scores {score}"


def _part_way_note(part, value: float) -> str:
    """Why a rounded-part-way value is wrong at 3 s.f. when its 2 s.f. form is the key's own:
    0.320 claims a third figure that the early rounding made, while 0.32 is 0.324 rounded (as
    the one s.f. judge, marking.judge_sig_figs, takes it)."""
    two = round_number(value, part.min_sig_figs)
    judged = marking.judge_sig_figs(marking.written(value, part.min_sig_figs), part.value,
                                    min_sf=part.min_sig_figs, check_sf=part.check_sig_figs)
    if judged.code != "correct":
        return ""
    key = format_number(abs(part.value), MISTAKE_SIG_FIGS)
    return (f" Written to {part.min_sig_figs} s.f., {format_number(abs(float(two)), part.min_sig_figs)} earns full "
            f"marks: it is the key's {key} rounded. Written to {MISTAKE_SIG_FIGS} s.f., "
            f"{format_number(abs(value), MISTAKE_SIG_FIGS)} claims a third figure, and the early rounding moved it.")


def option_marks(question: Question, index: int) -> str:
    """What a wrong option of a multiple-choice part scores (a named mistake: nothing)."""
    lines = question.part_lines(question.part_ids[index])
    return marks_kept(lines, marking.mistake_losses("physics"))


def wrong_answers(question: Question, index: int) -> list[WrongAnswer]:
    """The common wrong answers of a numeric part, each with what it scores: its named
    mistakes, the g = 9.8 slip, rounding part-way and, for a signed part, the sign slip."""
    part = question.parts[index]
    lines, losses = question.part_lines(question.part_ids[index]), marking.outcome_losses()
    rows = []
    for mistake in part.mistakes:
        if mistake.direction is not None:
            written = f"{format_number(abs(part.value), part.shown_sig_figs)} {unit_text(part.unit)} {mistake.direction}"
        else:
            value = mistake.value if part.direction == "signed" else abs(mistake.value)
            written = _value_with_unit(value, MISTAKE_SIG_FIGS, mistake.unit or part.unit)
        # where the scheme credits the working it shows, the key says which scheme
        feedback = (f"{mistake.feedback} The scheme credits this working ({mistake.credited})."
                    if mistake.credited else mistake.feedback)
        rows.append(WrongAnswer(written, mistake.name, feedback, marks_kept(lines, mistake.loses)))
    if part.g_nine_eight is not None:
        rows.append(WrongAnswer(_value_with_unit(part.g_nine_eight, MISTAKE_SIG_FIGS, part.unit), "used g = 9.8 m s⁻²",
                                "The data give g = 9.81 m s⁻²: 9.8 is close but moves the third figure.",
                                marks_kept(lines, losses["g-9.8"])))
    # A value the scheme's own working gives from the printed earlier answers is accepted
    # (Question.scheme_alternatives): no wrong answer, though a part-way rounding gives it too.
    accepted = {round_number(a.value, MISTAKE_SIG_FIGS) for a in question.scheme_alternatives(index)}
    for value, what in part.rounded_part_way:
        if round_number(value, MISTAKE_SIG_FIGS) in accepted:
            continue
        rows.append(WrongAnswer(_value_with_unit(value, MISTAKE_SIG_FIGS, part.unit), "rounded part-way",
                                f"Rounded {what} before the end: keep all the figures until the final answer."
                                + _part_way_note(part, value), marks_kept(lines, losses["rounded-part-way"])))
    if part.direction == "signed" and part.value != 0:
        rows.append(WrongAnswer(_value_with_unit(-part.value, part.shown_sig_figs, part.unit), "sign slip",
                                f"The size is right but the sign is wrong: positive is {part.positive}.",
                                marks_kept(lines, losses["sign"])))
    return rows


def _allowed_value(part, value: float) -> str:
    """An allowed value as the scheme writes it: to 2 s.f. (the A1's) where that is all its
    figures (0.86, not 0.860), else to 3 (the key's)."""
    value = value if part.direction == "signed" else abs(value)
    least = marking.sig_figs()["min"]
    figures = least if math.isclose(float(round_number(value, least)), value, rel_tol=1e-9) else MISTAKE_SIG_FIGS
    return _value_with_unit(value, figures, part.unit)


def accept_note(part) -> str:
    """What the key accepts beside a numeric or graph part's answer (plain text, the PDF key's
    and the sheet builder's): " (accept 2 or more significant figures)", or a reading's band;
    then what the part's scheme allows besides, each with its paper ("; allow 10.8 N: the
    force from ... (9702/...)", "; allow −4.0 N s (9702/...)")."""
    if part.reads_graph:
        return f" (read from the graph: accept {part.band_text()})"
    allowed = "".join(f"; allow {_allowed_value(part, a.value)}: {a.reason}" for a in part.alternatives)
    if part.allow_minus:
        allowed += f"; allow {_value_with_unit(-abs(part.value), part.shown_sig_figs, part.unit)} ({part.allow_minus})"
    if part.readings:  # worked from readings: what readings within half a small square give
        low, high = part.band
        return (f" (accept {part.min_sig_figs} or more significant figures; from readings of the "
                f"graph to half a small square, {format_number(low, MISTAKE_SIG_FIGS)} to "
                f"{format_number(high, MISTAKE_SIG_FIGS)}{allowed})")
    return f" (accept {part.min_sig_figs} or more significant figures{allowed})"


def working_text(part) -> str:
    """"Working: F = 1110 N; a = 0.694 m s⁻²." (plain text), or "" for a part without steps."""
    if not part.working:
        return ""
    return "Working: " + "; ".join(f"{step.name} = {_value_with_unit(step.value, step.sig_figs, step.unit)}"
                                   for step in part.working) + "."


def _key_part(question: Question, index: int, marks: int) -> list[str]:
    """The part in the key, as its kind writes it (parts/__init__.py)."""
    return question.parts[index].latex_key(question, index, marks, writer())


def writer() -> SimpleNamespace:
    """What a part kind writes its LaTeX sheet and key with (its ``latex_sheet`` and
    ``latex_key`` hooks, physics_figures/parts/__init__.py): the text helpers, the sizes, and the
    numeric and choice parts' key helpers."""
    return SimpleNamespace(tex=tex, rich=rich, WORKING_CM_PER_MARK=WORKING_CM_PER_MARK, LINES_PER_MARK=LINES_PER_MARK,
                           sketch_row=sketch_row, accept_note=accept_note, ecf_note=ecf_note, working_text=working_text,
                           wrong_answers=wrong_answers, option_marks=option_marks)


def _mark_line(label: str, text: str, code: str) -> str:
    line = "\\item "
    if label:
        line += "\\textbf{" + tex(label) + "} "
    line += rich(text)
    if code:
        line += " \\textbf{" + code + "}"
    return line


def answer_key(sheet: Sheet, version: Version) -> str:
    """The LaTeX of one version's answer key."""
    body = [
        r"{\raggedright\sffamily\bfseries\LARGE " + tex(sheet.title) + r"\par}",
        r"\vspace{4pt}{\sffamily\Large Answer key, version " + version.letter + r"\par}",
        r"\vspace{6pt}",
        tex(f"Total: {version.marks} marks. Seed {sheet.seed}. {KEY_CODES} {DATA_LINE}"),
    ]
    for number, item in enumerate(version.items, start=1):
        question = item.question
        body.append(f"\\question{{{number}}}{{\\sffamily\\bfseries {tex(item.template.title)}}} "
                    f"{{\\small ({tex(item.template.key)}, variant {item.variant})}}"
                    # the marks flush right, on the next line when the title leaves no room (TeXbook
                    # p. 106), never split and never into the margin
                    "\\unskip\\nobreak\\hfil\\penalty50\\hskip1em\\hbox{}\\nobreak\\hfil"
                    f"\\mbox{{\\textbf{{[{_marks(question.marks)}]}}}}"
                    "{\\parfillskip=0pt\\finalhyphendemerits=0\\par}")
        body.append("{\\small " + rich(question.text) + "}")
        for index, marks in enumerate(part_marks(question)):
            body.append("\\par\\needspace{3\\baselineskip}" + "\n\n".join(_key_part(question, index, marks)))
        lines = "\n".join(_mark_line(label, text, code) for label, text, code in question.mark_lines())
        body.append("\\par\\needspace{3\\baselineskip}\\textbf{Mark scheme}\n"
                    "\\begin{itemize}[leftmargin=1.5em,itemsep=0pt,topsep=2pt]\n" + lines + "\n\\end{itemize}")
    return _document("\n\n".join(body), footer=f"Answer key, version {version.letter}",
                     title=f"{sheet.title}: answer key (version {version.letter})")
