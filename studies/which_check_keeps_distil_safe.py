"""Which check keeps ``distil`` from scoring below its teacher: the default (100 practice
attempts, the paired mean less two standard errors), the paired mean alone on the same 100, and
the mean alone on 50, each practising the ``polymimic`` imitators of a finished benchmark run,
scored on the run's validation attempts (drawn as tuning draws them, apart from the
evaluation's), never on the evaluation's.

For each of ``--profiles`` (default ``one_good`` and ``half``), each of the first ``--trials``
trials (its seed is the practice's) and each of ``--checks``: the trial's imitator practises by
``distil`` for ``--steps`` environment steps, scored at the default checkpoints. Each finished
curve is written at once to ``--out`` (JSON; by default the committed file beside this script),
so a rerun goes on where it stopped; the summary prints each check's mean net goals per
checkpoint and its lowest point below the start.

Run: ``python studies/which_check_keeps_distil_safe.py RUN_DIR [--steps 50000] [--trials 2]
[--checks ...] [--profiles ...] [--out FILE]`` (needs ``polymimic[rl]``; about twelve minutes on
two cores at the default two trials, half an hour at five).
"""

from __future__ import annotations

import json
import pathlib

from _practice_curves import CurveFile, on_validation, validation_attempts
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
    options, run, config = on_validation(__doc__, variants="checks", choices=list(CHECKS),
                                         out=pathlib.Path(__file__).with_suffix(".json"))
    validation = validation_attempts(config)
    marks = [c for c in DEFAULT_CHECKPOINTS if c < options.steps] + [options.steps]
    curves = CurveFile(options.out)
    for key, check, trial_seed, policy in curves.pending(options, run, config, options.checks):
        attempts, z = CHECKS[check]

        def played(policy=policy, seed=trial_seed, attempts=attempts, z=z):
            return distil(policy, steps=options.steps, seed=seed, checkpoints=marks, evaluation=validation,
                          gate=Gate(attempts=attempts), confidence_z=z, field_config=config.field)
        curves.practise(key, played, scored_on=validation.count)
    for check in options.checks:
        summary = curves.summary(check, options.steps)
        if summary is not None:
            print(json.dumps(summary), flush=True)


if __name__ == "__main__":
    main()
