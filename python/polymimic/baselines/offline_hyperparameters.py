"""What ``offline_rl`` may tune: the algorithm (d3rlpy's discrete CQL or discrete BCQ) and its
conservatism, the learning rate, the network, the features, the step length, and how the
demonstrations are labelled (as ``bco``'s tuning chooses).

:func:`candidates` gives as many candidates as a cloning baseline's tuning tries, with the same
structure: two fixed first ones (:data:`DEFAULT_CQL`, :data:`DEFAULT_BCQ`), then seeded draws
with the algorithms taken in turn, and the first half of them each with both of ``bco``'s
labellings (:data:`~polymimic.baselines.hyperparameters.TUNED_LABELS`).

>>> for h in candidates(4, seed=0):
...     print(h.algorithm, h.labels)
discrete_cql steps
discrete_cql inverse_dynamics
discrete_bcq steps
discrete_bcq inverse_dynamics
>>> OfflineHyperparameters.from_dict(DEFAULT_CQL.to_dict()) == DEFAULT_CQL
True
"""

from __future__ import annotations

import dataclasses
import itertools
import json
import numbers
from collections.abc import Mapping
from typing import Any

import numpy as np

from polymimic.baselines.features import FEATURE_SETS
from polymimic.baselines.hyperparameters import FRAMES_PER_ACTION, TUNED_LABELS

__all__ = ["ALGORITHMS", "CONSERVATISM", "DEFAULT_BCQ", "DEFAULT_CQL", "GRADIENT_STEPS", "HIDDEN_LAYERS",
           "LEARNING_RATES", "OfflineHyperparameters", "candidates"]

ALGORITHMS = ("discrete_cql", "discrete_bcq")
"""d3rlpy's discrete offline-RL algorithms tried: ``DiscreteCQL`` (Kumar et al. 2020) and
``DiscreteBCQ`` (Fujimoto et al. 2019)."""

CONSERVATISM = {"discrete_cql": (0.5, 1.0, 4.0), "discrete_bcq": (0.1, 0.3, 0.6)}
"""Each algorithm's hold on the data: CQL's ``alpha`` (the weight of its penalty on actions the
data does not take), BCQ's ``action_flexibility`` (the least probability, relative to the most
likely action's under cloning, an action needs to be chosen)."""

LEARNING_RATES = (1e-4, 3e-4, 1e-3)
HIDDEN_LAYERS = ((64, 64), (256, 256))
"""The Q-network's hidden layers (ReLU), as d3rlpy's ``VectorEncoderFactory`` takes them."""

GRADIENT_STEPS = 10_000
"""Gradient steps of every fit (minibatches of :data:`BATCH_SIZE`); see the docs' measurements."""

BATCH_SIZE = 64
"""Transitions a gradient step learns from: d3rlpy draws each in Python, so a step costs about
in proportion to them."""
GAMMA = 0.99
TARGET_UPDATE_INTERVAL = 250
"""Gradient steps between copies of the Q-network into its target (d3rlpy's default, 8000, is
Atari's, for millions of steps): 40 copies in a fit."""

RETURN_STEPS = 10
"""Transitions each target looks ahead (d3rlpy's ``MultiStepTransitionPicker``): the reward
comes only at an episode's end, up to hundreds of samples after its start, and each copy of
the target carries it this many samples further back."""


@dataclasses.dataclass(frozen=True)
class OfflineHyperparameters:
    """One choice of ``offline_rl``'s hyperparameters.

    Attributes
    ----------
    algorithm : str
        One of :data:`ALGORITHMS`.
    conservatism : float
        CQL's ``alpha`` or BCQ's ``action_flexibility`` (:data:`CONSERVATISM`).
    learning_rate : float
    hidden_layers : tuple of int
    feature_set : str
        One of :data:`polymimic.baselines.features.FEATURE_SETS`, scaled as ``ppo`` scales them.
    frames_per_action : int
        Tracker frames each chosen primitive is held for.
    labels : str
        How the demonstrations' frames are labelled, as ``bco`` labels them
        (:data:`~polymimic.baselines.hyperparameters.TUNED_LABELS`).
    gradient_steps : int, default GRADIENT_STEPS
    """

    algorithm: str
    conservatism: float
    learning_rate: float
    hidden_layers: tuple[int, ...]
    feature_set: str
    frames_per_action: int
    labels: str = "inverse_dynamics"
    gradient_steps: int = GRADIENT_STEPS

    def __post_init__(self) -> None:
        if self.algorithm not in ALGORITHMS:
            raise ValueError(f"unknown algorithm {self.algorithm!r}; expected one of {', '.join(ALGORITHMS)}")
        for name in ("conservatism", "learning_rate"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 < float(value) < np.inf:
                raise ValueError(f"{name} must be a positive number, got {value!r}")
        if self.algorithm == "discrete_bcq" and not self.conservatism < 1:
            raise ValueError(f"conservatism (discrete_bcq's action_flexibility) must be below 1, "
                             f"got {self.conservatism!r}")
        layers = tuple(self.hidden_layers)
        if not layers or any(isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1 for n in layers):
            raise ValueError(f"hidden_layers must list layer sizes, each an integer ≥ 1, got {self.hidden_layers!r}")
        object.__setattr__(self, "hidden_layers", tuple(int(n) for n in layers))
        if self.feature_set not in FEATURE_SETS:
            raise ValueError(f"unknown feature_set {self.feature_set!r}; expected one of {', '.join(FEATURE_SETS)}")
        for name in ("frames_per_action", "gradient_steps"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise ValueError(f"{name} must be an integer ≥ 1, got {value!r}")
        if self.labels not in TUNED_LABELS:
            raise ValueError(f"unknown labels {self.labels!r}; expected one of {', '.join(map(repr, TUNED_LABELS))}")

    def to_dict(self) -> dict[str, Any]:
        """Plain data for a report (JSON-ready)."""
        return {"algorithm": self.algorithm, "conservatism": float(self.conservatism),
                "learning_rate": float(self.learning_rate), "hidden_layers": list(self.hidden_layers),
                "feature_set": self.feature_set, "frames_per_action": int(self.frames_per_action),
                "labels": self.labels, "gradient_steps": int(self.gradient_steps)}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> OfflineHyperparameters:
        """The hyperparameters :meth:`to_dict` wrote.

        Raises
        ------
        ValueError
            Naming a key that is missing or unknown, or a value out of range.
        """
        fields = [f.name for f in dataclasses.fields(cls)]
        unknown = sorted(set(data) - set(fields))
        if unknown:
            raise ValueError(f"unknown key {unknown[0]!r} in offline_rl's hyperparameters; "
                             f"expected {', '.join(fields)}")
        missing = [name for name in fields[:6] if name not in data]
        if missing:
            raise ValueError(f"offline_rl's hyperparameters have no {missing[0]!r}")
        return cls(**{**data, "hidden_layers": tuple(data["hidden_layers"])})

    def __str__(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True)


DEFAULT_CQL = OfflineHyperparameters("discrete_cql", 1.0, 3e-4, (256, 256), "goal_relative", 15)
"""The first candidate of every tuning: discrete CQL at its paper's ``alpha``, the goal-relative
features (what ``ppo`` sees) and a half-second step."""

DEFAULT_BCQ = OfflineHyperparameters("discrete_bcq", 0.3, 3e-4, (256, 256), "goal_relative", 15)
"""The second: discrete BCQ at d3rlpy's (and its paper's) action flexibility, 0.3."""


def candidates(budget: int, *, seed: int = 0) -> list[OfflineHyperparameters]:
    """``budget`` candidates: the first half of [:data:`DEFAULT_CQL`, :data:`DEFAULT_BCQ`, then
    draws of every other setting with the algorithms in turn] (rounded up), each with every
    labelling of :data:`~polymimic.baselines.hyperparameters.TUNED_LABELS` in turn."""
    if isinstance(budget, bool) or not isinstance(budget, (int, np.integer)) or budget < 1:
        raise ValueError(f"budget must be an integer ≥ 1 (candidates to try), got {budget!r}")
    rng = np.random.default_rng(seed)
    drawn = [DEFAULT_CQL, DEFAULT_BCQ]
    size = sum(len(c) for c in CONSERVATISM.values()) * len(LEARNING_RATES) * len(HIDDEN_LAYERS) \
        * len(FEATURE_SETS) * len(FRAMES_PER_ACTION)
    wanted = min(-(-budget // len(TUNED_LABELS)), size)
    for turn in itertools.count():
        if len(drawn) >= wanted:
            break
        algorithm = ALGORITHMS[turn % len(ALGORITHMS)]
        candidate = OfflineHyperparameters(
            algorithm, CONSERVATISM[algorithm][int(rng.integers(len(CONSERVATISM[algorithm])))],
            LEARNING_RATES[int(rng.integers(len(LEARNING_RATES)))],
            HIDDEN_LAYERS[int(rng.integers(len(HIDDEN_LAYERS)))],
            FEATURE_SETS[int(rng.integers(len(FEATURE_SETS)))],
            FRAMES_PER_ACTION[int(rng.integers(len(FRAMES_PER_ACTION)))])
        if candidate not in drawn:
            drawn.append(candidate)
    paired = [dataclasses.replace(h, labels=labels) for h in drawn[:wanted] for labels in TUNED_LABELS]
    return paired[:budget]
