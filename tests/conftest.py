"""Shared fixtures. `make test` builds the site into _build/html before pytest runs."""

import os
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[1]
# SITE_DIR lets a test run point at a site built elsewhere (e.g. --path-output builds).
SITE = Path(os.environ.get("SITE_DIR", ROOT / "_build" / "html"))


@pytest.fixture(scope="session")
def site_dir() -> Path:
    """The built HTML site (built by `make test` before pytest starts)."""
    if not (SITE / "index.html").exists():
        pytest.fail(f"no built site at {SITE}: run `make book` (or `make test`, which builds it first)")
    return SITE


@pytest.fixture(autouse=True)
def _fresh_matplotlib():
    """Each test starts from default rcParams and leaves no figure open."""
    import matplotlib.pyplot as plt

    with matplotlib.rc_context():
        yield
    plt.close("all")
