"""Baseline policies: observation batch in, primitive batch out, saved to and loaded from a file.

Every policy has ``frames_per_action`` (tracker frames each chosen primitive is held for),
``predict(observations)`` mapping an ``(n, 5)`` batch of ``PenaltyKick-v0`` observations to
``n`` primitive indices (0 forward, 1 backward, 2 left, 3 right, 4 stop: the environment's
actions), ``reset()`` (restarts any random stream, so evaluations repeat), and ``save(path)``;
:func:`load_policy` reads any of them back (see :mod:`polymimic.baselines.policy_file` for the format).

>>> import numpy as np, pathlib, tempfile
>>> policy = RandomPolicy(seed=3)
>>> first = policy.predict(np.zeros((4, 5)))
>>> path = pathlib.Path(tempfile.mkdtemp()) / "random.pmp"
>>> policy.save(path)
>>> again = load_policy(path)
>>> again.reset(); policy.reset()
>>> bool((again.predict(np.zeros((4, 5))) == policy.predict(np.zeros((4, 5)))).all())
True
"""

from __future__ import annotations

import os
from typing import Any, Protocol, runtime_checkable

import numpy as np

from polymimic._native import ModelFileError
from polymimic.baselines.features import check_observations, features, target_goal_of
from polymimic.baselines.hyperparameters import Hyperparameters
from polymimic.baselines.policy_file import read_policy_file, write_policy_file
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.field import PRIMITIVES

__all__ = ["ClonedPolicy", "Policy", "RandomPolicy", "load_policy"]


@runtime_checkable
class Policy(Protocol):
    """What :func:`polymimic.baselines.evaluate_policy` drives."""

    @property
    def frames_per_action(self) -> int:
        """Tracker frames each chosen primitive is held for."""

    def predict(self, observations: np.ndarray) -> np.ndarray:
        """The primitive id (0–4) to play for each observation.

        Parameters
        ----------
        observations : ndarray of shape (n, 5)
            Tracker readings: robot x, y (mm), θ (rad), ball x, y (mm).

        Returns
        -------
        ndarray of int64, shape (n,)
        """

    def reset(self) -> None:
        """Called before every episode; a stateless policy does nothing."""

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes the policy to ``path``, to be read back by :func:`polymimic.baselines.load_policy`."""


class ClonedPolicy:
    """A classifier from observation features to primitives, learned by a cloning method.

    Parameters
    ----------
    method : str
        The method that learned it (``"bc"``, ``"bco"``, …), for the record.
    hyperparameters : Hyperparameters
    classifier : fitted scikit-learn classifier
        Maps ``features(observations, feature_set=hyperparameters.feature_set)`` (on the body's
        field) to indices into :data:`polymimic.field.PRIMITIVES`.
    body : polymimic.Body, str or polymimic.bodies.WheeledBody, default "lego"
        The body the policy drives, on that body's field (kept as a :class:`polymimic.Body`).
    """

    body = Body("lego")  # what a policy saved before bodies were named drives

    def __init__(self, method: str, hyperparameters: Hyperparameters, classifier: Any, *,
                 body: BodySpec = "lego") -> None:
        self.method = method
        self.hyperparameters = hyperparameters
        self.classifier = classifier
        self.body = as_body(body)

    @property
    def frames_per_action(self) -> int:
        """Tracker frames each chosen primitive is held for (30 is one second)."""
        return int(self.hyperparameters.frames_per_action)

    def predict(self, observations: np.ndarray) -> np.ndarray:
        """The primitive index for each row of an ``(n, 5)`` observation batch."""
        obs = check_observations(observations)
        if len(obs) == 0:
            return np.empty(0, dtype=np.int64)
        return np.asarray(self.classifier.predict(self.features(obs)), dtype=np.int64)

    def features(self, observations: np.ndarray) -> np.ndarray:
        """What the classifier reads of an ``(n, 5)`` observation batch: its feature set's
        features, on the field of the policy's body."""
        return features(observations, feature_set=self.hyperparameters.feature_set,
                        target_goal_mm=target_goal_of(self.body))

    def reset(self) -> None:
        """Nothing to restart: a cloned policy is deterministic."""

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes the policy (its method, body, hyperparameters and fitted classifier) to ``path``;
        :func:`polymimic.baselines.load_policy` reads it back.
        """
        write_policy_file(path, {"kind": "cloned", "method": self.method, "body": self.body.name,
                                 "hyperparameters": self.hyperparameters.to_dict()}, self)

    def __repr__(self) -> str:
        body = "" if self.body == Body("lego") else f", body={self.body.name!r}"
        return f"ClonedPolicy({self.method}, {self.hyperparameters}{body})"


class RandomPolicy:
    """A uniformly random primitive every step, from a generator seeded with ``seed``.

    Parameters
    ----------
    seed : int, default 0
    frames_per_action : int, default 30
        The environment's step: one primitive a second.
    body : polymimic.Body, str or polymimic.bodies.WheeledBody, default "lego"
        The body the policy drives (kept as a :class:`polymimic.Body`).
    """

    body = Body("lego")  # what a policy saved before bodies were named drives

    def __init__(self, *, seed: int = 0, frames_per_action: int = 30, body: BodySpec = "lego") -> None:
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ValueError(f"seed must be an integer ≥ 0, got {seed!r}")
        if isinstance(frames_per_action, bool) or not isinstance(frames_per_action, (int, np.integer)) \
                or frames_per_action < 1:
            raise ValueError(f"frames_per_action must be an integer ≥ 1, got {frames_per_action!r}")
        self.method = "random"
        self.body = as_body(body)
        self.seed = int(seed)
        self._frames_per_action = int(frames_per_action)
        self.reset()

    @property
    def frames_per_action(self) -> int:
        """Tracker frames each random primitive is held for."""
        return self._frames_per_action

    def predict(self, observations: np.ndarray) -> np.ndarray:
        """One uniformly random primitive index per row of an ``(n, 5)`` batch."""
        obs = check_observations(observations)
        return self._rng.integers(len(PRIMITIVES), size=len(obs)).astype(np.int64)

    def reset(self) -> None:
        """Restart the random stream from ``seed``."""
        self._rng = np.random.default_rng(self.seed)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes the policy (its seed, body and step length) to ``path``."""
        write_policy_file(path, {"kind": "random", "method": "random", "seed": self.seed, "body": self.body.name,
                                 "frames_per_action": self._frames_per_action}, self)

    def __repr__(self) -> str:
        return f"RandomPolicy(seed={self.seed}, frames_per_action={self._frames_per_action})"


def load_policy(path: str | os.PathLike[str]) -> Policy:
    """The policy saved at ``path``, exactly as it was saved (a PPO policy needs
    stable-baselines3 to load).

    Raises
    ------
    polymimic.ModelFileError
        If the file is not a saved policy, is of a newer format, or is damaged.
    """
    header, policy = read_policy_file(path)
    if header.get("kind") not in _KINDS or not isinstance(policy, Policy):
        raise ModelFileError(f"{os.fspath(path)}: holds no baseline policy")
    _body_made_a_value(policy, path)
    return policy


def _body_made_a_value(policy: Any, path: str | os.PathLike[str]) -> None:
    """A policy saved while it kept its body's name drives that body: a built-in one, as a
    :class:`polymimic.Body`; the name of a body of one's own says nothing of it."""
    named = getattr(policy, "body", None)
    if isinstance(named, str):
        try:
            policy.body = as_body(named)
        except ValueError:
            raise ModelFileError(f"{os.fspath(path)}: the policy names its body {named!r}, which is not built in, "
                                 f"and holds no description of it") from None


_KINDS = ("cloned", "random", "ppo", "offline_rl")
