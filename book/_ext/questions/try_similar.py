""""Try a similar one": at the end of a worked example, a link to a practice question of the
same type (``{try-similar}``), found once every page is read."""

from __future__ import annotations

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from sphinx.util.docutils import SphinxDirective

from . import store


class try_similar(nodes.General, nodes.Element):
    """Filled, once every page is read, with a link to a practice question of the same type
    as the page's worked example."""


class TrySimilarDirective(SphinxDirective):
    """At the end of a worked example: a link to a question of the same type to practise."""

    def run(self):
        store.docs(self.env, "try-similar").add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        return [try_similar()]


def _similar_question(app, docname: str):
    """(template, page) of the first question in book order, outside the worked examples, of
    the type of this page's try-first question; practice pages first."""
    env = app.env

    def template(key):
        return store.template(app.config, key)

    kinds = {template(k).type for k in store.templates_used(env).get(docname, []) if template(k).try_first}
    if len(kinds) != 1:
        raise ValueError(f"try-similar on {docname}: the page must ask exactly one worked example's "
                         f"try-first question (its types: {sorted(kinds)})")
    kind = kinds.pop()
    found = [(template(key), page) for page in store.book_order(env, app.config.root_doc)
             for key in store.templates_used(env).get(page, [])
             if template(key).type == kind and not template(key).try_first]
    if not found:
        raise ValueError(f"try-similar on {docname}: no question of type {kind!r} is placed outside "
                         "the worked examples")
    practice = [f for f in found if "/practice" in f[1]]
    return (practice or found)[0]


def fill(app, doctree, docname):
    for similar in list(doctree.findall(try_similar)):
        template, page = _similar_question(app, store.source_page(app.env, similar, docname))
        title = app.env.titles[page].astext()
        line = nodes.paragraph(classes=["q-try-similar"])
        line += nodes.strong(text="Try a similar one: ")
        if app.builder.format == "html":
            uri = app.builder.get_relative_uri(docname, page) + f"#question-{template.key}"
            line += nodes.reference("", template.title, internal=True, refuri=uri)
            line += nodes.Text(f" ({title}).")
        else:
            line += nodes.Text(f"{template.title}, on the page “{title}”.")
        similar.replace_self(line)


def setup(app):
    app.add_node(try_similar)
    app.add_directive("try-similar", TrySimilarDirective)
