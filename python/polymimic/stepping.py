"""A trained imitator in any loop that speaks stable-baselines3's ``predict``.

:meth:`polymimic.ImitatorPolicy.predict` answers ``PenaltyKick-v0``'s observations (one, or a
batch from the vector env) with the primitives the imitator would run, as a stable-baselines3
policy does, so ``evaluate_policy`` or a plain Gymnasium loop runs it unchanged. Each
sub-environment gets an :class:`polymimic.ImitatorPlayer` of its own, which keeps what the
control keeps between decisions; every call is one decision (the env holds each action for a
second, as the imitator holds a primitive).

The env's observations are float32, the field's own readings float64: a decision near a tie
can flip on the rounding, so an episode played through ``predict`` may part from
:func:`polymimic.evaluate`'s from the same episode seed (measured in the docs' guide to
stepping the imitator); it never differs systematically.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, Protocol, TypeVar

import numpy as np
import numpy.typing as npt

__all__ = ["predict"]

_WIDTH = 5  # robot x, y, θ, ball x, y


class Deciding(Protocol):
    """A player that starts an episode and decides once per call (an imitator's, a practised
    policy's)."""

    def reset(self, episode: Mapping[str, Any] | None = None, *, start: int | Mapping[str, Any] | None = None,
              seed: int | None = None) -> None: ...

    def decide(self, robot_x_mm: float, robot_y_mm: float, robot_theta_rad: float, ball_x_mm: float,
               ball_y_mm: float) -> int: ...


P = TypeVar("P", bound=Deciding)
P_co = TypeVar("P_co", bound=Deciding, covariant=True)


class MakesPlayers(Protocol[P_co]):
    """A policy that makes players of itself."""

    def player(self) -> P_co: ...


def predict(policy: MakesPlayers[P], players: list[P], observation: npt.ArrayLike,
            state: Sequence[P] | None = None, episode_start: npt.ArrayLike | None = None,
            ) -> tuple[np.ndarray, tuple[P, ...]]:
    """The primitives ``policy`` runs next from ``observation`` (``(5,)`` or ``(n, 5)``: robot x,
    y mm, heading rad, ball x, y mm; NaN where the ball is not seen), one per sub-environment,
    and the players that decided them (stable-baselines3's ``state``: pass it back).

    ``players`` are the policy's own, used when ``state`` is None and grown to the batch. A
    player starts a new episode where ``episode_start`` is true and where it is new, from the
    observation itself (the robot's pose, the ball); the thesis control's draws then follow
    episode seed 0 (a :meth:`~polymimic.ImitatorPolicy.player` reset with the episode's seed
    plays it exactly).
    """
    array = np.asarray(observation, dtype=np.float64)
    single = array.ndim == 1
    batch = array.reshape(1, -1) if single else array
    if batch.ndim != 2 or batch.shape[1] != _WIDTH:
        raise ValueError(f"observation must be PenaltyKick-v0's: shape ({_WIDTH},) or (n, {_WIDTH}), got shape "
                         f"{np.shape(observation)}")
    n = len(batch)
    ours = list(state) if state is not None else players
    if len(ours) != n and state is not None:
        raise ValueError(f"state holds {len(ours)} players for a batch of {n} observations; pass back the state "
                         f"predict returned for this env")
    fresh = [False] * len(ours) + [True] * (n - len(ours))
    ours.extend(policy.player() for _ in range(n - len(ours)))
    del ours[n:]
    starting = _starts(episode_start, n)
    actions = np.empty(n, dtype=np.int64)
    for i, (row, player) in enumerate(zip(batch, ours)):
        x, y, theta, ball_x, ball_y = (float(v) for v in row)
        if starting[i] or fresh[i]:
            player.reset(start={"robot": (x, y, theta), "ball": (ball_x, ball_y)}, seed=0)
        actions[i] = player.decide(x, y, theta, ball_x, ball_y)
    return (actions[0] if single else actions), tuple(ours)


def _starts(episode_start: Any, n: int) -> list[bool]:
    if episode_start is None:
        return [False] * n
    flags = np.asarray(episode_start).reshape(-1)
    if len(flags) != n:
        raise ValueError(f"episode_start must hold one flag per observation ({n}), got {len(flags)}")
    return [bool(f) for f in flags]
