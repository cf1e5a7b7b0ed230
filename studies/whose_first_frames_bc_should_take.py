"""Whose first frames a cloned policy should take among its decision samples, measured on a
finished benchmark run's crowds.

``bc`` with fixed hyperparameters (histogram gradient boosting, ball-relative features, 15
frames a step, unbalanced) is fitted under ``--fits`` seeds with the decision samples
:func:`polymimic.baselines.training.sample_rows` draws (every stride-th frame from a drawn one)
and three ways with the demonstrations' first frames: those of the imitator's own body only
(the rule), every demonstration's, and none. Each fit plays the run's evaluation attempts.
Prints one JSON line per profile and way: net goals per fit. A crowd of the imitator's body
alone gives the same samples the first two ways. Run:
``python studies/whose_first_frames_bc_should_take.py RUN_DIR [--profiles one_good half] [--fits 8]``.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # batched predictions of ≤ 50 rows: threads only cost

import json  # noqa: E402
import statistics  # noqa: E402

from _benchmark_run import arguments, opened  # noqa: E402
from polymimic.baselines import training  # noqa: E402
from polymimic.baselines.evaluation import play  # noqa: E402
from polymimic.baselines.hyperparameters import Hyperparameters  # noqa: E402
from polymimic.baselines.labels import command_labels  # noqa: E402
from polymimic.datasets import load_demonstrations  # noqa: E402

CHOSEN = Hyperparameters("hist_gradient_boosting", (("learning_rate", 0.1), ("max_iter", 100), ("max_leaf_nodes", 31)),
                         "ball_relative", 15, False)
RULE = training.sample_rows


def every_demonstrations(demonstrations, **kwargs):
    """The frames :func:`~polymimic.baselines.training.sample_rows` draws with every first frame."""
    return RULE(demonstrations, **{**kwargs, "first_frames": [True] * len(demonstrations)})


def no_demonstrations(demonstrations, **kwargs):
    """The frames :func:`~polymimic.baselines.training.sample_rows` draws with no first frame."""
    return RULE(demonstrations, **{**kwargs, "first_frames": [False] * len(demonstrations)})


def main() -> None:
    args = arguments(__doc__, fits=8)
    run, config, evaluation = opened(args.run_dir)
    settings = config.benchmark
    for profile in args.profiles or list(settings.profiles):
        items = command_labels(load_demonstrations(run.crowd_path(profile)))
        for way, rows in (("own_body_first_frames", RULE), ("every_first_frame", every_demonstrations),
                          ("no_first_frame", no_demonstrations)):
            training.sample_rows = rows  # decision_samples looks it up when called
            nets = []
            for seed in range(args.fits):
                policy = training.train("bc", items, hyperparameters=CHOSEN, seed=seed,
                                        max_samples=settings.tuning.max_decision_samples)
                played = play(policy, evaluation, field_config=config.field)
                nets.append(played.goals - played.own_goals)
            print(json.dumps({"profile": profile, "way": way, "net": nets, "net_mean": statistics.mean(nets)}),
                  flush=True)
    training.sample_rows = RULE


if __name__ == "__main__":
    main()
