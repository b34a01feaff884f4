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
from functools import cache
from pathlib import Path

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
    """{"min": figures the A1 needs, "check": figures the key is trusted to, "feedback" and
    "feedback_padded": what a too-few-figures answer reads (too_few_sf_feedback)}."""
    table = rules()["sig_figs"]
    return {key: table[key] for key in ("min", "check", "feedback", "feedback_padded")}


def too_few_sf_feedback(few: int, *, min_sf: int | None = None, check_sf: int | None = None,
                        padded: bool = False) -> str:
    """The feedback on the key given to ``few`` s.f. where the A1 needs ``min_sf`` (the table's
    by default): "1 s.f.: the A1 needs 2 or more. Work to 3 s.f.; give 2 or
    more." padded: written with zeros after it (60. or 6.0e1 for 64), the same slip. The
    browser's engine (question-kinds/numeric.js) fills the same texts the same way."""
    table = sig_figs()
    min_sf = table["min"] if min_sf is None else min_sf
    check_sf = table["check"] if check_sf is None else check_sf
    if not 1 <= few < min_sf:
        raise ValueError(f"few must be at least 1 and fewer than min_sf={min_sf} (got few={few!r})")
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
