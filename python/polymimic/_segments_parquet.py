"""Segmented demonstrations as a Parquet table, in one place: the layout of a
:mod:`polymimic.segments` file and of the demonstrations a saved
:class:`~polymimic.ImitatorPolicy` learns from.

One row per demonstration: its ``demonstrator``, ``outcome``, ``pitch``, ``reach_mm`` (null where
unknown) and list columns of its segments (``label``, ``first_frame``, ``last_frame``,
``start``, ``end``, ``scores``); the schema metadata key ``polymimic`` holds ``{"format":
"polymimic.segments", "version": 2}``. Version 1 had no ``reach_mm``: its demonstrations' reach
reads as unknown. ``scores`` has a value per moving primitive of the recogniser that named the
segments: 4 for a wheeled body's, 7 for the humanoid's own (its side-steps and kick).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from typing import IO, Any, Union

import numpy as np

from polymimic._native import ModelFileError, SegmentedDemonstrations

FORMAT = "polymimic.segments"
FORMAT_VERSION = 2
_ARRAYS = {"first_frame": (np.int64, 0), "last_frame": (np.int64, 0), "start": (np.float64, 5),
           "end": (np.float64, 5), "scores": (np.float64, 4)}
"""Each segment column's dtype and row width (0: one value per segment); the scores' width is a
wheeled recogniser's, :data:`_SCORE_WIDTHS` every one's."""
_SCORE_WIDTHS = (4, 7)


def _width(key: str, width: int, rows: Sequence[np.ndarray]) -> int:
    """The row width of column ``key``: its own, but the scores' that of the rows themselves."""
    if key != "scores":
        return width
    return next((r.shape[1] for r in rows if r.ndim == 2 and r.shape[1] in _SCORE_WIDTHS), width)

Target = Union[str, os.PathLike[str], IO[bytes]]
"""A path, or a binary file open for writing or reading."""


def write_segments(items: SegmentedDemonstrations | Sequence[Mapping[str, Any]], target: Target) -> None:
    """Write segmented demonstrations to ``target`` as Parquet (not atomically: callers that
    write a file do so through :func:`polymimic._atomic.atomic_path`)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    items = list[Mapping[str, Any]](items)
    columns: dict[str, Any] = {key: pa.array([item[key] for item in items], pa.string())
                               for key in ("demonstrator", "outcome", "pitch")}
    columns["reach_mm"] = pa.array([item.get("reach_mm") for item in items], pa.float64())
    columns["label"] = pa.array([list(item["segments"]["label"]) for item in items], pa.list_(pa.string()))
    for key, (dtype, width) in _ARRAYS.items():
        value_type = pa.int64() if dtype is np.int64 else pa.float64()
        rows = [np.asarray(item["segments"][key], dtype=dtype) for item in items]
        width = _width(key, width, rows)
        cell_type = pa.list_(value_type, width) if width else value_type
        columns[key] = pa.array([r.tolist() for r in rows], pa.list_(cell_type))
    table = pa.table(columns).replace_schema_metadata(
        {"polymimic": json.dumps({"format": FORMAT, "version": FORMAT_VERSION})})
    pq.write_table(table, target)


def read_segments(source: Target, where: str) -> SegmentedDemonstrations:
    """The segmented demonstrations :func:`write_segments` wrote to ``source``, checked as every
    batch is; anything wrong is a :class:`~polymimic.ModelFileError` that names ``where``."""
    import pyarrow.parquet as pq

    try:
        table = pq.read_table(source)
    except (OSError, ValueError) as error:
        raise ModelFileError(f"{where}: not a readable Parquet file ({error})") from error
    try:
        meta = json.loads((table.schema.metadata or {}).get(b"polymimic", b"{}"))
    except ValueError as error:
        raise ModelFileError(f"{where}: unreadable 'polymimic' metadata ({error})") from error
    version = meta.get("version", 0) if isinstance(meta, dict) else None
    if not isinstance(meta, dict) or meta.get("format") != FORMAT or not isinstance(version, int) or \
            version > FORMAT_VERSION:
        raise ModelFileError(f"{where}: not a {FORMAT} file of version ≤ {FORMAT_VERSION}")
    data = table.to_pydict()
    required = ("demonstrator", "outcome", "pitch", *(("reach_mm",) if version >= 2 else ()), "label", *_ARRAYS)
    missing = [key for key in required if key not in data]
    if missing:
        raise ModelFileError(f"{where}: lacks column(s) {', '.join(missing)}")
    items = []
    for i, demonstrator in enumerate(data["demonstrator"]):
        segments: dict[str, Any] = {"label": list(data["label"][i])}
        for key, (dtype, width) in _ARRAYS.items():
            cells = data[key][i]
            if key == "scores" and cells and len(cells[0]) in _SCORE_WIDTHS:
                width = len(cells[0])
            array = np.array(cells, dtype=dtype)
            segments[key] = array.reshape(-1, width) if width else array
        items.append({"demonstrator": demonstrator, "outcome": data["outcome"][i], "segments": segments,
                      "pitch": data["pitch"][i], "reach_mm": data["reach_mm"][i] if "reach_mm" in data else None})
    try:
        return SegmentedDemonstrations(items)
    except (ValueError, TypeError) as error:
        raise ModelFileError(f"{where}: {error}") from error
