# SPDX-License-Identifier: GPL-3.0-or-later
"""The GIL is released while an estimator runs: another Python thread runs meanwhile.

With a switch interval of 1000 s the interpreter takes the GIL from no thread: a thread
blocked on an Event runs again only when the thread holding the GIL releases it. The worker
sets `entered` and calls the estimator: the main thread can run before the call returns
only if the call released the GIL, and then the worker cannot set `returned` (it needs the
GIL, which the main thread holds) until the main thread has looked. The main thread must wake
before the call ends, so the calls take 20 ms or more: at 1.5 ms, about one run of the file
in ten failed on this machine (the wake-up can take longer)."""

import sys
import threading

import pytest

import curvature_estimation as ce
from conftest import grid_graph
from test_bit_identity import tetrahedral_grid


def runs_alongside(call):
    """Whether the main thread ran while `call()` was running in another thread."""
    entered, returned = threading.Event(), threading.Event()
    errors = []

    def worker():
        entered.set()
        try:
            call()
        except BaseException as e:  # reported below
            errors.append(e)
        returned.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        entered.wait()
        ran_during_call = not returned.is_set()
    finally:
        sys.setswitchinterval(interval)
    thread.join()
    assert not errors, errors
    return ran_during_call


def test_the_check_sees_a_call_that_holds_the_gil():
    # sorted() on a long list holds the GIL throughout: the check must say so.
    data = list(range(3_000_000, 0, -1))
    assert not runs_alongside(lambda: sorted(data))


@pytest.mark.parametrize("threads", [0, 1])
def test_mesh_curvatures_releases_the_gil(threads):
    mesh = grid_graph(n=201)
    assert runs_alongside(lambda: ce.mesh_curvatures(*mesh, threads=threads))


def test_point_set_curvatures_releases_the_gil():
    points = grid_graph(n=201)[0]
    assert runs_alongside(lambda: ce.point_set_curvatures(points, threads=1))


def test_tetrahedral_curvatures_releases_the_gil():
    grid = tetrahedral_grid(n=13)
    assert runs_alongside(lambda: ce.tetrahedral_curvatures(*grid, threads=1))


def test_two_threads_give_the_values_of_one():
    mesh = grid_graph(n=41, jitter=0.3)
    expected = ce.mesh_curvatures(*mesh, threads=1)
    results = [None, None]

    def work(k):
        results[k] = ce.mesh_curvatures(*mesh, threads=1)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        for a, b in zip(r, expected):
            assert a.tobytes() == b.tobytes()
