"""A plain cloner beside ``bc`` on a finished benchmark run's crowds: the check that ``bc`` is
not weaker than a few lines of scikit-learn.

The plain cloner is scikit-learn's ``GradientBoostingClassifier`` on the environment's
observation plus the ball relative to the robot (``ball_relative``), each frame labelled with the
primitive of the command sent, on the crowd's demonstrations as recorded (no field is stretched
onto another), with at most the benchmark's number of decision samples, drawn with the fit's
seed. Its step length is chosen on the benchmark's validation attempts. It then plays the
benchmark's evaluation attempts once per fit seed. The script prints one JSON line per profile:
the plain cloner's net goals per seed and ``bc``'s, as the run's ``evaluation_bc_*.json`` has
them. Run: ``python studies/does_bc_match_a_plain_cloner.py RUN_DIR [--profiles mixed_bodies] [--fits 3]``.

Measured on the full benchmark's run (default seeds and sizes), net goals per fit seed 0, 1, 2:
the plain cloner netted 3, 5, 11 on ``one_good``; 6, 6, 2 on ``half``; 18, 19, 18 on ``equal``;
6, 6, 8 on ``linear``; 12, 21, 13 on ``mixed_bodies``; ``bc`` 18, 20, 18; 13, 18, 15; 22, 24, 26;
16, 8, 17; 24, 24, 20.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # batched predictions of ≤ 50 rows: threads only cost

import json  # noqa: E402

import numpy as np  # noqa: E402
from sklearn.ensemble import GradientBoostingClassifier  # noqa: E402

from polymimic.baselines.evaluation import play  # noqa: E402
from polymimic.baselines.features import features  # noqa: E402
from polymimic.baselines.hyperparameters import FRAMES_PER_ACTION  # noqa: E402
from polymimic.baselines.training import SAMPLE_STRIDE_FRAMES  # noqa: E402
from polymimic.baselines.tuning import validation_attempts  # noqa: E402
from polymimic.datasets import load_demonstrations  # noqa: E402
from polymimic.field import PRIMITIVES, command_primitives, primitives_sent  # noqa: E402
from polymimic.window_names import repeat_last_good  # noqa: E402

OBSERVATION = ("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm")
FEATURES = "ball_relative"


class PlainPolicy:
    """A fitted classifier holding each primitive for ``frames_per_action`` frames."""

    method = "plain"

    def __init__(self, model: GradientBoostingClassifier, frames_per_action: int) -> None:
        self.model, self.frames_per_action = model, frames_per_action

    def reset(self) -> None:
        pass

    def predict(self, observations: np.ndarray) -> np.ndarray:
        return self.model.predict(features(np.asarray(observations), feature_set=FEATURES)).astype(np.int64)

    def save(self, path: str) -> None:
        raise NotImplementedError("the plain cloner is not kept")


def samples(demonstrations, *, max_samples: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Every third frame of every demonstration, as recorded, with the primitive its command
    looks like from above (``polymimic.field.command_primitives``, the thesis's Table 4.4); at
    most ``max_samples`` of them, drawn with ``seed``."""
    lookup = np.array([PRIMITIVES.index(p) if p else -1 for p in command_primitives()])
    observations, labels = [], []
    for demo in demonstrations:
        primitives_sent(demo)  # refuses a demonstration whose commands were never recorded
        seen = repeat_last_good(np.column_stack([demo.frames[c] for c in OBSERVATION]).astype(np.float64))
        sent = lookup[demo.frames["command"].astype(np.int64)]
        rows = np.arange(0, len(seen), SAMPLE_STRIDE_FRAMES)
        keep = rows[sent[rows] >= 0]
        observations.append(seen[keep])
        labels.append(sent[keep])
    x, y = np.concatenate(observations), np.concatenate(labels)
    pick = np.sort(np.random.default_rng(seed).choice(len(y), size=min(max_samples, len(y)), replace=False))
    return x[pick], y[pick]


def fit(demonstrations, frames_per_action: int, *, max_samples: int, seed: int) -> PlainPolicy:
    x, y = samples(demonstrations, max_samples=max_samples, seed=seed)
    model = GradientBoostingClassifier(random_state=seed).fit(features(x, feature_set=FEATURES), y)
    return PlainPolicy(model, frames_per_action)


def chosen_step(demonstrations, validation, *, max_samples: int, field_config=None) -> tuple[int, dict[int, int]]:
    """The step length (frames) whose fit under seed 0 scores best on the validation attempts
    (net goals, then goals; the first best), and every step length's validation net goals.
    The step length is not the classifier's: one fit serves every candidate."""
    model = fit(demonstrations, FRAMES_PER_ACTION[0], max_samples=max_samples, seed=0).model
    scores = {}
    for frames in FRAMES_PER_ACTION:
        played = play(PlainPolicy(model, frames), validation, field_config=field_config)
        scores[frames] = (played.goals - played.own_goals, played.goals)
    return max(FRAMES_PER_ACTION, key=lambda k: scores[k]), {k: v[0] for k, v in scores.items()}


def main() -> None:
    # Here, not at the top: this file is also loaded by path, where studies/ is not importable.
    from _benchmark_run import arguments, opened

    args = arguments(__doc__, fits=3)
    run, config, evaluation = opened(args.run_dir)
    settings = config.benchmark
    validation = validation_attempts(settings.tuning.validation_attempts_per_configuration,
                                     validation_seed=settings.tuning.validation_seed)
    for profile in args.profiles or list(settings.profiles):
        demonstrations = load_demonstrations(run.crowd_path(profile))
        chosen, scores = chosen_step(demonstrations, validation, max_samples=settings.tuning.max_decision_samples,
                                     field_config=config.field)
        plain = []
        for seed in range(args.fits):
            played = play(fit(demonstrations, chosen, max_samples=settings.tuning.max_decision_samples, seed=seed),
                          evaluation, field_config=config.field)
            plain.append({"seed": seed, "goals": played.goals, "own_goals": played.own_goals,
                          "net": played.goals - played.own_goals})
        bc = [json.loads(p.read_text()) for p in sorted(run.profile_dir(profile).glob("evaluation_bc_[0-9]*.json"))]
        print(json.dumps({"profile": profile, "plain_frames_per_action": chosen,
                          "plain_validation_net": {str(k): v for k, v in scores.items()}, "plain": plain,
                          "bc": [{"trial_seed": e["trial_seed"], "goals": e["goals"], "own_goals": e["own_goals"],
                                  "net": e["goals"] - e["own_goals"]} for e in bc]}), flush=True)


if __name__ == "__main__":
    main()
