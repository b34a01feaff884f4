"""Work shared among every core: matplotlib's drawing is most of what the build and the exports
spend, and each template's graphs are its own.

    results = on_every_core(work, items)     # [work(item) for item in items], in order
"""

from __future__ import annotations

import multiprocessing
import os
import sys
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from typing import Any

#: The work of the pool running now: set before its processes fork, so they inherit it (a
#: closure over the build's state need not be pickled; only the items and results are).
_work: Callable[[Any], Any] | None = None


def _run(item):
    return _work(item)


def on_every_core(work: Callable[[Any], Any], items: Sequence) -> list:
    """``[work(item) for item in items]``, the items handed one at a time to forked worker
    processes, one per core. Each process starts as a copy of this one (on Linux, by fork), so
    `work` may read anything this process holds; what it returns comes back pickled, and what it
    writes must be its own item's files. With one core, one item, or no fork (not Linux), this
    process does the work itself."""
    global _work
    cores = os.cpu_count() or 1
    if cores == 1 or len(items) < 2 or sys.platform != "linux":
        return [work(item) for item in items]
    _work = work
    try:
        with ProcessPoolExecutor(max_workers=cores, mp_context=multiprocessing.get_context("fork")) as pool:
            return list(pool.map(_run, items))
    finally:
        _work = None
