"""Every baseline at its best: hyperparameters chosen on validation attempts, never on the
evaluation's, with the same number of candidates for every method (docs/results/benchmark.md).

**The seed rule.** Validation attempts are those of
``polymimic._native.attempt_seeds(n, seed=VALIDATION_SEED_BASE + validation_seed)``, and an
evaluation (:func:`polymimic.baselines.evaluate_policy`, like the imitator's) takes seeds below
``VALIDATION_SEED_BASE = 2**62``: the two seed spaces never meet. The episode seeds derived from
them are 64-bit hashes; :func:`tune` also checks that none of its episodes is one of the
``evaluation``'s (an :class:`~polymimic.Attempts`), and refuses to tune if one were.

**The effort.** ``budget`` candidates for every method (:func:`~polymimic.baselines.hyperparameters.candidates`:
the same draws for every method); each is fitted on all the demonstrations and scored by its net
goals (goals − own goals) over the validation attempts, then by goals; the first best wins.
``random`` has only its step length to choose, so it tries the distinct step lengths among the
candidates. ``bco`` chooses how its demonstrations are labelled too, by the recogniser's steps
or by the inverse dynamics model: it tries the first half of the drawn candidates with each
(:func:`~polymimic.baselines.hyperparameters.with_labellings`), as many candidates in all, and
its choice names the labelling (``labels``).

>>> import polymimic
>>> demos = polymimic.record("poor", configuration=1, n=2, seed=0)
>>> result = tune("bc", demos, budget=2, attempts_per_configuration=1)
>>> len(result.scores), result.method
(2, 'bc')
>>> sorted(result.chosen)
['balanced', 'classifier', 'feature_set', 'frames_per_action', 'params']
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.evaluation import VALIDATION_SEED_BASE, _check_seed, attempts_of, play
from polymimic.baselines.hyperparameters import Hyperparameters, with_labellings
from polymimic.baselines.hyperparameters import candidates as draw_candidates
from polymimic.baselines.labels import IMITATOR_BODY
from polymimic.baselines.methods import check_method, fit_prepared, prepare
from polymimic.baselines.policy import ClonedPolicy, Policy, RandomPolicy
from polymimic.baselines.training import MAX_DECISION_SAMPLES, check_max_samples
from polymimic.bodies import BodySpec
from polymimic.evaluation import Attempts, thesis_attempts
from polymimic.field import Demonstration

__all__ = ["LABELLING_TUNED", "Tuning", "tune", "validation_attempts", "validation_attempts_apart", "validation_rank"]

LABELLING_TUNED = ("bco", "bco_lp")
"""The methods whose tuning chooses how the demonstrations are labelled as well."""


@dataclasses.dataclass(frozen=True, eq=False)
class Tuning:
    """The outcome of :func:`tune`.

    Attributes
    ----------
    method : str
    hyperparameters : Hyperparameters
        The chosen candidate.
    chosen : dict
        The same as plain data, for a report (``random``: its step length only).
    policy : ClonedPolicy or RandomPolicy
        The chosen candidate fitted on all the demonstrations (what to evaluate).
    scores : list of dict
        Every candidate tried, in order: its hyperparameters, goals and own goals on validation.
    validation_attempts : list of (configuration, episode seed)
    """

    method: str
    hyperparameters: Hyperparameters
    chosen: dict[str, Any]
    policy: ClonedPolicy | RandomPolicy
    scores: list[dict[str, Any]]
    validation_attempts: list[tuple[int, int]]


def validation_attempts(attempts_per_configuration: int, *, validation_seed: int = 0) -> list[tuple[int, int]]:
    """The (configuration, episode seed) of every validation attempt under ``validation_seed``."""
    seed = _check_seed(validation_seed, low=0, high=2**63 - VALIDATION_SEED_BASE, what="added to 2**62")
    return attempts_of(attempts_per_configuration, seed=VALIDATION_SEED_BASE + seed)


def validation_attempts_apart(attempts_per_configuration: int, *, validation_seed: int,
                              evaluation: Attempts) -> list[tuple[int, int]]:
    """:func:`validation_attempts`, checked to share no episode seed with the ``evaluation``'s
    attempts (the seed rule above).

    Raises
    ------
    TypeError
        If ``evaluation`` is not an :class:`~polymimic.Attempts`.
    ValueError
        Naming the shared episode seeds, if any; for an ``evaluation`` from starts of its own
        or under a validation seed (from ``2**62``).
    """
    attempts = validation_attempts(attempts_per_configuration, validation_seed=validation_seed)
    evaluated = {s for _, s in _evaluation_episodes(evaluation)}
    shared = sorted(s for _, s in attempts if s in evaluated)
    if shared:
        raise ValueError(f"validation attempts share episode seeds {shared} with the evaluation; "
                         f"choose another validation_seed")
    return attempts


def _evaluation_episodes(evaluation: Attempts) -> list[tuple[int, int]]:
    """The episodes of ``evaluation``, refused where they are not an evaluation's: from starts of
    its own, or under a seed of validation's."""
    scored = thesis_attempts(evaluation, name="evaluation")
    if scored.seed >= VALIDATION_SEED_BASE:
        raise ValueError(f"evaluation's seed must be below 2**62 (seeds from 2**62 are validation's), "
                         f"got {scored.seed}")
    return scored.episodes()


def validation_rank(score: Mapping[str, Any]) -> tuple[int, int]:
    """How :func:`tune` ranks a candidate's validation ``{"goals", "own_goals"}``: by net goals,
    then goals (the first of the best is chosen)."""
    return int(score["goals"]) - int(score["own_goals"]), int(score["goals"])


PolicyT = TypeVar("PolicyT", bound=Policy)
CandidateT = TypeVar("CandidateT")


def best_on_validation(tried: Sequence[CandidateT], fit: Callable[[CandidateT], PolicyT],
                       attempts: list[tuple[int, int]], field_config: Any,
                       chosen: Callable[[CandidateT], dict[str, Any]]) -> tuple[int, PolicyT, list[dict[str, Any]]]:
    """Each candidate fitted and played on the validation ``attempts``: the index of the best
    by :func:`validation_rank` (the first of equals), its policy, and every candidate's score
    (``chosen(candidate)`` names its hyperparameters)."""
    scores: list[dict[str, Any]] = []
    best: tuple[tuple[int, int], int, PolicyT] | None = None
    for index, candidate in enumerate(tried):
        policy = fit(candidate)
        result = play(policy, attempts, field_config=field_config)
        scores.append({"hyperparameters": chosen(candidate), "goals": result.goals, "own_goals": result.own_goals})
        key = validation_rank(scores[-1])
        if best is None or key > best[0]:
            best = (key, index, policy)
    if best is None:
        raise ValueError("candidates is empty: tuning needs at least one candidate")
    return best[1], best[2], scores


def tune(method: str, demonstrations: Sequence[Demonstration], *, candidates: Sequence[Hyperparameters] | None = None,
         budget: int = 12, candidate_seed: int = 0, validation_seed: int = 0, attempts_per_configuration: int = 50,
         evaluation: Attempts = Attempts(), seed: int = 0,
         recognizer: PrimitiveRecognizer | None = None, weights: Mapping[str, float] | None = None,
         member: str | Sequence[str] | None = None, segmenter: Mapping[str, Any] | None = None,
         field_config: dict[str, Any] | str | None = None, max_samples: int = MAX_DECISION_SAMPLES,
         imitator: BodySpec = IMITATOR_BODY) -> Tuning:
    """Choose ``method``'s hyperparameters on validation attempts.

    Parameters
    ----------
    method : str
        One of :data:`polymimic.baselines.METHODS`.
    demonstrations : sequence of polymimic.Demonstration
    candidates : sequence of Hyperparameters, optional
        The candidates to try, as they are; default ``candidates(budget, seed=candidate_seed)``
        (for ``bco``, :func:`~polymimic.baselines.hyperparameters.with_labellings` of them).
    budget : int, default 12
        How many candidates (the same for every method).
    validation_seed : int, default 0
        Picks the validation attempts (see the seed rule above).
    attempts_per_configuration : int, default 50
        Validation attempts per field configuration.
    evaluation : Attempts, default Attempts()
        The evaluation the validation must not meet (checked): attempts from the thesis's
        configurations, under a seed below ``2**62``.
    seed : int, default 0
        Seeds every fit.
    recognizer, weights, member, segmenter
        What the method needs (see :func:`polymimic.baselines.fit`).
    field_config : dict or str, optional
        The field of the validation attempts.
    max_samples : int, default :data:`~polymimic.baselines.training.MAX_DECISION_SAMPLES`
        The most decision samples each fit takes.
    imitator : polymimic.Body, str or polymimic.bodies.WheeledBody, default "lego"
        The body the tuned policy drives, on its own field (validation attempts included).

    Raises
    ------
    ValueError
        On an unknown method, missing or bad input for it, an empty candidate list, a
        ``max_samples`` below 1, an ``evaluation`` from starts of its own, or a validation attempt
        that is also an evaluation attempt.
    TypeError
        If ``evaluation`` is not an :class:`~polymimic.Attempts`.
    """
    method = check_method(method)
    check_max_samples(max_samples)
    attempts = validation_attempts_apart(attempts_per_configuration, validation_seed=validation_seed,
                                         evaluation=evaluation)
    if candidates is None:
        drawn = draw_candidates(budget, seed=candidate_seed)
        tried = with_labellings(drawn) if method in LABELLING_TUNED else drawn
    else:
        tried = list(candidates)
    if not tried:
        raise ValueError("candidates is empty: tuning needs at least one candidate")
    if method == "random":
        steps = list(dict.fromkeys(h.frames_per_action for h in tried))
        tried = [next(h for h in tried if h.frames_per_action == k) for k in steps]
    prepared = prepare(method, list(demonstrations) if method != "random" else [], recognizer=recognizer,
                       weights=weights, member=member, segmenter=segmenter, max_samples=max_samples, seed=seed,
                       imitator=imitator, labels=list(dict.fromkeys(h.labels for h in tried)))
    index, policy, scores = best_on_validation(tried, lambda h: fit_prepared(prepared, hyperparameters=h), attempts,
                                               field_config, lambda h: _chosen(method, h))
    return Tuning(method=method, hyperparameters=tried[index], chosen=_chosen(method, tried[index]), policy=policy,
                  scores=scores, validation_attempts=attempts)


def _chosen(method: str, hyperparameters: Hyperparameters) -> dict[str, Any]:
    if method == "random":
        return {"frames_per_action": int(hyperparameters.frames_per_action)}
    if method in LABELLING_TUNED:
        return {**hyperparameters.to_dict(), "labels": hyperparameters.labels}
    return hyperparameters.to_dict()
