"""Segmented demonstrations, as the learner takes them, saved to and loaded from Parquet.

One row per demonstration: its ``demonstrator``, ``outcome``, ``pitch`` (``"large"`` or
``"small"``), ``reach_mm`` (how far from its centre its demonstrator's body moves the ball: see
:func:`polymimic.bodies.reach_mm`) and list columns of its segments (``label``, ``first_frame``, ``last_frame``,
``start`` and ``end`` (robot x, y, θ and ball x, y), ``scores`` (each HMM's log-likelihood)).
A round trip is exact, and a demonstration with no segment keeps its row.

Examples
--------
>>> import pathlib, tempfile
>>> import polymimic
>>> from polymimic import recognition
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=16)
>>> items = segment_demonstrations(polymimic.record("tiny", configuration=1, n=2, seed=0), recognizer)
>>> path = pathlib.Path(tempfile.mkdtemp()) / "segments_tiny.parquet"
>>> save_segments(items, path)
>>> again = load_segments(path)
>>> again == items, again[0]["pitch"], bool((again[0]["segments"]["start"] == items[0]["segments"]["start"]).all())
(True, 'small', True)
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import Any

from polymimic._atomic import atomic_path
from polymimic._native import PrimitiveRecognizer, SegmentedDemonstrations
from polymimic._segments_parquet import read_segments, write_segments
from polymimic.field import Demonstration
from polymimic.learning import segmented

__all__ = ["load_segments", "save_segments", "segment_demonstrations"]


def segment_demonstrations(demonstrations: Sequence[Demonstration], recognizer: PrimitiveRecognizer,
                           **segmenter: Any) -> SegmentedDemonstrations:
    """Demonstrations cut into named segments, in the form :func:`polymimic.run_trial` takes
    (:func:`polymimic.learning.segmented`)."""
    return segmented(demonstrations, recognizer, **segmenter)


def save_segments(items: SegmentedDemonstrations | Sequence[Mapping[str, Any]],
                  path: str | os.PathLike[str]) -> None:
    """Write segmented demonstrations to a Parquet file, atomically."""
    with atomic_path(path) as temporary:
        write_segments(items, temporary)


def load_segments(path: str | os.PathLike[str]) -> SegmentedDemonstrations:
    """The segmented demonstrations :func:`save_segments` wrote, checked as every batch is (a
    value out of range is a :class:`~polymimic.ModelFileError` naming the file)."""
    return read_segments(path, os.fspath(path))
