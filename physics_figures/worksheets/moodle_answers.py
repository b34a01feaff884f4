"""The answers of a Moodle numerical question (or a Cloze question's number box), in the order
Moodle tries them: the right forms the book accepts, then each slip and named mistake with the
grade of the lines it keeps (physics_figures.worksheets.moodle writes them).

Moodle's numerical question has one kind of tolerance, "nominal": an answer A with tolerance T
takes a response within A ± (T + 1e-14 max(|T|, |A|, 1e-14)) (qtype_numerical_answer::
get_tolerance_interval, PHP's precision of 14 digits), and the first answer whose range holds a
response wins. So no answer may lie inside the range of one listed before it (Moodle never
reaches it, and its import reports it): a right band that overlaps an earlier right answer is
given only as the pieces the earlier answers leave uncovered.
"""

from __future__ import annotations

import math

from .. import marking
from ..notation import round_number
from ..questions import Question
from .latex import MISTAKE_SIG_FIGS

#: The written forms of a right answer Moodle is given: the key at the figures the A1 needs and
#: at those the key is trusted to, 2 and 3 s.f. (the rule table's min and check: an answer at
#: 4 s.f. or more falls in the 3 s.f. band, as the book takes it).
RIGHT_SIG_FIGS = (marking.sig_figs()["min"], marking.sig_figs()["check"])
#: Moodle's allowed grades (question/engine/bank.php), in per cent.
MOODLE_GRADES = (100.0, 90.0, 83.33333, 80.0, 75.0, 70.0, 66.66667, 60.0, 50.0, 40.0, 33.33333, 30.0,
                 25.0, 20.0, 16.66667, 14.28571, 12.5, 11.11111, 10.0, 5.0, 0.0)
#: The width of an answer that takes one written value only (Moodle adds a tiny slack of its own).
EXACT = 1e-9


def grade(kept: int, marks: int) -> float:
    """kept of marks as a Moodle grade (per cent): the nearest allowed grade not above it
    (strict rather than lenient)."""
    if marks <= 0:
        raise ValueError(f"marks must be positive (got marks={marks!r})")
    exact = 100 * kept / marks
    return max(g for g in MOODLE_GRADES if g <= exact + 1e-4)


def _band(value: float, sig_figs: int) -> tuple[float, float]:
    """(centre, width): the value at sig_figs s.f. and half a unit in its last figure."""
    centre = float(round_number(value, sig_figs))
    if centre == 0:
        return 0.0, 0.0
    return centre, 0.5 * 10 ** (math.floor(math.log10(abs(centre))) - sig_figs + 1)


def _exact(value: float) -> tuple[float, float]:
    return value, EXACT * max(abs(value), 1e-12)


def right_forms(question: Question, index: int) -> list[tuple[float, float]]:
    """(value, width) of each 100 % answer of a numeric part, the key as it prints first: the key
    at 2 s.f. (that value only) and at 3 s.f. (half a unit in its 3rd figure), then each value
    the scheme also accepts at 3 s.f., and what readings within half a small square give; a reading
    from a graph within its tolerance."""
    part = question.parts[index]
    if part.reads_graph:
        return [(part.value, part.tolerance)]
    two = _exact(float(round_number(part.value, RIGHT_SIG_FIGS[0])))
    three = _band(part.value, RIGHT_SIG_FIGS[1])
    forms = [three, two] if part.shown_sig_figs >= RIGHT_SIG_FIGS[1] else [two, three]
    if abs(two[0] - three[0]) <= three[1]:  # the 3 s.f. band holds the 2 s.f. value: one answer
        forms = [three]
    # a key on a tie at 2 s.f. (225) is right rounded either way, as the book takes it
    step = 10 ** (math.floor(math.log10(abs(part.value))) - 1) if part.value else 0
    if step and math.isclose(abs(part.value) / step % 1, 0.5, abs_tol=1e-7):
        other = math.copysign(abs(two[0]) - step, part.value)
        forms.append(_exact(float(round_number(other, RIGHT_SIG_FIGS[0]))))
    # and on a tie at 3 s.f. (29.75) the band of each rounding (29.7 and 29.8), as the book takes it
    step = 10 ** (math.floor(math.log10(abs(part.value))) - 2) if part.value else 0
    if step and math.isclose(abs(part.value) / step % 1, 0.5, abs_tol=1e-7):
        forms.append(_band(math.copysign(abs(three[0]) - step, part.value), RIGHT_SIG_FIGS[1]))
    size = (lambda v: v) if part.direction == "signed" else abs
    # a value the scheme also accepts, at 3 s.f. and, as written to 2 s.f. (0.86 for 0.8627), that value only
    for alternative in (*part.alternatives, *question.scheme_alternatives(index)):
        forms += [_band(size(alternative.value), RIGHT_SIG_FIGS[1]),
                  _exact(float(round_number(size(alternative.value), RIGHT_SIG_FIGS[0])))]
    if part.readings:  # worked from readings of the graph: what readings within half a small square
        low, high = part.band  # give, after the key (whose value Moodle shows); not widened by the
        forms.append(((low + high) / 2, (high - low) / 2))  # student's rounding: strict
    if getattr(part, "allow_minus", ""):  # the scheme allows "-X" on this size: each form, negative too
        forms += [(-value, width) for value, width in forms]
    return uncovered(forms)


def uncovered(forms: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The ranges (value, width) as Moodle's answers, in order: the first whole, each later one
    as the pieces that the ones before it leave uncovered (none if they cover it), so that no
    answer lies inside the range of one listed before it."""
    out: list[tuple[float, float]] = []
    for value, width in forms:
        pieces = [(value - width, value + width)]
        for v, w in out:
            low, high = interval(v, w)
            pieces = [cut for a, b in pieces for cut in ((a, min(b, low)), (max(a, high), b)) if cut[1] > cut[0]]
        if len(pieces) == 1 and all(math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-300)
                                    for x, y in zip(pieces[0], (value - width, value + width), strict=True)):
            out.append((value, width))  # not overlapped (or at an end only): whole, its value as written
            continue
        # a piece narrower than a millionth of the value adds nothing Moodle could tell apart
        out += [((a + b) / 2, (b - a) / 2) for a, b in pieces if b - a > 1e-6 * max(abs(a), abs(b))]
    return out


def interval(value: float, width: float) -> tuple[float, float]:
    """The responses Moodle's numerical answer (value, tolerance) takes: nominal tolerance plus
    PHP's slack of 1e-14 (qtype_numerical_answer::get_tolerance_interval)."""
    slack = abs(width) + 1e-14 * max(abs(width), abs(value), 1e-14)
    return value - slack, value + slack


def _overlaps(value: float, width: float, taken: list[tuple[float, float]]) -> bool:
    """Ranges that share more than an end (Moodle takes the first that holds a response)."""
    return any(abs(value - v) < (width + w) * (1 - 1e-9) or value == v for v, w in taken)


def graded_answers(question: Question, index: int, *, direction_box: int = 0) -> list[tuple[float, float, float, str]]:
    """(grade, value, width, feedback as plain text) of a numeric part's answers, in the order
    Moodle tries them: the right forms, then each slip and named mistake with the grade of the
    lines it keeps, and a 1 s.f. answer. One Moodle could not reach (its band holds a right
    form or an earlier answer) is left out. direction_box: the marks a separate direction box
    gives (a Cloze question); the number's box then earns the rest of what the part keeps with
    the direction right."""
    part = question.parts[index]
    lines, losses = question.part_lines(question.part_ids[index]), marking.outcome_losses()
    rows = [(100.0, value, width, f"Right: {part.answer_text}.") for value, width in right_forms(question, index)]

    def kept(lost) -> float:
        earned = marking.lines_kept(lines, lost) - direction_box
        return grade(max(0, earned), len(lines) - direction_box)

    size = (lambda v: v) if part.direction == "signed" else abs
    wrong = [(size(m.value), kept(m.loses), f"{m.name[:1].upper()}{m.name[1:]}. {m.feedback}"
              + (f" The scheme credits this working ({m.credited})." if m.credited else ""))
             for m in part.mistakes if m.unit is None and m.direction is None]
    if part.g_nine_eight is not None:
        wrong.append((part.g_nine_eight, kept(losses["g-9.8"]),
                      "Used g = 9.8 m s⁻². The data give g = 9.81 m s⁻²: the A1 is lost."))
    wrong += [(value, kept(losses["rounded-part-way"]),
               f"Rounded {what} part-way through: keep every figure until the end. The A1 is lost.")
              for value, what in part.rounded_part_way]
    if part.direction == "signed" and part.value != 0:
        wrong.append((-part.value, kept(losses["sign"]),
                      f"The size is right but the sign is wrong: positive is {part.positive}."))
    taken = [(v, w) for _, v, w, _ in rows]
    for value, points, feedback in wrong:
        centre, width = _band(value, MISTAKE_SIG_FIGS)
        if width == 0:  # a mistake of zero: as near zero as the key's 4th figure
            width = _band(part.value, MISTAKE_SIG_FIGS + 1)[1]
        if not _overlaps(centre, width, taken):
            rows.append((points, centre, width, feedback))
            taken.append((centre, width))
    if not part.reads_graph and part.value != 0:  # right only to 1 s.f.: all but the A1
        rows += _too_few_rows(part, kept(losses["too-few-sf"]), taken)
    return rows


def _too_few_rows(part, points: float, taken: list[tuple[float, float]]) -> list[tuple[float, float, float, str]]:
    """The key written to too few figures (1 s.f., from the rule table's fewest up to the A1's
    min), with its feedback as for a number typed without zeros after it (Moodle reads the
    number, not its figures): (grade, value, width, feedback). Where the one s.f. judge takes
    that number as right (10 for 9.6 may be 2 s.f.), Moodle, which cannot see the figures, keeps
    the too-few grade: strict rather than lenient (CLARIFICATIONS, Marks: Moodle)."""
    rows = []
    for few in range(marking.sig_figs()["fewest"], part.min_sig_figs):
        value = float(round_number(part.value, few))
        judged = marking.judge_sig_figs(marking.written(value, few), part.value, min_sf=part.min_sig_figs,
                                        check_sf=part.check_sig_figs)
        if judged.code != "wrong" and not _overlaps(*_exact(value), taken):
            feedback = marking.too_few_sf_feedback(few, min_sf=judged.min_sf, check_sf=judged.check_sf)
            rows.append((points, *_exact(value), feedback))
            taken.append(_exact(value))
    return rows
