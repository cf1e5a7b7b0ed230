"""``polymimic benchmark``: polymimic against the baselines on crowds of demonstrators (docs/results/benchmark.md).

An application, like :mod:`polymimic.reproduce`: it drives the library (crowds, learning
trials, baselines) into a run directory and reports; nothing in the library imports it.

* :mod:`~polymimic.benchmark.config` — sizes, methods, tuning effort and the crowds, as TOML;
* :mod:`~polymimic.benchmark.rundir` — where every file of a benchmark lives;
* :mod:`~polymimic.benchmark.tasks` — trials, tunings and evaluations as tasks for any backend;
* :mod:`~polymimic.benchmark.driver` — the steps, resumable;
* :mod:`~polymimic.benchmark.summary` — ``benchmark.json``;
* :mod:`~polymimic.benchmark.targets`, :mod:`~polymimic.benchmark.report`,
  :mod:`~polymimic.benchmark.figures` — what the report says and shows.
"""
