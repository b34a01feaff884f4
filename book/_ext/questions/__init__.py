"""Questions that mark like an examiner (a local Sphinx extension), one module per job:

* directive.py: the ``question`` directive, placing a bank template by its key;
* variants.py: each template's variants and their graphs, for New numbers (redone only
  when what they come from changed);
* form.py: the answer form in HTML, marked in the browser (static/marking.js, the engine;
  static/questions.js, the page);
* print_form.py: the question in print, with answer lines (the question sheet reads it);
* answer_key.py: ``answer-key``, every answer and mark scheme of the book;
* progress.py: ``practice-progress``, Your practice by question type;
* class_page.py: ``class-progress``, the class at a glance from the students' exported files;
* sheet_builder.py: ``sheet-builder``, the teachers' worksheets made in the browser, and the
  teachers-only data it reads (the reserve variants' sheets and keys);
* mock_test.py: ``mock-test``, a timed mock test drawn fresh in the browser, marked at the end;
* try_similar.py: ``try-similar``, a worked example's link to a question of its type;
* book_map.py: ``book-map``, the landing page's map of parts, explorables and questions;
* self_test.py: the definitions self-test's bar;
* rules_table.py: ``marking-rules``, the rule table with the schemes' words;
* store.py: what reading the pages records, for the directives that gather from them all.
"""

from __future__ import annotations

from pathlib import Path

from sphinx.util import logging

from . import (
    answer_key,
    book_map,
    class_page,
    directive,
    form,
    mock_test,
    print_form,
    progress,
    rules_table,
    schedule,
    self_test,
    sheet_builder,
    store,
    try_similar,
    variants,
)

__version__ = "2.0"
logger = logging.getLogger(__name__)
STATIC = Path(__file__).parent / "static"


def add_static_path(app, config):
    config.html_static_path.append(str(STATIC))


def check_topics(app, env):
    """A book that holds a topic's pages holds them all: a page renamed or dropped would leave
    its types' method links and its feedback links dangling. (A small book that only asks a
    topic's questions, as the tests' are, holds none of them.)"""
    for topic in store.topics(app.config):
        missing = [page for page in topic.pages if page not in env.all_docs]
        if missing and len(missing) < len(topic.pages):
            logger.warning(f"topic {topic.key!r} names pages that are not in the book: {', '.join(missing)}")


def resolve(app, doctree, docname):
    """Once every page is read: fill what gathers from them all, then (outside HTML) give
    each question its printed form."""
    self_test.add_bars(app, doctree, docname)
    book_map.fill(app, doctree, docname)
    try_similar.fill(app, doctree, docname)
    progress.fill(app, doctree, docname)
    answer_key.fill(app, doctree, docname)
    print_form.fill(app, doctree, docname)


def setup(app):
    # The modules whose TOPIC the book asks questions from (physics_figures.topics).
    app.add_config_value("question_topics", [], "env", types=[list])
    app.add_node(directive.question, html=(form.visit_question, form.depart_question))
    app.add_node(directive.question_form, html=(form.visit_question_form, None))
    app.add_node(directive.worked_answer, html=(form.visit_worked_answer, form.depart_worked_answer))
    app.add_node(directive.graph_view, html=(form.visit_graph_view, form.depart_graph_view))
    app.add_directive("question", directive.QuestionDirective)
    for job in (answer_key, progress, try_similar, book_map, self_test, rules_table, class_page, sheet_builder,
                schedule, mock_test):
        job.setup(app)
    app.connect("config-inited", add_static_path)
    app.connect("env-purge-doc", store.purge)
    app.connect("env-merge-info", store.merge)
    app.connect("env-get-outdated", store.refresh_gathering_pages)
    app.connect("env-check-consistency", check_topics)
    app.connect("doctree-resolved", resolve)
    app.connect("html-page-context", form.add_assets)
    app.connect("build-finished", variants.write_variants)
    return {"version": __version__, "parallel_read_safe": True, "parallel_write_safe": True,
            "env_version": 5}  # 5: question figures written compact (svg_compact.py)
