"""Does Moodle grade the exported questions as the book does? The verdict table, in a real Moodle.

For every question of the Moodle export (every template, variant and part), the table's inputs:
the right answer at 2, 3 and 4 s.f., every named mistake, g = 9.8, each part-way rounding, a
unit slip (no unit), the right value in each prefix and spelling of its unit that the book's unit
reader takes (physics_figures.worksheets.moodle_units), a wrong unit, and every option of a
multiple-choice item. The book's fraction comes from the browser's own engine (marking.js under
Node, on the data the site ships); Moodle's from Moodle's question engine, through
scripts/moodle_verdicts.php on a Moodle where the file has been imported
(../shared/moodle: setup.sh, then import.php FILE.xml).

    python scripts/moodle_verdicts.py EXPORT.xml [--out verdicts.json]

Prints the rate of inputs that get the same fraction, leaving out the kinds Moodle's core types
cannot grade the book's way (CLARIFICATIONS, "Marks: Moodle"), and every case that differs.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

from physics_figures import bank, marking
from physics_figures.notation import format_number, plain_number
from physics_figures.questions import OPTION_LETTERS, unit_text
from physics_figures.textformat import to_plain
from physics_figures.worksheets.moodle import unit_forms, variant_indices

ROOT = Path(__file__).resolve().parents[1]
ENGINE = ROOT / "book" / "_ext" / "questions" / "static" / "marking.js"
#: Inputs Moodle's core types cannot grade the book's way: left out of the rate, listed.
CANNOT = {
    "shared": "a mark line shared by two parts",
    "direction-mistake": "a named mistake on a direction part (Moodle grades the direction box on its own)",
    "cloze-unit": "a unit inside a Cloze number box (it takes no unit, so no unit is marked there)",
    "trailing-zeros": "trailing zeros (Moodle reads the number, not the figures)",
}


#: The s.f. rule (marking_rules.json): the key is typed at min to one past check figures.
FIGURES = marking.sig_figs()


def typed(value: float, sig_figs: int) -> str:
    return plain_number(format_number(value, sig_figs))


def _inputs(question, index: int) -> list[dict]:
    """The verdict table's inputs for one part: {label, kind, answer (the site's form), parts
    (Moodle's), cannot (a CANNOT key or "")}."""
    part, part_id = question.parts[index], question.part_ids[index]
    rows = []
    if part.answer_grid:  # a letter to choose
        for letter, option in zip(OPTION_LETTERS, part.options, strict=True):
            rows.append({"label": f"option {letter}", "answer": {"choice": letter},
                         "parts": [{"choice": to_plain(option.text)}], "cannot": ""})
        return rows
    if not part.has_value:  # graded by a person (an essay)
        return []
    cloze = part.direction == "choice"
    direction = part.answer_direction

    def row(label, number, unit, *, way=direction, cannot=""):
        answer = {"value": number, "unit": unit, "direction": way}
        parts = [{"number": number, "unit": "" if cloze else unit}] + ([{"choice": way}] if cloze else [])
        return {"label": label, "answer": answer, "parts": parts, "cannot": cannot}

    size = (lambda v: v) if part.direction == "signed" else abs
    for sig_figs in range(FIGURES["min"], FIGURES["check"] + 2):  # the key at 2, 3 and 4 s.f.
        rows.append(row(f"key {sig_figs} s.f.", typed(part.value, sig_figs), part.unit))
    for mistake in part.mistakes:
        if mistake.direction is not None:
            rows.append(row(f"mistake: {mistake.name}", typed(part.value, 3), part.unit, way=mistake.direction,
                            cannot="direction-mistake"))
        elif mistake.unit is None:
            rows.append(row(f"mistake: {mistake.name}", typed(size(mistake.value), 3), part.unit))
        else:
            rows.append(row(f"mistake: {mistake.name}", typed(size(mistake.value), 3), mistake.unit,
                            cannot="cloze-unit" if cloze else ""))
    if part.g_nine_eight is not None:
        rows.append(row("g = 9.8", typed(part.g_nine_eight, 3), part.unit))
    for value, what in part.rounded_part_way:
        rows.append(row(f"part-way: {what}", typed(value, 3), part.unit))
    unit_cannot = "cloze-unit" if cloze else ""
    rows.append(row("unit slip (no unit)", typed(part.value, 3), "", cannot=unit_cannot))
    rows.append(row("wrong unit", typed(part.value, 3), "J" if part.unit != "J" else "N", cannot=unit_cannot))
    # the right value in each prefix and spelling the book's unit reader takes (as Moodle's units
    # declare them: moodle_units), typed as a student types it; a Cloze number box takes no unit,
    # so there one stands for all
    own = part.unit.replace(" ", "")
    others = [(t, m) for t, stored, m in (unit_forms(part.unit, part.units) if part.unit else ()) if stored != own]
    for form, multiplier in others[:1] if cloze else others:
        rows.append(row(f"in {form}", typed(part.value * multiplier, 3), form, cannot=unit_cannot))
    shared = any(len(question.parts_of(m)) > 1 and question.owner(m) == part_id for m in question.mark_scheme if m.code)
    for r in rows:
        r["cannot"] = r["cannot"] or ("shared" if shared else "")
    return rows


def _other_figures(text: str) -> list[str]:
    """The same number written to other significant figures ("0.7" -> "7e-01", "7.0e-01",
    "7.00e-01", ...): what Moodle cannot tell apart, as it reads the number, not the figures."""
    try:
        value = float(text)
    except ValueError:
        return []
    return [form for form in (f"{value:.{k}e}" for k in range(5)) if float(form) == value]


def _book_fractions(cases: list[tuple[dict, str, dict]]) -> list[float]:
    """The site's marks for each (question data, part id, answer), as a fraction of the part's."""
    script = (f"const e = require({json.dumps(str(ENGINE))}); let s = '';"
              "process.stdin.on('data', c => s += c).on('end', () => {"
              "const out = JSON.parse(s).map(([data, id, answer]) => {"
              "const m = e.markQuestion(data, {[id]: answer}).marks.byPart[id]; return m[0] / m[1]; });"
              "process.stdout.write(JSON.stringify(out)); });")
    result = subprocess.run(["node", "-e", script], input=json.dumps(cases), capture_output=True, text=True,
                            check=True)
    return json.loads(result.stdout)


def _book_table() -> dict:
    """Every input of every part that Moodle is asked, by question, with the book's fraction."""
    table, cases = {}, []
    for template in bank.TEMPLATES.values():
        if template.try_first:
            continue
        for variant in variant_indices(template):
            question = template.variant(variant)
            data = question.browser_data()
            for index, part_id in enumerate(question.part_ids):
                rows = _inputs(question, index)
                if rows:
                    table[f"{template.key}-v{variant}-{part_id}"] = rows
                    cases += [(data, part_id, r["answer"]) for r in rows]
    print(f">>> {sum(len(r) for r in table.values())} inputs to {len(table)} questions: the book's marks",
          file=sys.stderr)
    book = iter(_book_fractions(cases))
    for rows in table.values():
        for r in rows:
            r["book"] = next(book)
    return table


def _moodle_fractions(table: dict, php: str, xml: Path) -> list:
    """Moodle's fraction for each input (r["moodle"], None where Moodle has no such question);
    returns the questions not found in Moodle."""
    print(">>> Moodle's marks (scripts/moodle_verdicts.php)", file=sys.stderr)
    with tempfile.TemporaryDirectory() as folder:
        inputs, report = Path(folder) / "in.json", Path(folder) / "out.json"
        inputs.write_text(json.dumps({q: [{"label": r["label"], "parts": r["parts"]} for r in rows]
                                      for q, rows in table.items()}))
        subprocess.run([php, str(ROOT / "scripts" / "moodle_verdicts.php"), f"--inputs={inputs}",
                        f"--json={report}", f"--xml={xml.resolve()}"], check=True, stdout=subprocess.DEVNULL)
        moodle = json.loads(report.read_text())
    for question, rows in table.items():
        for r, got in zip(rows, moodle["results"].get(question) or [{"fraction": None}] * len(rows), strict=True):
            r["moodle"] = got["fraction"]
    return moodle.get("missing", [])


def _mark_trailing_zeros(table: dict) -> None:
    """A number Moodle grades otherwise than the book: is it the figures? If the book gives
    Moodle's fraction to the same number written to other figures (0.7 and 0.700; 1400 read
    as 2 or 4 s.f.), Moodle could not tell them apart."""
    differing = [(q, r) for q, rows in table.items() for r in rows if not r["cannot"] and r["moodle"] is not None
                 and abs(r["moodle"] - r["book"]) >= 0.01]
    asked = [(q, r, form) for q, r in differing for form in _other_figures(r["answer"].get("value", ""))]
    if asked:
        data = {q: bank.TEMPLATES[q.rsplit("-v", 1)[0]].variant(int(q.rsplit("-v", 1)[1].split("-")[0])).browser_data()
                for q, _, _ in asked}
        again = _book_fractions([(data[q], q.rsplit("-", 1)[1], {**r["answer"], "value": form}) for q, r, form in asked])
        for (_, r, _), fraction in zip(asked, again, strict=True):
            if abs(fraction - r["moodle"]) < 0.01:
                r["cannot"] = "trailing-zeros"


def _report(table: dict, missing: list) -> None:
    """How many inputs get the same fraction from both, what is left out and why, what differs."""
    same, counted, left_out, left_agree, differ = 0, 0, Counter(), Counter(), []
    for question, rows in table.items():
        for r in rows:
            agree = r["moodle"] is not None and abs(r["moodle"] - r["book"]) < 0.01
            if r["cannot"]:
                left_out[r["cannot"]] += 1
                left_agree[r["cannot"]] += agree
                continue
            counted += 1
            same += agree
            if not agree:
                differ.append(f"{question} {r['label']}: book {r['book']:.2f}, Moodle {r['moodle']} "
                              f"({unit_text(json.dumps(r['parts'], ensure_ascii=False))})")
    print(f"questions: {len(table)} asked, {len(missing)} not found in Moodle")
    print(f"same fraction: {same} of {counted} inputs = {100 * same / max(counted, 1):.1f} %")
    for kind, count in left_out.items():
        print(f"left out ({CANNOT[kind]}): {count}, of which {left_agree[kind]} get the same fraction anyway")
    print(f"differ: {len(differ)}")
    for line in differ:
        print("  " + line)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("xml", type=Path, help="the Moodle XML file imported into the harness's Moodle")
    parser.add_argument("--out", type=Path, default=None, help="write every verdict here (JSON)")
    parser.add_argument("--php", default="php")
    args = parser.parse_args(argv)

    table = _book_table()
    missing = _moodle_fractions(table, args.php, args.xml)
    _mark_trailing_zeros(table)
    _report(table, missing)
    if args.out:
        args.out.write_text(json.dumps(table, ensure_ascii=False, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
