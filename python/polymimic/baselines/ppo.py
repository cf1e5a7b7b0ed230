"""``ppo`` (optional): Proximal Policy Optimisation from stable-baselines3 on ``PenaltyKick-v0``.

Learns from the environment's reward (+1 goal, −1 own goal), not from demonstrations, at a
stated budget of environment steps (``total_timesteps``; one step is one primitive held for
``frames_per_action`` frames). Two environments run side by side, one per field configuration.
The network sees the ``feature_set`` features of the observation, scaled to about ±1
(:data:`FEATURE_SCALE`). stable-baselines3 and torch are needed to fit and to load a PPO
policy (``pip install "polymimic[rl]"``), not to import this module. ``examples/ppo_penalty_kick.py``
fits one and evaluates it as it learns.

>>> from polymimic.baselines import ppo
>>> ppo.available() in (True, False)
True
"""

from __future__ import annotations

import importlib.util
import io
import os
from typing import Any

import numpy as np

from polymimic.baselines.features import FEATURE_NAMES, check_observations, features
from polymimic.baselines.files import write_policy_file

__all__ = ["FEATURE_SCALE", "PPOPolicy", "available", "fit"]

FEATURE_SCALE = 500.0
"""Millimetre features are divided by this (angles' sines and cosines are left as they are)."""


def available() -> bool:
    """Whether stable-baselines3 (and so torch) is installed."""
    return importlib.util.find_spec("stable_baselines3") is not None


def _scaled(observations: np.ndarray, feature_set: str) -> np.ndarray:
    values = features(observations, feature_set=feature_set)
    millimetres = np.array([name.endswith("_mm") for name in FEATURE_NAMES[feature_set]])
    values[:, millimetres] = values[:, millimetres] / FEATURE_SCALE
    return values.astype(np.float32)


class PPOPolicy:
    """A trained stable-baselines3 PPO model, acting deterministically on observation batches."""

    def __init__(self, model: Any, *, feature_set: str, frames_per_action: int, total_timesteps: int) -> None:
        self.method = "ppo"
        self.model = model
        self.feature_set = feature_set
        self.total_timesteps = int(total_timesteps)
        self._frames_per_action = int(frames_per_action)

    @property
    def frames_per_action(self) -> int:
        return self._frames_per_action

    def predict(self, observations: np.ndarray) -> np.ndarray:
        obs = check_observations(observations)
        if len(obs) == 0:
            return np.empty(0, dtype=np.int64)
        actions, _ = self.model.predict(_scaled(obs, self.feature_set), deterministic=True)
        return np.asarray(actions, dtype=np.int64).reshape(len(obs))

    def reset(self) -> None:
        """Nothing to restart: the policy acts deterministically."""

    def save(self, path: str | os.PathLike[str]) -> None:
        write_policy_file(path, {"kind": "ppo", "method": "ppo", "feature_set": self.feature_set,
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
        **ppo_kwargs: Any) -> PPOPolicy:
    """PPO (``stable_baselines3.PPO("MlpPolicy", …)``) trained for ``total_timesteps`` steps.

    ``ppo_kwargs`` go to ``PPO`` (``n_steps``, ``learning_rate``, …); ``callback`` (a
    stable-baselines3 callback) to ``PPO.learn``, to look at the model while it learns.

    Raises
    ------
    ModuleNotFoundError
        If stable-baselines3 is not installed.
    ValueError
        If ``total_timesteps`` is not a positive integer.
    """
    if not available():
        raise ModuleNotFoundError("the ppo baseline needs stable-baselines3: pip install \"polymimic[rl]\"")
    if isinstance(total_timesteps, bool) or not isinstance(total_timesteps, (int, np.integer)) or total_timesteps < 1:
        raise ValueError(f"total_timesteps must be an integer ≥ 1 (environment steps), got {total_timesteps!r}")
    import gymnasium
    from stable_baselines3 import PPO  # type: ignore[import-not-found, unused-ignore]
    from stable_baselines3.common.vec_env import DummyVecEnv  # type: ignore[import-not-found, unused-ignore]

    from polymimic.env import PenaltyKickEnv

    class Scaled(gymnasium.ObservationWrapper):  # type: ignore[misc, unused-ignore]
        def __init__(self, env: Any) -> None:
            super().__init__(env)
            size = _scaled(np.zeros((1, 5)), feature_set).shape[1]
            self.observation_space = gymnasium.spaces.Box(-np.inf, np.inf, shape=(size,), dtype=np.float32)

        def observation(self, observation: np.ndarray) -> np.ndarray:
            return np.asarray(_scaled(np.asarray(observation, dtype=np.float64)[None, :], feature_set)[0])

    def make(configuration: int) -> Any:
        return lambda: Scaled(PenaltyKickEnv(configuration=configuration, frames_per_action=frames_per_action,
                                             config=field_config))

    env = DummyVecEnv([make(1), make(2)])
    env.seed(seed)
    model = PPO("MlpPolicy", env, seed=seed, verbose=0, device="cpu", **ppo_kwargs)
    model.learn(total_timesteps=int(total_timesteps), callback=callback)
    return PPOPolicy(model, feature_set=feature_set, frames_per_action=frames_per_action,
                     total_timesteps=total_timesteps)
