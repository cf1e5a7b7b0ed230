"""Demonstrations as a cloning method learns from them: what the robot saw, frame by frame,
and which primitive each frame is labelled with.

Three ways to label; the first is ``bc``'s, the second ``bco``'s (docs/results/benchmark.md):

- :func:`command_labels` (privileged): the primitive equivalent of the command the
  demonstrator sent in each frame (``polymimic.field.command_primitives()``);
- :func:`window_labels` (tracker frames only): the primitive the recogniser names for the
  second of motion that starts at each frame, as BCO's inverse model names each transition;
- :func:`segment_labels` (tracker frames only): the primitive of the recogniser's segment
  covering each frame (``recognizer.segment_many``, thesis §3.2.2). A segment grows until its motion
  exceeds any one primitive's, so the Expert's segments are 98 % forward while it turns in 31 %
  of its frames: a coarser label, kept for comparison (``bco.labelled(..., labels="segments")``).

Frames the recogniser calls a gap (its two best scores too close to call), or that no segment
covers, carry no label and give no training sample.

Observations are the frames' tracker readings (a dropout repeats the last good reading, as the
environment does), on the imitator's field. Here the cloning baselines part from the learner's
one correspondence (:func:`polymimic.bodies.onto_field`), because it weakens them: a
demonstration from a field no longer than the imitator's (the tiny's) is taken as recorded,
its field centred on the imitator's, and one from a longer field (a RoboCup-size log) has its
ball brought across by the correspondence while the robot keeps its offset from the ball in
millimetres. Measured on the benchmark's ``mixed_bodies`` crowd (``python
studies/how_bc_should_read_another_field.py RUN_DIR --fits 5``: histogram gradient boosting on the
ball-relative features, 5 frames a step, on the benchmark's evaluation attempts, kicks labelled
forward), ``bc``'s samples as recorded netted 16.0 ± 6.4 goals per 50 (5.4 own goals), brought
over by the correspondence (the humanoid's kicking reach and the tiny's touch mapped onto the
Lego's) 9.0 ± 4.3 (12.6), and stretched per axis onto the large field 3.8 ± 2.2 (19.6).

Labels are the imitator's own primitive for what the command did: the primitive that looks the
same from above (:func:`polymimic.field.command_primitives`, the thesis's Table 4.4), except
that the humanoid's kicks, made leaning back, are forward, since the wheeled imitator kicks by
driving into the ball (:data:`CLONING_EQUIVALENTS`). In the same ten fits that moved net goals
by +0.7 (mapped), +2.3 (as recorded) and 0.0 (stretched), within the fits' spread: it is kept
for what a kick does. The labellings from tracker frames alone cannot know what was sent: they
name a kick as it looks, backward, as a wheeled recogniser reads it, and so does the humanoid's
own recogniser once its windows and segments are named in the five
(:data:`polymimic.field.WHEELED_EQUIVALENT`).

>>> import polymimic
>>> demos = polymimic.record("poor", configuration=1, n=1, seed=0)
>>> labelled = command_labels(demos)
>>> labelled[0].observations.shape[1], set(labelled[0].labels.tolist()) <= {0, 1, 2, 3, 4}
(5, True)
"""

from __future__ import annotations

import dataclasses
import numbers
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._native import PrimitiveRecognizer
from polymimic.bodies import Body, BodySpec, as_body, onto_field
from polymimic.field import (
    PRIMITIVES,
    WHEELED_EQUIVALENT,
    Demonstration,
    command_primitives,
    command_table,
    primitives_sent,
)
from polymimic.window_names import NO_NAME, WINDOW_FRAMES, name_windows, repeat_last_good

__all__ = ["CLONING_EQUIVALENTS", "IMITATOR_BODY", "NO_LABEL", "WINDOW_FRAMES", "WINDOW_STRIDE_FRAMES", "Labelled",
           "check_demonstrations", "check_weights", "cloning_primitives", "command_labels",
           "segment_labels", "starts_as_imitator", "window_labels"]

NO_LABEL = NO_NAME
"""The label of a frame that gives no training sample (a gap, or no segment)."""

WINDOW_STRIDE_FRAMES = 3
"""By default a window is named at every third frame, the decision samples' densest stride
(:data:`polymimic.baselines.training.SAMPLE_STRIDE_FRAMES`)."""

CLONING_EQUIVALENTS = {"Kick Left": "forward", "Kick Right": "forward"}
"""Commands whose label for cloning is not the primitive they look like from above: a kick
moves the ball forward, which the wheeled imitator does by driving into it."""

IMITATOR_BODY = "lego"
"""The imitator's body unless a cloning baseline is told another (``imitator=``)."""

_SEGMENT_LABELS = {"F": 0, "B": 1, "L": 2, "R": 3, "S": 4, **{p: i for i, p in enumerate(PRIMITIVES)}}


@dataclasses.dataclass(frozen=True, eq=False)
class Labelled:
    """One demonstration, ready to learn from.

    Attributes
    ----------
    demonstrator : str
    observations : ndarray, shape (n_frames, 5)
        ``[robot x mm, robot y mm, robot θ rad, ball x mm, ball y mm]`` per frame, on the
        imitator's field.
    labels : ndarray of int, shape (n_frames,)
        Index into :data:`polymimic.field.PRIMITIVES` per frame, or :data:`NO_LABEL`.
    body : polymimic.Body, default the imitator's
        The demonstrator's body (given as a Body, a built-in body's name or a
        :class:`polymimic.bodies.WheeledBody`).
    imitator : polymimic.Body, default :data:`IMITATOR_BODY`
        The body the observations are on the field of, the one that learns (given as ``body``).
    """

    demonstrator: str
    observations: np.ndarray
    labels: np.ndarray
    body: Body = Body(IMITATOR_BODY)
    imitator: Body = Body(IMITATOR_BODY)

    def __post_init__(self) -> None:
        if self.observations.shape != (len(self.labels), 5):
            raise ValueError(f"observations must be ({len(self.labels)}, 5) for {len(self.labels)} labels, "
                             f"got {self.observations.shape}")
        object.__setattr__(self, "body", as_body(self.body))
        object.__setattr__(self, "imitator", as_body(self.imitator, what="imitator"))


def starts_as_imitator(body: BodySpec, imitator: BodySpec = IMITATOR_BODY) -> bool:
    """Whether a demonstrator of ``body`` starts its attempts as an imitator of body
    ``imitator`` starts its own: from the same state, deciding as the same body would (only the
    imitator's own body does)."""
    return as_body(body) == as_body(imitator, what="imitator")


def check_demonstrations(demonstrations: Sequence[Demonstration]) -> list[Demonstration]:
    """The demonstrations as a list, or a ValueError if there are none or one is not one."""
    demos = list(demonstrations)
    if not demos:
        raise ValueError("demonstrations is empty: cloning needs at least one demonstration")
    for i, demo in enumerate(demos):
        if not isinstance(demo, Demonstration):
            raise ValueError(f"demonstrations[{i}] must be a polymimic.Demonstration, got {type(demo).__name__}")
    return demos


def check_weights(weights: Mapping[str, float], demonstrations: Sequence[Demonstration]) -> dict[str, float]:
    """Every demonstrator's weight, in [0, 1], or a ValueError naming the one missing or wrong."""
    checked: dict[str, float] = {}
    for name in sorted({d.demonstrator for d in demonstrations}):
        if name not in weights:
            raise ValueError(f"weights has no weight for demonstrator {name!r}; it has {sorted(weights)}")
        value = weights[name]
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0.0 <= value <= 1.0:
            raise ValueError(f"weights[{name!r}] must be a number in [0, 1], got {value!r}")
        checked[name] = float(value)
    return checked


def observations_of(demo: Demonstration, imitator: BodySpec = IMITATOR_BODY) -> np.ndarray:
    """The ``(n, 5)`` observations of a demonstration's frames: NaN readings (lost tracking,
    a ball out of sight) repeat the last good one, on the imitator's field: as recorded from a
    field no longer than it, else the ball brought across by :func:`polymimic.bodies.onto_field`
    and the robot at its offset from it in millimetres."""
    frames = demo.frames
    obs = repeat_last_good(np.column_stack([frames[c] for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad",
                                                                 "ball_x_mm", "ball_y_mm")]).astype(np.float64))
    if demo.body.field.length_mm <= as_body(imitator, what="imitator").field.length_mm:
        return obs
    mapped = onto_field(obs, recorded_by=demo.body, imitator=imitator)
    mapped[:, [0, 1]] = mapped[:, [3, 4]] + (obs[:, [0, 1]] - obs[:, [3, 4]])
    return mapped


def cloning_primitives() -> np.ndarray:
    """A lookup array: ``cloning_primitives()[frames["command"]]`` is each frame's label (an
    index into :data:`~polymimic.field.PRIMITIVES`, or :data:`NO_LABEL` for an id no command has)."""
    index = np.array([PRIMITIVES.index(p) if p else NO_LABEL for p in command_primitives()], dtype=np.int64)
    for row in command_table():
        if row["name"] in CLONING_EQUIVALENTS:
            index[row["id"]] = PRIMITIVES.index(CLONING_EQUIVALENTS[row["name"]])
    return index


def command_labels(demonstrations: Sequence[Demonstration], *,
                   imitator: BodySpec = IMITATOR_BODY) -> list[Labelled]:
    """Each frame labelled with the imitator's primitive for the command sent (privileged):
    :func:`cloning_primitives`; observations on the field of body ``imitator``."""
    index = cloning_primitives()
    demos = check_demonstrations(demonstrations)
    for d in demos:
        primitives_sent(d)  # refuses a demonstration whose commands were never recorded
    return [Labelled(d.demonstrator, observations_of(d, imitator), index[d.frames["command"].astype(np.int64)],
                     d.body, as_body(imitator, what="imitator")) for d in demos]


def segment_labels(demonstrations: Sequence[Demonstration], recognizer: PrimitiveRecognizer, *,
                   imitator: BodySpec = IMITATOR_BODY, **segmenter: Any) -> list[Labelled]:
    """Each frame labelled with the primitive of the recogniser's segment covering it (none in
    a gap or outside every segment; the humanoid's own side-steps and kick by their wheeled
    equivalents, :data:`polymimic.field.WHEELED_EQUIVALENT`, as window names have them);
    ``segmenter`` passes the segmenter's settings, and the observations are on the field of body
    ``imitator``."""
    demos = check_demonstrations(demonstrations)
    segmented = recognizer.segment_many([d.frames for d in demos], **segmenter)
    labelled = []
    for demo, segments in zip(demos, segmented):
        labels = np.full(len(demo.frames), NO_LABEL, dtype=np.int64)
        for label, first, last in zip(segments["label"], segments["first_frame"], segments["last_frame"]):
            labels[int(first):int(last) + 1] = _SEGMENT_LABELS.get(WHEELED_EQUIVALENT.get(label, label), NO_LABEL)
        labelled.append(Labelled(demo.demonstrator, observations_of(demo, imitator), labels, demo.body,
                                 as_body(imitator, what="imitator")))
    return labelled


def window_labels(demonstrations: Sequence[Demonstration], recognizer: PrimitiveRecognizer, *,
                window_frames: int = WINDOW_FRAMES, stride_frames: int = WINDOW_STRIDE_FRAMES,
                frames: Sequence[np.ndarray] | None = None, stop_distance_mm: float = 1.0,
                stop_rotation_deg: float = 20.0, gap_margin: float = 2.0,
                imitator: BodySpec = IMITATOR_BODY) -> list[Labelled]:
    """Frames labelled with the primitive of the ``window_frames`` frames from them (from the
    demonstration's last full window near its end), named as the segmenter names a segment
    (:func:`polymimic.window_names.name_windows`): a stop if the robot ends the window within
    ``stop_distance_mm`` and ``stop_rotation_deg`` of where it started it, else the HMM that
    scores the window highest, and no label where the best two scores are within ``gap_margin``.

    Every ``stride_frames``-th frame from the first is named so; the frames between carry the
    label of the one named before them. Naming costs a reading of a whole window, so a caller
    that samples some frames only names just those: ``frames`` gives, per demonstration, the
    frames to name (as :func:`~polymimic.baselines.training.sample_rows` draws them), and every
    other frame is left without a label. Observations are on the field of body ``imitator``."""
    demos = check_demonstrations(demonstrations)
    if isinstance(stride_frames, bool) or not isinstance(stride_frames, (int, np.integer)) or stride_frames < 1:
        raise ValueError(f"stride_frames must be an integer ≥ 1, got {stride_frames!r}")
    if frames is not None and len(frames) != len(demos):
        raise ValueError(f"frames must list the frames to name for each of the {len(demos)} demonstrations, "
                         f"got {len(frames)}")
    labelled = []
    for i, demo in enumerate(demos):
        n = len(demo.frames)
        starts = np.arange(0, n, stride_frames) if frames is None else np.asarray(frames[i], dtype=np.int64)
        named = name_windows(demo.frames, recognizer, starts, window_frames=window_frames,
                             stop_distance_mm=stop_distance_mm, stop_rotation_deg=stop_rotation_deg,
                             gap_margin=gap_margin)
        if frames is None:
            labels = np.repeat(named, stride_frames)[:n]
        else:
            labels = np.full(n, NO_LABEL, dtype=np.int64)
            labels[starts] = named
        labelled.append(Labelled(demo.demonstrator, observations_of(demo, imitator), labels, demo.body,
                                 as_body(imitator, what="imitator")))
    return labelled
