"""``bco_lp``: :mod:`~polymimic.baselines.bco` with each sample weighted by its demonstrator's
LP, a weight in [0, 1] per demonstrator (e.g. the final LPs of a learning trial,
``{name: model.lp for name, model in trial.models.items()}``): the learning preference as a
plug-in for any learner. A demonstrator weighted 0 is exactly one left out.

>>> import polymimic
>>> from polymimic import recognition
>>> from polymimic.baselines import bco_lp
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=16)
>>> demos = polymimic.record("poor", configuration=1, n=1) + polymimic.record("expert", configuration=1, n=1)
>>> bco_lp.fit(demos, recognizer=recognizer, weights={"poor": 0.2, "expert": 0.9}).method
'bco_lp'
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.bco import labelled
from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters
from polymimic.baselines.labels import check_demonstrations, check_weights
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import train
from polymimic.field import Demonstration

__all__ = ["fit"]


def fit(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer | None = None,
        weights: Mapping[str, float], hyperparameters: Hyperparameters = DEFAULT, seed: int = 0,
        segmenter: Mapping[str, Any] | None = None) -> ClonedPolicy:
    """:func:`polymimic.baselines.bco.fit` with every sample weighted by ``weights[demonstrator]``
    (labelled as ``hyperparameters.labels`` says).

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty, a demonstrator has no weight or one outside [0, 1], or
        every weight is 0.
    """
    checked = check_weights(weights, check_demonstrations(demonstrations))
    return train("bco_lp", labelled(demonstrations, recognizer=recognizer, segmenter=segmenter,
                                    labels=hyperparameters.labels, seed=seed),
                 hyperparameters=hyperparameters, seed=seed, weights=checked)
