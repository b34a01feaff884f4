"""Matplotlib drawings of what ``physics_figures.models`` computes (never any physics here).

Plot functions take the model objects first, options as keywords, ``ax=None`` (draw into
that Axes, or a new Figure), and return a NamedTuple of the artists. Each figure module
also writes its caption and alt text from the same objects, and ends with the book's
figures it draws (:mod:`.book_figure` says what those carry); ``style`` is the one place
the look is set.

This package re-exports nothing: import the module you draw from (``from
physics_figures.figures import collisions``). Python runs this file on the way to any
figure module, so anything imported here would tie every page to every figure module
(``book/_ext/fresh_figures.py`` re-executes a page when a module it imports changes).
"""
