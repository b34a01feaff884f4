# ruff: noqa: RUF001  (feedback is typeset text: true minus, times and Greek letters)
"""The question schema: questions that mark like an examiner, computed from the models.

The questions themselves live in the bank (physics_figures/bank/, one module per question
type), each a ``Template`` whose ``build(**givens)`` returns a ``Question``: its text (in
the text format of physics_figures.textformat), the numbers the text states
(``givens``), one part per answer box, and the mark scheme. A part is of a kind, each kind
its own module in physics_figures/parts/ (numeric, graph, choice, explain; ``KINDS``) with
its marker in the browser (book/_ext/questions/static/question-kinds/). Each part knows its answer
(SI units, from the models), the unit, how many significant figures it needs, whether
direction matters, and its named mistakes: the classic wrong methods, each worked from
the same inputs, each with feedback that names the mistake and the idea to revisit. The
browser's engine (book/_ext/questions/static/marking.js, with each kind's marker) marks with
this data; the answer key prints it.

Mark-scheme lines are in the text format too. Each names the part it belongs to and its
Cambridge code: C1 for a calculation step (compensatory: a right final answer earns it
without the working), M1 and a dependent A1 only where a part asks to show that, explain
or state a principle, A1 for the answer, B1 for a single point.

A part also keeps its working (``Step`` values) and how the answer follows from them, so
the answers that rounding part-way through would give are computed here, and the browser
says "rounded part-way" only for those. A part whose answer depends on g names the g = 10
mistake and the g = 9.8 slip from the same formula. A later part that uses an earlier
part's answer carries an ``Ecf`` formula, so a wrong earlier answer is carried forward.
"""

from __future__ import annotations

import math
import re
from dataclasses import KW_ONLY, dataclass
from functools import cached_property

from . import marking, textformat
from .notation import round_number
from .parts import (  # the part kinds, one module each (physics_figures/parts/)
    KINDS,
    OPTION_LETTERS,
    Alternative,
    Arrow,
    Body,
    ChoicePart,
    Diagram,
    Ecf,
    ExplainPart,
    Graph,
    GraphPart,
    Mistake,
    Option,
    Part,
    Reading,
    Sketch,
    Step,
    TextPart,
    choices_in_order,
    format_reading,
    reading_places,
)
from .parts.common import (
    ASKS,
    DEFAULT_CHECK_SIG_FIGS,
    DEFAULT_MIN_SIG_FIGS,
    DIRECTION_MODES,
    G_NINE_EIGHT,
    G_TEN,
    MARK_CODES,
    PART_IDS,
    PART_WAY_SIG_FIGS,
    _require,
    number,
    unit_text,
)

__all__ = ["ASKS", "DEFAULT_CHECK_SIG_FIGS", "DEFAULT_MIN_SIG_FIGS", "DIRECTION_MODES", "G_NINE_EIGHT", "G_TEN",
           "KINDS", "MARK_CODES", "OPTION_LETTERS", "PART_IDS", "PART_WAY_SIG_FIGS", "Alternative", "Arrow", "Body",
           "ChoicePart", "Diagram", "Ecf", "ExplainPart", "Given", "Graph", "GraphPart", "Mark", "Mistake", "Option",
           "Part", "Question", "Reading", "Sketch", "Step", "choices_in_order", "format_reading", "number",
           "reading_places", "unit_text"]


@dataclass(frozen=True)
class Given:
    """A number the question's text states, as it is written there (e.g. 5.0 N)."""

    name: str
    value: float
    unit: str
    sig_figs: int

    @property
    def text(self) -> str:
        """The number as the question prints it, e.g. "5.0"."""
        return number(self.value, self.sig_figs)



@dataclass(frozen=True)
class Mark:
    """One line of the mark scheme (physics_figures.textformat), the mark it earns and its part(s).

    part: the ids of the parts the line belongs to ("a", or "ab" for working that
    serves two parts); "" in a one-part question means that part. A line of two parts is
    earned in one of them (``Question.owner``), so a right part never shows fewer than its
    own marks. earns: "direction" for the B1 that is a direction's own (it alone is lost
    for a wrong direction); otherwise the line's code says what it earns (marking.py).
    """

    text: str
    code: str = ""
    part: str = ""
    _: KW_ONLY
    earns: str = ""

    def __post_init__(self):
        _require(self.code in MARK_CODES, "code", self.code, f"must be one of {MARK_CODES}")
        _require(not self.earns or self.code == "B1", "earns", self.earns,
                 "is for a B1 line (a direction's own mark); C1, M1 and A1 earn what their code says")
        if self.earns:
            marking.line_roles(self.code, earns=self.earns)  # raises ValueError naming a bad role
        _require("$" not in self.text, "text", self.text,
                 "must be in the text format (m s<sup>−1</sup>, ×, −), not $...$ maths")
        textformat.parse(self.text)  # raises ValueError naming a bad tag


@dataclass(frozen=True)
class Question:
    """A question's data: the numbers its text states, its parts and its mark scheme."""

    key: str
    givens: tuple[Given, ...]
    parts: tuple[Part | GraphPart | ChoicePart | ExplainPart | TextPart, ...]
    mark_scheme: tuple[Mark, ...]
    #: The question as the student reads it (physics_figures.textformat), for a template;
    #: empty when the page states it (worked examples' try-first parts).
    text: str = ""
    #: The graph the question prints, when a part reads from it (GraphPart).
    graph: Graph | None = None
    #: The situation drawn beside the text (bodies before and after), from the variant's givens.
    diagram: Diagram | None = None

    def __post_init__(self):
        readings = [p for p in self.parts if p.reads_graph]
        # a "which graph?" item shows its graph too: its options are sketches drawn from it
        # (and a sketch part may be drawn from one)
        sketches = any(p.sketches or p.drawn_from_graph for p in self.parts)
        _require(bool(readings) == (self.graph is not None) or (sketches and not readings), "graph", self.graph,
                 f"goes with a part read from it (GraphPart) in {self.key}: both or neither")
        carried = [r for p in self.parts for r in getattr(p, "readings", ())]
        _require(not carried or self.graph is not None, "readings", carried,
                 f"are read off a graph, which {self.key} does not print")
        if self.graph is not None:
            halves = (self.graph.time_division / 2, self.graph.value_division / 2)
            for part in (*readings, *carried):
                _require(any(math.isclose(part.tolerance, h, rel_tol=1e-9) for h in halves), "tolerance",
                         part.tolerance, f"must be half a small square of the graph, {halves} ({self.key})")
        _require(re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", self.key) is not None, "key", self.key,
                 "must be lower-case words joined by hyphens")
        _require(len(self.parts) >= 1, "parts", self.parts, "must hold at least one part")
        _require(any(m.code for m in self.mark_scheme), "mark_scheme", self.mark_scheme,
                 "must award at least one mark")
        self._check_mark_codes()
        self._check_ecf()
        self._check_direction_lines()
        self._check_dependent_a1()
        if self.text:
            textformat.parse(self.text)  # raises ValueError naming a bad tag

    def _check_ecf(self) -> None:
        """Every method of a later part must give its key from the earlier keys: one source."""
        answers = dict(zip(self.part_ids, (p.value for p in self.parts), strict=True))
        for index, part in enumerate(self.parts):
            for method in part.ecf_methods:
                _require(all(PART_IDS.index(u) < index for u in method.uses), "ecf", method.formula,
                         f"may use only earlier parts than ({self.part_ids[index]}) in {self.key}")
                worked = method.evaluate(answers)
                if part.direction != "signed":
                    worked = abs(worked)
                _require(math.isclose(worked, part.value, rel_tol=1e-9, abs_tol=1e-12), "ecf", method.formula,
                         f"must give ({self.part_ids[index]})'s key {part.value!r} in {self.key}, not {worked!r}")

    def _check_direction_lines(self) -> None:
        """A line that earns a direction belongs to a part that asks for one."""
        for mark in self.mark_scheme:
            if mark.earns == "direction":
                part = self.parts[self.part_ids.index(self.owner(mark))]
                _require(part.direction != "none", "earns", mark.earns,
                         f"'direction' needs a part that asks for a direction ({self.key}: {mark.text!r})")

    def _check_dependent_a1(self) -> None:
        """9702's M1 A1: the A1 needs the M1 before it (marking_rules.json, "dependent-a1"), so a
        named mistake of a part with an M1 may not keep the answer's line and lose the method's."""
        for part_id, part in zip(self.part_ids, self.parts, strict=True):
            if not any(m.code == "M1" and self.owner(m) == part_id for m in self.mark_scheme if m.code):
                continue
            for mistake in getattr(part, "mistakes", ()):
                _require(not ("method" in mistake.loses and "answer" not in mistake.loses), "keeps",
                         mistake.keeps, f"keeps the A1 without the M1 it depends on ({self.key} ({part_id}): "
                                        f"{mistake.name})")

    def owner(self, mark: Mark) -> str:
        """The part whose marks a line counts in. A line of two parts ("(a, b) C1 C1") goes to
        the one of them with fewer marks so far (the earlier on a tie), so the working's marks
        stay spread over the parts it serves and each is earned on that part's own terms."""
        return self._owners[self.mark_scheme.index(mark)]

    @cached_property
    def _owners(self) -> list[str]:
        counts = dict.fromkeys(self.part_ids, 0)
        owners: list[str] = [""] * len(self.mark_scheme)
        shared = []
        for index, mark in enumerate(self.mark_scheme):
            if not mark.code:
                continue
            parts = self.parts_of(mark)
            if len(parts) == 1:
                owners[index] = parts[0]
                counts[parts[0]] += 1
            else:
                shared.append((index, parts))
        for index, parts in shared:
            fewest = min(parts, key=lambda part: (counts[part], parts.index(part)))
            owners[index] = fewest
            counts[fewest] += 1
        return owners

    def part_marks(self) -> list[int]:
        """The marks of each part, [2] on a paper: the one number the site, the sheets and
        Moodle print."""
        owners = [o for o in self._owners if o]
        return [owners.count(part_id) for part_id in self.part_ids]

    def line_roles(self, mark: Mark) -> tuple[str, ...]:
        """What a line earns (marking.py). In a part that asks for a direction but has no line
        of its own for it, the answer line carries the direction: a wrong one loses the A1."""
        roles = marking.line_roles(mark.code, earns=mark.earns)
        part_id = self.owner(mark)
        part = self.parts[self.part_ids.index(part_id)]
        own_line = any(m.earns == "direction" for m in self.mark_scheme if m.code and self.owner(m) == part_id)
        if part.direction != "none" and not own_line and "answer" in roles:
            roles = (*roles, "direction")
        return roles

    def part_lines(self, part_id: str) -> list[tuple[str, tuple[str, ...]]]:
        """(code, roles) of each mark line that counts in a part, in the scheme's order."""
        return [(m.code, self.line_roles(m)) for m in self.mark_scheme if m.code and self.owner(m) == part_id]

    def scheme_alternatives(self, index: int) -> tuple[Alternative, ...]:
        """What the scheme's own working gives for a later part: its formula worked from the
        earlier answers as the key prints them, where that differs from the key at the
        marker's precision (an examiner credits it)."""
        part = self.parts[index]
        if part.reads_graph or not part.ecf_methods:
            return ()
        printed = {pid: round_number(p.value, p.shown_sig_figs) if p.value is not None else None
                   for pid, p in zip(self.part_ids, self.parts, strict=True)}
        found: dict[str, Alternative] = {}
        for method in part.ecf_methods:
            if any(printed[u] is None for u in method.uses):
                continue
            value = method.evaluate({u: float(printed[u]) for u in method.uses})
            value = value if part.direction == "signed" else abs(value)
            typed = number(value, part.check_sig_figs)
            if part._accepted(value) or part._named(value) or part._allowed(value) or typed in found:
                continue
            found[typed] = Alternative(value, "the value the scheme's working gives from the "
                                              "earlier answers as printed")
        return tuple(found.values())

    def carried_mistakes(self, index: int) -> dict[str, tuple[str, ...]]:
        """{name: the earlier parts it follows from} for each named mistake of a later part that
        one of its ecf methods gives from the same-named mistake in the earlier parts it uses
        (the rest right): sin and cos swapped in (a) and (b) gives (d)'s "sin and cos swapped".
        After those earlier answers it earns ecf like any wrong answer carried forward
        (CLARIFICATIONS, "ecf after a named mistake"): the browser's engine carries the earlier
        answer with all the figures of the value it matched (marking.js, earlierValues)."""
        part = self.parts[index]
        keys = dict(zip(self.part_ids, (p.value for p in self.parts), strict=True))
        found: dict[str, tuple[str, ...]] = {}
        for mistake in getattr(part, "mistakes", ()):
            if mistake.unit is not None or mistake.direction is not None:
                continue
            for method in part.ecf_methods:
                earlier = {u: {m.name: m.value for m in self.parts[self.part_ids.index(u)].mistakes}
                           for u in method.uses}
                showing = tuple(u for u in method.uses if mistake.name in earlier[u])
                if not showing:
                    continue
                worked = method.evaluate({**keys, **{u: earlier[u][mistake.name] for u in showing}})
                worked = worked if part.direction == "signed" else abs(worked)
                if math.isclose(worked, mistake.value, rel_tol=1e-9, abs_tol=1e-12):
                    found[mistake.name] = showing
                    break
        return found

    def _check_mark_codes(self) -> None:
        """9702's codes: M1 only where a part asks to show, explain or state; every A1
        after a C1 or M1 of its own part (an answer alone is a B1)."""
        earned: set[str] = set()
        for mark in self.mark_scheme:
            if not mark.code:
                continue
            parts = self.parts_of(mark)
            for part_id in parts:
                part = self.parts[self.part_ids.index(part_id)]
                if mark.code == "M1":
                    _require(part.asks != "calculate", "code", mark.code,
                             f"M1 is for show that, explain or state, not for a calculation step "
                             f"({self.key} ({part_id}): {mark.text!r}); use C1")
                if mark.code == "A1":
                    _require(part_id in earned, "code", mark.code,
                             f"A1 needs a C1 or M1 before it in its part ({self.key} ({part_id}): "
                             f"{mark.text!r}); a result on its own is B1")
            if mark.code in ("C1", "M1"):
                earned.update(parts)

    def parts_of(self, mark: Mark) -> tuple[str, ...]:
        """The ids of the parts a mark line belongs to."""
        if not mark.part:
            _require(len(self.parts) == 1, "part", mark.part,
                     f"must name the part of each mark line in {self.key}, which has several")
            return ("a",)
        for part_id in mark.part:
            _require(part_id in self.part_ids, "part", mark.part, f"must be among {self.part_ids}")
        return tuple(mark.part)

    @property
    def part_ids(self) -> tuple[str, ...]:
        """"a", "b", ... (one part alone has the id "a" too)."""
        return PART_IDS[:len(self.parts)]

    def label(self, index: int) -> str:
        """"(a) " before a part's prompt when there are several parts, else ""."""
        return f"({self.part_ids[index]}) " if len(self.parts) > 1 else ""

    @property
    def marks(self) -> int:
        return sum(1 for m in self.mark_scheme if m.code)

    def browser_data(self) -> dict:
        """What the marking script needs: the parts and, per mark line, the part it counts in,
        its code and the roles it plays (marking.py)."""
        parts = []
        for index, (part_id, part) in enumerate(zip(self.part_ids, self.parts, strict=True)):
            data = part.browser_data(part_id)
            extra = self.scheme_alternatives(index)
            if extra:
                data["alternatives"] = data["alternatives"] + [{"value": a.value, "why": a.why} for a in extra]
            parts.append(data)
        lines = [m for m in self.mark_scheme if m.code]
        # the givens: help on a later part tells an earlier part's answer from a given that
        # has its value (static/help-steps.js)
        return {"id": self.key, "parts": parts,
                "marks": [self._line_data(m, index, lines) for index, m in enumerate(lines)],
                "givens": [{"value": g.value, "unit": g.unit} for g in self.givens]}

    def _line_data(self, mark: Mark, index: int, lines: list[Mark]) -> dict:
        data = {"part": self.owner(mark), "code": mark.code, "roles": list(self.line_roles(mark)),
                "html": textformat.to_html(mark.text, paragraphs=False) if self.text else ""}
        part = self.parts[self.part_ids.index(data["part"])]
        if part.self_marked and mark.code == "A1":
            # a self-marked A1 depends on the M1 before it in its part (9702's M1 A1)
            before = [i for i in range(index) if lines[i].code == "M1" and self.owner(lines[i]) == data["part"]]
            if before:
                data["needs"] = before[-1]
        return data

    def variant_data(self) -> dict:
        """One variant for the browser's New numbers: its text, mark scheme and marking data."""
        return {"text": self.text_html(), "scheme": self.mark_scheme_html(), **self.browser_data()}

    def mark_lines(self) -> list[tuple[str, str, str]]:
        """(part label, text, code) per mark-scheme line; the label only when the part changes."""
        lines, last = [], ""
        for mark in self.mark_scheme:
            label = ""
            if len(self.parts) > 1 and mark.part and mark.part != last:
                label, last = f"({', '.join(mark.part)})", mark.part
            lines.append((label, mark.text, mark.code))
        return lines

    def text_html(self) -> str:
        """The question's text as HTML (from physics_figures.textformat)."""
        return textformat.to_html(self.text)

    def mark_scheme_html(self) -> str:
        """The mark scheme as an HTML list, for a question written in the text format."""
        items = "".join(
            f"<li><p>{f'<strong>{label}</strong> ' if label else ''}"
            f"{textformat.to_html(text, paragraphs=False)}{f' <strong>{code}</strong>' if code else ''}</p></li>"
            for label, text, code in self.mark_lines())
        return f"<ul>{items}</ul>"


