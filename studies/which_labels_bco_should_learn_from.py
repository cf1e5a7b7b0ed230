"""``bco``'s two labellings side by side: the recogniser's steps and the inverse dynamics model
learned from the imitator's exploration (:mod:`polymimic.baselines.inverse_dynamics`).

1. Agreement with the commands sent (:func:`polymimic.baselines.agreement.command_agreement`),
   every frame named, on ten demonstrations of each built-in demonstrator (five per field
   configuration, seed 3), then on each crowd profile's small crowd.
2. ``bco``'s net goals with each labelling on a small crowd of each profile (``--n``
   demonstrations per member and configuration, crowd seed 0): the benchmark's first
   ``--budget`` candidates, every one with that labelling, chosen on 40 validation attempts
   (validation seed 0), the choice fitted under seeds 0, 1, … and played on the same 50
   evaluation attempts (seed 1000); then ``bco`` as it tunes itself (the labellings paired over
   the first half of the candidates), and ``bc`` (the commands sent) for reference.

The recogniser is the full benchmark's (1000 self-observed sequences a primitive, 512
codewords, its seeds), the segmenter's settings the benchmark's. Prints one JSON line per
measurement. Run: ``python studies/which_labels_bco_should_learn_from.py [--profiles linear] [--n 3] [--fits 3]
[--budget 4] [--max-samples 6000]``.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # small fits and batched predictions: threads only contend

import argparse  # noqa: E402
import dataclasses  # noqa: E402
import json  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

import polymimic  # noqa: E402
from polymimic import baselines  # noqa: E402
from polymimic.baselines import inverse_dynamics  # noqa: E402
from polymimic.baselines.agreement import command_agreement  # noqa: E402
from polymimic.baselines.evaluation import attempts_of, play  # noqa: E402
from polymimic.baselines.hyperparameters import TUNED_LABELS, candidates  # noqa: E402
from polymimic.baselines.labels import window_labels  # noqa: E402
from polymimic.benchmark.config import BenchmarkConfig  # noqa: E402
from polymimic.crowds import PROFILES, record_crowd  # noqa: E402
from polymimic.field import DEMONSTRATORS  # noqa: E402

EVALUATION_SEED, VALIDATION_PER_CONFIGURATION, EVALUATION_PER_CONFIGURATION = 1000, 20, 25


def emit(**row) -> None:
    print(json.dumps(row), flush=True)


def recognizer_and_segmenter():
    config = BenchmarkConfig()
    sequences = polymimic.self_observation(config.recognizer.train_per_primitive,
                                           seed=config.seeds.self_observation_train, config=config.field)
    return config.recognizer.train(sequences), dataclasses.asdict(config.segmenter)


def agreements(demos, recognizer, segmenter, model) -> dict:
    """Each labelling's agreement with the commands sent, every frame named."""
    stop_and_gap = {k: segmenter[k] for k in ("stop_distance_mm", "stop_rotation_deg", "gap_margin")}
    steps = command_agreement(window_labels(demos, recognizer, stride_frames=1, **stop_and_gap), demos)
    inverse = command_agreement(inverse_dynamics.inverse_dynamics_labels(demos, model, stride_frames=1), demos)
    return {"steps": round(steps.agreement, 3), "steps_coverage": round(steps.coverage, 3),
            "inverse_dynamics": round(inverse.agreement, 3), "inverse_dynamics_coverage": round(inverse.coverage, 3)}


def net(policy, attempts) -> int:
    played = play(policy, attempts)
    return played.goals - played.own_goals


def tuned_nets(method, demos, tried, *, budget, fits, max_samples, **inputs) -> dict:
    """``method`` chosen among ``tried`` (``budget`` drawn candidates when None) on validation,
    then its choice's net goals on the evaluation attempts under each fit seed."""
    tuning = baselines.tune(method, demos, candidates=tried, budget=budget,
                            attempts_per_configuration=VALIDATION_PER_CONFIGURATION,
                            evaluation=polymimic.Attempts(per_configuration=EVALUATION_PER_CONFIGURATION,
                                                          seed=EVALUATION_SEED),
                            max_samples=max_samples, **inputs)
    evaluation = attempts_of(EVALUATION_PER_CONFIGURATION, seed=EVALUATION_SEED)
    nets = [net(baselines.fit(method, demos, hyperparameters=tuning.hyperparameters, seed=seed,
                              max_samples=max_samples, **inputs), evaluation) for seed in range(fits)]
    best = max(tuning.scores, key=baselines.tuning.validation_rank)
    return {"fits": fits, "nets": nets, "mean": round(statistics.mean(nets), 1),
            "sd": round(statistics.stdev(nets), 1) if len(nets) > 1 else 0.0,
            "validation_net": best["goals"] - best["own_goals"], "chosen": tuning.chosen}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--profiles", nargs="+", default=["linear"], choices=list(PROFILES))
    parser.add_argument("--n", type=int, default=3, help="demonstrations per member and configuration")
    parser.add_argument("--fits", type=int, default=3, help="fit seeds 0, 1, …")
    parser.add_argument("--budget", type=int, default=4, help="candidates per tuning")
    parser.add_argument("--max-samples", type=int, default=6000, help="decision samples per fit at most")
    parser.add_argument("--skip-goals", action="store_true", help="agreement only")
    args = parser.parse_args()
    started = time.perf_counter()
    recognizer, segmenter = recognizer_and_segmenter()
    model = inverse_dynamics.learn("lego")
    emit(stage="models", seconds=round(time.perf_counter() - started, 1))
    for who in DEMONSTRATORS:
        demos = [d for configuration in (1, 2) for d in polymimic.record(who, configuration=configuration, n=5, seed=3)]
        emit(demonstrator=who, **agreements(demos, recognizer, segmenter, model))
    for profile in args.profiles:
        demos = record_crowd(PROFILES[profile], n=args.n, seed=0)
        emit(profile=profile, demonstrations=len(demos), **agreements(demos, recognizer, segmenter, model))
        if args.skip_goals:
            continue
        inputs = {"recognizer": recognizer, "segmenter": segmenter}
        sizes = {"budget": args.budget, "fits": args.fits, "max_samples": args.max_samples}
        drawn = candidates(args.budget, seed=0)
        for labels in TUNED_LABELS:
            tried = [dataclasses.replace(h, labels=labels) for h in drawn]
            emit(profile=profile, method="bco", labels=labels, **tuned_nets("bco", demos, tried, **sizes, **inputs))
        emit(profile=profile, method="bco", labels="tuned", **tuned_nets("bco", demos, None, **sizes, **inputs))
        emit(profile=profile, method="bc", **tuned_nets("bc", demos, drawn, **sizes))
    emit(stage="done", seconds=round(time.perf_counter() - started, 1))


if __name__ == "__main__":
    main()
