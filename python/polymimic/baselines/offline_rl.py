"""``offline_rl`` (optional): d3rlpy's discrete CQL or BCQ on the crowd's demonstrations, a peer
that knows the objective as polymimic's imitator does.

The cloners (``bc``, ``bco``, ``bc_best``) learn everything from the data; the imitator knows
what a goal is. Offline RL is the field's answer to mixed-quality data with known outcomes: it
learns the value of each action from the outcomes the data shows, and keeps to the actions the
data takes. Here it learns from the tracker frames alone, as ``bco`` does: the same decision
samples, labelled as ``bco`` labels them (never the commands sent), rewarded by the outcome
read off the frames (+1 a goal, −1 an own goal: :mod:`polymimic.baselines.offline_data`). The
network sees the ``feature_set`` features scaled as ``ppo`` scales them
(:func:`polymimic.baselines.ppo.scaled`) and the policy plays the action of highest value.

:func:`tune` chooses among :func:`~polymimic.baselines.offline_hyperparameters.candidates` (the
algorithm among them) on validation attempts, under the seed rule and with the effort of the
cloning baselines (:mod:`polymimic.baselines.tuning`). d3rlpy and torch are needed to fit and to
load a policy (``pip install "polymimic[offline]"``), not to import this module.

>>> from polymimic.baselines import offline_rl
>>> offline_rl.available() in (True, False)
True
"""

from __future__ import annotations

import contextlib
import dataclasses
import importlib.util
import logging
import os
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.bco import labelled as bco_labelled
from polymimic.baselines.features import check_observations
from polymimic.baselines.labels import IMITATOR_BODY, Labelled, check_demonstrations
from polymimic.baselines.offline_data import Transitions, transitions
from polymimic.baselines.offline_hyperparameters import (
    BATCH_SIZE,
    DEFAULT_CQL,
    GAMMA,
    RETURN_STEPS,
    TARGET_UPDATE_INTERVAL,
    OfflineHyperparameters,
)
from polymimic.baselines.offline_hyperparameters import candidates as draw_candidates
from polymimic.baselines.policy_file import write_policy_file
from polymimic.baselines.ppo import scaled
from polymimic.baselines.training import MAX_DECISION_SAMPLES, check_fit_seed, check_max_samples
from polymimic.baselines.tuning import best_on_validation, validation_attempts_apart
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.evaluation import Attempts
from polymimic.field import PRIMITIVES, Demonstration

__all__ = ["OfflineRLPolicy", "OfflineTuning", "Prepared", "available", "fit", "fit_prepared", "prepare", "tune"]


def available() -> bool:
    """Whether d3rlpy (and so torch) is installed."""
    return importlib.util.find_spec("d3rlpy") is not None


def _require() -> None:
    if not available():
        raise ModuleNotFoundError("the offline_rl baseline needs d3rlpy: pip install \"polymimic[offline]\"")


class OfflineRLPolicy:
    """A d3rlpy Q-learning algorithm fitted offline, playing the action of highest value for
    each observation of its ``body``'s field (the imitator's :class:`polymimic.Body`)."""

    def __init__(self, algo: Any, hyperparameters: OfflineHyperparameters, *, body: BodySpec = IMITATOR_BODY) -> None:
        self.method = "offline_rl"
        self.algo = algo
        self.hyperparameters = hyperparameters
        self.body = as_body(body)

    @property
    def frames_per_action(self) -> int:
        """Tracker frames each chosen primitive is held for."""
        return int(self.hyperparameters.frames_per_action)

    def predict(self, observations: np.ndarray) -> np.ndarray:
        """The primitive of highest value (0–4) for each row of an ``(n, 5)`` observation batch."""
        obs = check_observations(observations)
        if len(obs) == 0:
            return np.empty(0, dtype=np.int64)
        return np.asarray(self.algo.predict(scaled(obs, self.hyperparameters.feature_set, self.body)),
                          dtype=np.int64).reshape(len(obs))

    def values(self, observations: np.ndarray) -> np.ndarray:
        """The ``(n, 5)`` action values the network gives each row of an observation batch."""
        obs = scaled(check_observations(observations), self.hyperparameters.feature_set, self.body)
        actions = np.arange(len(PRIMITIVES))
        return np.column_stack([np.asarray(self.algo.predict_value(obs, np.full(len(obs), a))) for a in actions])

    def reset(self) -> None:
        """Nothing to restart: the policy acts deterministically."""

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes the policy (its network, body and hyperparameters) to ``path``;
        :func:`polymimic.baselines.load_policy` reads it back (with d3rlpy installed)."""
        write_policy_file(path, {"kind": "offline_rl", "method": self.method, "body": self.body.name,
                                 "hyperparameters": self.hyperparameters.to_dict()}, self)

    def __getstate__(self) -> dict[str, Any]:
        from d3rlpy.base import dump_learnable  # type: ignore[import-not-found, import-untyped, unused-ignore]

        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "algo.d3")
            dump_learnable(self.algo, path)
            with open(path, "rb") as file:
                return {**self.__dict__, "algo": file.read()}

    def __setstate__(self, state: dict[str, Any]) -> None:
        from d3rlpy.base import load_learnable  # type: ignore[import-not-found, import-untyped, unused-ignore]

        state = dict(state)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "algo.d3")
            with open(path, "wb") as file:
                file.write(state["algo"])
            state["algo"] = load_learnable(path, device="cpu:0")
        self.__dict__.update(state)

    def __repr__(self) -> str:
        body = "" if self.body == Body(IMITATOR_BODY) else f", body={self.body.name!r}"
        return f"OfflineRLPolicy({self.hyperparameters}{body})"


@dataclasses.dataclass(frozen=True, eq=False)
class Prepared:
    """The demonstrations labelled in each way the fits will ask for (``by_labels``: labelling →
    one :class:`~polymimic.baselines.labels.Labelled` per demonstration), at the frames fits of
    at most ``max_samples`` decision samples under ``seed`` take, for an imitator of body
    ``imitator``."""

    demonstrations: list[Demonstration]
    by_labels: dict[str, list[Labelled]]
    seed: int
    max_samples: int
    imitator: Body

    def transitions_for(self, hyperparameters: OfflineHyperparameters) -> Transitions:
        """The episodes a fit with ``hyperparameters`` learns from."""
        if hyperparameters.labels not in self.by_labels:
            raise ValueError(f"offline_rl was prepared with labels {', '.join(map(repr, self.by_labels))}, not "
                             f"{hyperparameters.labels!r}: prepare it with labels=[{hyperparameters.labels!r}, …]")
        return transitions(self.demonstrations, self.by_labels[hyperparameters.labels])


def prepare(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer | None = None,
            segmenter: Mapping[str, Any] | None = None, labels: Sequence[str] = ("inverse_dynamics",),
            max_samples: int = MAX_DECISION_SAMPLES, seed: int = 0,
            imitator: BodySpec = IMITATOR_BODY) -> Prepared:
    """Label the demonstrations as ``bco`` does, in each way of ``labels``, once
    (:func:`polymimic.baselines.bco.labelled`: the same frames, the same labels); the
    ``"steps"`` labelling needs ``recognizer``."""
    demos = check_demonstrations(demonstrations)
    check_max_samples(max_samples)
    check_fit_seed(seed)
    body = as_body(imitator, what="imitator")
    wanted = list(dict.fromkeys([labels] if isinstance(labels, str) else labels))
    if not wanted:
        raise ValueError("labels is empty: offline_rl needs at least one way to label (steps or inverse_dynamics)")
    by_labels = {name: bco_labelled(demos, recognizer=recognizer, segmenter=segmenter, labels=name,
                                    max_samples=max_samples, seed=seed, imitator=imitator) for name in wanted}
    return Prepared(demos, by_labels, seed, max_samples, body)


def fit_prepared(prepared: Prepared, *, hyperparameters: OfflineHyperparameters = DEFAULT_CQL) -> OfflineRLPolicy:
    """The policy d3rlpy learns with ``hyperparameters`` from the prepared episodes, seeded
    with the preparation's seed (d3rlpy seeds Python's, numpy's and torch's global generators)."""
    _require()
    import d3rlpy  # type: ignore[import-not-found, import-untyped, unused-ignore]

    data = prepared.transitions_for(hyperparameters)
    with _quiet():
        dataset = d3rlpy.dataset.MDPDataset(
            scaled(data.observations, hyperparameters.feature_set, prepared.imitator), data.actions,
            data.rewards.astype(np.float32), data.terminals, data.timeouts,
            action_space=d3rlpy.ActionSpace.DISCRETE, action_size=len(PRIMITIVES),
            transition_picker=d3rlpy.dataset.MultiStepTransitionPicker(RETURN_STEPS, GAMMA))
    d3rlpy.seed(prepared.seed)
    common = {"learning_rate": hyperparameters.learning_rate, "batch_size": BATCH_SIZE, "gamma": GAMMA,
              "target_update_interval": TARGET_UPDATE_INTERVAL,
              "encoder_factory": d3rlpy.models.VectorEncoderFactory(list(hyperparameters.hidden_layers))}
    if hyperparameters.algorithm == "discrete_cql":
        config: Any = d3rlpy.algos.DiscreteCQLConfig(alpha=hyperparameters.conservatism, **common)
    else:
        config = d3rlpy.algos.DiscreteBCQConfig(action_flexibility=hyperparameters.conservatism, **common)
    algo = config.create(device="cpu:0")
    with _quiet():
        algo.fit(dataset, n_steps=hyperparameters.gradient_steps, n_steps_per_epoch=hyperparameters.gradient_steps,
                 show_progress=False, save_interval=hyperparameters.gradient_steps + 1,
                 logger_adapter=d3rlpy.logging.NoopAdapterFactory())
    return OfflineRLPolicy(algo, hyperparameters, body=prepared.imitator)


@contextlib.contextmanager
def _quiet() -> Iterator[None]:
    """d3rlpy's structlog messages below warnings (the dataset's signatures, each epoch's
    metrics) held back while it works, structlog's configuration restored after."""
    import structlog  # type: ignore[import-not-found, import-untyped, unused-ignore]

    saved = structlog.get_config()
    structlog.configure(wrapper_class=structlog.make_filtering_bound_logger(logging.WARNING))
    try:
        yield
    finally:
        structlog.configure(**saved)


def fit(demonstrations: Sequence[Demonstration], *, hyperparameters: OfflineHyperparameters = DEFAULT_CQL,
        seed: int = 0, recognizer: PrimitiveRecognizer | None = None, segmenter: Mapping[str, Any] | None = None,
        max_samples: int = MAX_DECISION_SAMPLES, imitator: BodySpec = IMITATOR_BODY) -> OfflineRLPolicy:
    """d3rlpy's discrete CQL or BCQ (``hyperparameters.algorithm``) fitted on ``demonstrations``.

    Parameters
    ----------
    demonstrations : sequence of polymimic.Demonstration
    hyperparameters : OfflineHyperparameters, default DEFAULT_CQL
    seed : int, default 0
        Draws the decision samples' frames (as ``bco``'s) and seeds the fit.
    recognizer : polymimic.PrimitiveRecognizer, optional
        Needed by ``labels="steps"``.
    segmenter : mapping, optional
        The segmenter's settings the steps are named with.
    max_samples : int, default MAX_DECISION_SAMPLES
    imitator : str or polymimic.bodies.WheeledBody, default "lego"

    Raises
    ------
    ModuleNotFoundError
        If d3rlpy is not installed.
    ValueError
        If ``demonstrations`` is empty, the labels need a recogniser and none is given, or no
        demonstration has a labelled sample.
    """
    _require()
    prepared = prepare(demonstrations, recognizer=recognizer, segmenter=segmenter, labels=(hyperparameters.labels,),
                       max_samples=max_samples, seed=seed, imitator=imitator)
    return fit_prepared(prepared, hyperparameters=hyperparameters)


@dataclasses.dataclass(frozen=True, eq=False)
class OfflineTuning:
    """The outcome of :func:`tune`, as :class:`polymimic.baselines.Tuning` holds a cloner's."""

    method: str
    hyperparameters: OfflineHyperparameters
    chosen: dict[str, Any]
    policy: OfflineRLPolicy
    scores: list[dict[str, Any]]
    validation_attempts: list[tuple[int, int]]


def tune(demonstrations: Sequence[Demonstration], *, candidates: Sequence[OfflineHyperparameters] | None = None,
         budget: int = 12, candidate_seed: int = 0, validation_seed: int = 0, attempts_per_configuration: int = 50,
         evaluation: Attempts = Attempts(), seed: int = 0,
         recognizer: PrimitiveRecognizer | None = None, segmenter: Mapping[str, Any] | None = None,
         field_config: dict[str, Any] | str | None = None, max_samples: int = MAX_DECISION_SAMPLES,
         imitator: BodySpec = IMITATOR_BODY) -> OfflineTuning:
    """Choose ``offline_rl``'s hyperparameters on validation attempts, as
    :func:`polymimic.baselines.tune` chooses a cloner's: ``budget`` candidates (default
    :func:`~polymimic.baselines.offline_hyperparameters.candidates` of ``candidate_seed``), each
    fitted under ``seed`` and ranked by its net goals, then goals, on the validation attempts
    (which must not meet the ``evaluation``'s, an :class:`~polymimic.Attempts`); the first best
    wins.

    Raises
    ------
    ModuleNotFoundError
        If d3rlpy is not installed.
    ValueError
        On bad input (see :func:`fit`), an empty candidate list, an ``evaluation`` from starts of
        its own, or a validation attempt that is also an evaluation attempt.
    TypeError
        If ``evaluation`` is not an :class:`~polymimic.Attempts`.
    """
    _require()
    attempts = validation_attempts_apart(attempts_per_configuration, validation_seed=validation_seed,
                                         evaluation=evaluation)
    tried = draw_candidates(budget, seed=candidate_seed) if candidates is None else list(candidates)
    if not tried:
        raise ValueError("candidates is empty: tuning needs at least one candidate")
    prepared = prepare(demonstrations, recognizer=recognizer, segmenter=segmenter,
                       labels=[h.labels for h in tried], max_samples=max_samples, seed=seed, imitator=imitator)
    index, policy, scores = best_on_validation(tried, lambda h: fit_prepared(prepared, hyperparameters=h), attempts,
                                               field_config, lambda h: h.to_dict())
    return OfflineTuning(method="offline_rl", hyperparameters=tried[index], chosen=tried[index].to_dict(),
                         policy=policy, scores=scores, validation_attempts=attempts)
