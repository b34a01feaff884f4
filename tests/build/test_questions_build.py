# ruff: noqa: RUF001  (mark schemes are typeset text: true minus, times)
"""The question directive in small Sphinx books: the HTML form, the print and LaTeX builds, a
strict build's refusals and a re-read after a bank edit (the questions themselves:
tests/no_site/test_questions.py)."""

from __future__ import annotations

import pickle
from pathlib import Path

import pytest
from support.sphinx import QUICK_CHECK_1, small_book, sphinx_build


@pytest.mark.build
def test_html_question_has_labelled_boxes_status_feedback_and_a_hidden_worked_answer(directive_book):
    page = (directive_book("html") / "asked.html").read_text()
    assert '<form class="q-form" data-question="quick-check-1" data-type="force-momentum" data-variant="0"' in page
    assert page.count('role="status"') == 2
    # Named for its part (issue "reading", item 9): "(a) value", not just "Value".
    assert '<label class="q-field" for="q-quick-check-1-a-value"><span>(a) value</span>' in page
    assert '<details class="q-worked" hidden>' in page
    assert "final momentum = " in page  # the answer line for print and no-JS
    key = page[page.index('<details class="q-key"'):]
    assert "final momentum: 15 N s" in key and "<strong>C1</strong>" in key
    assert 'href="#question-quick-check-1"' in key
    # The script and styles are added only where a question is asked.
    assert "_static/questions.js" in page and "_static/questions.css" in page
    plain = (directive_book("html") / "plain.html").read_text()
    assert "questions.js" not in plain and "questions.css" not in plain


@pytest.mark.build
def test_print_builds_show_the_question_with_answer_lines_and_the_key(directive_book):
    text = (directive_book("text") / "asked.txt").read_text()
    question = text[:text.index("Answer key")]
    assert "(a) final momentum = ...." in question and "(b) speed = ...." in question
    assert "15 N s" not in question and "Check" not in question
    key = text[text.index("Answer key"):]
    assert "(a) final momentum: 15 N s" in key and "(b) speed: 7.5 m s⁻¹" in key
    assert "= 7.5 m s^−1 **A1**" in key  # the mark scheme line, with its mark


@pytest.mark.build
def test_latex_build_prints_the_question_and_its_key(directive_book):
    tex = (directive_book("latex") / "book.tex").read_text()
    assert "initially at rest" in tex and "final momentum =" in tex
    assert "Answer key" in tex and r"\sphinxstylestrong{C1}" in tex


@pytest.mark.build
def test_a_template_directive_with_text_or_an_unknown_key_fails_the_strict_build(tmp_path):
    """A template writes its own text (so the page cannot disagree with its numbers)."""
    broken = QUICK_CHECK_1.replace("quick-check-1\n", "quick-check-1\nA force of 6.0 N\n") + "\n```{question} quick-check-99\n```\n"
    source = small_book(tmp_path, {"asked": "# Questions\n\n" + broken})
    result = sphinx_build(source, "html")
    assert result.returncode != 0
    assert "question quick-check-1: a template writes its own text; leave the directive empty" in result.stderr
    assert "question: no template 'quick-check-99' in the topics physics_figures.bank" in result.stderr


@pytest.mark.build
def test_an_edit_to_the_bank_re_reads_the_page(directive_book):
    """The directive notes the bank's source files (the modules it imports, through
    book/_ext/fresh_figures.py) as dependencies, so an incremental build re-reads a page when
    a template changes."""
    with (directive_book("html") / ".doctrees" / "environment.pickle").open("rb") as file:
        env = pickle.load(file)
    depends = {Path(path).name for path in env.dependencies["asked"]}
    assert {"force_momentum.py", "questions.py", "variants.py"} <= depends
    assert not env.dependencies.get("plain")
