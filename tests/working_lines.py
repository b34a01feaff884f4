# ruff: noqa: RUF001, RUF002, RUF003  (a mark scheme is typeset: true minus, times, halves)
"""The arithmetic steps of a mark scheme, read as an examiner reads them.

A step is "expression = result", where the expression is numbers and operators only
(+ − × / ½ ² √ brackets, sin/cos/tan of degrees, ×10ⁿ). `wrong_steps` works the expression
out from the numbers as printed and reports the step when the result, at the precision it
is printed with, is not what they give ("−4.9 + 5.5 = 0.64": it is 0.6). A line that starts
with "=" continues the line before it (the scheme's A1 after its C1).
"""

from __future__ import annotations

import ast
import itertools
import math
import operator
import re

NUMBER = r"[−-]?\d+(?:\.\d+)?(?: ?× ?10<sup>[−-]?\d+</sup>)?"
OPERATOR_SIGNS = re.compile(r"[+×/÷−\-²³√½]|<sup>|\b(?:sin|cos|tan)\b")
FUNCTIONS = {"sqrt": math.sqrt, "sin": lambda d: math.sin(math.radians(d)),
             "cos": lambda d: math.cos(math.radians(d)), "tan": lambda d: math.tan(math.radians(d))}
OPERATORS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
             ast.Pow: operator.pow, ast.USub: operator.neg, ast.UAdd: operator.pos}


def plain(text: str) -> str:
    """A scheme line without its markup; a subscript (v<sub>A</sub>) makes a symbol."""
    text = text.replace("\u202f", "").replace("\u00a0", " ")
    text = re.sub(r"<sub>.*?</sub>", "_", text)
    return re.sub(r"<(?!/?sup>)[^>]+>", "", text)


def _python(expression: str) -> str:
    s = re.sub(r"<sup>(.*?)</sup>", r"**(\1)", expression.strip())
    for printed, python in (("−", "-"), ("×", "*"), ("÷", "/"), ("·", "*"), ("½", "(1/2)"),
                            ("²", "**2"), ("³", "**3")):
        s = s.replace(printed, python)
    s = re.sub(r"√\s*\(", "sqrt(", s)
    s = re.sub(r"√\s*([\d.]+)", r"sqrt(\1)", s)
    s = re.sub(r"\b(sin|cos|tan)\s*\(?\s*([\d.]+)\s*°\)?", r"\1(\2)", s)
    s = re.sub(r"(\d)\s*(\(|sin|cos|tan|sqrt)", r"\1*\2", s)  # 2(3 + 4), 1.8 cos 60°: implied times
    return re.sub(r"\)\s*(\d|\()", r")*\1", s)


def _value(node: ast.AST) -> float:
    if isinstance(node, ast.Constant) and isinstance(node.value, int | float):
        return float(node.value)
    if isinstance(node, ast.BinOp) and type(node.op) in OPERATORS:
        return OPERATORS[type(node.op)](_value(node.left), _value(node.right))
    if isinstance(node, ast.UnaryOp) and type(node.op) in OPERATORS:
        return OPERATORS[type(node.op)](_value(node.operand))
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS
            and len(node.args) == 1):
        return FUNCTIONS[node.func.id](_value(node.args[0]))
    raise ValueError("not arithmetic")


def evaluate(expression: str) -> float | None:
    """The value of a purely numeric expression as printed; None for anything else (a
    number alone, or words and symbols)."""
    if not OPERATOR_SIGNS.search(expression.strip().lstrip("−-")):
        return None
    try:
        return _value(ast.parse(_python(expression), mode="eval").body)
    except (SyntaxError, ValueError, ZeroDivisionError, OverflowError):
        return None


def result(text: str) -> tuple[float, float] | None:
    """The number a segment starts with, as a result, and the place of its last digit (the
    trailing zeros of a whole number hold the place: 9970 is to the nearest 10)."""
    found = re.match(rf"\s*({NUMBER})", text)
    if not found or re.match(r"\s*[A-Za-z]?[×+−/*(]|[A-Za-z(]", text[found.end():] or " "):
        return None  # the start of another expression, not a result
    mantissa, _, power = found[1].replace("−", "-").partition("×")
    mantissa = mantissa.strip()
    exponent = int(re.sub(r"[^\d-]", "", power)) if power else 0
    if "." in mantissa:
        place = exponent - len(mantissa.split(".")[1])
    else:
        digits = mantissa.lstrip("-")
        place = exponent + len(digits) - len(digits.rstrip("0")) if digits.strip("0") else exponent
    return float(mantissa) * 10**exponent, 10.0**place


def scheme_lines(question) -> list[str]:
    """Each part's scheme lines, a line that starts with "=" joined to the one before."""
    joined: list[tuple[str, str]] = []
    for mark in question.mark_scheme:
        text = plain(mark.text)
        if text.lstrip().startswith("=") and joined and joined[-1][0] == mark.part:
            joined[-1] = (mark.part, f"{joined[-1][1]} {text.strip()}")
        else:
            joined.append((mark.part, text))
    return [text for _, text in joined]


def wrong_steps(question) -> tuple[list[str], int]:
    """The steps whose printed numbers do not give their printed result, and how many
    steps were checked."""
    wrong, checked = [], 0
    for text in scheme_lines(question):
        for left, right in itertools.pairwise(re.split(r"\s=\s|^=\s", text)):
            expression = left.rsplit(":", 1)[-1]  # "Momentum: 0.20 × 3.0 + ..." -> the sum
            printed, value = result(right), evaluate(expression)
            if printed is None or value is None:
                continue
            checked += 1
            number, place = printed
            # a size printed without its sign (the direction is stated in words) counts too
            if min(abs(value - number), abs(abs(value) - abs(number))) > place / 2 * (1 + 1e-9):
                wrong.append(f"{expression.strip()} = {right.strip()[:40]} (the numbers give {value:.4g})")
    return wrong, checked
