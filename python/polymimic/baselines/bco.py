"""``bco``: behavioural cloning from observation (Torabi et al. 2018), from tracker frames only.

BCO learns an inverse model from the imitator's own experience and labels each transition of the
demonstrations with it; here the inverse model is by default the imitator's primitive
recogniser, learned from self-observation (thesis §3.1). Each decision sample is labelled with the primitive the
recogniser names for the second of motion that starts at its frame
(:func:`polymimic.baselines.labels.window_labels`: a stop by the segmenter's stop rule, else the
best-scoring HMM). **A second too close to call (a gap) is no primitive and gives no sample.**

``labels="inverse_dynamics"`` labels each sample with the primitive an inverse dynamics model
names for the same second of motion instead: BCO's own kind of inverse model, a classifier
learned from the imitator's exploration of its field (with the ball) rather than the HMMs
(:mod:`polymimic.baselines.inverse_dynamics`; one model per imitator body, learned under seed 0
as the recogniser is learned once). It names every frame: no gaps. Tuning chooses between the
two on validation attempts (:func:`polymimic.baselines.hyperparameters.with_labellings`). Its
labels agree with the commands sent in 92 % of ten Expert demonstrations' frames and 93 % of a
small ``linear`` crowd's, where the benchmark's recogniser's window labels agree in 84 % and 76 %
(:mod:`polymimic.baselines.agreement`).
On small crowds (five demonstrations per member and configuration; each labelling tuned among
the benchmark's six candidates on 40 validation attempts, then five fits, each playing the same
50 attempts: ``python studies/which_labels_bco_should_learn_from.py --profiles linear one_good half equal
mixed_bodies --n 5 --fits 5 --budget 6 --max-samples 10000``) ``bco`` netted, per 50, on
``linear``, ``one_good``, ``half``, ``equal`` and ``mixed_bodies``, 15.6, 18.4, 14.6, 21.6 and
17.2 with the inverse model's labels against 9.6, 8.2, 18.2, 9.2 and 13.6 with the window labels
(``bc``, from the commands sent: 15.4, 16.0, 12.2, 18.4 and 14.8).

``labels="segments"`` labels each frame with its segment's primitive instead (thesis §3.2.2). On ten
Expert demonstrations, read by the full reproduction's recogniser, the window labels agree with
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
from polymimic.baselines.hyperparameters import DEFAULT, LABELS, Hyperparameters
from polymimic.baselines.inverse_dynamics import inverse_dynamics_labels, learn
from polymimic.baselines.labels import (
    IMITATOR_BODY,
    Labelled,
    check_demonstrations,
    segment_labels,
    starts_as_imitator,
    window_labels,
)
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import MAX_DECISION_SAMPLES, sample_rows, train
from polymimic.bodies import BodySpec, as_body
from polymimic.field import Demonstration
from polymimic.window_names import segmenter_settings, window_settings

__all__ = ["INVERSE_DYNAMICS_SEED", "LABELS", "check_recognizer", "fit", "labelled"]

INVERSE_DYNAMICS_SEED = 0
"""The exploration seed of the inverse dynamics model ``labels="inverse_dynamics"`` reads with:
one model per imitator body, whatever the fit's seed."""


def check_recognizer(recognizer: Any) -> PrimitiveRecognizer:
    """``recognizer`` if it is a trained :class:`polymimic.PrimitiveRecognizer`, else a ValueError
    (``None`` included: the labels named need one)."""
    if not isinstance(recognizer, PrimitiveRecognizer):
        raise ValueError(f"recognizer must be a trained polymimic.PrimitiveRecognizer (see "
                         f"polymimic.recognition.train_recognizer), got {type(recognizer).__name__}")
    return recognizer


def labelled(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer | None = None,
             segmenter: Mapping[str, Any] | None = None, labels: str = "steps",
             max_samples: int = MAX_DECISION_SAMPLES, seed: int = 0,
             imitator: BodySpec = IMITATOR_BODY) -> list[Labelled]:
    """The demonstrations labelled by the recogniser (``recognizer``): by the window (the second of motion)
    from each frame (``labels="steps"``; only the frames a fit of at most ``max_samples`` decision samples
    under ``seed`` takes are named, :func:`~polymimic.baselines.training.sample_rows`) or every
    frame by its segment (``"segments"``), gaps giving no label; or those same frames by the
    inverse dynamics model of body ``imitator`` (``"inverse_dynamics"``, which needs no
    recogniser). Observations are on the field of body ``imitator``, whose self-observation the
    recogniser should have learned from."""
    if labels not in LABELS:
        raise ValueError(f"unknown labels {labels!r}; expected one of {', '.join(map(repr, LABELS))}")
    settings, imitator = segmenter_settings(segmenter), as_body(imitator, what="imitator")
    if labels == "segments":
        return segment_labels(demonstrations, check_recognizer(recognizer), imitator=imitator, **settings)
    demos = check_demonstrations(demonstrations)
    rows = sample_rows([(d.demonstrator, len(d.frames)) for d in demos], max_samples=max_samples, seed=seed,
                       first_frames=[starts_as_imitator(d.body, imitator) for d in demos])
    if labels == "inverse_dynamics":
        return inverse_dynamics_labels(demos, learn(imitator, seed=INVERSE_DYNAMICS_SEED), frames=rows)
    return window_labels(demos, check_recognizer(recognizer), frames=rows, imitator=imitator,
                       **window_settings(settings))


def fit(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer | None = None,
        hyperparameters: Hyperparameters = DEFAULT, seed: int = 0,
        segmenter: Mapping[str, Any] | None = None, labels: str | None = None) -> ClonedPolicy:
    """A policy cloned from the recogniser's (or the inverse dynamics model's) labels of the
    demonstrations.

    Parameters
    ----------
    demonstrations : sequence of polymimic.Demonstration
    recognizer : polymimic.PrimitiveRecognizer
        Trained on the imitator's self-observation (needed unless the labels are the inverse
        dynamics model's).
    hyperparameters : Hyperparameters, default DEFAULT
    seed : int, default 0
    segmenter : mapping, optional
        The segmenter's settings (``min_frames``, ``gap_margin``, …); steps are named with
        its stop tolerances and gap margin.
    labels : {"steps", "segments", "inverse_dynamics"}, optional
        Label each frame by the recogniser's name for the second from it, by its segment, or
        by the inverse dynamics model's name for that second; by default
        ``hyperparameters.labels``.

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty, ``labels`` is unknown, the labels need a recogniser and
        none is given, or no frame is labelled (all gaps).
    """
    chosen = hyperparameters.labels if labels is None else labels
    return train("bco", labelled(demonstrations, recognizer=recognizer, segmenter=segmenter, labels=chosen, seed=seed),
                 hyperparameters=hyperparameters, seed=seed)
