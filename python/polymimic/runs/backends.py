"""Many independent tasks at once: in this process, on a local process pool, or on a Ray cluster.

A task is ``fn(shared, arg)``, where ``fn`` is a module-level function (so that workers can
import it), ``shared`` is sent to each worker once (process pool) or put in the object store once
(Ray), and ``arg`` is the task's own. Results come back in the order tasks finish, each with its
argument; callers key results by argument, so what they keep never depends on the backend or the
number of workers.

>>> import operator
>>> with TaskRunner(workers=1) as runner:
...     sorted(runner.map(operator.pow, 2, [1, 2, 3]))
[(1, 2), (2, 4), (3, 8)]
"""

from __future__ import annotations

import concurrent.futures
import logging
import multiprocessing
import os
import signal
from collections.abc import Callable, Iterator, Sequence
from typing import Any, TypeVar

__all__ = ["BACKENDS", "TaskRunner"]

A = TypeVar("A")
R = TypeVar("R")

BACKENDS = ("local", "ray")

_worker_fn: Callable[[Any, Any], Any] | None = None
_worker_shared: Any = None


_ONE_THREAD_EACH = {"RAYON_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
                    "MKL_NUM_THREADS": "1"}
"""The environment of a Ray task: Ray already spreads tasks over the cores."""


def _init_worker(fn: Callable[[Any, Any], Any], shared: Any, threads: int) -> None:
    global _worker_fn, _worker_shared
    # The parent handles Ctrl-C and cancels what is left; workers just stop with it.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    # Workers already split the machine between them; more threads each would oversubscribe it:
    # two scikit-learn fits side by side, each with a BLAS thread per core, take 4× as long.
    os.environ.setdefault("RAYON_NUM_THREADS", str(threads))
    try:
        from threadpoolctl import threadpool_limits  # type: ignore[import-untyped, unused-ignore]
    except ImportError:  # no BLAS-heavy library installed: only Rust's threads to limit
        pass
    else:
        threadpool_limits(limits=threads)  # in force from now on, in this process
    _worker_fn, _worker_shared = fn, shared


def _worker_context(modules: Sequence[str]) -> multiprocessing.context.BaseContext:
    """How workers start. Never forked from this process: forking a process whose Rust thread
    pools are running can deadlock. Where it can, a fork server (started once, with no Rust
    threads, having imported polymimic and ``modules``) forks them, which takes milliseconds
    where starting a fresh interpreter and importing polymimic takes about a second; elsewhere
    they are spawned."""
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    context = multiprocessing.get_context("forkserver")
    # Only heard before the server first starts; later pools reuse the server.
    context.set_forkserver_preload(["polymimic", *modules])
    return context


def _run_in_worker(arg: Any) -> tuple[Any, Any]:
    assert _worker_fn is not None
    return arg, _worker_fn(_worker_shared, arg)


class TaskRunner:
    """Where tasks run: ``backend="local"`` on ``workers`` processes (default: one per core; one
    runs tasks in this process), or ``backend="ray"`` on a Ray cluster (``address`` to join one;
    default: start a local one with ``workers`` CPUs, shut down on leaving the ``with``)."""

    def __init__(self, *, backend: str = "local", workers: int | None = None, address: str | None = None) -> None:
        if backend not in BACKENDS:
            raise ValueError(f"backend must be one of {', '.join(BACKENDS)}, got {backend!r}")
        if workers is not None and workers < 1:
            raise ValueError(f"workers must be at least 1, got {workers}")
        if address is not None and backend != "ray":
            raise ValueError("an address is for the Ray backend: add --backend ray")
        self.backend, self.address = backend, address
        self.workers = workers or os.cpu_count() or 1
        self._started_ray = False
        self._preload: tuple[str, ...] = ()

    def start(self, modules: Sequence[str]) -> None:
        """Start the local workers' fork server now, importing polymimic and ``modules`` (the
        tasks' modules and what they import lazily) while this process goes on with its own work;
        otherwise the first pool starts it and waits for the imports. Does nothing where workers
        are not forked from a server, or the server is already running."""
        self._preload = tuple(modules)
        if self.backend != "local" or self.workers == 1:
            return
        context = _worker_context(self._preload)
        if context.get_start_method() == "forkserver":
            import multiprocessing.forkserver

            multiprocessing.forkserver.ensure_running()

    def __repr__(self) -> str:
        return f"TaskRunner(backend={self.backend!r}, workers={self.workers}, address={self.address!r})"

    def __enter__(self) -> TaskRunner:
        return self

    def __exit__(self, *exc: object) -> None:
        if self._started_ray:
            import ray

            ray.shutdown()
            self._started_ray = False

    def map(self, fn: Callable[[Any, A], R], shared: Any, args: Sequence[A]) -> Iterator[tuple[A, R]]:
        """``(arg, fn(shared, arg))`` for every ``arg``, as each finishes."""
        if not args:
            return iter(())
        if self.backend == "ray":
            return self._map_ray(fn, shared, args)
        if self.workers == 1 or len(args) == 1:
            return ((arg, fn(shared, arg)) for arg in args)
        return self._map_pool(fn, shared, args)

    def _map_pool(self, fn: Callable[[Any, A], R], shared: Any, args: Sequence[A]) -> Iterator[tuple[A, R]]:
        workers = min(self.workers, len(args))
        threads = max(1, (os.cpu_count() or 1) // workers)
        context = _worker_context([*self._preload, fn.__module__])
        pool = concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=context,
                                                      initializer=_init_worker,
                                                      initargs=(fn, shared, threads))
        try:
            futures = [pool.submit(_run_in_worker, arg) for arg in args]
            for future in concurrent.futures.as_completed(futures):
                yield future.result()
        finally:
            pool.shutdown(wait=True, cancel_futures=True)

    def _map_ray(self, fn: Callable[[Any, A], R], shared: Any, args: Sequence[A]) -> Iterator[tuple[A, R]]:
        import ray

        if not ray.is_initialized():
            if self.address is None:
                ray.init(num_cpus=self.workers, include_dashboard=False, log_to_driver=False,
                         logging_level=logging.WARNING)
            else:
                ray.init(address=self.address, log_to_driver=False, logging_level=logging.WARNING)
            self._started_ray = True
        # One task per CPU, each on one thread: Ray already spreads tasks over the cores.
        remote = ray.remote(num_cpus=1, runtime_env={"env_vars": _ONE_THREAD_EACH})(fn)
        shared_ref = ray.put(shared)
        pending = {remote.remote(shared_ref, arg): arg for arg in args}
        try:
            while pending:
                done, _ = ray.wait(list(pending), num_returns=1)
                for ref in done:
                    yield pending.pop(ref), ray.get(ref)
        finally:
            for ref in pending:
                ray.cancel(ref)
