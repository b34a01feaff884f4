"""on_every_core: the work of many items shared among forked processes, the results in order."""

from __future__ import annotations

import os

from physics_figures.cores import on_every_core


def test_the_results_come_back_in_the_items_order_from_other_processes():
    state = {"offset": 1000}  # the work reads what this process held when the pool forked
    results = on_every_core(lambda n: (n + state["offset"], os.getpid()), range(40))
    assert [value for value, _ in results] == list(range(1000, 1040))
    if (os.cpu_count() or 1) > 1:
        assert os.getpid() not in {pid for _, pid in results}, "the items were not worked on in the pool"


def test_one_item_is_worked_on_here():
    assert on_every_core(lambda n: os.getpid(), [7]) == [os.getpid()]
