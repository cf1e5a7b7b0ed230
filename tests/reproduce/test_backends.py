"""Where tasks run: results keyed by argument on every backend, and workers that do not
oversubscribe the machine."""

import os

import pytest

from polymimic.runs.backends import TaskRunner


def _thread_pools(shared, arg):
    """The BLAS and OpenMP thread pools' sizes where this task runs."""
    from threadpoolctl import threadpool_info

    return shared + arg, sorted({pool["num_threads"] for pool in threadpool_info()})


def test_pooled_workers_split_the_cores_between_their_thread_pools():
    pytest.importorskip("threadpoolctl")
    import numpy  # noqa: F401  (loads the BLAS whose pool is limited)

    with TaskRunner(workers=2) as runner:
        runner.start([__name__, "numpy"])
        results = dict(runner.map(_thread_pools, 10, [1, 2, 3]))
    assert {arg: total for arg, (total, _) in results.items()} == {1: 11, 2: 12, 3: 13}
    each = max(1, (os.cpu_count() or 1) // 2)
    assert all(pools == [each] for _, pools in results.values()), results


def test_one_worker_runs_here_and_starts_no_server():
    with TaskRunner(workers=1) as runner:
        runner.start(["numpy"])  # nothing to start
        assert sorted(runner.map(pow, 2, [3, 4])) == [(3, 8), (4, 16)]
