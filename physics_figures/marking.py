# ruff: noqa: RUF001, RUF003  (a number as students type it: the times sign)

"""How marks are earned: the rule table (``marking_rules.json``), read once.

A part's marks are its mark lines. Each line plays a role: "method" (C1, M1: a step of the
working), "answer" (A1, or a B1 that is the answer itself) or "direction" (the B1 that is
the direction's own). The browser's engine classifies an answer (right, 1 s.f., unit
missing, a named mistake...); the table says which roles that outcome loses, and a line
earns its mark unless it plays a lost role. The table is JSON so that this module and the
browser (which gets its ``outcomes`` from the build) read the same rules: the engine
(``marking.js`` and the kinds' markers) has no marking rule of its own.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from .notation import format_number, plain_number

RULES_FILE = Path(__file__).with_name("marking_rules.json")
#: The roles a mark line can play, in the order feedback names them.
ROLES = ("method", "answer", "direction")
#: What a named mistake is, for what it keeps (CLARIFICATIONS, "Marks: the rule table").
MISTAKE_KINDS = ("slip", "direction", "physics")


@cache
def rules() -> dict:
    """The whole rule table: roles of each code, what each outcome and each kind of mistake loses."""
    return json.loads(RULES_FILE.read_text(encoding="utf-8"))


def outcome_losses() -> dict[str, list[str]]:
    """{outcome code: the roles it loses}, for the browser (a named mistake's are its own)."""
    return {code: rule["loses"] for code, rule in rules()["outcomes"].items()
            if isinstance(rule["loses"], list)}


def slips() -> dict[str, dict]:
    """{name: {"outcomes": [codes], "rule": code}}: the slips a student's record names as
    mistakes (a sign or direction, a unit, 1 s.f.), and the rule each links to."""
    return rules()["slips"]["names"]


def outcome_slips() -> dict[str, str]:
    """{outcome code: the slip's name}, for the browser's engine."""
    return {code: name for name, slip in slips().items() for code in slip["outcomes"]}


def sig_figs() -> dict:
    """The s.f. rule, as the browser's engine gets it: {"min": figures the A1 needs, "check":
    figures the key is trusted to, "fewest": the fewest figures a too-few answer is judged at,
    "whole_number_zeros": how a whole number's trailing zeros count, "part_way": the figures
    that rounding part-way rounds to, "feedback" and "feedback_padded": what a too-few-figures
    answer reads (too_few_sf_feedback)}."""
    table = rules()["sig_figs"]
    return {key: table[key] for key in ("min", "check", "fewest", "whole_number_zeros", "part_way",
                                        "feedback", "feedback_padded")}


def too_few_sf_feedback(few: int, *, min_sf: int | None = None, check_sf: int | None = None,
                        padded: bool = False) -> str:
    """The feedback on the key given to ``few`` s.f. where the A1 needs ``min_sf`` (the table's
    by default): "1 s.f.: the A1 needs 2 or more. Work to 3 s.f.; give 2 or
    more." padded: written with zeros after it (60. or 6.0e1 for 64), the same slip. The
    browser's engine (question-kinds/numeric.js) fills the same texts the same way."""
    table = sig_figs()
    min_sf = table["min"] if min_sf is None else min_sf
    check_sf = table["check"] if check_sf is None else check_sf
    if not table["fewest"] <= few < min_sf:
        raise ValueError(f"few must be at least {table['fewest']} and fewer than min_sf={min_sf} (got few={few!r})")
    text = table["feedback_padded" if padded else "feedback"]
    return text.format(few=few, min=min_sf, work=max(check_sf, min_sf + 1))


def mark_names() -> dict[str, str]:
    """What feedback calls a mark line: {code or "direction" or "point": name}, e.g. "C1":
    "method mark" (the browser's engine glosses each code it names with these)."""
    return {key: name for key, name in rules()["mark_names"].items() if key != "why"}


def mistake_losses(kind: str) -> tuple[str, ...]:
    """The roles a named mistake of this kind loses by default."""
    kinds = rules()["mistakes"]
    if kind not in kinds:
        raise ValueError(f"kind must be one of {tuple(kinds)} (got kind={kind!r})")
    return tuple(kinds[kind]["loses"])


def line_roles(code: str, *, earns: str = "") -> tuple[str, ...]:
    """The roles of a mark line: its code's, or "direction" where the line says it earns it."""
    if earns:
        if earns not in ROLES:
            raise ValueError(f"earns must be one of {ROLES} (got earns={earns!r})")
        return (earns,)
    return tuple(rules()["roles"][code])



def documented_rules() -> list[dict]:
    """The rules the docs' table shows, each with the published schemes that show it:
    [{"id", "rule", "sources": [{"paper", "says"}]}], outcomes first, then the kinds of
    named mistake ("mistake-slip"), then the general principles."""
    table = rules()
    rows = []
    for section, prefix in (("outcomes", ""), ("mistakes", "mistake-"), ("principles", "")):
        for name, rule in table[section].items():
            if rule.get("sources"):
                rows.append({"id": prefix + name, "rule": rule["rule"], "sources": rule["sources"]})
    return rows


def lines_kept(lines: list[tuple[str, tuple[str, ...]]], lost) -> int:
    """How many of a part's lines ((code, roles) each) an outcome that loses these roles keeps:
    a line is kept unless it plays a lost role (the table's one reading, for what cannot run
    the browser's engine: the sheets and Moodle)."""
    return sum(1 for _, roles in lines if not set(roles) & set(lost))


# ------------------------------------------------------------------ the s.f. judge

#: A number as students write it (the browser's reader, answer-reading.js, reads the same):
#: 4.5, -.25, 1.5e3, 1.5 x 10^3, 1.5 × 10^(3), 4.5×10 (10 to the 1).
_NUMBER = re.compile(r"^([+-]?)([0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE]([+-]?[0-9]+)|\s*[x×X*·]\s*10"
                     r"(?:\s*\^\s*(?:\(\s*([+-]?[0-9]+)\s*\)|([+-]?[0-9]+)))?)?$")
_POWER_ONLY = re.compile(r"^([+-]?)10\s*\^\s*\(?\s*([+-]?[0-9]+)\s*\)?$")
_SUPERSCRIPT_DIGITS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")


@dataclass(frozen=True)
class Written:
    """A number as written: its value, the significant figures it may have (sf_min to sf_max:
    a whole number's trailing zeros may or may not count) and lead, the power of ten of its
    first significant figure (its last figure is at lead - sf + 1)."""

    value: float
    sf_min: int
    sf_max: int
    lead: int


def read_written(written: str) -> Written:
    """The number a student wrote, with its figures counted as the rule table says (leading
    zeros never, zeros after a point always, a whole number's trailing zeros as its
    "whole_number_zeros"). ValueError for what is no number (1,500; 10-3; a word)."""
    text = re.sub(r"[\u2212\u2012\u2013\u2014]", "-", str(written))
    text = re.sub(r"[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]+", lambda run: "^" + run[0].translate(_SUPERSCRIPT_DIGITS), text)
    text = re.sub(r"^([+-])\s+(?=[0-9.])", r"\1", text.replace("**", "^").strip())
    if "," in text or re.search(r"(^|[x×X*·\s])10\s*-\s*[0-9]+$", text):
        raise ValueError(f"written must be a number with a decimal point and a power as 10^-3 or e-3 "
                         f"(got written={written!r})")
    if match := _NUMBER.match(text):
        sign, mantissa = match[1], match[2]
        powers = [int(p) for p in match.groups()[2:] if p is not None]
        exponent = powers[0] if powers else int(bool(re.search("[x×X*·]", text[len(sign) + len(mantissa):])))
    elif match := _POWER_ONLY.match(text):
        sign, mantissa, exponent = match[1], "1", int(match[2])
    else:
        raise ValueError(f"written must be a number such as 7.5, -0.25, 1.5e3 or 1.5 × 10^3 (got written={written!r})")
    whole, _, fraction = mantissa.partition(".")
    digits = (whole + fraction).lstrip("0")
    value = float(f"{sign}{mantissa}e{exponent}")
    if not digits:  # zero: only the decimal places written say anything
        figures = max(1, len(fraction))
        return Written(value, figures, figures, -len(fraction) + figures - 1 + exponent)
    sf_max = len(digits)
    sf_min = sf_max if "." in mantissa or _whole_number_zeros_count() else max(1, len(digits.rstrip("0")))
    leading = len(whole.lstrip("0")) - 1 if whole.lstrip("0") else -(len(fraction) - len(fraction.lstrip("0")) + 1)
    return Written(value, sf_min, sf_max, leading + exponent)


def _whole_number_zeros_count() -> bool:
    """Whether a whole number's trailing zeros are significant (the rule table's
    "whole_number_zeros": "significant"), rather than ambiguous ("ambiguous": 4500 has 2 to 4)."""
    rule = sig_figs()["whole_number_zeros"]
    if rule not in ("ambiguous", "significant"):
        raise ValueError(f"whole_number_zeros must be 'ambiguous' or 'significant' (got whole_number_zeros={rule!r})")
    return rule == "significant"


@dataclass(frozen=True)
class SigFigJudgement:
    """What the judge makes of a written value against a key: ``code`` the rule table's outcome
    ("correct": the key to min or more figures; "too-few-sf": the key to fewer, however many
    zeros follow it; "wrong"), and for "too-few-sf" the figures its feedback names (``few``) and
    whether zeros written after it make it look like more (``padded``: 60. or 6.0e1 for 64);
    min_sf and check_sf: the figures it was judged with."""

    code: str
    min_sf: int
    check_sf: int
    few: int | None = None
    padded: bool = False

    @property
    def feedback(self) -> str:
        """The rule table's feedback on a too-few answer ("" for the others)."""
        if self.code != "too-few-sf":
            return ""
        return too_few_sf_feedback(self.few, min_sf=self.min_sf, check_sf=self.check_sf, padded=self.padded)


def _steps(x: float, place: int) -> list[int]:
    """Whole numbers of steps of 10^place nearest x; both neighbours on a tie."""
    q = x / 10.0**place
    n = math.floor(q)
    if abs(q - n - 0.5) < 1e-7:
        return [n, n + 1]
    return [n if q - n < 0.5 else n + 1]


def _rounds_to(value: float, key: float, figures: int) -> bool:
    """Whether value is the key rounded to ``figures`` s.f. (60 for 56.0 at 1 s.f.; not 10 for 7.5)."""
    place = math.floor(math.log10(abs(key)) + 1e-12) - figures + 1
    scaled = value / 10.0**place
    return (any(abs(abs(scaled) - n) < 1e-7 * max(1, n) for n in _steps(abs(key), place))
            and (value < 0) == (key < 0))


def judge_sig_figs(written: str, key: float, *, min_sf: int | None = None,
                   check_sf: int | None = None) -> SigFigJudgement:
    """The one judge of a written answer's significant figures against a (signed) key, as the
    browser's numeric kind marks it (question-kinds/numeric.js, compare; the shared case table
    tests/fixtures/sig_fig_cases.json runs through both). The answer is compared with the key
    at its own last figure, at each count of figures it may have, but never finer than the
    key's check_sf-th figure (the key is trusted that far); right at min_sf or more figures is
    "correct", the key rounded to fewer (from the table's "fewest") is "too-few-sf". min_sf and
    check_sf are the rule table's unless a part says otherwise."""
    table = sig_figs()
    min_sf = table["min"] if min_sf is None else min_sf
    check_sf = table["check"] if check_sf is None else check_sf
    if not 1 <= min_sf <= check_sf:
        raise ValueError(f"min_sf must be between 1 and check_sf={check_sf} (got min_sf={min_sf!r})")
    number = read_written(written)
    if key == 0:  # zero has no significant figures
        return SigFigJudgement("correct" if number.value == 0 else "wrong", min_sf, check_sf)
    key_lead = math.floor(math.log10(abs(key)) + 1e-12)
    check_place = key_lead - check_sf + 1
    # Right: equal to the key at the answer's last figure, where that figure is no coarser than
    # the key's min_sf-th ("1.0" is 0.97 to 1 s.f., not 2), or the key rounded to min_sf or more
    # figures where rounding carries into a new digit ("1.0" for 0.997 to 2 s.f.).
    for figures in range(max(number.sf_min, min_sf), number.sf_max + 1):
        place = max(number.lead - figures + 1, check_place)
        if place <= key_lead - min_sf + 1 and any(
                a == b for a in _steps(number.value, place) for b in _steps(key, place)):
            return SigFigJudgement("correct", min_sf, check_sf)
    carried = abs(number.value) >= 10.0 ** (key_lead + 1)
    if carried and any(number.sf_min <= f <= number.sf_max and _rounds_to(number.value, key, f)
                       for f in range(min_sf, check_sf + 1)):
        return SigFigJudgement("correct", min_sf, check_sf)
    few = max((f for f in range(table["fewest"], min_sf) if _rounds_to(number.value, key, f)), default=None)
    if few is None:
        return SigFigJudgement("wrong", min_sf, check_sf)
    few = min(number.sf_max, few)
    return SigFigJudgement("too-few-sf", min_sf, check_sf, few, number.sf_max > few)


def written(value: float, figures: int) -> str:
    """``value`` as a student types it to ``figures`` s.f. ("4.4e-3", "-30000"): what the
    judge reads, for the code that asks how a value written so would be marked."""
    return plain_number(format_number(value, figures))
