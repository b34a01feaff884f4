"""One way to write a number (physics_figures.notation), checked against the shared case
table that the browser's twin (notation.js) also runs: tests/js/notation.test.js."""

import json
import re
from pathlib import Path

import pytest

from physics_figures.notation import (
    format_number,
    format_quantity,
    join_units,
    plain_number,
    round_number,
    tex_number,
)

CASES = json.loads((Path(__file__).parents[1] / "notation_cases.json").read_text())["cases"]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c['value']}-{c.get('sig_figs', c.get('decimals'))}")
def test_format_number_writes_each_case_of_the_shared_table(case):
    text = format_number(case["value"], case.get("sig_figs"), decimals=case.get("decimals"),
                         plus=case.get("plus", False))
    assert text == case["text"], case.get("why", "")


def test_tex_and_plain_forms_keep_the_same_digits():
    assert tex_number("\u22121.5 \u00d7 10\u207b\u2074") == r"-1.5 \times 10^{-4}"
    assert tex_number("30\u202f000") == r"30\,000"
    assert plain_number("\u22121.5 \u00d7 10\u2075") == "-1.5e5"
    assert plain_number("30\u202f000") == "30000"


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"sig_figs": 0}, "sig_figs must be a whole number of at least 1"),
    ({"sig_figs": 2, "decimals": 1}, "give exactly one of sig_figs and decimals"),
    ({}, "give exactly one of sig_figs and decimals"),
    ({"decimals": -1}, "decimals must be a whole number, 0 or more"),
])
def test_a_bad_precision_is_refused_with_the_rule(kwargs, message):
    with pytest.raises(ValueError, match=message):
        round_number(1.0, kwargs.pop("sig_figs", None), **kwargs)


def test_a_value_that_is_not_finite_is_refused():
    with pytest.raises(ValueError, match=r"value must be a finite number \(got value=nan\)"):
        format_number(float("nan"), 2)


def test_no_other_code_rounds_a_number_for_print():
    """notation.py and notation.js are the only number writers: no other module formats with
    a precision of its own (f"{x:.2f}", round(x, n), toPrecision, toFixed for text)."""
    root = Path(__file__).resolve().parents[2]
    python = re.compile(r"\{[^{}]*:[^{}]*\.\d+[fge]\}|\bround\([^()]*,\s*\w+\)|Decimal\(")
    offenders = [path.relative_to(root).as_posix()
                 for path in sorted((root / "physics_figures").rglob("*.py"))
                 # models/ may import only constants: its error messages use Python's own format
                 if path.name != "notation.py" and "models" not in path.parts
                 and python.search(path.read_text())]
    javascript = re.compile(r"toPrecision\(|toFixed\(")
    for path in sorted((root / "book" / "_ext").rglob("*.js")):
        lines = [line for line in path.read_text().splitlines() if javascript.search(line)
                 # an input's own value and an SVG path's coordinates are not printed numbers
                 and not re.search(r"\.value = Number\(|self\.[xy]\(", line)]
        if lines and path.name != "notation.js":
            offenders.append(path.relative_to(root).as_posix())
    assert not offenders, f"format numbers with physics_figures.notation / notation.js: {offenders}"


QUANTITIES = json.loads((Path(__file__).parents[1] / "notation_cases.json").read_text())["quantities"]


@pytest.mark.parametrize("case", QUANTITIES, ids=lambda c: f"{c['value']}-{c['unit']}")
def test_format_quantity_joins_number_and_unit_as_the_shared_table_says(case):
    text = format_quantity(case["value"], case.get("sig_figs"), case["unit"], decimals=case.get("decimals"))
    assert text == case["text"], case.get("why", "")


PROSE = json.loads((Path(__file__).parents[1] / "notation_cases.json").read_text())["prose"]


@pytest.mark.parametrize("case", PROSE, ids=lambda c: c["text"].strip())
def test_join_units_joins_every_number_to_its_unit_in_prose(case):
    assert join_units(case["text"], after_number=case.get("after_number", False)) == case["joined"], case.get("why")


def test_every_unit_the_questions_use_is_one_join_units_knows():
    from physics_figures.bank import TEMPLATES
    from physics_figures.notation import UNIT_SYMBOLS

    used = set()
    for template in TEMPLATES.values():
        for part in template.variant(0).parts:
            for symbol in re.split(r"[ /]", getattr(part, "unit", "") or ""):
                used.add(re.sub(r"\^-?\d+$", "", symbol))
    used -= {"", "degrees", "per", "%", "°"}
    assert used, "no units found: the bank's interface changed"
    assert used <= set(UNIT_SYMBOLS), sorted(used - set(UNIT_SYMBOLS))
