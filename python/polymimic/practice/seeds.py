"""Where practice plays: attempts from a seed space of their own.

Evaluation seeds lie in ``[0, 2**62)`` and validation seeds in ``[2**62, 2**63)``
(:mod:`polymimic.baselines.evaluation`); practice rounds play from ``[2**63, 2**64)``, so the
attempts an imitator practises on are never the ones it is scored or tuned on. The episode seeds
derived from them are checked against the evaluation's all the same, as tuning checks its own.

>>> round_seed(0, 0) == PRACTICE_SEED_BASE, round_seed(1, 2) - round_seed(1, 0)
(True, 2)
"""

from __future__ import annotations

import functools
from collections.abc import Iterable

from polymimic.evaluation import Attempts, thesis_attempts

__all__ = ["MAX_ROUNDS", "PRACTICE_SEED_BASE", "check_apart", "round_seed"]

PRACTICE_SEED_BASE = 2**63
MAX_ROUNDS = 2**24
"""Rounds one practice seed has room for: far more than any budget of steps asks."""


def round_seed(seed: int, round_index: int) -> int:
    """The seed round ``round_index`` of practice under ``seed`` plays its attempts from."""
    return PRACTICE_SEED_BASE + (seed * MAX_ROUNDS + round_index) % PRACTICE_SEED_BASE


def check_apart(practice_episodes: Iterable[tuple[int, int]], *, evaluation: Attempts) -> None:
    """A ``ValueError`` if any practice attempt's (configuration, episode seed) is one of the
    ``evaluation``'s attempts (from the thesis's configurations): an imitator must never practise
    on what scores it."""
    scored = _scored(thesis_attempts(evaluation, name="evaluation"))
    met = [episode for episode in practice_episodes if episode in scored]
    if met:
        configuration, seed = met[0]
        raise ValueError(f"practice would play the evaluation's attempt (configuration {configuration}, episode seed "
                         f"{seed}) under the evaluation's seed {evaluation.seed}: choose another practice seed")


@functools.lru_cache(maxsize=8)
def _scored(evaluation: Attempts) -> frozenset[tuple[int, int]]:
    """The evaluation's (configuration, episode seed) pairs, made once for every round that checks them."""
    return frozenset(evaluation.episodes())
