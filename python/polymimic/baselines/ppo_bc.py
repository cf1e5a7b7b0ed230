"""``ppo_bc`` (optional): PPO whose policy network first clones the crowd's commands, then
learns from the reward: the peer a user would pick to combine demonstrations and reinforcement
learning (docs/guides/practice.md).

Cloning is real behavioural cloning of the network PPO then fine-tunes: the decision samples
``bc`` learns from (:func:`polymimic.baselines.labels.command_labels`, the commands sent, drawn
by :func:`polymimic.baselines.training.decision_samples`), seen through PPO's features
(:func:`polymimic.baselines.ppo.scaled`), and the actor's log-likelihood of the labelled
primitive maximised with Adam over minibatches (the value head is left to PPO). How long and how
fast it clones is chosen among :data:`PRETRAINING_CANDIDATES` on validation attempts, as every
baseline's hyperparameters are (:func:`tune_pretraining`); PPO then learns from the reward with
stable-baselines3's defaults, as ``ppo`` does, scored on the evaluation attempts at the same
checkpoints (:func:`learning_curve`). Needs stable-baselines3 and torch (``pip install
"polymimic[rl]"``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

import numpy as np

from polymimic.baselines import ppo
from polymimic.baselines.evaluation import play
from polymimic.baselines.labels import IMITATOR_BODY, command_labels
from polymimic.baselines.training import MAX_DECISION_SAMPLES, decision_samples
from polymimic.baselines.tuning import validation_attempts_apart, validation_rank
from polymimic.bodies import BodySpec, as_body
from polymimic.evaluation import Attempts
from polymimic.field import Demonstration

__all__ = ["PRETRAINING_CANDIDATES", "Pretraining", "agreement", "clone_into", "cloning_samples", "learning_curve",
           "pretrained", "tune_pretraining"]


@dataclasses.dataclass(frozen=True)
class Pretraining:
    """How the network clones: passes over the samples, Adam's step size, minibatch size."""

    epochs: int
    learning_rate: float
    batch_size: int = 256

    def to_dict(self) -> dict[str, Any]:
        """The pretraining's settings as plain JSON values."""
        return dataclasses.asdict(self)


PRETRAINING_CANDIDATES = (Pretraining(10, 1e-3), Pretraining(30, 1e-3), Pretraining(100, 1e-3),
                          Pretraining(30, 3e-4), Pretraining(100, 3e-4), Pretraining(300, 3e-4))
"""What :func:`tune_pretraining` tries, the first ``budget`` of them."""


def cloning_samples(demonstrations: Sequence[Demonstration], *, feature_set: str = "goal_relative",
                    imitator: BodySpec = IMITATOR_BODY, max_samples: int = MAX_DECISION_SAMPLES,
                    seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """``bc``'s decision samples (the commands sent, as its labels read them) as PPO's network
    sees them: scaled features ``(n, k)`` and primitive indices ``(n,)``."""
    observations, labels, _ = decision_samples(command_labels(demonstrations, imitator=imitator),
                                               max_samples=max_samples, seed=seed)
    return ppo.scaled(observations, feature_set, imitator), labels


def clone_into(model: Any, features: np.ndarray, labels: np.ndarray, pretraining: Pretraining, *,
               seed: int = 0) -> None:
    """Train ``model``'s actor (a stable-baselines3 PPO) to give ``labels`` for ``features``:
    minibatches drawn with ``seed``, the mean negative log-likelihood minimised with Adam."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    torch.manual_seed(seed)
    policy = model.policy
    optimiser = torch.optim.Adam(policy.parameters(), lr=pretraining.learning_rate)
    x = torch.as_tensor(features, dtype=torch.float32)
    y = torch.as_tensor(labels, dtype=torch.int64)
    order = np.random.default_rng(seed)
    policy.set_training_mode(True)
    for _ in range(pretraining.epochs):
        for batch in np.array_split(order.permutation(len(y)), max(1, len(y) // pretraining.batch_size)):
            index = torch.as_tensor(batch)
            loss = -policy.get_distribution(x[index]).log_prob(y[index]).mean()
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
    policy.set_training_mode(False)


def pretrained(demonstrations: Sequence[Demonstration], pretraining: Pretraining, *, seed: int = 0,
               feature_set: str = "goal_relative", frames_per_action: int = 30,
               field_config: dict[str, Any] | str | None = None, imitator: BodySpec = IMITATOR_BODY,
               max_samples: int = MAX_DECISION_SAMPLES) -> ppo.PPOPolicy:
    """A new PPO network under ``seed`` that has cloned the demonstrations and not yet learned
    from the reward."""
    model = ppo.new_model(frames_per_action=frames_per_action, feature_set=feature_set, seed=seed,
                          field_config=field_config, imitator=imitator)
    features, labels = cloning_samples(demonstrations, feature_set=feature_set, imitator=imitator,
                                       max_samples=max_samples, seed=seed)
    clone_into(model, features, labels, pretraining, seed=seed)
    return ppo.PPOPolicy(model, feature_set=feature_set, frames_per_action=frames_per_action, total_timesteps=0,
                         method="ppo_bc", body=as_body(imitator, what="imitator"))


def agreement(policy: Any, demonstrations: Sequence[Demonstration], *, imitator: BodySpec = IMITATOR_BODY,
              max_samples: int = MAX_DECISION_SAMPLES, seed: int = 0) -> float:
    """The share of the demonstrations' decision samples where ``policy`` (anything with
    ``predict(observations)``) names the primitive of the command sent."""
    observations, labels, _ = decision_samples(command_labels(demonstrations, imitator=imitator),
                                               max_samples=max_samples, seed=seed)
    return float(np.mean(policy.predict(observations) == labels))


@dataclasses.dataclass(frozen=True)
class PretrainingChoice:
    """What :func:`tune_pretraining` chose and every candidate's validation score."""

    chosen: Pretraining
    scores: list[dict[str, Any]]


def tune_pretraining(demonstrations: Sequence[Demonstration], *, budget: int = 6, validation_seed: int = 0,
                     attempts_per_configuration: int = 50, evaluation: Attempts = Attempts(), seed: int = 0,
                     feature_set: str = "goal_relative", frames_per_action: int = 30,
                     field_config: dict[str, Any] | str | None = None, imitator: BodySpec = IMITATOR_BODY,
                     max_samples: int = MAX_DECISION_SAMPLES) -> PretrainingChoice:
    """The first ``budget`` of :data:`PRETRAINING_CANDIDATES`, each cloned under ``seed`` and
    played (before any reward) on the validation attempts of ``validation_seed``; the best by net
    goals, then goals, the first of equals (:func:`polymimic.baselines.tuning.validation_rank`).
    As :func:`polymimic.baselines.tune`, it refuses validation attempts that share an episode seed
    with the ``evaluation``'s (an :class:`~polymimic.Attempts` from the thesis's configurations)."""
    if isinstance(budget, bool) or not isinstance(budget, int) or not 1 <= budget <= len(PRETRAINING_CANDIDATES):
        raise ValueError(f"budget must be an integer in 1..{len(PRETRAINING_CANDIDATES)}, got {budget!r}")
    attempts = validation_attempts_apart(attempts_per_configuration, validation_seed=validation_seed,
                                         evaluation=evaluation)
    scores = []
    for candidate in PRETRAINING_CANDIDATES[:budget]:
        policy = pretrained(demonstrations, candidate, seed=seed, feature_set=feature_set,
                            frames_per_action=frames_per_action, field_config=field_config, imitator=imitator,
                            max_samples=max_samples)
        played = play(policy, attempts, field_config=field_config)
        scores.append({**candidate.to_dict(), "goals": played.goals, "own_goals": played.own_goals})
    best = max(range(len(scores)), key=lambda i: (validation_rank(scores[i]), -i))
    return PretrainingChoice(chosen=PRETRAINING_CANDIDATES[best], scores=scores)


def learning_curve(demonstrations: Sequence[Demonstration], pretraining: Pretraining, *, total_timesteps: int,
                   eval_every: int, evaluation: Attempts = Attempts(), seed: int = 0, frames_per_action: int = 30,
                   feature_set: str = "goal_relative",
                   field_config: dict[str, Any] | str | None = None, imitator: BodySpec = IMITATOR_BODY,
                   max_samples: int = MAX_DECISION_SAMPLES) -> tuple[ppo.PPOPolicy, list[ppo.Checkpoint], Any]:
    """:func:`polymimic.baselines.ppo.learning_curve` with the network cloned first, played on
    the ``evaluation`` attempts: its first checkpoint (0 steps) is the cloned network's."""
    features, labels = cloning_samples(demonstrations, feature_set=feature_set, imitator=imitator,
                                       max_samples=max_samples, seed=seed)
    return ppo.learning_curve(total_timesteps=total_timesteps, eval_every=eval_every, evaluation=evaluation, seed=seed,
                              frames_per_action=frames_per_action, feature_set=feature_set, field_config=field_config,
                              method="ppo_bc", imitator=imitator,
                              before_learning=lambda model: clone_into(model, features, labels, pretraining, seed=seed))
