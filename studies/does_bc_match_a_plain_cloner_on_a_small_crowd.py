"""``bc`` beside the plain cloner of ``studies/does_bc_match_a_plain_cloner.py`` on a small mixed-body
crowd recorded here; ``tests/library/test_bc_vs_plain_cloner.py`` keeps it in the suite.

The crowd is ``mixed_bodies`` with 3 demonstrations per member and configuration (crowd seed
0). Both methods take at most 3000 decision samples and are chosen on the same 40 validation
attempts (the plain cloner its step length, ``bc`` the benchmark's 6 candidates), then fitted
under seeds 0, 1 and 2 and played on the same 50 evaluation attempts (seed 1000). Prints both
methods' net goals per fit and ``bc``'s choice. Run:
``python studies/does_bc_match_a_plain_cloner_on_a_small_crowd.py``.
"""

import importlib.util
import json
import pathlib
import statistics

from polymimic import Attempts, baselines
from polymimic.baselines.evaluation import attempts_of, play
from polymimic.baselines.tuning import validation_attempts
from polymimic.crowds import PROFILES, record_crowd

FITS, MAX_SAMPLES, EVALUATION_SEED, BUDGET = (0, 1, 2), 3000, 1000, 6


def plain_cloner():
    path = pathlib.Path(__file__).with_name("does_bc_match_a_plain_cloner.py")
    spec = importlib.util.spec_from_file_location("does_bc_match_a_plain_cloner", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def net(policy, attempts) -> int:
    played = play(policy, attempts)
    return played.goals - played.own_goals


def compare() -> tuple[list[int], list[int], dict]:
    """The plain cloner's net goals per fit, ``bc``'s, and ``bc``'s choice."""
    demos = record_crowd(PROFILES["mixed_bodies"], n=3, seed=0)
    validation = validation_attempts(20, validation_seed=0)
    evaluation = attempts_of(25, seed=EVALUATION_SEED)
    plain = plain_cloner()
    frames, _ = plain.chosen_step(demos, validation, max_samples=MAX_SAMPLES)
    plain_nets = [net(plain.fit(demos, frames, max_samples=MAX_SAMPLES, seed=seed), evaluation) for seed in FITS]
    tuned = baselines.tune("bc", demos, budget=BUDGET, attempts_per_configuration=20,
                           evaluation=Attempts(per_configuration=25, seed=EVALUATION_SEED), max_samples=MAX_SAMPLES)
    bc_nets = [net(baselines.fit("bc", demos, hyperparameters=tuned.hyperparameters, seed=seed,
                                 max_samples=MAX_SAMPLES), evaluation) for seed in FITS]
    return plain_nets, bc_nets, tuned.chosen


def main() -> None:
    plain_nets, bc_nets, chosen = compare()
    print(json.dumps({"plain": plain_nets, "bc_chosen": chosen, "bc": bc_nets, "bc_sd": statistics.stdev(bc_nets),
                      "bc_within_its_sd": statistics.mean(bc_nets) >= statistics.mean(plain_nets)
                      - statistics.stdev(bc_nets)}))


if __name__ == "__main__":
    main()
