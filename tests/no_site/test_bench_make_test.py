"""scripts/bench_make_test.py: the phases of `make test` read from a log stamped as it writes one."""

from __future__ import annotations

from bench_make_test import PHASES, phases

# make test's own lines, as the Makefile prints them, with the second each arrived
LOG = """\
[    0.4] >>> creating .venv
[   21.0] >>> building the book; beside it, the tests that need no site
[   22.0] ============================= test session starts ==============================
[  160.5] >>> the tests of the built site, in Chromium too, on both cores
[  161.0] ============================= test session starts ==============================
[  590.0] ======================= 895 passed in 428.50s (0:07:08) ========================
[  600.0] >>> the tests that need no site:
[  600.0] ====================== 11956 passed in 557.23s (0:09:17) =======================
[  600.1] >>> the tests that measure speed, alone
[  629.0] ============================== 1 passed in 28.77s ==============================
"""


def test_each_phase_ends_where_the_next_begins_and_the_last_at_the_end():
    took = phases(LOG, 630.0)
    assert list(took) == [name for name, _ in PHASES]
    assert took == {
        "install and lint": 21.0,
        "the book (the runs that need no site beside it)": 160.5 - 21.0,
        "the site's tests": 590.0 - 160.5,
        "waiting for the runs that need no site": 600.0 - 590.0,
        "the tests that measure speed, alone": 630.0 - 600.0,
    }
    assert sum(took.values()) == 630.0


def test_a_run_that_stopped_early_has_only_the_phases_it_reached():
    stopped = "".join(LOG.splitlines(keepends=True)[:3])  # the book failed: no site's run
    assert phases(stopped, 150.0) == {"install and lint": 21.0}
