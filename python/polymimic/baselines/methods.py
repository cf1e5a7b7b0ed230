"""Every baseline by name: what each learns from, prepared once, and fitted for any choice of
hyperparameters (what :func:`polymimic.baselines.tune` needs to try many cheaply).

>>> import polymimic
>>> policy = fit("bc", polymimic.record("poor", configuration=1, n=1, seed=0))
>>> policy.method
'bc'
>>> fit("bcx", [])
Traceback (most recent call last):
...
ValueError: unknown method 'bcx'; expected one of bc, bco, bco_lp, bc_best, random
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any

from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.bc import labelled as bc_labelled
from polymimic.baselines.bc_best import labelled as bc_best_labelled
from polymimic.baselines.bco import labelled as bco_labelled
from polymimic.baselines.hyperparameters import DEFAULT, LABELS, Hyperparameters
from polymimic.baselines.labels import IMITATOR_BODY, Labelled, check_demonstrations, check_weights
from polymimic.baselines.policy import ClonedPolicy, RandomPolicy
from polymimic.baselines.training import MAX_DECISION_SAMPLES, check_fit_seed, check_max_samples, train
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.field import Demonstration

__all__ = ["METHODS", "Prepared", "check_method", "fit", "fit_prepared", "prepare"]

METHODS = ("bc", "bco", "bco_lp", "bc_best", "random")
"""The benchmark's baselines (docs/results/benchmark.md) that learn from demonstrations (or
nothing); ``ppo`` learns from the environment instead (:mod:`polymimic.baselines.ppo`)."""


def check_method(method: Any) -> str:
    """``method`` if it is one of :data:`METHODS`, else a ``ValueError`` naming them."""
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; expected one of {', '.join(METHODS)}")
    return str(method)


@dataclasses.dataclass(frozen=True, eq=False)
class Prepared:
    """What a method learns from: labelled demonstrations and per-demonstrator weights, for
    fits of at most about ``max_samples`` decision samples drawn with ``seed`` (``bco`` names
    only the frames those fits take, so a fit of another seed or size needs another preparation).
    ``bco`` and ``bco_lp`` hold each labelling asked for in ``by_labels`` (``labelled`` is the
    first), and a fit takes the one its hyperparameters name."""

    method: str
    labelled: list[Labelled]
    seed: int
    max_samples: int
    weights: dict[str, float] | None = None
    imitator: Body = Body(IMITATOR_BODY)
    by_labels: dict[str, list[Labelled]] = dataclasses.field(default_factory=dict)

    def labelled_for(self, hyperparameters: Hyperparameters) -> list[Labelled]:
        """The labelled demonstrations a fit with ``hyperparameters`` learns from."""
        if not self.by_labels:
            return self.labelled
        if hyperparameters.labels not in self.by_labels:
            raise ValueError(f"{self.method} was prepared with labels {', '.join(map(repr, self.by_labels))}, not "
                             f"{hyperparameters.labels!r}: prepare it with labels=[{hyperparameters.labels!r}, …]")
        return self.by_labels[hyperparameters.labels]


def prepare(method: str, demonstrations: Sequence[Demonstration], *,
            recognizer: PrimitiveRecognizer | None = None, weights: Mapping[str, float] | None = None,
            member: str | Sequence[str] | None = None, segmenter: Mapping[str, Any] | None = None,
            max_samples: int = MAX_DECISION_SAMPLES, seed: int = 0,
            imitator: BodySpec = IMITATOR_BODY, labels: Sequence[str] = ("steps",)) -> Prepared:
    """Label the demonstrations as ``method`` does (reading them once with the recogniser, for
    ``bco``, at the frames fits of at most ``max_samples`` decision samples under ``seed`` take),
    for an imitator of body ``imitator`` (its field, its first frames; the policy drives it).

    ``recognizer`` is needed by ``bco`` and ``bco_lp`` (unless every labelling of ``labels``
    is the inverse dynamics model's), ``weights`` by ``bco_lp``, ``member`` by ``bc_best``;
    ``random`` needs nothing (and takes an empty list). ``bco`` and ``bco_lp`` are labelled in
    each way of ``labels`` (:data:`~polymimic.baselines.hyperparameters.LABELS`) the fits will
    ask for.
    """
    method = check_method(method)
    check_max_samples(max_samples)
    check_fit_seed(seed)
    imitator = as_body(imitator, what="imitator")
    if method == "random":
        return Prepared(method, [], seed, max_samples, imitator=imitator)
    demos = check_demonstrations(demonstrations)
    if method == "bc":
        return Prepared(method, bc_labelled(demos, imitator=imitator), seed, max_samples, imitator=imitator)
    if method == "bc_best":
        if member is None:
            raise ValueError("bc_best needs member: the name of the demonstrator to clone")
        return Prepared(method, bc_best_labelled(demos, member=member, imitator=imitator), seed, max_samples,
                        imitator=imitator)
    wanted = list(dict.fromkeys([labels] if isinstance(labels, str) else labels))
    if not wanted:
        raise ValueError(f"labels is empty: {method} needs at least one way to label (one of {', '.join(LABELS)})")
    if recognizer is None and any(name != "inverse_dynamics" for name in wanted):
        raise ValueError(f"{method} needs recognizer: a polymimic.PrimitiveRecognizer trained on self-observation")
    by_labels = {name: bco_labelled(demos, recognizer=recognizer, segmenter=segmenter, labels=name,
                                    max_samples=max_samples, seed=seed, imitator=imitator) for name in wanted}
    first = by_labels[wanted[0]]
    if method == "bco":
        return Prepared(method, first, seed, max_samples, imitator=imitator, by_labels=by_labels)
    if weights is None:
        raise ValueError("bco_lp needs weights: a weight in [0, 1] for every demonstrator (e.g. its final LP)")
    return Prepared(method, first, seed, max_samples, check_weights(weights, demos), imitator=imitator,
                    by_labels=by_labels)


def fit_prepared(prepared: Prepared, *, hyperparameters: Hyperparameters | None = None) -> ClonedPolicy | RandomPolicy:
    """The policy ``prepared.method`` learns with ``hyperparameters`` (default
    :data:`~polymimic.baselines.hyperparameters.DEFAULT`) from the decision samples the
    preparation's seed draws; ``random`` takes only their step length, and without them holds
    each primitive for the environment's one second."""
    if prepared.method == "random":
        return RandomPolicy(seed=prepared.seed, frames_per_action=30 if hyperparameters is None
                            else hyperparameters.frames_per_action, body=prepared.imitator)
    hyperparameters = hyperparameters or DEFAULT
    return train(prepared.method, prepared.labelled_for(hyperparameters), hyperparameters=hyperparameters,
                 seed=prepared.seed, weights=prepared.weights, max_samples=prepared.max_samples)


def fit(method: str, demonstrations: Sequence[Demonstration], *, hyperparameters: Hyperparameters | None = None,
        seed: int = 0, recognizer: PrimitiveRecognizer | None = None, weights: Mapping[str, float] | None = None,
        member: str | Sequence[str] | None = None, segmenter: Mapping[str, Any] | None = None,
        max_samples: int = MAX_DECISION_SAMPLES,
        imitator: BodySpec = IMITATOR_BODY) -> ClonedPolicy | RandomPolicy:
    """Fit baseline ``method`` (one of :data:`METHODS`) on ``demonstrations``.

    The same as the method's own ``fit`` (:func:`polymimic.baselines.bc.fit`, …), by name.
    ``hyperparameters`` default to :data:`~polymimic.baselines.hyperparameters.DEFAULT` (for
    ``random``: one primitive a second, the environment's step); ``bco`` and ``bco_lp`` label
    the demonstrations as they say (``hyperparameters.labels``). ``max_samples`` caps the
    decision samples (:data:`~polymimic.baselines.training.MAX_DECISION_SAMPLES`: the sample
    stride widens evenly to stay under it); ``seed`` draws which frames they are
    (:func:`~polymimic.baselines.training.sample_rows`) and seeds the classifier. ``imitator``
    is the body the policy drives (the Lego robot by default), on its own field.

    Raises
    ------
    ValueError
        If ``method`` is unknown, the method's input is missing or bad (see :func:`prepare`), or
        ``max_samples`` is not an integer ≥ 1.
    """
    prepared = prepare(method, demonstrations, recognizer=recognizer, weights=weights, member=member,
                       segmenter=segmenter, max_samples=max_samples, seed=seed, imitator=imitator,
                       labels=((hyperparameters or DEFAULT).labels,))
    return fit_prepared(prepared, hyperparameters=hyperparameters)
