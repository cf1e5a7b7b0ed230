"""Which practice method earns the default: each of :data:`polymimic.practice.methods.METHODS`,
and ``refine`` (replaying its own policy, refining the ball's response and the states' values:
``practice(..., explore=0, refines=None)``, which this study found earns no method of its own),
practises the ``polymimic`` imitators of a finished benchmark run, scored on the run's
validation attempts (drawn as tuning draws them, apart from the evaluation's), never on the
evaluation's.

For each of ``--profiles`` (default ``one_good`` and ``half``), each of the first ``--trials``
trials (its seed is the practice's) and each of ``--methods``: the trial's imitator practises
for ``--steps`` environment steps, scored at the default checkpoints. Each finished curve is
written at once to ``--out`` (JSON; by default the committed file beside this script), so a
rerun goes on where it stopped; the summary prints each method's mean net goals per checkpoint
and its lowest point below where it started.

Run: ``python studies/which_practice_wins_on_validation.py RUN_DIR [--steps 50000] [--trials 2]
[--methods ...] [--profiles ...] [--out FILE]`` (``jsrl`` and ``distil`` need ``polymimic[rl]``;
about ten minutes at full size on two cores).
"""

from __future__ import annotations

import dataclasses
import json
import pathlib

from _practice_curves import CurveFile, on_validation, validation_attempts
from polymimic.practice import practice
from polymimic.practice.methods import METHODS, practise

STUDIED = ("refine", *METHODS)


def main() -> None:
    options, run, config = on_validation(__doc__, variants="methods", choices=STUDIED,
                                         out=pathlib.Path(__file__).with_suffix(".json"))
    segmenter = dataclasses.asdict(config.segmenter)
    validation = validation_attempts(config)
    curves = CurveFile(options.out)
    for key, method, trial_seed, policy in curves.pending(options, run, config, options.methods):
        if method == "refine":
            def played(policy=policy, seed=trial_seed):
                return practice(policy, steps=options.steps, seed=seed, evaluation=validation,
                                field_config=config.field, segmenter=segmenter, explore=0.0, refines=None)
        else:
            def played(policy=policy, seed=trial_seed, method=method):
                return practise(policy, method=method, steps=options.steps, seed=seed, evaluation=validation,
                                field_config=config.field, segmenter=segmenter)
        curves.practise(key, played, scored_on=validation.count)
    for profile in options.profiles:
        for method in options.methods:
            summary = curves.summary(method, options.steps, profile)
            if summary is not None:
                print(json.dumps(summary), flush=True)


if __name__ == "__main__":
    main()
