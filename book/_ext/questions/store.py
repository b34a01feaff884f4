"""What the questions extension keeps between reading pages and writing them.

Reading a page records the questions it asks (for the answer key, the map and Your
practice) and which gathering directives it holds; once every page is read, those
directives are filled from here. Kept on the Sphinx environment, so a rebuild re-reads
only what changed, and merged after a parallel read.
"""

from __future__ import annotations

from docutils import nodes

#: What a question's text, marks and key come from besides its topic's module (which imports
#: the models it uses), and what draws a question's graph: a page placing a question is re-read
#: when these change, and so are the pages that gather the questions (answer key, progress,
#: try similar, map).
SHARED_MODULES = ("physics_figures.textformat", "physics_figures.variants", "physics_figures.topics")
GRAPH_MODULE = "physics_figures.figures.question_graph"
DIAGRAM_MODULE = "physics_figures.figures.question_diagram"

#: The pages holding each directive that gathers from every page, filled once all are read.
GATHERING = ("answer-key", "practice-progress", "try-similar", "book-map", "mock-test")
#: Pages with a definitions self-test (they load its script), and the page with the rule table
#: (feedback links to its rows).
SELF_TEST, RULES_TABLE = "self-test", "marking-rules"


def topics(config) -> list:
    """The topics the book asks questions from: the modules _config.yml names in
    question_topics, each with a TOPIC (physics_figures.topics)."""
    from physics_figures.topics import load

    return [load(module) for module in config.question_topics]


def book_id(config) -> str:
    """The book's id in progress exports ("dynamics"): its topics' keys, so a book of other
    topics writes files this book's class page refuses (static/progress.js)."""
    return "+".join(topic.key for topic in topics(config))


def bank_modules(config) -> tuple[str, ...]:
    """The modules a page placing or gathering questions is re-read for."""
    return (*config.question_topics, *SHARED_MODULES)


def template(config, key: str):
    """The template of that key in the book's topics; ValueError naming them if none has it."""
    for topic in topics(config):
        if key in topic.by_key:
            return topic.by_key[key]
    raise ValueError(f"no template {key!r} in the topics {', '.join(config.question_topics)} "
                     "(_config.yml: question_topics)")


def _store(env) -> dict:
    if not hasattr(env, "questions_store"):
        env.questions_store = {"asked": {}, "templates": {},
                               "docs": {name: set() for name in (*GATHERING, SELF_TEST, RULES_TABLE)}}
    return env.questions_store


def questions(env) -> dict[str, list[dict]]:
    """Each page's questions, in page order: {key, title, marks, answers, scheme}."""
    return _store(env)["asked"]


def templates_used(env) -> dict[str, list[str]]:
    """Each page's bank templates, by key, in page order."""
    return _store(env)["templates"]


def docs(env, directive: str) -> set[str]:
    """The pages that hold a directive of GATHERING (or the SELF_TEST)."""
    return _store(env)["docs"].setdefault(directive, set())


def purge(app, env, docname):
    store = _store(env)
    store["asked"].pop(docname, None)
    store["templates"].pop(docname, None)
    for pages in store["docs"].values():
        pages.discard(docname)


def merge(app, env, docnames, other):
    store, theirs = _store(env), _store(other)
    for docname in docnames:
        for name in ("asked", "templates"):
            if docname in theirs[name]:
                store[name][docname] = theirs[name][docname]
        for directive, pages in theirs["docs"].items():
            if docname in pages:
                store["docs"].setdefault(directive, set()).add(docname)


def refresh_gathering_pages(app, env, added, changed, removed):
    """A page's questions changed: re-read the pages that gather them."""
    if not added | changed | removed:
        return []
    return sorted(set().union(*(docs(env, name) for name in GATHERING)))


def book_order(env, root: str) -> list[str]:
    """Every page, in table-of-contents order from root, then any page outside it."""
    order, seen = [], set()

    def visit(docname):
        if docname in seen:
            return
        seen.add(docname)
        order.append(docname)
        for child in env.toctree_includes.get(docname, []):
            visit(child)

    visit(root)
    return order + sorted(set(env.all_docs) - seen)


def page_of(node, env) -> str | None:
    """The page a node of the merged doctree came from (the LaTeX builder's one book).

    Sphinx marks each page's sections with their docname when it merges the pages
    (sphinx-jupyterbook-latex moves the start_of_file markers, so they are no guide).
    """
    parent = node.parent
    while parent is not None:
        if isinstance(parent, nodes.Element) and parent.get("docname") in env.all_docs:
            return parent["docname"]
        parent = parent.parent
    return None


def source_page(env, node, docname: str) -> str:
    """The page a node came from: in a merged book the page_of it, else the page resolved."""
    return page_of(node, env) or docname


def count(number: int, one: str, many: str) -> str:
    """"1 mark", "12 marks": a count as the book writes numbers."""
    from physics_figures.notation import format_number

    return f"{format_number(number, decimals=0)} {one if number == 1 else many}"
