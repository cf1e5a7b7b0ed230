"""Which practice method earns the default: each of :data:`polymimic.practice.methods.METHODS`,
and ``refine`` (replaying its own policy, refining the ball's response and the states' values:
``practice(..., explore=0, refines=None)``, which this study found earns no method of its own),
practises the ``polymimic`` imitators of a finished benchmark run, scored on the run's
validation attempts (drawn as tuning draws them, apart from the evaluation's), never on the
evaluation's.

For each of ``--profiles`` (default ``one_good`` and ``half``), each of the first ``--trials``
trials (its seed is the practice's) and each of ``--methods``: the trial's imitator practises
for ``--steps`` environment steps, scored at the default checkpoints. Each finished curve is
written at once to ``--out`` (JSON), so a rerun goes on where it stopped; the summary prints each
method's mean net goals per checkpoint and its lowest point below where it started.

Run: ``python studies/which_practice_wins_on_validation.py RUN_DIR [--steps 50000] [--trials 2]
[--out FILE]`` (``jsrl`` and ``distil`` need ``polymimic[rl]``; about ten minutes at full size on two cores).
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
from polymimic import Attempts
from polymimic._atomic import atomic_write_text
from polymimic.baselines.tuning import VALIDATION_SEED_BASE
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.practice import practice
from polymimic.practice.methods import METHODS, practise

STUDIED = ("refine", *METHODS)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", default=["one_good", "half"])
    parser.add_argument("--methods", nargs="+", default=list(STUDIED), choices=STUDIED)
    parser.add_argument("--trials", type=int, default=2)
    parser.add_argument("--steps", type=int, default=50_000)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("practice_on_validation.json"))
    options = parser.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")  # torch on a small machine: one thread learns fastest
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    segmenter = dataclasses.asdict(config.segmenter)
    settings = config.benchmark
    done: dict[str, Any] = json.loads(options.out.read_text()) if options.out.exists() else {}
    for profile in options.profiles:
        for trial_seed, policy in imitators(run, config, profile, options.trials):
            for method in options.methods:
                key = f"{method}/{profile}/{trial_seed}/{options.steps}"
                if key in done:
                    continue
                started = time.perf_counter()
                # the validation's episodes, as tuning draws them: apart from the evaluation's
                validation = Attempts(per_configuration=settings.tuning.validation_attempts_per_configuration,
                                      seed=VALIDATION_SEED_BASE + settings.tuning.validation_seed)
                if method == "refine":
                    result = practice(policy, steps=options.steps, seed=trial_seed, evaluation=validation,
                                      field_config=config.field, segmenter=segmenter, explore=0.0, refines=None)
                else:
                    result = practise(policy, method=method, steps=options.steps, seed=trial_seed,
                                      evaluation=validation, field_config=config.field, segmenter=segmenter)
                curve = [[p.checkpoint, p.steps, p.net_goals] for p in result.curve]
                done[key] = {"curve": curve, "seconds": round(time.perf_counter() - started, 1)}
                atomic_write_text(options.out, json.dumps(done, indent=1) + "\n")
                scored = 2 * settings.tuning.validation_attempts_per_configuration
                print(f"{key}: {curve[0][2]:+.0f} -> {curve[-1][2]:+.0f} of {scored} ({done[key]['seconds']:.0f} s)",
                      flush=True)
    summarise(done, options)


def summarise(done: dict[str, Any], options: argparse.Namespace) -> None:
    """Per method and profile: mean net goals at each checkpoint, and the deepest dip below the start."""
    for profile in options.profiles:
        for method in options.methods:
            curves = [v["curve"] for k, v in done.items()
                      if k.startswith(f"{method}/{profile}/") and k.endswith(f"/{options.steps}")]
            if not curves:
                continue
            means = [round(statistics.fmean(c[i][2] for c in curves), 2) for i in range(len(curves[0]))]
            dip = min(min(p[2] for p in c) - c[0][2] for c in curves)
            print(json.dumps({"profile": profile, "method": method, "trials": len(curves),
                              "checkpoints": [p[0] for p in curves[0]], "mean_net_goals": means,
                              "deepest_dip": dip}), flush=True)


if __name__ == "__main__":
    main()
