"""Attempts that explore around the ball: the imitator plays, but at a decision with the ball
near, with probability ``epsilon`` it runs a random primitive of its own set instead of its
choice, so that its own attempts show pushes from states its policy never chooses (what a
crowd of poor players shows: many pushes, from many places, into both goals).

The draws follow each attempt's episode seed, so the same attempts explore the same way.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from polymimic import _native
from polymimic._arguments import probability
from polymimic.field import PRIMITIVE_SETS, Demonstration, as_frames, primitive_command
from polymimic.learning import ImitatorPolicy
from polymimic.practice.playing import play_episode

__all__ = ["EXPLORE_RATE", "explored_attempts"]

EXPLORE_RATE = 0.3
"""Practice's rate of random primitives with the ball near (``practice``'s default ``explore``)."""

_EXPLORATION_STREAM = 0x6578706C  # apart from every stream the field draws from


def explored_attempts(policy: ImitatorPolicy, *, attempts_per_configuration: int, seed: int, epsilon: float,
                      near_ball_mm: float | None = None, field_config: str | None = None) -> list[Demonstration]:
    """``attempts_per_configuration`` attempts from each configuration under ``seed`` (the
    episodes :func:`polymimic.evaluate` would play), exploring at rate ``epsilon`` whenever the
    ball is within ``near_ball_mm`` of the robot (default: four times the body's reach)."""
    epsilon = probability("epsilon", epsilon)
    body = policy.body
    near_mm = 4.0 * body.imitating_reach_mm if near_ball_mm is None else float(near_ball_mm)
    own = PRIMITIVE_SETS[body.primitive_set]
    commands = [primitive_command(p, body) for p in own[:5]]
    out = []
    for configuration, episode_seed in _native.attempt_seeds(attempts_per_configuration, seed=seed):
        rng = np.random.default_rng([episode_seed, _EXPLORATION_STREAM])

        def instead(seen: dict[str, Any], chosen: str, episode: Any, rng: np.random.Generator = rng) -> str:
            near = seen["ball"] is not None and math.dist(seen["robot"][:2], seen["ball"]) < near_mm
            if near and rng.random() < epsilon:
                index = int(rng.integers(len(own)))
                return commands[index] if index < len(commands) else str(episode.command_for(own[index]))
            return chosen

        episode = play_episode(policy.player(), body, configuration=configuration, seed=episode_seed,
                               field_config=field_config, instead=instead)
        out.append(Demonstration(frames=as_frames(episode.frames), outcome=str(episode.outcome),
                                 demonstrator="imitator", configuration=configuration, seed=episode_seed,
                                 body=body))
    return out
