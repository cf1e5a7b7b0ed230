"""``bco``: behavioural cloning from observation (Torabi et al. 2018), from tracker frames only.

BCO learns an inverse model from the imitator's own experience and labels each step of the
demonstrations with it; here the inverse model is the imitator's primitive recogniser, learned
from self-observation (SPEC §2). Each decision sample is labelled with the primitive the
recogniser names for the second of motion that starts at its frame
(:func:`polymimic.baselines.labels.step_labels`: a stop by the segmenter's stop rule, else the
best-scoring HMM). **A second too close to call (a gap) is no primitive and gives no sample.**

``labels="segments"`` labels each frame with its segment's primitive instead (SPEC §3). On ten
Expert demonstrations, read by the full reproduction's recogniser, the step labels agree with
the commands sent in 87 % of frames and the segment labels in 70 %: a segment grows until its
motion exceeds any one primitive's, so the Expert's segments are 98 % forward while it turns in
31 % of its frames.

>>> import polymimic
>>> from polymimic import recognition
>>> from polymimic.baselines import bco
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=16)
>>> policy = bco.fit(polymimic.record("poor", configuration=1, n=2, seed=0), recognizer=recognizer)
>>> policy.method
'bco'
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters
from polymimic.baselines.labels import (
    IMITATOR_BODY,
    Labelled,
    check_demonstrations,
    segment_labels,
    starts_as_imitator,
    step_labels,
)
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import MAX_DECISION_SAMPLES, sample_rows, train
from polymimic.bodies import WheeledBody, body_name
from polymimic.field import Demonstration
from polymimic.step_names import LABELS, segmenter_settings, step_settings

__all__ = ["LABELS", "check_recognizer", "fit", "labelled"]



def check_recognizer(recognizer: Any) -> PrimitiveRecognizer:
    """``recognizer`` if it is a trained :class:`polymimic.PrimitiveRecognizer`, else a ValueError."""
    if not isinstance(recognizer, PrimitiveRecognizer):
        raise ValueError(f"recognizer must be a trained polymimic.PrimitiveRecognizer (see "
                         f"polymimic.recognition.train_recognizer), got {type(recognizer).__name__}")
    return recognizer


def labelled(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer,
             segmenter: Mapping[str, Any] | None = None, labels: str = "steps",
             max_samples: int = MAX_DECISION_SAMPLES, seed: int = 0,
             imitator: str | WheeledBody = IMITATOR_BODY) -> list[Labelled]:
    """The demonstrations labelled by the recogniser: by the step from each frame
    (``labels="steps"``; only the frames a fit of at most ``max_samples`` decision samples
    under ``seed`` takes are named, :func:`~polymimic.baselines.training.sample_rows`) or every
    frame by its segment (``"segments"``); gaps give no label. Observations are on the field of
    body ``imitator``, whose self-observation the recogniser should have learned from."""
    recognizer = check_recognizer(recognizer)
    settings = segmenter_settings(segmenter)
    if labels == "steps":
        demos = check_demonstrations(demonstrations)
        rows = sample_rows([(d.demonstrator, len(d.frames)) for d in demos], max_samples=max_samples, seed=seed,
                           first_frames=[starts_as_imitator(d.body, body_name(imitator)) for d in demos])
        return step_labels(demos, recognizer, frames=rows, imitator=imitator, **step_settings(settings))
    if labels == "segments":
        return segment_labels(demonstrations, recognizer, imitator=imitator, **settings)
    raise ValueError(f"unknown labels {labels!r}; expected one of {', '.join(map(repr, LABELS))}")


def fit(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer,
        hyperparameters: Hyperparameters = DEFAULT, seed: int = 0,
        segmenter: Mapping[str, Any] | None = None, labels: str = "steps") -> ClonedPolicy:
    """A policy cloned from the recogniser's labels of the demonstrations.

    Parameters
    ----------
    demonstrations : sequence of polymimic.Demonstration
    recognizer : polymimic.PrimitiveRecognizer
        Trained on the imitator's self-observation.
    hyperparameters : Hyperparameters, default DEFAULT
    seed : int, default 0
    segmenter : mapping, optional
        The segmenter's settings (``min_frames``, ``gap_margin``, …); steps are named with
        its stop tolerances and gap margin.
    labels : {"steps", "segments"}, default "steps"
        Label each frame by the recogniser's name for the second from it, or by its segment.

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty, ``labels`` is unknown, or no frame is labelled (all gaps).
    """
    return train("bco", labelled(demonstrations, recognizer=recognizer, segmenter=segmenter, labels=labels, seed=seed),
                 hyperparameters=hyperparameters, seed=seed)
