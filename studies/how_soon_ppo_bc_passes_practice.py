"""ppo_bc on a finished benchmark run's crowd: its cloning chosen on the run's validation attempts,
then PPO learning from the reward, scored on the run's evaluation attempts every ``--eval-every``
steps; beside it, the steps it took to first reach ``--target`` net goals (the practised
imitator's, say). What ``polymimic benchmark --methods … ppo_bc`` runs per profile, for one
profile of a run made without it.

Prints one JSON line: the cloning chosen, every candidate's validation score, and the curve.
Needs stable-baselines3 (``pip install "polymimic[rl]"``). Run:
``python studies/how_soon_ppo_bc_passes_practice.py RUN_DIR --profile one_good [--timesteps 1000000] [--seed 0]``.
"""

import argparse
import json
import time

import torch

from polymimic.baselines import ppo_bc
from polymimic.baselines.ppo import steps_to_reach
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.benchmark.tasks import PPO_FEATURE_SET, PPO_FRAMES_PER_ACTION
from polymimic.datasets import load_demonstrations


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profile", default="one_good")
    parser.add_argument("--timesteps", type=int, default=1_000_000)
    parser.add_argument("--eval-every", type=int, default=50_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--target", type=float, help="net goals whose first reaching is reported")
    options = parser.parse_args()
    torch.set_num_threads(1)
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    settings = config.benchmark
    demos = load_demonstrations(run.crowd_path(options.profile))
    started = time.perf_counter()
    common = {"feature_set": PPO_FEATURE_SET, "frames_per_action": PPO_FRAMES_PER_ACTION, "field_config": config.field,
              "max_samples": settings.tuning.max_decision_samples}
    budget = min(settings.tuning.tuning_budget, len(ppo_bc.PRETRAINING_CANDIDATES))
    choice = ppo_bc.tune_pretraining(demos, budget=budget,
                                     validation_seed=settings.tuning.validation_seed,
                                     attempts_per_configuration=settings.tuning.validation_attempts_per_configuration,
                                     evaluation=config.evaluation_attempts(), seed=config.seeds.first_trial, **common)
    _, curve, _ = ppo_bc.learning_curve(demos, choice.chosen, total_timesteps=options.timesteps,
                                        eval_every=options.eval_every,
                                        evaluation=config.evaluation_attempts(), seed=options.seed, **common)
    points = [c.to_dict() for c in curve]
    print(json.dumps({"profile": options.profile, "seed": options.seed, "chosen": choice.chosen.to_dict(),
                      "scores": choice.scores, "curve": points,
                      "steps_to_target": None if options.target is None else steps_to_reach(points, options.target),
                      "seconds": round(time.perf_counter() - started)}), flush=True)


if __name__ == "__main__":
    main()
