"""The landing page's map of the book (``{book-map} parts``, ``explorables`` or
``questions``): the parts with a time estimate, the explorables, or the question pages,
filled once every page is read."""

from __future__ import annotations

from docutils import nodes
from fresh_figures import uses_modules  # book/_ext: re-read a page when its modules change
from sphinx.util.docutils import SphinxDirective

from . import store


class book_map(nodes.General, nodes.Element):
    """A list for the landing page, filled once every page is read: the book's parts with a
    time estimate, its explorables, or its question pages."""


class BookMapDirective(SphinxDirective):
    """``{book-map} parts`` (or ``explorables``, ``questions``) on the landing page."""

    required_arguments = 1

    def run(self):
        if self.arguments[0] not in BOOK_MAPS:
            raise self.error(f"book-map: choose one of {', '.join(BOOK_MAPS)} (got {self.arguments[0]!r})")
        store.docs(self.env, "book-map").add(self.env.docname)
        uses_modules(self.env, *store.bank_modules(self.config))
        return [book_map(what=self.arguments[0])]


BOOK_MAPS = ("parts", "explorables", "questions")
#: The time estimate: reading at WORDS_PER_MINUTE, MINUTES_PER_MARK for each mark of a page's
#: questions and MINUTES_PER_EXPLORABLE for each explorable, rounded up to 5 minutes a part.
WORDS_PER_MINUTE, MINUTES_PER_MARK, MINUTES_PER_EXPLORABLE = 100, 1.5, 5


def _parts(app) -> list[tuple[str, list[str]]]:
    """(caption, [pages, sections included]) for each part of the table of contents."""
    from sphinx import addnodes

    env = app.env
    root = env.get_doctree(app.config.root_doc)
    parts = []
    for toctree in root.findall(addnodes.toctree):
        pages = []
        for _, docname in toctree["entries"]:
            pages.extend(_book_order_from(env, docname))
        parts.append((toctree.get("caption") or "", pages))
    return parts


def _book_order_from(env, start: str) -> list[str]:
    order = [start]
    for child in env.toctree_includes.get(start, []):
        order.extend(_book_order_from(env, child))
    return order


def _minutes(app, docname: str) -> float:
    env = app.env
    words = len(env.get_doctree(docname).astext().split())
    marks = sum(item["marks"] for item in store.questions(env).get(docname, []))
    explorables = len(getattr(env, "explorables_by_doc", {}).get(docname, ()))
    return words / WORDS_PER_MINUTE + MINUTES_PER_MARK * marks + MINUTES_PER_EXPLORABLE * explorables


def _link(app, fromdoc: str, docname: str, text: str, anchor: str = "") -> nodes.Node:
    if app.builder.format == "html":
        uri = app.builder.get_relative_uri(fromdoc, docname) + anchor
        return nodes.reference("", text, internal=True, refuri=uri)
    return nodes.Text(text)


def _title(app, docname: str) -> str:
    number = app.env.toc_secnumbers.get(docname, {}).get("")
    title = app.env.titles[docname].astext()
    return f"{'.'.join(map(str, number))}. {title}" if number else title


def _book_map_content(app, fromdoc: str, what: str) -> list[nodes.Node]:
    from physics_figures.notation import format_number

    env, items = app.env, nodes.bullet_list(classes=["book-map", f"book-map-{what}"])
    if what == "parts":
        for caption, pages in _parts(app):
            minutes = 5 * -(-sum(_minutes(app, page) for page in pages) // 5)
            item = nodes.paragraph()
            item += nodes.strong(text=caption)
            item += nodes.Text(f" (about {format_number(minutes, decimals=0)} minutes): ")
            for index, page in enumerate(pages):
                if index:
                    item += nodes.Text("; ")
                item += _link(app, fromdoc, page, _title(app, page))
            items += nodes.list_item("", item)
    elif what == "explorables":
        from explorables import DESCRIPTIONS  # book/_ext/explorables

        for docname in store.book_order(env, app.config.root_doc):
            for name in sorted(getattr(env, "explorables_by_doc", {}).get(docname, ())):
                title, shows = DESCRIPTIONS[name]
                item = nodes.paragraph()
                item += _link(app, fromdoc, docname, title)
                item += nodes.Text(f" (on “{_title(app, docname)}”): {shows}.")
                items += nodes.list_item("", item)
    else:
        for docname in store.book_order(env, app.config.root_doc):
            asked = [q for q in store.questions(env).get(docname, [])]
            if not asked or docname.rpartition("/")[2].startswith("example-"):
                continue  # a worked example's try-first part is the example's, listed with it
            marks = sum(q["marks"] for q in asked)
            item = nodes.paragraph()
            item += _link(app, fromdoc, docname, _title(app, docname))
            item += nodes.Text(f": {store.count(len(asked), 'question', 'questions')}, "
                               f"{store.count(marks, 'mark', 'marks')}")
            items += nodes.list_item("", item)
    return [items]


def fill(app, doctree, docname):
    for listing in list(doctree.findall(book_map)):
        listing.replace_self(_book_map_content(app, docname, listing["what"]))


def setup(app):
    app.add_node(book_map)
    app.add_directive("book-map", BookMapDirective)
