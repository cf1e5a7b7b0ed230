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
import statistics
import time
from typing import Any

from _benchmark_run import imitators
from polymimic._atomic import atomic_write_text
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
    per_configuration = config.benchmark.sizes.attempts_per_configuration
    done: dict[str, Any] = json.loads(options.out.read_text()) if options.out.exists() else {}
    profiles = options.profiles or list(config.benchmark.profiles)
    for profile in profiles:
        for trial_seed, policy in imitators(run, config, profile, options.trials):
            key = f"{options.method}/{profile}/{trial_seed}/{options.steps}"
            if key in done:
                continue
            started = time.perf_counter()
            result = practise(policy, method=options.method, steps=options.steps, seed=trial_seed,
                              evaluation=config.evaluation_attempts(), field_config=config.field, segmenter=segmenter)
            done[key] = {"curve": [[p.checkpoint, p.steps, p.net_goals] for p in result.curve],
                         "seconds": round(time.perf_counter() - started, 1)}
            atomic_write_text(options.out, json.dumps(done, indent=1) + "\n")
            curve = done[key]["curve"]
            print(f"{key}: {curve[0][2]:+.0f} -> {curve[-1][2]:+.0f} of {2 * per_configuration} "
                  f"({done[key]['seconds']:.0f} s)", flush=True)
    for profile in profiles:
        curves = [v["curve"] for k, v in done.items()
                  if k.startswith(f"{options.method}/{profile}/") and k.endswith(f"/{options.steps}")]
        if not curves:
            continue
        means = [round(statistics.fmean(c[i][2] for c in curves), 2) for i in range(len(curves[0]))]
        print(json.dumps({"profile": profile, "method": options.method, "trials": len(curves),
                          "checkpoints": [p[0] for p in curves[0]], "mean_net_goals": means,
                          "gain": round(means[-1] - means[0], 2),
                          "deepest_dip": min(min(p[2] for p in c) - c[0][2] for c in curves)}), flush=True)


if __name__ == "__main__":
    main()
