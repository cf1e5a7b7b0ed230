"""Practice on a finished benchmark run: the ``polymimic`` imitators of the first ``--trials``
trials of each profile practise for ``--steps`` environment steps (practice seed = the trial's
seed) and are scored at every default checkpoint on the run's evaluation attempts.

Prints one JSON line per profile: the mean net goals at each checkpoint over the trials, and
each trial's curve. Run: ``python studies/what_practice_buys.py RUN_DIR [--trials 5] [--steps 25000]``.
"""

import argparse
import dataclasses
import json
import statistics
import time

from polymimic._native import PrimitiveRecognizer, TrialResult
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.datasets import load_demonstrations
from polymimic.learning import ImitatorPolicy, segmented
from polymimic.practice import practice


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", help="default: every profile of the run")
    parser.add_argument("--trials", type=int, default=5)
    parser.add_argument("--steps", type=int, default=25_000)
    parser.add_argument("--weight", type=float, default=1.0)
    options = parser.parse_args()
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.recognizer_path)
    segmenter = dataclasses.asdict(config.segmenter)
    per_configuration = config.benchmark.attempts_per_configuration
    for profile in options.profiles or list(config.benchmark.profiles):
        started = time.perf_counter()
        batch = segmented(load_demonstrations(run.crowd_path(profile)), recognizer, **segmenter)
        curves = []
        for trial_seed in range(options.trials):
            trial = TrialResult.from_json(run.trial_path(profile, trial_seed).read_text())
            policy = ImitatorPolicy(trial, recognizer=recognizer, config=config.learning, control="improved",
                                    demonstrations=batch, body=config.imitator_body())
            result = practice(policy, steps=options.steps, seed=trial_seed, evaluation_seed=config.seeds.evaluation,
                              evaluation_attempts=per_configuration, field_config=config.field, segmenter=segmenter,
                              weight=options.weight)
            curves.append([(p.checkpoint, p.steps, p.net_goals) for p in result.curve])
        checkpoints = [c for c, _, _ in curves[0]]
        means = [round(statistics.fmean(curve[k][2] for curve in curves), 2) for k in range(len(checkpoints))]
        print(json.dumps({"profile": profile, "checkpoints": checkpoints, "mean_net_goals": means,
                          "gain": round(means[-1] - means[0], 2), "curves": curves,
                          "seconds": round(time.perf_counter() - started, 1)}), flush=True)


if __name__ == "__main__":
    main()
