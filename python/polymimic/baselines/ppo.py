"""``ppo`` (optional): Proximal Policy Optimisation from stable-baselines3 on ``PenaltyKick-v0``.

Learns from the environment's reward (+1 goal, −1 own goal), not from demonstrations, at a
stated budget of environment steps (``total_timesteps``; one step is one primitive held for
``frames_per_action`` frames). Two environments run side by side, one per field configuration.
The network sees the ``feature_set`` features of the observation, scaled to about ±1
(:data:`FEATURE_SCALE` on the Lego's field, in proportion on another). The imitator may be any body
(``imitator=``: a :class:`polymimic.Body`, a built-in body's name or a :class:`~polymimic.bodies.WheeledBody`);
it plays on its own field, and the policy remembers its body. stable-baselines3 and torch are
needed to fit and to load a PPO policy (``pip install "polymimic[rl]"``), not to import this
module.

:func:`learning_curve` trains one and plays the imitator's evaluation attempts with it as it
learns (the same starts and noise at every checkpoint, so the curve shows learning, not the luck
of the draw); ``polymimic benchmark --methods … ppo`` and ``examples/ppo_penalty_kick.py`` use it.

>>> from polymimic.baselines import ppo
>>> ppo.available() in (True, False)
True
"""

from __future__ import annotations

import dataclasses
import importlib.util
import io
import os
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from polymimic.baselines.features import FEATURE_NAMES, check_observations, features, target_goal_of
from polymimic.baselines.policy_file import write_policy_file
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.evaluation import Attempts, thesis_attempts

__all__ = ["FEATURE_SCALE", "Checkpoint", "PPOPolicy", "available", "fit", "learning_curve", "new_model", "scaled",
           "steps_to_reach"]

FEATURE_SCALE = 500.0
"""Millimetre features are divided by this on the Lego's field, and by this times the ratio of
the imitator's field length to the Lego's on another (angles' sines and cosines are left as
they are)."""

IMITATOR_BODY = "lego"
"""The imitator's body unless one is given: the thesis's Lego robot."""


def available() -> bool:
    """Whether stable-baselines3 (and so torch) is installed."""
    return importlib.util.find_spec("stable_baselines3") is not None


def _require() -> None:
    if not available():
        raise ModuleNotFoundError("the ppo baseline needs stable-baselines3: pip install \"polymimic[rl]\"")


@dataclasses.dataclass(frozen=True)
class Checkpoint:
    """What the policy scored on the evaluation attempts after learning from ``env_steps`` steps."""

    env_steps: int
    goals: int
    own_goals: int
    attempts: int
    wall_s: float
    """Seconds since training started, evaluations included."""

    @property
    def net_goals(self) -> int:
        """Goals minus own goals."""
        return self.goals - self.own_goals

    def to_dict(self) -> dict[str, Any]:
        """The checkpoint as plain JSON values (wall time rounded to 0.1 s)."""
        return {"env_steps": self.env_steps, "goals": self.goals, "own_goals": self.own_goals,
                "net_goals": self.net_goals, "attempts": self.attempts, "wall_s": round(self.wall_s, 1)}


def steps_to_reach(curve: list[Checkpoint] | list[dict[str, Any]], net_goals: float) -> int | None:
    """The environment steps of the first checkpoint scoring at least ``net_goals``, or None.

    >>> curve = [Checkpoint(0, 0, 3, 50, 0.0), Checkpoint(4096, 30, 0, 50, 9.0), Checkpoint(8192, 41, 0, 50, 18.0)]
    >>> steps_to_reach(curve, 38.4), steps_to_reach(curve, 45)
    (8192, None)
    """
    for point in curve:
        row = point.to_dict() if isinstance(point, Checkpoint) else point
        if row["net_goals"] >= net_goals:
            return int(row["env_steps"])
    return None


def scaled(observations: np.ndarray, feature_set: str, imitator: BodySpec = IMITATOR_BODY) -> np.ndarray:
    """The ``feature_set`` features of observations on ``imitator``'s field as the network sees
    them: millimetres over :data:`FEATURE_SCALE` (in proportion to the field's length), as
    float32.

    >>> lego = np.array([[-170.0, 0.0, 0.0, 170.0, 0.0]])
    >>> tiny = lego * [560 / 1020, 1, 1, 560 / 1020, 1]   # the same place on the tiny's field
    >>> round(float(scaled(lego, "raw")[0, 0]), 4), round(float(scaled(tiny, "raw", "tiny")[0, 0]), 4)
    (-0.34, -0.34)
    """
    values = features(observations, feature_set=feature_set, target_goal_mm=target_goal_of(imitator))
    millimetres = np.array([name.endswith("_mm") for name in FEATURE_NAMES[feature_set]])
    scale = FEATURE_SCALE * (as_body(imitator).field.length_mm / as_body(IMITATOR_BODY).field.length_mm)
    values[:, millimetres] = values[:, millimetres] / scale
    return values.astype(np.float32)


class PPOPolicy:
    """A trained stable-baselines3 PPO model, acting deterministically on observation batches
    of its ``body``'s field (the imitator's :class:`polymimic.Body`)."""

    body = Body(IMITATOR_BODY)  # what a policy saved before bodies were named drives

    def __init__(self, model: Any, *, feature_set: str, frames_per_action: int, total_timesteps: int,
                 method: str = "ppo", body: BodySpec = IMITATOR_BODY) -> None:
        self.method = method
        self.body = as_body(body)
        self.model = model
        self.feature_set = feature_set
        self.total_timesteps = int(total_timesteps)
        self._frames_per_action = int(frames_per_action)

    @property
    def frames_per_action(self) -> int:
        """Tracker frames each chosen primitive is held for (30: one environment step)."""
        return self._frames_per_action

    def predict(self, observations: np.ndarray) -> np.ndarray:
        """The primitive id PPO's network plays, deterministically, for each observation.

        Parameters
        ----------
        observations : ndarray of shape (n, 5)
            Tracker readings: robot x, y (mm), θ (rad), ball x, y (mm).

        Returns
        -------
        ndarray of int64, shape (n,)
        """
        obs = check_observations(observations)
        if len(obs) == 0:
            return np.empty(0, dtype=np.int64)
        actions, _ = self.model.predict(scaled(obs, self.feature_set, self.body), deterministic=True)
        return np.asarray(actions, dtype=np.int64).reshape(len(obs))

    def reset(self) -> None:
        """Nothing to restart: the policy acts deterministically."""

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes the policy (its network, body and features) to ``path``."""
        write_policy_file(path, {"kind": "ppo", "method": self.method, "body": self.body.name,
                                 "feature_set": self.feature_set,
                                 "frames_per_action": self._frames_per_action,
                                 "total_timesteps": self.total_timesteps}, self)

    def __getstate__(self) -> dict[str, Any]:
        buffer = io.BytesIO()
        self.model.save(buffer)
        state = dict(self.__dict__)
        state["model"] = buffer.getvalue()
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        from stable_baselines3 import PPO  # type: ignore[import-not-found, unused-ignore]

        state = dict(state)
        state["model"] = PPO.load(io.BytesIO(state["model"]), device="cpu")
        self.__dict__.update(state)


def fit(*, total_timesteps: int = 200_000, frames_per_action: int = 30, feature_set: str = "goal_relative",
        seed: int = 0, field_config: dict[str, Any] | str | None = None, callback: Any = None,
        before_learning: Callable[[Any], None] | None = None, method: str = "ppo",
        imitator: BodySpec = IMITATOR_BODY, **ppo_kwargs: Any) -> PPOPolicy:
    """PPO (``stable_baselines3.PPO("MlpPolicy", …)``) trained for ``total_timesteps`` steps,
    driving ``imitator`` on its own field.

    ``ppo_kwargs`` go to ``PPO`` (``n_steps``, ``learning_rate``, …); ``callback`` (a
    stable-baselines3 callback) to ``PPO.learn``, to look at the model while it learns;
    ``before_learning(model)`` runs on the new model before it learns (``ppo_bc``'s cloning,
    :mod:`polymimic.baselines.ppo_bc`), and ``method`` names the policy.

    Raises
    ------
    ModuleNotFoundError
        If stable-baselines3 is not installed.
    ValueError
        If ``total_timesteps`` is not a positive integer.
    """
    _require()
    if isinstance(total_timesteps, bool) or not isinstance(total_timesteps, (int, np.integer)) or total_timesteps < 1:
        raise ValueError(f"total_timesteps must be an integer ≥ 1 (environment steps), got {total_timesteps!r}")
    model = new_model(frames_per_action=frames_per_action, feature_set=feature_set, seed=seed,
                      field_config=field_config, imitator=imitator, **ppo_kwargs)
    if before_learning is not None:
        before_learning(model)
    model.learn(total_timesteps=int(total_timesteps), callback=callback)
    return PPOPolicy(model, feature_set=feature_set, frames_per_action=frames_per_action,
                     total_timesteps=total_timesteps, method=method, body=as_body(imitator, what="imitator"))


def new_model(*, frames_per_action: int = 30, feature_set: str = "goal_relative", seed: int = 0,
              field_config: dict[str, Any] | str | None = None, imitator: BodySpec = IMITATOR_BODY,
              wrap: Callable[[Any], Any] | None = None, **ppo_kwargs: Any) -> Any:
    """A new, untrained ``stable_baselines3.PPO`` on ``PenaltyKick-v0`` with ``imitator``'s
    body, one environment per field configuration, seeing the scaled ``feature_set`` features.
    ``wrap`` wraps each field's env before its observations are scaled (practice's roll-in by
    a teacher, :mod:`polymimic.practice.teacher`)."""
    _require()
    import gymnasium
    from stable_baselines3 import PPO  # type: ignore[import-not-found, unused-ignore]
    from stable_baselines3.common.logger import Logger  # type: ignore[import-not-found, unused-ignore]
    from stable_baselines3.common.vec_env import DummyVecEnv  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines.evaluation import ball_as_read
    from polymimic.env import PenaltyKickEnv

    length_mm = as_body(imitator).field.length_mm

    class Scaled(gymnasium.ObservationWrapper):  # type: ignore[misc, unused-ignore]
        """The scaled features of what the robot sees, the ball out of sight read as it is in
        the evaluation (:func:`~polymimic.baselines.evaluation.ball_as_read`)."""

        def __init__(self, env: Any) -> None:
            super().__init__(env)
            size = scaled(np.zeros((1, 5)), feature_set, imitator).shape[1]
            self.observation_space = gymnasium.spaces.Box(-np.inf, np.inf, shape=(size,), dtype=np.float32)
            self._last: np.ndarray | None = None

        def reset(self, **kwargs: Any) -> Any:
            self._last = None
            return super().reset(**kwargs)

        def observation(self, observation: np.ndarray) -> np.ndarray:
            read = np.asarray(observation, dtype=np.float64).copy()
            read[3:5] = ball_as_read(read[3:5], self._last, robot_x_mm=float(read[0]), field_length_mm=length_mm)
            self._last = read
            return np.asarray(scaled(read[None, :], feature_set, imitator)[0])

    def make(configuration: int) -> Any:
        def env() -> Any:
            field = PenaltyKickEnv(configuration=configuration, frames_per_action=frames_per_action,
                                   config=field_config, body=imitator)
            return Scaled(field if wrap is None else wrap(field))
        return env

    env = DummyVecEnv([make(1), make(2)])
    env.seed(seed)
    model = PPO("MlpPolicy", env, seed=seed, verbose=0, device="cpu", **ppo_kwargs)
    # Its own quiet logger would make an empty SB3-<time> folder in the temporary directory.
    model.set_logger(Logger(folder=None, output_formats=[]))
    return model


def _checkpoints(every: int, evaluate: Callable[[Any], None]) -> Any:
    """A stable-baselines3 callback calling ``evaluate(model)`` before training, at the first
    rollout at or past each multiple of ``every`` steps, and after training."""
    from stable_baselines3.common.callbacks import BaseCallback  # type: ignore[import-not-found, unused-ignore]

    class Checkpoints(BaseCallback):  # type: ignore[misc, unused-ignore]
        def __init__(self) -> None:
            super().__init__()
            self.last: int | None = None

        def _evaluate(self) -> None:
            self.last = self.model.num_timesteps
            evaluate(self.model)

        def _on_training_start(self) -> None:
            self._evaluate()

        def _on_rollout_start(self) -> None:
            # At a rollout's start the policy has just been updated on every step so far.
            assert self.last is not None
            if self.model.num_timesteps >= (self.last // every + 1) * every:
                self._evaluate()

        def _on_step(self) -> bool:
            return True

        def _on_training_end(self) -> None:
            if self.model.num_timesteps != self.last:
                self._evaluate()

    return Checkpoints()


def learning_curve(*, total_timesteps: int, eval_every: int, evaluation: Attempts = Attempts(), seed: int = 0,
                   frames_per_action: int = 30, feature_set: str = "goal_relative",
                   field_config: dict[str, Any] | str | None = None,
                   on_checkpoint: Callable[[list[Checkpoint]], None] | None = None,
                   before_learning: Callable[[Any], None] | None = None, method: str = "ppo",
                   imitator: BodySpec = IMITATOR_BODY,
                   **ppo_kwargs: Any) -> tuple[PPOPolicy, list[Checkpoint], Any]:
    """PPO trained as :func:`fit` trains it, driving ``imitator``, and played on the
    ``evaluation`` attempts (an :class:`~polymimic.Attempts` from the thesis's configurations:
    :func:`polymimic.baselines.evaluate_policy`, on the imitator's field) before training, at the
    first policy update at or past every multiple of ``eval_every`` steps and at the end.

    PPO updates its policy once every ``n_steps × 2`` steps (4096 by default), so a checkpoint
    records the steps the policy has learned from. ``on_checkpoint`` sees the curve so far after
    every checkpoint (to write it down as it grows).

    Returns
    -------
    (PPOPolicy, list of Checkpoint, polymimic.Evaluation)
        The final policy, the curve, and the final policy's evaluation (its attempts).

    Raises
    ------
    ModuleNotFoundError
        If stable-baselines3 is not installed.
    ValueError
        If ``total_timesteps`` or ``eval_every`` is not a positive integer, or ``evaluation`` is
        from starts of its own.
    TypeError
        If ``evaluation`` is not an :class:`~polymimic.Attempts`.
    """
    _require()
    if isinstance(eval_every, bool) or not isinstance(eval_every, (int, np.integer)) or eval_every < 1:
        raise ValueError(f"eval_every must be an integer ≥ 1 (environment steps), got {eval_every!r}")
    scored_on = thesis_attempts(evaluation, name="evaluation")
    from polymimic.baselines.evaluation import evaluate_policy

    start = time.perf_counter()
    curve: list[Checkpoint] = []
    latest: list[Any] = []  # only the last evaluation's attempts are kept

    def evaluate(model: Any) -> None:
        policy = PPOPolicy(model, feature_set=feature_set, frames_per_action=frames_per_action,
                           total_timesteps=model.num_timesteps, method=method, body=as_body(imitator, what="imitator"))
        played = evaluate_policy(policy, attempts=scored_on, field_config=field_config)
        latest[:] = [played]
        curve.append(Checkpoint(env_steps=int(model.num_timesteps), goals=played.goals, own_goals=played.own_goals,
                                attempts=len(played.attempts), wall_s=time.perf_counter() - start))
        if on_checkpoint is not None:
            on_checkpoint(curve)

    policy = fit(total_timesteps=total_timesteps, frames_per_action=frames_per_action, feature_set=feature_set,
                 seed=seed, field_config=field_config, callback=_checkpoints(int(eval_every), evaluate),
                 before_learning=before_learning, method=method, imitator=imitator, **ppo_kwargs)
    return policy, curve, latest[0]
