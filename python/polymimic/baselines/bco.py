"""``bco``: behavioural cloning from observation (Torabi et al. 2018), from tracker frames only.

BCO learns an inverse model from the imitator's own experience and labels the demonstrations
with it; here the inverse model is the imitator's primitive recogniser, learned from
self-observation (SPEC §2). Each demonstration is segmented by ``recognizer.segment_many``
(SPEC §3: segments labelled F/B/L/R/S or gap, with first and last frame), and each decision
sample is labelled with the primitive of the segment covering its frame. **Gaps are not
primitives: a frame in a gap segment (or after the last segment) gives no sample.**

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
from polymimic.baselines.labels import Labelled, segment_labels
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import train
from polymimic.field import Demonstration

__all__ = ["check_recognizer", "fit", "labelled"]


def check_recognizer(recognizer: Any) -> PrimitiveRecognizer:
    """``recognizer`` if it is a trained :class:`polymimic.PrimitiveRecognizer`, else a ValueError."""
    if not isinstance(recognizer, PrimitiveRecognizer):
        raise ValueError(f"recognizer must be a trained polymimic.PrimitiveRecognizer (see "
                         f"polymimic.recognition.train_recognizer), got {type(recognizer).__name__}")
    return recognizer


def labelled(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer,
             segmenter: Mapping[str, Any] | None = None) -> list[Labelled]:
    """The demonstrations with every frame labelled by its segment's primitive (gaps: none)."""
    return segment_labels(demonstrations, check_recognizer(recognizer), **dict(segmenter or {}))


def fit(demonstrations: Sequence[Demonstration], *, recognizer: PrimitiveRecognizer,
        hyperparameters: Hyperparameters = DEFAULT, seed: int = 0,
        segmenter: Mapping[str, Any] | None = None) -> ClonedPolicy:
    """A policy cloned from the recogniser's labels of the demonstrations.

    Parameters
    ----------
    demonstrations : sequence of polymimic.Demonstration
    recognizer : polymimic.PrimitiveRecognizer
        Trained on the imitator's self-observation.
    hyperparameters : Hyperparameters, default DEFAULT
    seed : int, default 0
    segmenter : mapping, optional
        The segmenter's settings (``min_frames``, ``gap_margin``, …).

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty, or no frame is labelled (all gaps).
    """
    return train("bco", labelled(demonstrations, recognizer=recognizer, segmenter=segmenter),
                 hyperparameters=hyperparameters, seed=seed)
