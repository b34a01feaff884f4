"""The command line: a teacher's own worksheets, or the site's.

    python -m physics_figures.worksheets --types drag,two-d --marks 30 --versions 4 --seed 2027 --out sheets/
    python -m physics_figures.worksheets --templates quick-check-3,practice-lift --versions 2 --out sheets/
    python -m physics_figures.worksheets --list
    python -m physics_figures.worksheets --site --out _build/html/teachers     (make worksheets)
    python -m physics_figures.worksheets --topic my_topic --site --out sheets/  (another topic)
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .. import topics
from ..notation import format_number
from ..topics import Topic
from . import (
    DEFAULT_TOPIC,
    SITE_SEED,
    bank_templates,
    plan,
    ready_made_repeats,
    select,
    site_sheets,
    template_marks,
)


def _names(text: str) -> list[str]:
    return [name.strip() for name in text.split(",") if name.strip()]


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m physics_figures.worksheets",
        description="Worksheets in several versions (different numbers, the same marks), each "
                    "with its own answer key, typeset by xelatex.")
    p.add_argument("--topic", default=DEFAULT_TOPIC,
                   help=f"the topic's module, whose TOPIC the sheets draw from (default {DEFAULT_TOPIC})")
    p.add_argument("--types", default="", help="question types, comma-separated (see --list)")
    p.add_argument("--templates", default="", help="template keys, comma-separated (see --list)")
    p.add_argument("--marks", type=int, default=None,
                   help="total marks (default: every template asked for)")
    p.add_argument("--versions", type=int, default=3, help="number of versions, A, B, C... (default 3)")
    p.add_argument("--seed", type=int, default=SITE_SEED, help=f"the seed (default {SITE_SEED})")
    p.add_argument("--name", default="worksheet", help="file names: NAME-A.pdf, NAME-key-A.pdf")
    p.add_argument("--title", default="", help="the title on the cover")
    p.add_argument("--out", type=Path, default=Path("sheets"), help="output folder (default sheets/)")
    p.add_argument("--work", type=Path, default=None,
                   help="where the LaTeX sources and logs go (default OUT/.tex)")
    p.add_argument("--jobs", type=int, default=None, help="xelatex runs at a time (default: one per core)")
    p.add_argument("--site", action="store_true", help="build the site's sheets (make worksheets)")
    p.add_argument("--list", action="store_true", help="list the types and templates, then stop")
    return p


def _list(topic: Topic) -> None:
    for question_type in topic.types:
        print(f"{question_type.key}: {question_type.title}")
        for template in bank_templates(topic):
            if template.type == question_type.key:
                print(f"  {template.key:32} {template_marks(template):2} marks  "
                      f"{len(template.reserve_variants):2} variants for sheets  {'/'.join(template.kinds)}"
                      + ("  (shared with the site)" if template.shares_variants else ""))


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        topic = topics.load(args.topic)
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if args.list:
        _list(topic)
        return 0
    from .build import build  # after argument errors: they need no TeX

    try:
        if args.site:
            sheets = site_sheets(topic=topic)
        else:
            types, keys = _names(args.types), _names(args.templates)
            if not types and not keys:
                raise ValueError("types or templates must name what to ask (got neither): e.g. "
                                 "--types drag,two-d or --templates quick-check-3")
            templates = select(types=types, templates=keys, topic=topic)
            title = args.title or ("Worksheet: " + "; ".join(topic.type(t).title for t in types)
                                   if types and not keys else "Worksheet")
            sheets = [plan(args.name, title, templates, versions=args.versions, seed=args.seed,
                           marks=args.marks, topic=topic)]
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except RuntimeError as error:  # the draw runs under Node (worksheets/draw.py)
        print(f"error: {error}", file=sys.stderr)
        return 1
    start = time.perf_counter()
    try:
        pdfs = build(sheets, args.out, parallel=args.jobs, work=args.work)
    except RuntimeError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    for sheet in sheets:
        print(f"{sheet.name}: {len(sheet.versions)} versions, {sheet.marks} marks, "
              f"{len(sheet.templates)} questions ({', '.join(t.key for t in sheet.templates)})")
    print(f"wrote {len(pdfs)} PDFs to {args.out} in {format_number(time.perf_counter() - start, decimals=1)} s")
    repeats = [] if args.site else ready_made_repeats(sheets[0], topic)
    if repeats:  # the draw takes a ready-made worksheet's numbers only when no others are left
        print("note: these questions repeat a ready-made worksheet's numbers (fewer versions avoid them): "
              + "; ".join(repeats), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
