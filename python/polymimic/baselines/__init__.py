"""The baselines polymimic is compared with (docs/results/benchmark.md), each usable on its own.

============== ==================================== ===========================================
method         learns from                          module
============== ==================================== ===========================================
``bc``         frames + the commands sent           :mod:`polymimic.baselines.bc`
``bco``        tracker frames only                  :mod:`polymimic.baselines.bco`
``bco_lp``     tracker frames + a weight per member :mod:`polymimic.baselines.bco_lp`
``bc_best``    frames + commands of one member      :mod:`polymimic.baselines.bc_best`
``random``     nothing                              :mod:`polymimic.baselines.random_primitive`
``ppo``        the environment's reward (optional)  :mod:`polymimic.baselines.ppo`
``offline_rl`` tracker frames + outcomes (optional) :mod:`polymimic.baselines.offline_rl`
============== ==================================== ===========================================

Every policy maps a batch of ``PenaltyKick-v0`` observations to primitives
(:mod:`~polymimic.baselines.policy`), holds each for its ``frames_per_action``, saves to a file
and loads back (:func:`load_policy`). :func:`evaluate_policy` plays the imitator's own attempts,
and :func:`tune` chooses each method's hyperparameters on validation attempts that never meet
them.

>>> import polymimic
>>> from polymimic import baselines
>>> demos = polymimic.record("poor", configuration=1, n=2, seed=0)
>>> policy = baselines.fit("bc", demos)
>>> result = baselines.evaluate_policy(policy, attempts_per_configuration=1, seed=0)
>>> result.goals + result.own_goals <= 2
True
"""

from polymimic.baselines import bc, bc_best, bco, bco_lp, ppo, random_primitive
from polymimic.baselines.evaluation import VALIDATION_SEED_BASE, evaluate_policy
from polymimic.baselines.features import FEATURE_NAMES, FEATURE_SETS, features
from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters, candidates
from polymimic.baselines.methods import METHODS, fit
from polymimic.baselines.policy import ClonedPolicy, Policy, RandomPolicy, load_policy
from polymimic.baselines.tuning import Tuning, tune, validation_attempts

__all__ = [
    "DEFAULT",
    "FEATURE_NAMES",
    "FEATURE_SETS",
    "METHODS",
    "VALIDATION_SEED_BASE",
    "ClonedPolicy",
    "Hyperparameters",
    "Policy",
    "RandomPolicy",
    "Tuning",
    "bc",
    "bc_best",
    "bco",
    "bco_lp",
    "candidates",
    "evaluate_policy",
    "features",
    "fit",
    "load_policy",
    "ppo",
    "random_primitive",
    "tune",
    "validation_attempts",
]
