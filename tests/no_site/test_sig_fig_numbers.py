"""Every number of the significant-figure rule lives in physics_figures/marking_rules.json
("sig_figs"), and the code reads it there (issue 39): no s.f. number is typed in the code that
marks, keys or exports answers. Found by reading the source, as a reviewer would:

- a name for figures (sig_figs, SIG_FIGS, min_sf, minSf, sfMax, few, ...) given a number: assigned
  one (a constant, a field's default, a parameter's default, a loop over numbers), compared
  with one above 1, or defaulted to one (``|| 2``);
- in the modules that judge and write keys, a number rounded or written to a typed count of
  figures (round_number(x, 2), format_number(x, 3)).

A template's own figures (a keyword in its Part(...) call: the notes' precision, or a scheme
that allows 1 s.f.) are its data, not the rule. The figures (figures/: labels), the models and
the explorables' readouts do not mark, and vendored scripts are not ours."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "physics_figures"
#: The Python that marks, keys and exports answers: the package but for what only draws or
#: computes physics, and the scripts.
PYTHON = sorted(path for path in [*PACKAGE.rglob("*.py"), *(ROOT / "scripts").rglob("*.py"),
                                  *(ROOT / "book" / "_ext" / "questions").glob("*.py")]
                if not {"figures", "models"} & set(path.relative_to(PACKAGE).parts[:-1]
                                                   if path.is_relative_to(PACKAGE) else ())
                and path != PACKAGE / "bank" / "diagrams.py")  # labels a figure draws: the givens as printed
#: The browser's engine, its part kinds and the pages that mark (not vendored: none lives there).
SCRIPTS = sorted((ROOT / "book" / "_ext" / "questions" / "static").rglob("*.js"))
#: Where a count of figures passed to a rounding or writing function is the rule's.
JUDGES = [PACKAGE / name for name in ("marking.py", "questions.py", "variants.py")] + sorted(
    [*(PACKAGE / "parts").glob("*.py"), *(PACKAGE / "worksheets").glob("*.py")])
ROUNDING = {"round_number", "format_number", "number", "format_quantity", "_value_with_unit", "_band",
            "_round_sf", "band_takes", "accepted_band", "written", "typed"}
FIGURES_NAME = re.compile(r"(?i:sig_?figs?|(?:^|_)sf(?:_|$))|[a-z]Sf(?:[A-Z]|$)|^sf[A-Z]|^few$")


def _literal(node: ast.AST | None) -> bool:
    """A number typed in (or a tuple, list or choice of them)."""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, int) and not isinstance(node.value, bool)
    if isinstance(node, ast.Tuple | ast.List):
        return bool(node.elts) and all(_literal(e) for e in node.elts)
    if isinstance(node, ast.IfExp):
        return _literal(node.body) or _literal(node.orelse)
    return False


def _names(target: ast.AST) -> list[str]:
    if isinstance(target, ast.Name):
        return [target.id]
    if isinstance(target, ast.Attribute):
        return [target.attr]
    if isinstance(target, ast.Tuple | ast.List):
        return [name for element in target.elts for name in _names(element)]
    return []


def _defaults(args: ast.arguments) -> list[tuple[str, ast.AST | None]]:
    positional = [*args.posonlyargs, *args.args]
    pairs = list(zip([a.arg for a in positional[len(positional) - len(args.defaults):]], args.defaults, strict=True))
    return pairs + [(a.arg, d) for a, d in zip(args.kwonlyargs, args.kw_defaults, strict=True)]


def python_figures_typed(source: str, *, judge: bool) -> list[str]:
    """Each s.f. number typed in a Python module: "line N: what"."""
    found = []
    for node in ast.walk(ast.parse(source)):
        pairs: list[tuple[str, ast.AST | None]] = []
        if isinstance(node, ast.Assign):
            pairs = [(name, node.value) for target in node.targets for name in _names(target)]
        elif isinstance(node, ast.AnnAssign | ast.AugAssign):
            pairs = [(name, node.value) for name in _names(node.target)]
        elif isinstance(node, ast.For):
            pairs = [(name, node.iter) for name in _names(node.target)]
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            pairs = _defaults(node.args)
        elif isinstance(node, ast.Compare) and isinstance(node.left, ast.Name | ast.Attribute):
            pairs = [(name, c) for name in _names(node.left) for c in node.comparators
                     if isinstance(c, ast.Constant) and isinstance(c.value, int) and c.value > 1]
        elif judge and isinstance(node, ast.Call):
            called = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if called in ROUNDING:
                figures = [*node.args[1:2], *(k.value for k in node.keywords if k.arg and FIGURES_NAME.search(k.arg))]
                pairs = [(f"{called}(...)", value) for value in figures]
                found += [f"line {node.lineno}: {called}(..., {ast.unparse(v)})" for _, v in pairs if _literal(v)]
                continue
        found += [f"line {node.lineno}: {name} = {ast.unparse(value)}" for name, value in pairs
                  if FIGURES_NAME.search(name) and _literal(value)]
    return sorted(set(found))


#: In a script: a figures name given a number (var minSf = 2; sfMax >= 2; opts.sf || 3; sf: 2).
JS_TYPED = re.compile(r"\b([A-Za-z_$][\w$]*)\s*(?:=(?!=)|:|\|\||>=|<=|===|==|<|>)\s*\[?\s*(\d+)")


def script_figures_typed(source: str) -> list[str]:
    """Each s.f. number typed in a browser script (comments and strings aside): "line N: what"."""
    code = re.sub(r"/\*.*?\*/|//[^\n]*", lambda m: "\n" * m[0].count("\n"), source, flags=re.DOTALL)
    code = re.sub(r'"(?:\\.|[^"\\\n])*"', '""', code)
    found = []
    for number, line in enumerate(code.splitlines(), start=1):
        for name, value in JS_TYPED.findall(line):
            if FIGURES_NAME.search(name) and not (int(value) <= 1 and re.search(rf"{name}\s*[<>]=?\s*{value}", line)):
                found.append(f"line {number}: {name} … {value}")
    return found


def test_the_scan_reads_the_code_it_names():
    assert len(PYTHON) > 40 and len(SCRIPTS) > 20 and len(JUDGES) > 15
    assert PACKAGE / "worksheets" / "moodle.py" in PYTHON and PACKAGE / "variants.py" in JUDGES


@pytest.mark.parametrize("path", PYTHON, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_significant_figure_number_is_typed_in_the_python(path):
    typed = python_figures_typed(path.read_text(encoding="utf-8"), judge=path in JUDGES)
    assert not typed, f"{path.relative_to(ROOT)}: s.f. numbers typed in, not read from marking_rules.json: {typed}"


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_significant_figure_number_is_typed_in_the_engine_s_scripts(path):
    typed = script_figures_typed(path.read_text(encoding="utf-8"))
    assert not typed, f"{path.relative_to(ROOT)}: s.f. numbers typed in, not read from marking_rules.json: {typed}"


@pytest.mark.parametrize("line", ["RIGHT_SIG_FIGS = (2, 3)", "MISTAKE_SIG_FIGS = 3",
                                  "def band(key, sig_figs=2): pass", "for sig_figs in (2, 3, 4): pass",
                                  "shown_sig_figs: int = 2", "if number.sf_max >= 2: pass"])
def test_the_scan_finds_a_number_put_back_in_python(line):
    assert python_figures_typed(line, judge=False)


def test_the_scan_finds_a_count_of_figures_typed_in_a_judge():
    assert python_figures_typed("x = round_number(value, 2)", judge=True)
    assert not python_figures_typed("x = round_number(value, table['min'])", judge=True)


@pytest.mark.parametrize("line", ["var minSf = 2;", "if (number.sfMax >= 2) x();", "var sf = opts.sf || 3;",
                                  "for (var few = 1; few < minSf; few++) {}"])
def test_the_scan_finds_a_number_put_back_in_a_script(line):
    assert script_figures_typed(line)
