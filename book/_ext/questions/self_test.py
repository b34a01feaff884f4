"""The definitions self-test: a box of definitions with class ``self-test`` gets a bar to
hide them and count the ones a student knows (static/selftest.js, on its pages only)."""

from __future__ import annotations

from docutils import nodes

from . import schedule, store


def find(app, doctree):
    """A box of definitions with class self-test: its page loads selftest.js."""
    if any("self-test" in node["classes"] for node in doctree.findall(nodes.admonition)):
        store.docs(app.env, store.SELF_TEST).add(app.env.docname)


def _bar(count: int) -> nodes.raw:
    """The self-test's bar, in the page rather than added by selftest.js, which would push the
    list down after the first paint (a layout shift); hidden without JavaScript."""
    return nodes.raw("", '<div class="st-bar"><button type="button" class="st-toggle" aria-pressed="false">'
                     'Test yourself: hide the definitions</button><p class="st-status" role="status">'
                     f'Known: 0 of {count} definitions.</p></div>', format="html")


def add_bars(app, doctree, docname):
    if app.builder.format != "html":
        return
    for box in doctree.findall(nodes.admonition):
        lists = [child for child in box.children if isinstance(child, (nodes.bullet_list, nodes.enumerated_list))]
        if "self-test" in box["classes"] and lists:
            box.insert(box.index(lists[0]), _bar(len(lists[0].children)))


def add_assets(app, pagename, templatename, context, doctree):
    if pagename in store.docs(app.env, store.SELF_TEST):
        app.add_css_file("selftest.css")
        schedule.add_store_script(app)  # each mark is kept in the progress store
        app.add_js_file("selftest.js", loading_method="defer")


def setup(app):
    app.connect("doctree-read", find)
    app.connect("html-page-context", add_assets)
