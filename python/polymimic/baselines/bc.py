"""``bc``: behavioural cloning on the primitive equivalent of the commands each demonstrator
sent (privileged: the frames' ``command`` column, which the tracker records for evaluation).

Each decision sample is a frame's observation labelled with the primitive equivalent of the
command sent in that frame (``polymimic.field.command_primitives()``): an Expert's arc is a
forward, its spin a left or right, its brake a stop.

>>> import polymimic
>>> from polymimic.baselines import bc
>>> demos = polymimic.record("poor", configuration=1, n=2, seed=0)
>>> policy = bc.fit(demos, seed=0)
>>> policy.method, policy.frames_per_action
('bc', 15)
"""

from __future__ import annotations

from collections.abc import Sequence

from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters
from polymimic.baselines.labels import IMITATOR_BODY, Labelled, command_labels
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import train
from polymimic.bodies import BodySpec
from polymimic.field import Demonstration

__all__ = ["fit", "labelled"]


def labelled(demonstrations: Sequence[Demonstration], *, imitator: BodySpec = IMITATOR_BODY) -> list[Labelled]:
    """The demonstrations with every frame labelled by its command's primitive, seen on the
    field of body ``imitator``."""
    return command_labels(demonstrations, imitator=imitator)


def fit(demonstrations: Sequence[Demonstration], *, hyperparameters: Hyperparameters = DEFAULT,
        seed: int = 0) -> ClonedPolicy:
    """A policy cloned from the primitive equivalents of the commands sent.

    Parameters
    ----------
    demonstrations : sequence of polymimic.Demonstration
        Anyone's, any number (at least one).
    hyperparameters : Hyperparameters, default :data:`~polymimic.baselines.hyperparameters.DEFAULT`
        Classifier, features, step length, balancing (choose them with
        :func:`polymimic.baselines.tune`).
    seed : int, default 0
        Seeds the classifier.

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty.
    """
    return train("bc", labelled(demonstrations), hyperparameters=hyperparameters, seed=seed)
