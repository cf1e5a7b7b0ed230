"""The thesis's recognition figures, re-measured on the simulated field (thesis §4.2, §4.3).

Each function takes plain data (self-observation sequences, demonstrations, a trained
recogniser) and returns plain data: dictionaries keyed by primitive or demonstrator, ready for
a report.

>>> import polymimic
>>> train = polymimic.self_observation(60, seed=1)
>>> test = polymimic.self_observation(30, seed=2)
>>> recognizer = train_recognizer(train, codebook_size=64)
>>> sorted(accuracy_table(recognizer, test))
['backward', 'forward', 'left', 'right']
"""

from __future__ import annotations

import collections
import time
from collections.abc import Sequence
from typing import Any, Literal, TypedDict

import numpy as np

from polymimic._native import PrimitiveRecognizer, thesis_table_3_1
from polymimic.field import Demonstration, PrimitiveSequence, primitive_set_of, primitives_sent

MOVING = ("forward", "backward", "left", "right")
"""The wheeled set's moving primitives; a recogniser's own are its ``moving``."""

Representation = Literal["thesis", "egocentric"]
Emissions = Literal["discrete", "gaussian"]

CLASSIFIABLE_SHARE = 0.75
"""A segment is classifiable when this share of its frames carry one equivalent primitive."""


def train_recognizer(sequences: Sequence[PrimitiveSequence], *, n_states: int = 1, codebook_size: int = 512,
                     representation: Representation = "thesis", emissions: Emissions = "discrete",
                     seed: int = 0) -> PrimitiveRecognizer:
    """A :class:`~polymimic.PrimitiveRecognizer` trained on self-observation sequences, with an
    HMM per moving primitive of their set (:func:`primitive_set_of`).

    >>> import polymimic
    >>> own = polymimic.self_observation(20, seed=1, body="humanoid", primitives="own")
    >>> recognizer = train_recognizer(own, codebook_size=64)
    >>> recognizer.primitive_set, recognizer.moving
    ('humanoid', ['forward', 'backward', 'left', 'right', 'sidestep_left', 'sidestep_right', 'kick'])
    """
    return PrimitiveRecognizer.train([s.frames for s in sequences], [s.primitive for s in sequences],
                                     n_states=n_states, codebook_size=codebook_size,
                                     representation=representation, emissions=emissions, seed=seed,
                                     primitives=primitive_set_of(sequences))


def primitive_table(recognizer: PrimitiveRecognizer) -> dict[str, dict[str, float]]:
    """Table 3.1 as measured on the recogniser's training set, with the thesis's beside it.

    Rows are primitives; columns ``distance_mean_mm``, ``distance_sd_mm``,
    ``rotation_mean_deg``, ``rotation_sd_deg`` and the same prefixed ``thesis_``.
    """
    ours, thesis = recognizer.motion_stats(), thesis_table_3_1()
    table = {}
    for primitive, row in ours.items():
        table[primitive] = dict(row)
        for key, value in thesis.get(primitive, {}).items():
            table[primitive][f"thesis_{key}"] = value
    return table


def _scores(recognizer: PrimitiveRecognizer, test: Sequence[PrimitiveSequence]) -> tuple[np.ndarray, np.ndarray]:
    own = recognizer.moving
    moving = [s for s in test if s.primitive in own]
    if not moving:
        raise ValueError(f"test holds no moving primitive of the recogniser's ({', '.join(own)})")
    truth = np.array([s.primitive for s in moving])
    return recognizer.log_likelihoods_many([s.frames for s in moving]), truth


def log_likelihood_table(recognizer: PrimitiveRecognizer,
                         test: Sequence[PrimitiveSequence]) -> dict[str, dict[str, float]]:
    """Fig 4.5: mean log-likelihood of each HMM (outer key) on each primitive's test set
    (inner key). Sequences a model cannot have produced (−inf) are left out of its mean."""
    scores, truth = _scores(recognizer, test)
    moving = recognizer.moving
    table: dict[str, dict[str, float]] = {}
    for column, model in enumerate(moving):
        table[model] = {}
        for primitive in moving:
            values = scores[truth == primitive, column]
            finite = values[np.isfinite(values)]
            table[model][primitive] = float(finite.mean()) if finite.size else float("-inf")
    return table


def confusion_matrix(recognizer: PrimitiveRecognizer, test: Sequence[PrimitiveSequence]) -> np.ndarray:
    """Counts of test sequences of each primitive (row) named as each primitive (column), in
    the order of the recogniser's ``moving``."""
    scores, truth = _scores(recognizer, test)
    named = scores.argmax(axis=1)
    moving = recognizer.moving
    matrix = np.zeros((len(moving), len(moving)), dtype=int)
    for row, primitive in enumerate(moving):
        matrix[row] = np.bincount(named[truth == primitive], minlength=len(moving))
    return matrix


def accuracy_table(recognizer: PrimitiveRecognizer, test: Sequence[PrimitiveSequence]) -> dict[str, float]:
    """Table 4.3: the share of each moving primitive's held-out sequences named correctly."""
    matrix = confusion_matrix(recognizer, test)
    totals = matrix.sum(axis=1)
    return {p: float(matrix[i, i] / totals[i]) if totals[i] else float("nan")
            for i, p in enumerate(recognizer.moving)}


def state_sweep(train: Sequence[PrimitiveSequence], test: Sequence[PrimitiveSequence], *,
                states: Sequence[int] = (1, 5, 10, 15, 20), codebook_size: int = 512,
                seed: int = 0) -> list[dict[str, Any]]:
    """§3.1.4's sweep: for each number of states, the accuracy per primitive, the training time
    (s, codebooks included) and the time to score the test set (s)."""
    rows = []
    for n_states in states:
        started = time.perf_counter()
        recognizer = train_recognizer(train, n_states=n_states, codebook_size=codebook_size, seed=seed)
        trained = time.perf_counter()
        accuracy = accuracy_table(recognizer, test)
        rows.append({"n_states": n_states, "accuracy": accuracy, "train_s": trained - started,
                     "score_s": time.perf_counter() - trained})
    return rows


def segment_table(recognizer: PrimitiveRecognizer, demonstrations: Sequence[Demonstration],
                  **segmenter: Any) -> dict[str, dict[str, float]]:
    """Table 4.5: per demonstrator, ``command_match`` (share of classifiable segments whose
    label is the equivalent primitive of the commands sent) and ``gaps`` (share of all
    segments that are gaps), with the counts behind them."""
    tally: dict[str, collections.Counter[str]] = collections.defaultdict(collections.Counter)
    segmented = recognizer.segment_many([d.frames for d in demonstrations], **segmenter)
    for demo, segments in zip(demonstrations, segmented):
        sent = primitives_sent(demo)
        counts = tally[demo.demonstrator]
        for label, first, last in zip(segments["label"], segments["first_frame"], segments["last_frame"]):
            counts["segments"] += 1
            counts["gaps"] += label == "gap"
            primitive, frames = collections.Counter(sent[first:last + 1]).most_common(1)[0]
            if frames >= CLASSIFIABLE_SHARE * (last - first + 1):
                counts["classifiable"] += 1
                counts["matched"] += label == primitive
    return {
        who: {
            "command_match": c["matched"] / c["classifiable"] if c["classifiable"] else float("nan"),
            "gaps": c["gaps"] / c["segments"] if c["segments"] else float("nan"),
            "segments": c["segments"],
            "classifiable": c["classifiable"],
        }
        for who, c in tally.items()
    }


class Variant(TypedDict):
    """One way of recognising primitives: how frames are represented, how symbols are emitted."""

    name: str
    representation: Representation
    emissions: Emissions


VARIANTS: tuple[Variant, ...] = (
    {"name": "thesis (positional/rotational, discrete)", "representation": "thesis", "emissions": "discrete"},
    {"name": "egocentric, discrete", "representation": "egocentric", "emissions": "discrete"},
    {"name": "thesis, Gaussian", "representation": "thesis", "emissions": "gaussian"},
    {"name": "egocentric, Gaussian", "representation": "egocentric", "emissions": "gaussian"},
)
"""The recogniser variants measured side by side: the thesis's way first."""


def matching_segments(recognizer: PrimitiveRecognizer, originals: Sequence[Demonstration],
                      others: Sequence[Demonstration], **segmenter: Any) -> tuple[int, int]:
    """How many of the originals' segments the others have too, with the same label, first and
    last frame (the others taken pairwise: the same episodes another way, say a tracker log's
    round trip), and how many segments the originals have.

    >>> import polymimic
    >>> recognizer = train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)
    >>> demos = polymimic.record("poor", configuration=1, n=2, seed=0)
    >>> same, total = matching_segments(recognizer, demos, demos)
    >>> same == total > 0
    True
    """
    same = total = 0
    for a, b in zip(recognizer.segment_many([d.frames for d in originals], **segmenter),
                    recognizer.segment_many([d.frames for d in others], **segmenter)):
        theirs = set(zip(b["label"], b["first_frame"].tolist(), b["last_frame"].tolist()))
        ours = list(zip(a["label"], a["first_frame"].tolist(), a["last_frame"].tolist()))
        same += sum(s in theirs for s in ours)
        total += len(ours)
    return same, total


def variant_comparison(train: Sequence[PrimitiveSequence], test: Sequence[PrimitiveSequence], *,
                       n_states: int = 1, codebook_size: int = 512, seed: int = 0) -> list[dict[str, Any]]:
    """Accuracy per primitive, training time and scoring time (s) of every variant in
    :data:`VARIANTS`, on the same data."""
    rows = []
    for variant in VARIANTS:
        started = time.perf_counter()
        recognizer = train_recognizer(train, n_states=n_states, codebook_size=codebook_size,
                                      representation=variant["representation"], emissions=variant["emissions"],
                                      seed=seed)
        trained = time.perf_counter()
        accuracy = accuracy_table(recognizer, test)
        rows.append({**variant, "accuracy": accuracy, "train_s": trained - started,
                     "score_s": time.perf_counter() - trained})
    return rows
