"""The answer key: every question of the book, with its answers and mark scheme, in
table-of-contents order::

    ```{answer-key}
    ```

Filled once every page is read. In HTML it is one folded block; in print a section the
question sheet's key is made from (book/_latex/latex_question_sheets.py).
"""

from __future__ import annotations

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from sphinx.util.docutils import SphinxDirective

from . import store


class answer_key(nodes.General, nodes.Element):
    """Filled, once every page is read, with each question's answers and mark scheme."""


class AnswerKeyDirective(SphinxDirective):
    """Where the answer key goes: every question of the book, filled in later."""

    def run(self):
        store.docs(self.env, "answer-key").add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        return [answer_key()]


def has_maths(app, doctree):
    """The key's mark schemes hold maths, so the page needs MathJax (runs after the math domain)."""
    if any(doctree.findall(answer_key)):
        app.env.get_domain("math").data["has_equations"][app.env.docname] = True


def _content(app, fromdoc: str) -> list[nodes.Node]:
    env, content = app.env, []
    for docname in store.book_order(env, app.config.root_doc):
        asked = store.questions(env).get(docname)
        if not asked:
            continue
        page = env.titles[docname].astext() if docname in env.titles else docname
        content.append(nodes.paragraph("", "", nodes.strong(text=page), classes=["q-key-page"]))
        for item in asked:
            uri = app.builder.get_relative_uri(fromdoc, docname) + f"#question-{item['key']}"
            # the question it answers, as data: the printed key numbers its entries by it
            heading = nodes.paragraph(classes=["q-key-title"], question=item["key"], try_first=item["try_first"])
            heading += nodes.reference("", item["title"], internal=True, refuri=uri)
            heading += nodes.Text(f" [{store.count(item['marks'], 'mark', 'marks')}]")
            content.append(heading)
            answers = nodes.bullet_list(classes=["q-key-answers"])
            for line in item["answers"]:
                answers += nodes.list_item("", nodes.paragraph(text=line))
            content.append(answers)
            content.extend(child.deepcopy() for child in item["scheme"])
    return content


def fill(app, doctree, docname):
    for key in list(doctree.findall(answer_key)):
        key.extend(_content(app, docname))
        if app.builder.format != "html":
            printed = nodes.container(classes=["q-key"])
            printed += nodes.rubric(text="Answer key")
            printed.extend(key.children)
            key.replace_self(printed)


def visit_answer_key(self, node):
    self.body.append(self.starttag(node, "details", CLASS="q-key"))
    self.body.append("<summary>Answer key: every answer with its mark scheme</summary>\n")


def depart_answer_key(self, node):
    self.body.append("</details>\n")


def setup(app):
    app.add_node(answer_key, html=(visit_answer_key, depart_answer_key))
    app.add_directive("answer-key", AnswerKeyDirective)
    app.connect("doctree-read", has_maths)
