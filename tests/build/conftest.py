"""What the build tests share: one small book of the directives, each builder run on it once."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from support.sphinx import DIRECTIVE_CONF, DIRECTIVE_PAGES, small_book, sphinx_build


@pytest.fixture(scope="session")
def directive_book(tmp_path_factory) -> Callable[[str], Path]:
    """builder -> the folder its build of the directives' small book (support.sphinx's
    DIRECTIVE_PAGES) went to. The tests only read it; each builder runs once a session (a small
    Sphinx build costs a few seconds, most of it starting up). A test that edits its book and
    builds again makes a book of its own."""
    source = small_book(tmp_path_factory.mktemp("directives"), DIRECTIVE_PAGES, conf=DIRECTIVE_CONF)
    built: dict[str, Path] = {}

    def build(builder: str) -> Path:
        if builder not in built:
            result = sphinx_build(source, builder)
            assert result.returncode == 0, result.stderr
            built[builder] = source / "_out" / builder
        return built[builder]

    return build
