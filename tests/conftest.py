"""Shared fixtures. `make test` builds the site into _build/html before pytest runs."""

import os
import sys
from pathlib import Path

import matplotlib
import pytest
from hypothesis import settings

matplotlib.use("Agg")

# The book's own Sphinx extensions (site_assets, offline, ...) are importable in tests, as
# they are in the build (_config.yml's local_extensions).
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
# scripts/browser.py (serve the built site, open it in Chromium) is shared with scripts/bench.py,
# which imports nothing from tests/.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))
import browser  # from scripts/, just put on the path

# One profile for every Hypothesis test: no deadline (a loaded CI machine is slow, and a
# timing failure says nothing about the physics), and the same examples on every CI run.
settings.register_profile("book", deadline=None, derandomize=bool(os.environ.get("CI")))
settings.load_profile("book")


#: What a test needs beyond Python: `make check` leaves these out, `make test` runs them.
NEEDS = {
    "site": "the built site or PDFs (make book)",
    "browser": "Chromium (scripts/ensure-debian-packages test)",
    "build": "its own Sphinx or xelatex builds (slow)",
    "network": "PyPI (pip-compile resolves the lock again)",
}
_current_test = None


def pytest_configure(config):
    for marker, needs in NEEDS.items():
        config.addinivalue_line("markers", f"{marker}: needs {needs}; left out of `make check`")
    config.addinivalue_line("markers", "variant(index, count): a test of one variant of a template (variant_param)")
    config.addinivalue_line("markers", "alone: measures speed, so `make test` runs it by itself, after the "
                                       "parallel run of the site's tests")


def pytest_addoption(parser):
    parser.addoption("--sample-variants", action="store_true",
                     help="test three variants of each template (the printed one, the next and the last) "
                          "instead of every one: `make check`'s fast loop; `make test` tests them all")


def variant_param(template, index: int, *values):
    """A test's parameters for variant `index` of `template`, named TEMPLATE-INDEX and marked so
    that --sample-variants can leave it out."""
    return pytest.param(*values, id=f"{template.key}-{index}",
                        marks=pytest.mark.variant(index, len(template.values)))


#: The folders of tests/ follow the markers: a test lives in the folder of the heaviest thing it
#: needs (a build of its own, then Chromium, then the built site, then PyPI), and the folder gives
#: it that marker. tests/no_site/ holds what `make check` runs. A test marked `alone` (it measures
#: speed) lives with the others of what it needs: `alone` says when make test runs it, not what
#: it needs.
FOLDERS = ("build", "browser", "site", "network")
NO_SITE_FOLDER = "no_site"
TESTS = Path(__file__).resolve().parent


def folder_for(markers) -> str:
    """The folder of tests/ that a test carrying `markers` belongs in."""
    return next((folder for folder in FOLDERS if folder in markers), NO_SITE_FOLDER)


def test_folder(path: Path) -> str:
    """The folder of tests/ that a test module sits in (the first one under tests/)."""
    return Path(path).resolve().relative_to(TESTS).parts[0]


#: The modules that take longest (tens of seconds, on two workers), run first. pytest-xdist
#: (--dist loadscope) hands a worker a whole module, in the order they are collected: a long
#: module collected last kept one core busy for a minute while the other had nothing left.
#: Measured with --durations on an idle machine; the order within this list is longest first.
RUN_FIRST = (
    # tests/site, tests/browser: make test's run of the built site
    "test_site.py", "test_offline_browser.py", "test_sketch_browser.py", "test_css_pruning.py",
    "test_sheet_builder_browser.py", "test_ecf_browser.py", "test_reading_browser.py",
    "test_text_marking_browser.py", "test_class_browser.py",
    # tests/build: each builds books of its own
    "test_incremental_build.py", "test_build.py", "test_worksheets_pdf_build.py",
    "test_second_topic.py", "test_progress_build.py",
    # tests/no_site: make check's
    "test_question_diagrams.py", "test_figures.py", "test_graph_readings.py", "test_models_drag.py",
    "test_allowances.py", "test_questions_engine.py", "test_figure_data.py", "test_worksheets.py",
    "test_programs.py", "test_graph_labels.py",
)


def run_first(items) -> None:
    """Order `items` so that RUN_FIRST's modules come first, longest first; the rest keep their
    order. A name in RUN_FIRST that is no module of tests/ is an error, not a silent no-op."""
    missing = [name for name in RUN_FIRST if not any(TESTS.glob(f"*/{name}"))]
    if missing:
        raise pytest.UsageError(f"RUN_FIRST (tests/conftest.py) names no module: {missing}")
    rank = {name: place for place, name in enumerate(RUN_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(RUN_FIRST)))  # stable: a module stays whole


@pytest.hookimpl(tryfirst=True)  # before -m deselects by marker
def pytest_collection_modifyitems(config, items):
    run_first(items)
    misplaced = []
    for item in items:
        folder = test_folder(item.path)
        if folder in FOLDERS:
            item.add_marker(folder)
        carried = {marker.name for marker in item.iter_markers()}
        if folder_for(carried) != folder:
            misplaced.append(f"{item.nodeid} carries {sorted(carried & set(FOLDERS))}: "
                             f"it belongs in tests/{folder_for(carried)}/")
    if misplaced:
        raise pytest.UsageError("tests in a folder whose marker they do not follow:\n" + "\n".join(misplaced))
    if not config.getoption("--sample-variants"):
        return
    kept, left_out = [], []
    for item in items:
        marker = item.get_closest_marker("variant")
        index, count = marker.args if marker else (0, 1)
        (kept if index in (0, 1, count - 1) else left_out).append(item)
    if left_out:
        config.hook.pytest_deselected(items=left_out)
        items[:] = kept


def pytest_runtest_setup(item):
    if "site_dir" in getattr(item, "fixturenames", ()) and item.get_closest_marker("site") is None:
        pytest.fail(f"{item.nodeid} uses the built site: mark it @pytest.mark.site")


@pytest.fixture(autouse=True)
def _remember_test(request):
    """Lets require_marker see which test is running (scripts/browser.py has no request)."""
    global _current_test
    _current_test = request.node
    yield
    _current_test = None


def require_marker(marker: str) -> None:
    """Fail a test that uses what `marker` stands for without carrying the marker, so the
    split between `make check` and `make test` cannot drift."""
    if _current_test is not None and _current_test.get_closest_marker(marker) is None:
        pytest.fail(f"{_current_test.nodeid} needs {NEEDS[marker]}: mark it @pytest.mark.{marker}")


browser.BEFORE_CHROMIUM.append(lambda: require_marker("browser"))

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


@pytest.fixture(scope="module")
def base_url(site_dir):
    """The built site, served as a static host serves it (scripts/browser.py), for a module."""
    from browser import serve_site

    with serve_site(site_dir) as base:
        yield base


@pytest.fixture(scope="session")
def chromium():
    """Headless Chromium (scripts/browser.py), one for the whole test process: each launch, with
    playwright's driver, costs about 0.7 core-seconds, and a run of the site's tests opened one
    per module. A test's state lives in its own browser context, not in the browser."""
    from browser import open_browser

    with open_browser() as launched:
        yield launched


@pytest.fixture(scope="module")
def browser(chromium):
    """Chromium for a module's tests. The contexts (and pages) a module leaves open are closed
    after it, as closing its own browser did: no page of one module runs on into the next."""
    yield chromium
    for context in chromium.contexts:
        context.close()


@pytest.fixture(scope="module")
def site(browser, base_url):
    """(browser, base_url), for a module whose tests open their own browser contexts."""
    return browser, base_url


@pytest.fixture(scope="module")
def question_site(site, site_dir):
    """(browser, base_url, {template key: the site path of the first page that asks it})."""
    from browser import question_pages

    return (*site, question_pages(site_dir))
