"""From labelled demonstrations to a cloned policy: decision samples, weights, a classifier.

A decision sample is one frame's observation and its label, taken every
:data:`SAMPLE_STRIDE_FRAMES` frames (any frame is a moment the policy may decide at); frames
without a label give none. Where that would give more than :data:`MAX_DECISION_SAMPLES` (a
crowd of ten members gives about 100 000), the stride widens evenly for every demonstration
until it does not, so that a fit costs the same whatever the crowd's size. A
demonstration's first frame gives a sample when its demonstrator has the imitator's body
(:func:`~polymimic.baselines.labels.starts_as_imitator`), since every attempt starts in such a
state; where its strided samples start is drawn with the fit's seed (:func:`sample_rows`): fits
under other seeds learn from other frames, so that even a deterministic classifier (gradient
boosting without early stopping, k-NN, logistic regression) gives a spread over fits, not one
draw. With fixed hyperparameters (``python studies/whose_first_frames_bc_should_take.py RUN_DIR``: histogram
gradient boosting, ball-relative features, 15 frames a step, eight fits on the benchmark's
evaluation attempts), the first frames raised ``bc``'s mean net goals per 50 from 2.1 to 11.6 on
``one_good``, 4.0 to 8.6 on ``half``, 17.9 to 22.1 on ``equal`` and 6.9 to 15.4 on ``linear``.
On ``mixed_bodies`` every member's first frame lowered them to 11.6 from 16.9 without any; the
humanoid's did the harm. It starts where the Lego starts, but a walker's first move from there
(turning on the spot, waiting) is not a wheeled robot's, and a first frame is the one state
every attempt meets. The tiny starts elsewhere, on its small field. Only the first frames of
the imitator's own body, then, give samples: 19.4 on ``mixed_bodies`` in the same fits (the
other profiles are all of the Lego's body).

Each sample weighs its demonstrator's weight (1 unless a method says otherwise: ``bco_lp`` uses
the LP), and, when the hyperparameters ask for balance, its
primitive's balancing weight too (every primitive's samples then weigh the same in total,
scikit-learn's ``"balanced"`` rule on the weighted counts). Samples of weight 0 are dropped
before fitting, so that a member weighted 0 is exactly a member left out.

>>> import polymimic
>>> from polymimic.baselines.labels import command_labels
>>> labelled = command_labels(polymimic.record("poor", configuration=1, n=2, seed=0))
>>> policy = train("bc", labelled, hyperparameters=DEFAULT, seed=0)
>>> policy.predict(labelled[0].observations[:1]).tolist()
[0]
"""

from __future__ import annotations

import zlib
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic.baselines.classifiers import fit_weighted, make_classifier
from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters
from polymimic.baselines.labels import NO_LABEL, Labelled, starts_as_imitator
from polymimic.baselines.policy import ClonedPolicy

__all__ = ["DEFAULT", "MAX_DECISION_SAMPLES", "SAMPLE_STRIDE_FRAMES", "check_fit_seed", "check_max_samples",
           "decision_samples", "sample_rows", "stride_for_frames", "train"]

SAMPLE_STRIDE_FRAMES = 3
"""Frames between decision samples (every 0.1 s): consecutive frames differ by tracker noise
only, so denser sampling adds time, not information."""

MAX_DECISION_SAMPLES = 20_000
"""The most decision samples one fit takes (before dropping unlabelled frames). In the full
benchmark, fits of at most 20 000 scored as well as fits of at most 30 000 (the four cloning
baselines' evaluated net goals summed over the five profiles +0.2, their best validation scores
+9) in two thirds of the fitting time."""


def check_max_samples(max_samples: Any) -> int:
    """``max_samples`` if it is an integer ≥ 1, else a ``ValueError`` naming it."""
    if isinstance(max_samples, bool) or not isinstance(max_samples, (int, np.integer)) or max_samples < 1:
        raise ValueError(f"max_samples must be an integer ≥ 1 (decision samples a fit takes at most), "
                         f"got {max_samples!r}")
    return int(max_samples)


def check_fit_seed(seed: Any) -> int:
    """``seed`` if it is an integer in [0, 2**32) (what scikit-learn's classifiers take), else a
    ``ValueError`` naming it."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2**32:
        raise ValueError(f"seed must be an integer in [0, 2**32) (it draws a fit's decision samples and seeds "
                         f"its classifier), got {seed!r}")
    return int(seed)


def stride_for_frames(frames: int, *, max_samples: int = MAX_DECISION_SAMPLES) -> int:
    """The decision samples' stride over demonstrations of ``frames`` frames in all:
    :data:`SAMPLE_STRIDE_FRAMES`, widened so that they give at most about ``max_samples``.

    >>> stride_for_frames(9000), stride_for_frames(180_000), stride_for_frames(9000, max_samples=1000)
    (3, 9, 9)
    """
    return max(SAMPLE_STRIDE_FRAMES, -(-frames // check_max_samples(max_samples)))


def sample_rows(demonstrations: Sequence[tuple[str, int]], *, max_samples: int = MAX_DECISION_SAMPLES,
                seed: int = 0, first_frames: Sequence[bool] | None = None) -> list[np.ndarray]:
    """The frames each demonstration, given as (demonstrator, frames), gives a decision sample
    at: its first frame, where every attempt starts (unless ``first_frames``, one flag per
    demonstration, says no; by default every one), then every stride-th
    (:func:`stride_for_frames` over them all) from a frame in ``[1, stride]`` drawn with
    ``seed``, the demonstrator's name and the demonstration's place among that demonstrator's.
    Leaving a demonstrator out changes no other one's frames (so a member weighted 0 is a
    member left out).

    >>> two = [("a", 10), ("a", 10)]
    >>> [rows.tolist() for rows in sample_rows(two, max_samples=5, seed=0)]
    [[0, 1, 5, 9], [0, 3, 7]]
    >>> [rows.tolist() for rows in sample_rows(two, max_samples=5, seed=0, first_frames=[True, False])]
    [[0, 1, 5, 9], [3, 7]]
    """
    if first_frames is not None and len(first_frames) != len(demonstrations):
        raise ValueError(f"first_frames must hold one flag per demonstration ({len(demonstrations)}), "
                         f"got {len(first_frames)}")
    stride = stride_for_frames(sum(length for _, length in demonstrations), max_samples=max_samples)
    seed = check_fit_seed(seed)
    seen: dict[str, int] = {}
    rows = []
    for i, (name, length) in enumerate(demonstrations):
        place = seen[name] = seen.get(name, -1) + 1
        first = 1 + np.random.default_rng([seed, zlib.crc32(name.encode()), place]).integers(stride)
        starts = min(length, 1) if first_frames is None or first_frames[i] else 0
        rows.append(np.concatenate([np.arange(starts), np.arange(first, length, stride)]))
    return rows


def decision_samples(labelled: Sequence[Labelled], *, weights: Mapping[str, float] | None = None,
                     balanced: bool = False, max_samples: int = MAX_DECISION_SAMPLES,
                     seed: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Observations ``(n, 5)``, labels ``(n,)`` and weights ``(n,)`` of every decision sample,
    at most about ``max_samples`` of them, at the frames :func:`sample_rows` draws with ``seed``."""
    observations, labels, sample_weight = [], [], []
    every = sample_rows([(item.demonstrator, len(item.labels)) for item in labelled], max_samples=max_samples,
                        seed=seed, first_frames=[starts_as_imitator(item.body, item.imitator) for item in labelled])
    for item, rows in zip(labelled, every):
        rows = rows[item.labels[rows] != NO_LABEL]
        observations.append(item.observations[rows])
        labels.append(item.labels[rows])
        weight = 1.0 if weights is None else float(weights[item.demonstrator])
        sample_weight.append(np.full(len(rows), weight))
    X = np.concatenate(observations) if observations else np.empty((0, 5))
    y = np.concatenate(labels).astype(np.int64) if labels else np.empty(0, dtype=np.int64)
    w = np.concatenate(sample_weight) if sample_weight else np.empty(0)
    if balanced and len(y):
        totals = np.bincount(y, weights=w, minlength=5)
        present = totals > 0
        per_class = np.zeros(5)
        per_class[present] = w.sum() / (present.sum() * totals[present])
        w = w * per_class[y]
    return X, y, w


def train(method: str, labelled: Sequence[Labelled], *, hyperparameters: Hyperparameters, seed: int = 0,
          weights: Mapping[str, float] | None = None, max_samples: int = MAX_DECISION_SAMPLES) -> ClonedPolicy:
    """A :class:`ClonedPolicy` fitted on the decision samples of ``labelled`` (at most about
    ``max_samples``); ``seed`` draws the samples' frames and seeds the classifier.

    Raises
    ------
    ValueError
        If no sample has a positive weight (nothing labelled, or every weight 0), or
        ``max_samples`` is not an integer ≥ 1.
    """
    X, y, w = decision_samples(labelled, weights=weights, balanced=hyperparameters.balanced, max_samples=max_samples,
                               seed=seed)
    if not (w > 0).any():
        raise ValueError(f"{method}: no decision sample to learn from (no labelled frame, or every weight 0)")
    model = make_classifier(hyperparameters.classifier, dict(hyperparameters.params), seed=seed)
    imitators = {item.imitator for item in labelled}
    if len(imitators) != 1:
        names = sorted(body.name for body in imitators)
        raise ValueError(f"{method}: the demonstrations are labelled for imitators {names}; one policy has one body")
    policy = ClonedPolicy(method, hyperparameters, model, body=imitators.pop())
    policy.classifier = fit_weighted(model, policy.features(X), y, w)
    return policy
