"""Which check keeps ``distil`` from scoring below its teacher: the default (100 practice
attempts, the paired mean less two standard errors), the paired mean alone on the same 100, and
the mean alone on 50, each practising the ``polymimic`` imitators of a finished benchmark run,
scored on the run's validation attempts (drawn as tuning draws them, apart from the
evaluation's), never on the evaluation's.

For each of ``--profiles`` (default ``one_good`` and ``half``), each of the first ``--trials``
trials (its seed is the practice's) and each of ``--checks``: the trial's imitator practises by
``distil`` for ``--steps`` environment steps, scored at the default checkpoints. Each finished
curve is written at once to ``--out`` (JSON), so a rerun goes on where it stopped; the summary
prints each check's mean net goals per checkpoint and its lowest point below the start.

Run: ``python studies/which_check_keeps_distil_safe.py RUN_DIR [--steps 50000] [--trials 2]
[--out FILE]`` (needs ``polymimic[rl]``; about a quarter of an hour on two cores).
"""

from __future__ import annotations

import argparse
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
from polymimic.practice.curve import DEFAULT_CHECKPOINTS
from polymimic.practice.distil import distil
from polymimic.practice.teacher import Gate

CHECKS = {
    # name: (practice attempts per configuration, standard errors taken off the paired mean)
    "confident_100": (50, 2.0),
    "mean_100": (50, 0.0),
    "mean_50": (25, 0.0),
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", default=["one_good", "half"])
    parser.add_argument("--checks", nargs="+", default=list(CHECKS), choices=CHECKS)
    parser.add_argument("--trials", type=int, default=2)
    parser.add_argument("--steps", type=int, default=50_000)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("distil_checks_on_validation.json"))
    options = parser.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")  # torch on a small machine: one thread learns fastest
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    tuning = config.benchmark.tuning
    # the validation's episodes, as tuning draws them: apart from the evaluation's
    validation = Attempts(per_configuration=tuning.validation_attempts_per_configuration,
                          seed=VALIDATION_SEED_BASE + tuning.validation_seed)
    marks = [c for c in DEFAULT_CHECKPOINTS if c < options.steps] + [options.steps]
    done: dict[str, Any] = json.loads(options.out.read_text()) if options.out.exists() else {}
    for profile in options.profiles:
        for trial_seed, policy in imitators(run, config, profile, options.trials):
            for check in options.checks:
                key = f"{check}/{profile}/{trial_seed}/{options.steps}"
                if key in done:
                    continue
                attempts, z = CHECKS[check]
                started = time.perf_counter()
                result = distil(policy, steps=options.steps, seed=trial_seed, checkpoints=marks, evaluation=validation,
                                gate=Gate(attempts=attempts), confidence_z=z, field_config=config.field)
                curve = [[p.checkpoint, p.steps, p.net_goals] for p in result.curve]
                done[key] = {"curve": curve, "seconds": round(time.perf_counter() - started, 1)}
                atomic_write_text(options.out, json.dumps(done, indent=1) + "\n")
                print(f"{key}: {curve[0][2]:+.0f} -> {curve[-1][2]:+.0f} ({done[key]['seconds']:.0f} s)", flush=True)
    for check in options.checks:
        curves = [v["curve"] for k, v in done.items() if k.startswith(f"{check}/") and k.endswith(f"/{options.steps}")]
        if curves:
            means = [round(statistics.fmean(c[i][2] for c in curves), 2) for i in range(len(curves[0]))]
            dip = min(min(p[2] for p in c) - c[0][2] for c in curves)
            print(json.dumps({"check": check, "curves": len(curves), "mean_net_goals": means, "deepest_dip": dip}))


if __name__ == "__main__":
    main()
