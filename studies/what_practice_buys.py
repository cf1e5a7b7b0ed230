"""Practice on a finished benchmark run: the ``polymimic`` imitators of the first ``--trials``
trials of each profile practise by ``--method`` for ``--steps`` environment steps (practice seed
= the trial's seed) and are scored at every default checkpoint on the run's evaluation attempts.

Each finished curve is written at once to ``--out`` (JSON, under 300 kB at the default size), so
a rerun goes on where it stopped; the summary prints one JSON line per profile: the mean net
goals at each checkpoint over the trials, and the deepest dip below the start.

Run: ``python studies/what_practice_buys.py RUN_DIR [--method distil] [--trials 3]
[--steps 50000] [--profiles one_good half] [--out FILE]`` (``jsrl`` and ``distil`` need
``polymimic[rl]``; a few minutes per trial).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import pathlib

from _benchmark_run import imitators
from _practice_curves import CurveFile
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.practice.methods import METHODS, practise


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", help="default: every profile of the run")
    parser.add_argument("--method", default="distil", choices=METHODS)
    parser.add_argument("--trials", type=int, default=3)
    parser.add_argument("--steps", type=int, default=50_000)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("practice.json"))
    options = parser.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")  # torch on a small machine: one thread learns fastest
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    segmenter = dataclasses.asdict(config.segmenter)
    evaluation = config.evaluation_attempts()
    curves = CurveFile(options.out)
    profiles = options.profiles or list(config.benchmark.profiles)
    for profile in profiles:
        for trial_seed, policy in imitators(run, config, profile, options.trials):
            key = f"{options.method}/{profile}/{trial_seed}/{options.steps}"
            if key in curves:
                continue

            def played(policy=policy, seed=trial_seed):
                return practise(policy, method=options.method, steps=options.steps, seed=seed, evaluation=evaluation,
                                field_config=config.field, segmenter=segmenter)
            curves.practise(key, played, scored_on=evaluation.count)
    for profile in profiles:
        summary = curves.summary(options.method, options.steps, profile)
        if summary is not None:
            print(json.dumps(summary), flush=True)


if __name__ == "__main__":
    main()
