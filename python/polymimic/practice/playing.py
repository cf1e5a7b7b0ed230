"""A player (an imitator's, a practised policy's) stepped through a fresh episode in Python,
one decision a second, as :func:`polymimic.evaluate` plays it in Rust."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from polymimic import _native

__all__ = ["play_episode"]

FRAMES_PER_DECISION = 30

Instead = Callable[[dict[str, Any], str, Any], str]
"""``instead(seen, chosen, episode)``: the command to send in place of the player's ``chosen``."""


def play_episode(player: Any, body: Any, *, configuration: int, seed: int, field_config: str | None = None,
                 instead: Instead | None = None) -> Any:
    """``player`` (reset here) through the episode of ``configuration`` and episode ``seed`` on
    ``body`` (as the field takes it), a reading a second; returns the finished episode."""
    player.reset(start=configuration, seed=seed)
    episode = _native.Episode(body, configuration=configuration, seed=seed, config=field_config)
    while not episode.finished:
        seen = episode.observation()
        ball = seen["ball"] if seen["ball"] is not None else (math.nan, math.nan)
        chosen = player.act((seen["t_s"], *seen["robot"], *ball))
        if instead is not None:
            chosen = instead(seen, chosen, episode)
        episode.run([chosen] * FRAMES_PER_DECISION)
    return episode
