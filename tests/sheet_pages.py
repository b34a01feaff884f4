"""Where a sheet's choice questions fall on printed pages (tests/build/test_sheet_print.py): read a PDF
page by page with pdftotext and find, in order, each choice part's stem and its answer line.

Text is compared by its letters alone (a PDF's spaces, hyphens and symbols are not the
source's), from a running position, so a stem that begins like an earlier one is found after it."""

from __future__ import annotations

import re

from physics_figures.worksheets import Version

ANSWER_LINE = "AnswerABCorD"
STEM_LETTERS = 40


def letters(text: str) -> str:
    return re.sub(r"[^A-Za-z]", "", text)


def _stem(question, index: int) -> str:
    """The words a choice part starts from: the question's text for its first part, else the
    part's own prompt."""
    source = re.sub(r"<[^>]+>", "", question.text_html()) if index == 0 else question.parts[index].prompt
    return letters(source)[:STEM_LETTERS]


def split_choices(pages: list[str], versions: list[Version]) -> list[str]:
    """Each choice part whose stem and answer line (after its options) print on different
    pages, as "version A, question 3 (key): stem on page 2, answer line on page 3"."""
    text, starts = "", []
    for page in pages:
        starts.append(len(text))
        text += letters(page)

    def page_of(offset: int) -> int:
        return max(n for n, start in enumerate(starts) if start <= offset) + 1

    split, cursor = [], 0
    for version in versions:
        for number, item in enumerate(version.items, start=1):
            # each question from where it starts, past the one before: two questions can open with
            # the same letters (digits are not letters: "puck A of mass 0.60 kg" and "… 0.30 kg")
            start = text.find(_stem(item.question, 0), cursor)
            cursor = max(cursor, start)
            for index, part in enumerate(item.question.parts):
                if part.kind != "mcq":
                    continue
                stem = start if index == 0 else text.find(_stem(item.question, index), cursor)
                answer = text.find(ANSWER_LINE, max(stem, 0))
                assert stem >= 0 and answer >= 0, (version.letter, number, item.template.key, _stem(item.question, index))
                if page_of(stem) != page_of(answer):
                    split.append(f"version {version.letter}, question {number} ({item.template.key}): stem on page "
                                 f"{page_of(stem)}, answer line on page {page_of(answer)}")
                cursor = answer + len(ANSWER_LINE)
            cursor = max(cursor, start + 1)
    return split
