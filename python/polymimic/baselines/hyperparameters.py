"""What a cloning method may tune: classifier family and parameters, features, step length,
and for ``bco`` how the demonstrations are labelled.

:func:`candidates` draws the same number of candidates for every method from one grid, with a
seed, so that every method gets the same tuning effort (docs/results/benchmark.md); the first two candidates
are always :data:`DEFAULT` and :data:`PLAIN_BOOSTING`. ``bco`` tries the first half of them
with each of its two labellings in turn (:func:`with_labellings`): as many candidates, paired
so that the labellings meet the same classifiers.

>>> [h.classifier for h in candidates(4, seed=0)]
['mlp', 'hist_gradient_boosting', 'hist_gradient_boosting', 'random_forest']
>>> [(h.classifier, h.labels) for h in with_labellings(candidates(2, seed=0))]
[('mlp', 'steps'), ('mlp', 'inverse_dynamics')]
>>> Hyperparameters.from_dict(DEFAULT.to_dict()) == DEFAULT
True
"""

from __future__ import annotations

import dataclasses
import itertools
import json
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic.baselines.classifiers import FAMILIES
from polymimic.baselines.features import FEATURE_SETS

__all__ = ["DEFAULT", "FRAMES_PER_ACTION", "GRID", "LABELS", "PLAIN_BOOSTING", "TUNED_LABELS", "Hyperparameters",
           "candidates", "with_labellings"]

FRAMES_PER_ACTION = (5, 10, 15, 30)
"""Step lengths (tracker frames a primitive is held for) a candidate may take; 30 is the
environment's default one-second primitive."""

LABELS = ("steps", "segments", "inverse_dynamics")
"""How ``bco`` and ``bco_lp`` may label the demonstrations' frames: by the recogniser's name for
the second of motion from each (:func:`polymimic.baselines.labels.window_labels`), by the
segment each lies in (:func:`~polymimic.baselines.labels.segment_labels`), or by the inverse
dynamics model learned from the imitator's exploration
(:func:`polymimic.baselines.inverse_dynamics.inverse_dynamics_labels`)."""

TUNED_LABELS = ("steps", "inverse_dynamics")
"""The labellings ``bco``'s tuning chooses between (:func:`with_labellings`)."""


@dataclasses.dataclass(frozen=True)
class Hyperparameters:
    """One choice of a cloning method's hyperparameters.

    Attributes
    ----------
    classifier : str
        A family of :data:`polymimic.baselines.classifiers.FAMILIES`.
    params : tuple of (str, value) pairs
        The family's parameters (a tuple so the choice is hashable; :meth:`to_dict` gives a dict).
    feature_set : str
        One of :data:`polymimic.baselines.features.FEATURE_SETS`.
    frames_per_action : int
        Tracker frames each chosen primitive is held for (1/30 s each).
    balanced : bool
        Whether every primitive's samples weigh the same in total (the Expert stops rarely, the
        Poor never turns: unbalanced, a rare primitive is never chosen).
    labels : str, default "steps"
        How ``bco`` and ``bco_lp`` label the frames (one of :data:`LABELS`); the other methods
        learn from the commands sent and ignore it.
    """

    classifier: str
    params: tuple[tuple[str, Any], ...]
    feature_set: str
    frames_per_action: int
    balanced: bool
    labels: str = "steps"

    def __post_init__(self) -> None:
        if self.classifier not in FAMILIES:
            raise ValueError(f"unknown classifier {self.classifier!r}; expected one of {', '.join(FAMILIES)}")
        if self.feature_set not in FEATURE_SETS:
            raise ValueError(f"unknown feature_set {self.feature_set!r}; expected one of {', '.join(FEATURE_SETS)}")
        if isinstance(self.frames_per_action, bool) or not isinstance(self.frames_per_action, (int, np.integer)) \
                or self.frames_per_action < 1:
            raise ValueError(f"frames_per_action must be an integer ≥ 1, got {self.frames_per_action!r}")
        if self.labels not in LABELS:
            raise ValueError(f"unknown labels {self.labels!r}; expected one of {', '.join(map(repr, LABELS))}")

    def to_dict(self) -> dict[str, Any]:
        """Plain data for a report (JSON-ready). The labelling is left out at its default, the
        recogniser's steps, so that a method that ignores it is recorded as before."""
        data = {"classifier": self.classifier, "params": dict(self.params), "feature_set": self.feature_set,
                "frames_per_action": int(self.frames_per_action), "balanced": self.balanced}
        return data if self.labels == "steps" else {**data, "labels": self.labels}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Hyperparameters:
        """The hyperparameters :meth:`to_dict` wrote (lists read back as tuples)."""
        params = {k: tuple(v) if isinstance(v, list) else v for k, v in dict(data["params"]).items()}
        return cls(classifier=data["classifier"], params=tuple(sorted(params.items())),
                   feature_set=data["feature_set"], frames_per_action=int(data["frames_per_action"]),
                   balanced=bool(data["balanced"]), labels=str(data.get("labels", "steps")))

    def __str__(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True)


def _params(**values: Any) -> tuple[tuple[str, Any], ...]:
    return tuple(sorted(values.items()))


GRID: dict[str, tuple[tuple[tuple[str, Any], ...], ...]] = {
    "hist_gradient_boosting": tuple(_params(max_iter=m, learning_rate=r, max_leaf_nodes=n)
                                    for m, r, n in itertools.product((100, 300), (0.05, 0.1), (15, 31))),
    "random_forest": tuple(_params(n_estimators=100, min_samples_leaf=s, max_features=f)
                           for s, f in itertools.product((1, 3, 10), ("sqrt", None))),
    "knn": tuple(_params(n_neighbors=k, weights=w) for k, w in itertools.product((5, 15, 45), ("uniform", "distance"))),
    "logistic_regression": tuple(_params(C=c) for c in (0.1, 1.0, 10.0)),
    "mlp": tuple(_params(hidden_layer_sizes=h, alpha=a) for h, a in itertools.product(((64,), (64, 64)), (1e-4, 1e-2))),
}
"""Each family's parameter choices."""

DEFAULT = Hyperparameters("mlp", _params(hidden_layer_sizes=(64, 64), alpha=1e-4), "ball_relative", 15, True)
"""The first candidate of every tuning: the best BC on the Expert's demonstrations over two
sets of validation attempts (validation seeds 0 and 1, never the evaluation's), a smooth
classifier with a half-second step."""

PLAIN_BOOSTING = Hyperparameters("hist_gradient_boosting",
                                 _params(max_iter=100, learning_rate=0.1, max_depth=3, min_samples_leaf=1),
                                 "ball_relative", 15, False)
"""The second candidate of every tuning: what a few lines of scikit-learn would fit, boosted
trees as ``GradientBoostingClassifier`` grows them by default (100 of them, depth 3, a leaf may
hold one sample) on the ball-relative features, unbalanced. With it among the candidates, a
method's tuning can always choose the plain cloner's recipe; without it ``bc`` netted 9, 8 and
12 on a small mixed crowd where a plain gradient-boosting cloner netted 22, 23 and 19
(``studies/does_bc_match_a_plain_cloner_on_a_small_crowd.py``). Leaves of one sample matter on so few
demonstrations: on that crowd, over eight fits at ten frames a step, these trees netted
20.9 ± 2.9, scikit-learn's own 21.9 ± 2.4, and trees of seven leaves holding at least 20
samples each (this candidate before) 14.8 ± 7.0."""


def candidates(budget: int, *, seed: int = 0) -> list[Hyperparameters]:
    """``budget`` distinct candidates: :data:`DEFAULT` and :data:`PLAIN_BOOSTING`, then draws
    from :data:`GRID` with the families taken in turn (so every family is tried about as often),
    each with parameters, a feature set, a step length and balancing drawn at random, seeded."""
    if isinstance(budget, bool) or not isinstance(budget, (int, np.integer)) or budget < 1:
        raise ValueError(f"budget must be an integer ≥ 1 (candidates to try), got {budget!r}")
    rng = np.random.default_rng(seed)
    chosen = [DEFAULT, PLAIN_BOOSTING][:budget]
    size = sum(len(g) for g in GRID.values()) * len(FEATURE_SETS) * len(FRAMES_PER_ACTION) * 2 + 1
    turn = 0
    while len(chosen) < min(budget, size):
        family = FAMILIES[turn % len(FAMILIES)]
        grid = GRID[family]
        candidate = Hyperparameters(family, grid[int(rng.integers(len(grid)))],
                                    FEATURE_SETS[int(rng.integers(len(FEATURE_SETS)))],
                                    FRAMES_PER_ACTION[int(rng.integers(len(FRAMES_PER_ACTION)))],
                                    bool(rng.integers(2)))
        if candidate not in chosen:
            chosen.append(candidate)
            turn += 1
    return chosen


def with_labellings(candidates: Sequence[Hyperparameters]) -> list[Hyperparameters]:
    """As many candidates as ``candidates``: the first half of them (rounded up), each with
    every labelling of :data:`TUNED_LABELS` in turn, so that the labellings are compared on the
    same classifiers at the same tuning effort (``bco``'s candidates)."""
    paired = [dataclasses.replace(h, labels=labels) for h in candidates for labels in TUNED_LABELS]
    return paired[:len(candidates)]
