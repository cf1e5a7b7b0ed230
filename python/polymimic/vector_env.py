"""Many penalty kicks at once: ``PenaltyKick-v0`` as a Gymnasium vector environment whose
episodes all step together in Rust (one call, in parallel, with the GIL released), so that a
policy answers one batch of observations per step.

It is the same environment as :class:`~polymimic.env.PenaltyKickEnv`, episode for episode:
sub-environment ``i`` reset with seed ``s + i`` draws its start and its episode seed from
Gymnasium's generator for that seed exactly as a single environment does, steps are held for
the same frames, and rewards, ends and infos are what ``gymnasium.vector.SyncVectorEnv`` over
single environments returns, bit for bit. Ended episodes reset on the next step
(``AutoresetMode.NEXT_STEP``, Gymnasium's default): that step returns the new episode's first
observation with reward 0. ``reset(options={"reset_mask": mask})`` resets only some.

>>> import gymnasium
>>> envs = gymnasium.make_vec("PenaltyKick-v0", num_envs=4, vectorization_mode="vector_entry_point")
>>> observations, infos = envs.reset(seed=1)
>>> observations.shape, envs.action_space
((4, 5), MultiDiscrete([5 5 5 5]))
>>> observations, rewards, terminations, truncations, infos = envs.step([0, 0, 2, 3])
>>> infos["t_s"].tolist()
[1.0, 1.0, 1.0, 1.0]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, ClassVar

import numpy as np

from polymimic._native import EpisodeBatch
from polymimic.bodies import BodySpec, as_body
from polymimic.env import _check_configuration, observation_space
from polymimic.field import OUTCOMES, PRIMITIVE_SETS
from polymimic.field_config import native_field_config

try:
    import gymnasium
    from gymnasium.utils import seeding
    from gymnasium.vector import AutoresetMode, VectorEnv
    from gymnasium.vector.utils import batch_space
except ImportError:  # the `gym` extra is not installed: the module still imports, the env does not
    gymnasium = None  # type: ignore[assignment]

__all__ = ["PenaltyKickVectorEnv"]

_Base: Any = VectorEnv if gymnasium is not None else object
_REWARD_OF_OUTCOME = np.array([{"goal": 1.0, "own_goal": -1.0}.get(o, 0.0) for o in OUTCOMES])
_TIME_UP = OUTCOMES.index("time_up")


class PenaltyKickVectorEnv(_Base):  # type: ignore[misc]
    """``num_envs`` penalty kicks stepped together.

    Parameters
    ----------
    num_envs : int
        Sub-environments.
    configuration, frames_per_action, config, body
        As for :class:`~polymimic.env.PenaltyKickEnv`, for every sub-environment.
    """

    metadata: ClassVar[dict[str, Any]] = {
        "autoreset_mode": AutoresetMode.NEXT_STEP if gymnasium is not None else None, "render_modes": []}

    def __init__(self, num_envs: int = 8, *, configuration: int | str = "random", frames_per_action: int = 30,
                 config: dict[str, Any] | str | None = None, body: BodySpec = "lego") -> None:
        if gymnasium is None:
            raise ModuleNotFoundError("PenaltyKickVectorEnv needs gymnasium: pip install \"polymimic[gym]\"")
        if not isinstance(num_envs, (int, np.integer)) or isinstance(num_envs, bool) or num_envs < 1:
            raise ValueError(f"num_envs must be an integer ≥ 1, got {num_envs!r}")
        _check_configuration(configuration)
        self.num_envs = int(num_envs)
        self.configuration = configuration
        self.body = as_body(body)
        self._batch = EpisodeBatch(self.num_envs, frames_per_action=frames_per_action,
                                   config=native_field_config(config), body=self.body)
        self.frames_per_action = int(frames_per_action)
        field = self.body.field
        self.single_observation_space = observation_space((field.length_mm, field.width_mm))
        self.primitives = PRIMITIVE_SETS[self.body.primitive_set]
        self.single_action_space = gymnasium.spaces.Discrete(len(self.primitives))
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._generators: list[np.random.Generator | None] = [None] * self.num_envs
        self._autoreset = np.zeros(self.num_envs, dtype=np.bool_)
        self._episode_seeds = np.zeros(self.num_envs, dtype=np.int64)
        self._started = False

    def reset(self, *, seed: int | Sequence[int | None] | None = None,
              options: dict[str, Any] | None = None) -> tuple[np.ndarray, dict[str, Any]]:
        """Start every sub-environment (or those ``options["reset_mask"]`` marks) afresh;
        ``seed`` is one int (sub-environment ``i`` gets ``seed + i``) or one per sub-environment."""
        super().reset(seed=seed if isinstance(seed, int) else None)
        seeds = self._seeds(seed)
        options = dict(options or {})
        mask = self._reset_mask(options.pop("reset_mask", None))
        configuration = options.pop("configuration", self.configuration)
        if options:
            raise ValueError(f"unknown reset option(s) {', '.join(map(repr, options))}; expected 'configuration' "
                             "or 'reset_mask'")
        _check_configuration(configuration)
        if not self._started and not mask.all():
            raise ValueError("the first reset must reset every sub-environment: leave out reset_mask")
        for i in np.flatnonzero(mask):
            if seeds[i] is not None or self._generators[i] is None:
                self._generators[i], _ = seeding.np_random(seeds[i])
            self._start(int(i), configuration)
        self._autoreset[mask] = False
        self._started = True
        observations, t_s, outcomes, valid = self._batch.status()
        return observations, self._infos(t_s, outcomes, valid, mask)

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """One primitive held in every sub-environment; those whose episode ended on the last
        step start a new one instead (reward 0)."""
        if not self._started:
            raise gymnasium.error.ResetNeeded("call reset() before step()")
        chosen = self._actions(actions)
        resetting = self._autoreset.copy()
        for i in np.flatnonzero(resetting):
            self._start(int(i), self.configuration)
        chosen[resetting] = -1
        observations, t_s, outcomes, valid = self._batch.step(chosen.tolist())
        ended = (outcomes >= 0) & ~resetting
        rewards = np.where(ended, _REWARD_OF_OUTCOME[outcomes], 0.0)
        truncations = ended & (outcomes == _TIME_UP)
        terminations = ended & ~truncations
        self._autoreset = terminations | truncations
        return observations, rewards, terminations, truncations, self._infos(t_s, outcomes, valid)

    def _start(self, index: int, configuration: int | str) -> None:
        """A new episode in slot ``index``, drawn from its generator as a single env draws it."""
        generator = self._generators[index]
        assert generator is not None
        if configuration == "random":
            configuration = int(generator.integers(1, 3))
        episode_seed = int(generator.integers(0, 2**63))
        self._episode_seeds[index] = episode_seed
        self._batch.reset(index, configuration=int(configuration), seed=episode_seed)

    def _seeds(self, seed: int | Sequence[int | None] | None) -> list[int | None]:
        if seed is None:
            return [None] * self.num_envs
        if isinstance(seed, bool):
            raise ValueError(f"seed must be an integer or one per sub-environment, got {seed!r}")
        if isinstance(seed, (int, np.integer)):
            return [int(seed) + i for i in range(self.num_envs)]
        seeds = list(seed)
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed holds {len(seeds)} seeds for {self.num_envs} sub-environments")
        return seeds

    def _reset_mask(self, mask: Any) -> np.ndarray:
        if mask is None:
            return np.ones(self.num_envs, dtype=np.bool_)
        if not isinstance(mask, np.ndarray) or mask.dtype != np.bool_ or mask.shape != (self.num_envs,):
            raise ValueError(f"options['reset_mask'] must be a bool array of shape ({self.num_envs},), got {mask!r}")
        if not mask.any():
            raise ValueError("options['reset_mask'] resets no sub-environment")
        return mask

    def _actions(self, actions: Any) -> np.ndarray:
        array, last = np.asarray(actions), len(self.primitives) - 1
        if array.shape != (self.num_envs,) or not np.issubdtype(array.dtype, np.integer):
            raise ValueError(f"actions must be {self.num_envs} integers in 0..{last} (one per sub-environment), got "
                             f"shape {array.shape} of {array.dtype}")
        bad = np.flatnonzero((array < 0) | (array > last))
        if len(bad):
            raise ValueError(f"actions[{bad[0]}] = {array[bad[0]]}: an action is an integer in 0..{last} "
                             f"({', '.join(self.primitives)})")
        return array.astype(np.int64)

    def _infos(self, t_s: np.ndarray, outcomes: np.ndarray, valid: np.ndarray,
               mask: np.ndarray | None = None) -> dict[str, Any]:
        """As SyncVectorEnv gathers the single environments' infos: one array per key, with a
        ``_key`` mask of the sub-environments that gave it."""
        given = np.ones(self.num_envs, dtype=np.bool_) if mask is None else mask.copy()
        names = np.array([None, *OUTCOMES], dtype=object)[outcomes + 1]
        return {"t_s": np.where(given, t_s, 0.0), "_t_s": given.copy(),
                "outcome": np.where(given, names, None), "_outcome": given.copy(),
                "valid": np.where(given, valid, False), "_valid": given.copy(),
                "episode_seed": np.where(given, self._episode_seeds, 0), "_episode_seed": given.copy()}

