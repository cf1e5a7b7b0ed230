"""Whether a cloned policy needs each demonstration's first frame among its decision samples,
measured on a finished benchmark run's crowds.

``bc`` with fixed hyperparameters (histogram gradient boosting, ball-relative features, 15
frames a step, unbalanced) is fitted under ``--fits`` seeds with the decision samples
:func:`polymimic.baselines.training.sample_rows` draws (each demonstration's first frame, then
every stride-th from a drawn frame) and with the same samples less the first frames, and plays
the run's evaluation attempts. Prints one JSON line per profile and way: net goals per fit.
Run: ``python benches/bc_first_frames.py RUN_DIR [--profiles one_good half] [--fits 8]``.
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
WITH_FIRST = training.sample_rows


def without_first(demonstrations, **kwargs):
    """The frames :func:`~polymimic.baselines.training.sample_rows` draws, less each first frame."""
    return [rows[1:] for rows in WITH_FIRST(demonstrations, **kwargs)]


def main() -> None:
    args = arguments(__doc__, fits=8)
    run, config, evaluation = opened(args.run_dir)
    settings = config.benchmark
    for profile in args.profiles or list(settings.profiles):
        items = command_labels(load_demonstrations(run.crowd_path(profile)))
        for way, rows in (("with_first_frames", WITH_FIRST), ("without", without_first)):
            training.sample_rows = rows  # decision_samples looks it up when called
            nets = []
            for seed in range(args.fits):
                policy = training.train("bc", items, hyperparameters=CHOSEN, seed=seed,
                                        max_samples=settings.max_decision_samples)
                played = play(policy, evaluation, field_config=config.field)
                nets.append(played.goals - played.own_goals)
            print(json.dumps({"profile": profile, "way": way, "net": nets, "net_mean": statistics.mean(nets)}),
                  flush=True)
    training.sample_rows = WITH_FIRST


if __name__ == "__main__":
    main()
