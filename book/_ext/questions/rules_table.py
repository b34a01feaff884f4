"""The rule table the marking follows (physics_figures/marking_rules.json), for the page that
explains it: ``{marking-rules}``, each rule with the published 9702 schemes that show it."""

from __future__ import annotations

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

from physics_figures import marking

from . import store


class MarkingRules(SphinxDirective):
    """The rule table the marking follows (physics_figures/marking_rules.json), each rule with
    the published 9702 schemes that show it: ``{marking-rules}``."""

    def run(self):
        self.env.note_dependency(str(marking.RULES_FILE))
        store.docs(self.env, store.RULES_TABLE).add(self.env.docname)
        table = nodes.table(classes=["q-rules-table"])
        group = nodes.tgroup(cols=2)
        table += group
        group += nodes.colspec(colwidth=40)
        group += nodes.colspec(colwidth=60)
        head = nodes.thead()
        head += nodes.row("", *(nodes.entry("", nodes.paragraph(text=t))
                               for t in ("Your answer, and the marks it earns", "What the published schemes say")))
        group += head
        body = nodes.tbody()
        for row in marking.documented_rules():
            sources = nodes.bullet_list()
            for source in row["sources"]:
                item = nodes.paragraph()
                item += nodes.strong(text=source["paper"])
                item += nodes.Text(f": “{source['says']}”")
                sources += nodes.list_item("", item)
            rule = nodes.paragraph(text=row["rule"][:1].upper() + row["rule"][1:] + ".")
            body += nodes.row("", nodes.entry("", rule), nodes.entry("", sources), ids=[f"rule-{row['id']}"])
        group += body
        return [table]


def setup(app):
    app.add_directive("marking-rules", MarkingRules)
