"""How a demonstration from another field reaches ``bc``'s samples, and how a humanoid's kick is
labelled, measured on a finished benchmark run's crowd (``mixed_bodies`` by default).

One classifier of fixed hyperparameters (histogram gradient boosting, ball-relative features,
5 frames a step, unbalanced) is fitted under ``--fits`` seeds for each way of bringing the
tiny's small field onto the imitator's and each kick label, and plays the run's evaluation
attempts. The ways:

- ``stretch``: the whole small field stretched per axis, x by 1020/560 and y by 810/345 (what
  the cloning baselines once did);
- ``mapped``: the ball's position scaled by the fields' lengths alone and the robot at its
  true offset from it (what they once did with a field longer than the imitator's);
- ``correspondence``: :func:`polymimic.bodies.onto_field`, the learner's one correspondence
  between fields (what every part of polymimic does now): the ball by the lengths along and
  goal mouth onto goal mouth across, the robot at its offset from the ball;
- ``recorded``: the tiny's frames as recorded, its field centred on the imitator's (what they
  once did with a field no longer than it).

Kicks are labelled ``backward`` (as they look from above, Table 4.4) or ``forward`` (what
``bc`` does). Prints one JSON line per way and label: net goals, goals and own goals per fit.
Run: ``python studies/how_bc_should_read_another_field.py RUN_DIR [--profile mixed_bodies] [--fits 10]``.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # batched predictions of ≤ 50 rows: threads only cost

import json  # noqa: E402
import statistics  # noqa: E402

import numpy as np  # noqa: E402

from _benchmark_run import arguments, opened  # noqa: E402
from polymimic.baselines.evaluation import play  # noqa: E402
from polymimic.baselines.hyperparameters import Hyperparameters  # noqa: E402
from polymimic.baselines.labels import Labelled, command_labels  # noqa: E402
from polymimic.baselines.training import train  # noqa: E402
from polymimic.bodies import as_body, onto_field  # noqa: E402
from polymimic.datasets import load_demonstrations  # noqa: E402
from polymimic.field import PRIMITIVES, command_table  # noqa: E402
from polymimic.window_names import repeat_last_good  # noqa: E402

OBSERVATION = ("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm")
CHOSEN = Hyperparameters("hist_gradient_boosting", (("learning_rate", 0.1), ("max_iter", 100), ("max_leaf_nodes", 31)),
                         "ball_relative", 5, False)
KICKS = [row["id"] for row in command_table() if row["name"] in ("Kick Left", "Kick Right")]


def observations(demo, way: str) -> np.ndarray:
    seen = repeat_last_good(np.column_stack([demo.frames[c] for c in OBSERVATION]).astype(np.float64))
    if as_body(demo.body).field != as_body("tiny").field or way == "recorded":
        return seen
    if way == "correspondence":
        return onto_field(seen, recorded_by=demo.body)
    if way == "mapped":
        mapped = seen.copy()
        mapped[:, [3, 4]] *= 1020.0 / 560.0
        mapped[:, [0, 1]] = mapped[:, [3, 4]] + (seen[:, [0, 1]] - seen[:, [3, 4]])
        return mapped
    stretched = seen.copy()
    stretched[:, [0, 3]] *= 1020.0 / 560.0
    stretched[:, [1, 4]] *= 810.0 / 345.0
    return stretched


def labelled(demonstrations, way: str, kick: str) -> list[Labelled]:
    items = []
    for demo, item in zip(demonstrations, command_labels(demonstrations)):
        labels = item.labels.copy()
        labels[np.isin(demo.frames["command"], KICKS)] = PRIMITIVES.index(kick)
        items.append(Labelled(item.demonstrator, observations(demo, way), labels))
    return items


def main() -> None:
    args = arguments(__doc__, fits=10, one_profile=True)
    run, config, evaluation = opened(args.run_dir)
    settings = config.benchmark
    demonstrations = load_demonstrations(run.crowd_path(args.profile))
    for way in ("stretch", "mapped", "correspondence", "recorded"):
        for kick in ("backward", "forward"):
            items = labelled(demonstrations, way, kick)
            fits = []
            for seed in range(args.fits):
                policy = train("bc", items, hyperparameters=CHOSEN, seed=seed,
                               max_samples=settings.tuning.max_decision_samples)
                played = play(policy, evaluation, field_config=config.field)
                fits.append({"net": played.goals - played.own_goals, "goals": played.goals,
                             "own_goals": played.own_goals})
            nets = [f["net"] for f in fits]
            print(json.dumps({"profile": args.profile, "way": way, "kick": kick, "net_mean": statistics.mean(nets),
                              "net_sd": statistics.stdev(nets) if len(nets) > 1 else 0.0,
                              "own_goals_mean": statistics.mean(f["own_goals"] for f in fits), "fits": fits}),
                  flush=True)


if __name__ == "__main__":
    main()
