"""The book PDF (`make pdf`) says what a printed page can do (issue 37): the web's sentences on
the question pages ("marked as you go", "tick each point") stay on the web. Read with pdftotext,
as a reader meets it; PDF_DIR points at PDFs built elsewhere, as in tests/site/test_pdf.py."""

from __future__ import annotations

import pytest
from test_pdf import BOOK, squash, squashed

pytestmark = [pytest.mark.site]

#: What only the web version can do: mark as you type, tick points, press a button, tap.
WEB_ONLY = ("marked as you go", "tick each", "press Check", "Show a step", "tap a graph", "New numbers")


def test_the_book_pdf_keeps_no_web_only_sentence():
    text = squashed(BOOK).lower()
    assert [phrase for phrase in WEB_ONLY if squash(phrase).lower() in text] == []


def test_the_practice_page_says_what_print_can_do():
    text = squashed(BOOK)
    assert squash("Write your answers in the spaces, then mark them with the answer key") in text
    assert squash("compare your answer with them point by point") in text
