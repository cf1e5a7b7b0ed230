"""Segmented demonstrations, as the learner takes them, saved to and loaded from Parquet.

One row per demonstration: its ``demonstrator``, ``outcome``, ``pitch`` (``"large"`` or
``"small"``) and list columns of its segments (``label``, ``first_frame``, ``last_frame``,
``start`` and ``end`` (robot x, y, θ and ball x, y), ``scores`` (each HMM's log-likelihood)).
A round trip is exact, and a demonstration with no segment keeps its row.

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

import json
import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._atomic import atomic_path
from polymimic._native import ModelFileError, PrimitiveRecognizer, SegmentedDemonstrations
from polymimic.field import Demonstration
from polymimic.learning import segmented

__all__ = ["load_segments", "save_segments", "segment_demonstrations"]

FORMAT = "polymimic.segments"
FORMAT_VERSION = 1
_ARRAYS = {"first_frame": (np.int64, 0), "last_frame": (np.int64, 0), "start": (np.float64, 5),
           "end": (np.float64, 5), "scores": (np.float64, 4)}
"""Each segment column's dtype and row width (0: one value per segment)."""


def segment_demonstrations(demonstrations: Sequence[Demonstration], recognizer: PrimitiveRecognizer,
                           **segmenter: Any) -> SegmentedDemonstrations:
    """Demonstrations cut into named segments, in the form :func:`polymimic.run_trial` takes
    (:func:`polymimic.learning.segmented`)."""
    return segmented(demonstrations, recognizer, **segmenter)


def save_segments(items: SegmentedDemonstrations | Sequence[Mapping[str, Any]],
                  path: str | os.PathLike[str]) -> None:
    """Write segmented demonstrations to a Parquet file, atomically."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    items = list[Mapping[str, Any]](items)
    columns: dict[str, Any] = {key: pa.array([item[key] for item in items], pa.string())
                               for key in ("demonstrator", "outcome", "pitch")}
    columns["label"] = pa.array([list(item["segments"]["label"]) for item in items], pa.list_(pa.string()))
    for key, (dtype, width) in _ARRAYS.items():
        value_type = pa.int64() if dtype is np.int64 else pa.float64()
        rows = [np.asarray(item["segments"][key], dtype=dtype) for item in items]
        cell_type = pa.list_(value_type, width) if width else value_type
        columns[key] = pa.array([r.tolist() for r in rows], pa.list_(cell_type))
    table = pa.table(columns).replace_schema_metadata(
        {"polymimic": json.dumps({"format": FORMAT, "version": FORMAT_VERSION})})
    with atomic_path(path) as temporary:
        pq.write_table(table, temporary)


def load_segments(path: str | os.PathLike[str]) -> SegmentedDemonstrations:
    """The segmented demonstrations :func:`save_segments` wrote, checked as every batch is (a
    value out of range is a :class:`~polymimic.ModelFileError` naming the file)."""
    import pyarrow.parquet as pq

    try:
        table = pq.read_table(path)
    except (OSError, ValueError) as error:
        raise ModelFileError(f"{os.fspath(path)}: not a readable Parquet file ({error})") from error
    meta = json.loads((table.schema.metadata or {}).get(b"polymimic", b"{}"))
    if meta.get("format") != FORMAT or meta.get("version", 0) > FORMAT_VERSION:
        raise ModelFileError(f"{os.fspath(path)}: not a {FORMAT} file of version ≤ {FORMAT_VERSION}")
    data = table.to_pydict()
    items = []
    for i, demonstrator in enumerate(data["demonstrator"]):
        segments: dict[str, Any] = {"label": list(data["label"][i])}
        for key, (dtype, width) in _ARRAYS.items():
            array = np.array(data[key][i], dtype=dtype)
            segments[key] = array.reshape(-1, width) if width else array
        items.append({"demonstrator": demonstrator, "outcome": data["outcome"][i], "segments": segments,
                      "pitch": data["pitch"][i]})
    try:
        return SegmentedDemonstrations(items)
    except (ValueError, TypeError) as error:
        raise ModelFileError(f"{os.fspath(path)}: {error}") from error
