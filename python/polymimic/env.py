"""The penalty kick as a Gymnasium environment, so standard imitation and RL tools can play it.

The imitator (the Lego robot, or the ``body`` given) faces the ball in configuration 1 or 2 of
its field, or at a start of one's own, and each action is one of its own primitives. Importing
this module registers ``PenaltyKick-v0`` when Gymnasium is installed (``pip install "polymimic[gym]"``);
``gymnasium.make("polymimic.env:PenaltyKick-v0")`` imports it and makes the environment in one
call.

- **Observation**: the latest tracker reading, ``[robot x mm, robot y mm, robot θ rad,
  ball x mm, ball y mm]`` as float32, in field coordinates (origin at the centre, +x toward the
  target goal). During a tracking dropout the last good reading is repeated, as the field's
  own controllers see it.
- **Action**: the body's own primitive set, :data:`polymimic.field.PRIMITIVE_SETS`: on a
  wheeled body ``Discrete(5)``, 0 forward, 1 backward, 2 left, 3 right, 4 stop; on the
  humanoid ``Discrete(8)``, the same five as the walks, turns and waiting that execute them
  (:func:`polymimic.field.primitive_command`), then 5 side-step left, 6 side-step right and
  7 kick, with the foot on the side of the ball the robot sees, as the imitator's control
  kicks.
- **Step**: one primitive held for one second (30 tracker frames, via ``Episode.run``), as the
  thesis's imitator executes primitives (§3.1.1); the motors' lag carries motion from one step
  into the next. ``frames_per_action`` changes it.
- **Reward**: +1 for a goal, −1 for an own goal, 0 otherwise (sparse: the episode's outcome).
- **End**: ``terminated`` when the ball crosses a line (goal, own goal, out) or the robot leaves
  the field; ``truncated`` when the field's time limit (60 s, so 60 steps) runs out (outcome
  ``time_up``): the clock is not part of the observation, so by Gymnasium's convention this is
  a truncation, not a terminal state. ``info`` holds ``t_s``, ``outcome`` (None while running),
  ``valid`` (False once tracking has dropped out) and the ``episode_seed``.
- **Reset options**: ``configuration`` (1, 2 or ``"random"``), or a ``start`` of one's own
  (``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``, refused by name off the
  field or on the robot); ``episode_seed`` fixes the episode's noise (any integer in
  ``[0, 2**64)``, so :func:`polymimic.evaluate`'s episodes can be played here too: its
  attempts' ``seed``), otherwise drawn from the env's generator.

>>> import gymnasium
>>> env = gymnasium.make("polymimic.env:PenaltyKick-v0")
>>> observation, info = env.reset(seed=1, options={"configuration": 1})
>>> (observation.round(-1) + 0).tolist()   # robot at −L/6 facing +x, ball at +L/6
[-170.0, 0.0, 0.0, 170.0, 0.0]
>>> observation, reward, terminated, truncated, info = env.step(0)   # forward for one second
>>> info["t_s"], terminated, truncated
(1.0, False, False)
"""

from __future__ import annotations

import math
from typing import Any, ClassVar

import numpy as np

from polymimic._arguments import integer
from polymimic._native import Episode, FieldRunError
from polymimic.bodies import BodySpec, as_body
from polymimic.field import OUTCOME_REWARDS, PRIMITIVE_SETS, PRIMITIVES, primitive_command
from polymimic.field_config import native_field_config
from polymimic.plots import state_image

try:
    import gymnasium
    from gymnasium import spaces
except ImportError:  # the `gym` extra is not installed: the module still imports, the env does not
    gymnasium = None  # type: ignore[assignment]

__all__ = ["ENV_ID", "PenaltyKickEnv", "register"]

ENV_ID = "PenaltyKick-v0"
"""The id under which :func:`register` makes the environment known to Gymnasium."""

_TRUNCATING = frozenset({"time_up"})
_Base: Any = gymnasium.Env if gymnasium is not None else object


class PenaltyKickEnv(_Base):  # type: ignore[misc]
    """The imitator's penalty kick: one primitive a second, rewarded by the outcome.

    Parameters
    ----------
    configuration : {1, 2, "random"}, default "random"
        The field configuration used when ``reset`` gets no ``options={"configuration": ...}``;
        ``"random"`` draws 1 or 2, with equal chances, for every episode from the env's own
        random generator (so ``reset(seed=...)`` fixes it too).
    frames_per_action : int, default 30
        Tracker frames (1/30 s each) one action is held for.
    config : dict or str, optional
        Field configuration overrides (see :func:`polymimic.field.default_config`).
    body : polymimic.Body, str or polymimic.bodies.WheeledBody, default "lego"
        The imitator's body (a :class:`polymimic.Body`, a built-in body's name or a described
        wheeled body; the env's ``body`` is it as a :class:`polymimic.Body`); it plays on its
        own field, which the observation space spans.
    render_mode : {None, "rgb_array"}
        ``"rgb_array"``: :meth:`render` returns a picture of the field now.

    Examples
    --------
    >>> env = PenaltyKickEnv(configuration=2)
    >>> observation, info = env.reset(seed=3)
    >>> bool(observation[0] > 0 and observation[3] < 0)   # robot at +L/6, ball at −L/6
    True
    >>> env.action_space, env.observation_space.shape
    (Discrete(5), (5,))
    """

    metadata: ClassVar[dict[str, Any]] = {"render_modes": ["rgb_array"], "render_fps": 1}

    def __init__(self, *, configuration: int | str = "random", frames_per_action: int = 30,
                 config: dict[str, Any] | str | None = None, body: BodySpec = "lego",
                 render_mode: str | None = None) -> None:
        if gymnasium is None:
            raise ModuleNotFoundError("PenaltyKickEnv needs gymnasium: pip install \"polymimic[gym]\"")
        super().__init__()
        _check_configuration(configuration)
        if not isinstance(frames_per_action, (int, np.integer)) or isinstance(frames_per_action, bool) \
                or frames_per_action < 1:
            raise ValueError(f"frames_per_action must be an integer ≥ 1, got {frames_per_action!r}")
        if render_mode not in (None, *self.metadata["render_modes"]):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        self.configuration = configuration
        self.frames_per_action = int(frames_per_action)
        self.render_mode = render_mode
        self._config = native_field_config(config)
        self.body = as_body(body)
        self.primitives = PRIMITIVE_SETS[self.body.primitive_set]
        self._commands = [primitive_command(p, self.body) for p in PRIMITIVES]
        # Fails now on a bad config, and tells the body's field.
        field_mm = Episode(self.body, configuration=1, seed=0, config=self._config).observation()["field"]
        self.observation_space = observation_space(field_mm)
        self.action_space = spaces.Discrete(len(self.primitives))
        self._episode_seed = 0
        self._episode: Episode | None = None

    def reset(self, *, seed: int | None = None,
              options: dict[str, Any] | None = None) -> tuple[np.ndarray, dict[str, Any]]:
        """Start a new episode: ``options={"configuration": 1, 2 or "random"}`` (default: the
        constructor's) or ``{"start": {...}}`` picks the start, ``{"episode_seed": s}`` the
        episode's noise (see the module's documentation)."""
        super().reset(seed=seed)
        options = dict(options or {})
        start = options.pop("start", None)
        configuration = options.pop("configuration", None if start is not None else self.configuration)
        episode_seed = options.pop("episode_seed", None)
        if options:
            raise ValueError(f"unknown reset option(s) {', '.join(map(repr, options))}; expected 'configuration', "
                             f"'start' or 'episode_seed'")
        if start is not None and configuration is not None:
            raise ValueError("reset options: give 'configuration' or 'start', not both")
        if configuration is not None:
            _check_configuration(configuration)
            if configuration == "random":
                configuration = int(self.np_random.integers(1, 3))
        drawn = int(self.np_random.integers(0, 2**63))
        self._episode_seed = drawn if episode_seed is None else integer("episode_seed", episode_seed, 0, 2**64 - 1)
        self._episode = Episode(self.body, configuration=configuration, seed=self._episode_seed,
                                config=self._config, start=start)
        return self._observation(), self._info()

    def step(self, action: int) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """Hold primitive ``action`` for ``frames_per_action`` tracker frames."""
        if self._episode is None:
            raise FieldRunError("call reset() before step()")
        if self._episode.finished:
            raise FieldRunError(f"the episode has ended ({self._episode.outcome}); call reset()")
        if not self.action_space.contains(action):
            raise ValueError(f"action must be an integer in 0..{len(self.primitives) - 1} "
                             f"({', '.join(self.primitives)}), got {action!r}")
        index = int(action)
        # Only a kick depends on what the robot sees now (which foot).
        command = self._commands[index] if index < len(self._commands) else \
            self._episode.command_for(self.primitives[index])
        _, outcome = self._episode.run([command] * self.frames_per_action)
        reward = OUTCOME_REWARDS.get(outcome, 0.0) if outcome is not None else 0.0
        terminated = outcome is not None and outcome not in _TRUNCATING
        truncated = outcome in _TRUNCATING
        return self._observation(), reward, terminated, truncated, self._info()

    def render(self) -> np.ndarray | None:
        """With ``render_mode="rgb_array"``: an ``(H, W, 3)`` uint8 picture of the field now."""
        if self.render_mode is None or self._episode is None:
            return None
        seen = self._episode.observation()
        return state_image(self.body, seen["robot"], seen["ball"], f"t = {seen['t_s']:.1f} s")

    def _observation(self) -> np.ndarray:
        assert self._episode is not None
        seen = self._episode.observation()
        ball = seen["ball"] if seen["ball"] is not None else (math.nan, math.nan)
        return np.array([*seen["robot"], *ball], dtype=np.float32)

    def _info(self) -> dict[str, Any]:
        assert self._episode is not None
        return {"t_s": self._episode.observation()["t_s"], "outcome": self._episode.outcome,
                "valid": self._episode.valid, "episode_seed": self._episode_seed}


def observation_space(field_mm: tuple[float, float] = (1020.0, 810.0)) -> Any:
    """The observation's space on a field of ``field_mm`` (length, width; the thesis's large
    field by default): the field with a quarter of its size around it (a robot or ball leaving
    the field is seen a little beyond the line), and the heading in [−π, π]."""
    length_mm, width_mm = field_mm
    half_x, half_y = 0.75 * length_mm, 0.75 * width_mm
    high = np.array([half_x, half_y, math.pi, half_x, half_y], dtype=np.float32)
    return spaces.Box(low=-high, high=high, dtype=np.float32)


def register() -> None:
    """Register ``PenaltyKick-v0`` with Gymnasium (again is a no-op); needs Gymnasium.

    Examples
    --------
    >>> import gymnasium
    >>> register()
    >>> "PenaltyKick-v0" in gymnasium.registry
    True
    """
    if gymnasium is None:
        raise ModuleNotFoundError("registering PenaltyKick-v0 needs gymnasium: pip install \"polymimic[gym]\"")
    if ENV_ID not in gymnasium.registry:
        gymnasium.register(id=ENV_ID, entry_point="polymimic.env:PenaltyKickEnv",
                           vector_entry_point="polymimic.vector_env:PenaltyKickVectorEnv")


def _check_configuration(configuration: Any) -> None:
    if configuration == "random" and isinstance(configuration, str):
        return
    if not isinstance(configuration, (int, np.integer)) or isinstance(configuration, bool) \
            or configuration not in (1, 2):
        raise ValueError(f"configuration must be 1, 2 or \"random\", got {configuration!r}")


if gymnasium is not None:
    register()
