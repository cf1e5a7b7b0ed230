"""The recogniser's name for the second of motion that starts at a frame: what BCO's inverse
model names a transition, read with the imitator's own HMMs (thesis §3.1) and the segmenter's rules
(thesis §3.2.2).

A window of :data:`WINDOW_FRAMES` frames is a stop if the robot ends it within the stop
tolerances of where it started it; otherwise the HMM that scores it highest names it, and none
does (:data:`NO_NAME`) where the best two scores are within the gap margin. A window that would
run past the demonstration's end is moved back to its last full window. Both ``bco``'s labels
(:func:`polymimic.baselines.labels.window_labels`) and Minari's actions
(:func:`polymimic.export.steps_of`) are named so.

Examples
--------
>>> import polymimic
>>> from polymimic import recognition
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=16)
>>> frames, _ = polymimic.Episode("lego", configuration=1, seed=0).run(["forward"] * 60)
>>> [polymimic.field.PRIMITIVES[i] for i in name_windows(polymimic.field.as_frames(frames), recognizer, [0, 30])]
['forward', 'forward']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._arguments import finite
from polymimic._native import PrimitiveRecognizer
from polymimic.field import PRIMITIVE_SETS, PRIMITIVES, WHEELED_EQUIVALENT

__all__ = ["LABELS", "NO_NAME", "SEGMENTER_SETTINGS", "WINDOW_FRAMES", "name_windows", "repeat_last_good",
           "segmenter_settings", "window_settings"]

LABELS = ("steps", "segments")
"""How a recogniser may label demonstrations: by the second of motion from each frame (the
default), or by the segments (thesis §3.2.2) the frames lie in."""

SEGMENTER_SETTINGS = ("min_frames", "stop_distance_mm", "stop_rotation_deg", "limit_sds", "gap_margin")
"""The settings :meth:`polymimic.PrimitiveRecognizer.segment` takes."""

# The segmenter's settings that name a window as they name a segment.
_WINDOW_SETTINGS = ("stop_distance_mm", "stop_rotation_deg", "gap_margin")

NO_NAME = -1
"""The name of a window too close to call (a gap) or too short to read."""

WINDOW_FRAMES = 30
"""Frames the recogniser reads to name a window: one second, the length of every self-observed
primitive it learned from."""

_MOVING = -2
_MOVING_BY_COLUMNS = {len(moving): moving for moving in
                      ([p for p in own if p != "stop"] for own in PRIMITIVE_SETS.values())}
"""Each set's moving primitives, by how many score columns its recogniser gives."""
_STOP = PRIMITIVES.index("stop")


def repeat_last_good(values: np.ndarray) -> np.ndarray:
    """A copy of ``values`` (one reading a row) with each NaN replaced, column by column, by the
    last finite reading before it, and those before any by the first finite one: the nearest
    reading there is, for a dropout at the start too. A column of NaN alone stays NaN."""
    values = np.asarray(values)
    if not len(values):
        return values.copy()
    good = np.isfinite(values)
    rows = np.arange(len(values)).reshape(-1, *[1] * (values.ndim - 1))
    last_good = np.maximum.accumulate(np.where(good, rows, -1), axis=0)
    # argmax finds a column's first finite row; an all-NaN column's row 0 is NaN, and stays so.
    index = np.where(last_good < 0, np.argmax(good, axis=0), last_good)
    return np.take_along_axis(values, index, axis=0)


def segmenter_settings(segmenter: Mapping[str, Any] | None) -> dict[str, Any]:
    """``segmenter`` as a dict, or a ValueError naming the keys that are none of
    :data:`SEGMENTER_SETTINGS` (a misspelt one would otherwise leave its default in force)."""
    settings = dict(segmenter or {})
    unknown = [k for k in settings if k not in SEGMENTER_SETTINGS]
    if unknown:
        raise ValueError(f"segmenter has no setting {', '.join(map(repr, unknown))}; its settings are "
                         f"{', '.join(SEGMENTER_SETTINGS)}")
    return settings


def window_settings(segmenter: Mapping[str, Any] | None) -> dict[str, Any]:
    """The segmenter's settings that :func:`name_windows` names a window with (a ValueError for
    a key the segmenter has not)."""
    return {k: v for k, v in segmenter_settings(segmenter).items() if k in _WINDOW_SETTINGS}


def name_windows(frames: np.ndarray, recognizer: PrimitiveRecognizer, starts: Sequence[int] | np.ndarray, *,
                 window_frames: int = WINDOW_FRAMES, stop_distance_mm: float = 1.0, stop_rotation_deg: float = 20.0,
                 gap_margin: float = 2.0) -> np.ndarray:
    """The index into :data:`polymimic.field.PRIMITIVES` of the window of ``window_frames``
    frames from each of ``starts`` (a tracker-frame record array), or :data:`NO_NAME`. A
    recogniser of the humanoid's own primitives names its side-steps and kick by their wheeled
    equivalents (:data:`polymimic.field.WHEELED_EQUIVALENT`): every name is one of the five.
    ``starts`` are frame indices in time order; the tolerances and ``gap_margin`` are finite
    and ≥ 0, as the segmenter has them. Lost readings repeat the last good one, as the
    environment repeats them."""
    if isinstance(window_frames, bool) or not isinstance(window_frames, (int, np.integer)) or window_frames < 2:
        raise ValueError(f"window_frames must be an integer ≥ 2, got {window_frames!r}")
    for name, value in (("stop_distance_mm", stop_distance_mm), ("stop_rotation_deg", stop_rotation_deg),
                        ("gap_margin", gap_margin)):
        finite(name, value, low=0)
    n = len(frames)
    poses = repeat_last_good(np.column_stack([np.asarray(frames[c], dtype=np.float64)
                                              for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad")]))
    first = np.minimum(_checked_starts(starts, n), max(n - window_frames, 0))
    windows = [poses[s:s + window_frames] for s in first]
    named = np.array([_stop_or_moving(w, stop_distance_mm, stop_rotation_deg) for w in windows], dtype=np.int64)
    moving = np.flatnonzero(named == _MOVING)
    if len(moving):
        scores = recognizer.log_likelihoods_many([windows[i] for i in moving])
        # Each score column's primitive (a column per moving primitive of the recogniser's set),
        # as an index into PRIMITIVES.
        columns = _MOVING_BY_COLUMNS[scores.shape[1]]
        as_wheeled = np.array([PRIMITIVES.index(WHEELED_EQUIVALENT.get(p, p)) for p in columns])
        best_two = np.sort(scores, axis=1)[:, -2:]
        # A window no HMM can have made (every score −inf) is a gap too, as the segmenter has it.
        with np.errstate(invalid="ignore"):
            close = ~np.isfinite(best_two[:, 1]) | (best_two[:, 1] - best_two[:, 0] < gap_margin)
        named[moving] = np.where(close, NO_NAME, as_wheeled[scores.argmax(axis=1)])
    return named


def _checked_starts(starts: Sequence[int] | np.ndarray, n_frames: int) -> np.ndarray:
    """``starts`` as int64 frame indices, or a ValueError: each must be a frame of the
    demonstration (a negative one would slice from its end), and they run in time order (a
    repeat is allowed)."""
    checked = np.asarray(starts)
    if checked.ndim != 1 or (checked.size and checked.dtype.kind not in "iu"):
        raise ValueError(f"starts must be a sequence of integer frame indices, got {starts!r}")
    checked = checked.astype(np.int64)
    outside = np.flatnonzero((checked < 0) | (checked >= n_frames))
    if len(outside):
        i = int(outside[0])
        raise ValueError(f"starts[{i}] = {checked[i]} is not a frame index of these {n_frames} frames "
                         f"(0 to {n_frames - 1})")
    backwards = np.flatnonzero(np.diff(checked) < 0)
    if len(backwards):
        i = int(backwards[0]) + 1
        raise ValueError(f"starts must not decrease: starts[{i}] = {checked[i]} follows starts[{i - 1}] = "
                         f"{checked[i - 1]}")
    return checked


def _stop_or_moving(poses: np.ndarray, stop_distance_mm: float, stop_rotation_deg: float) -> int:
    """:data:`_STOP` if the window's robot ends within the stop tolerances of where it started
    (the segmenter's stop test, over the window), :data:`NO_NAME` for a window too short to
    read, else :data:`_MOVING` (for the HMMs)."""
    if len(poses) < 2 or not np.isfinite(poses).all():
        return NO_NAME
    moved = np.hypot(poses[-1, 0] - poses[0, 0], poses[-1, 1] - poses[0, 1])
    turned = np.degrees(np.abs(np.angle(np.exp(1j * (poses[-1, 2] - poses[0, 2])))))
    return _STOP if moved < stop_distance_mm and turned < stop_rotation_deg else _MOVING
