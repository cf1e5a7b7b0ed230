"""An inverse dynamics model learned from the imitator's own exploration, as BCO (Torabi et al.
2018) learns one: a classifier of how the robot moved over a window of tracker frames → the
primitive it was executing at the window's first frame. ``bco`` may label demonstrations with
it instead of the recogniser (``labels="inverse_dynamics"``).

**Exploration** (:func:`explore`): the imitator plays random primitives on its own field, with
the ball, from each field configuration's start, for :data:`EXPLORATION_FRAMES` frames or
until the episode ends. Each primitive is held for one second half the time (as the
self-observation's babbler and a crowd member's lapses hold it), else for 1 to 60 frames drawn
log-uniformly (a demonstrator's quick corrections, a long push).

**Features** (:func:`transition_features`): the robot's displacement from its pose at the
window's first frame *t*, in its own frame at *t* (forward and left, mm), and its heading change
(rad), at :data:`HORIZONS` of the window (2, 4, 7, 11, 17 and 29 frames of a 30-frame one), and
over the :data:`BEFORE_FRAMES` frames before *t*. The tracker gives no velocity, and a body's
lag shows the primitive before *t* in a window's first frames: the motion the robot carries
into *t* tells the two apart (without it, 87.1 % of held-out exploration windows were named as
executed instead of 91.5 %, and the Expert's labels agreed with its commands in 90.5 % of
frames instead of 92.2 %). The ball's displacement is left out: it moved neither figure by more
than a point.

**Classifier**: histogram gradient boosting (100 trees), seeded, on a window from every third
frame of :data:`EXPLORATION_EPISODES` episodes: the same seed gives the same model.

Where the recogniser's steps agree with the commands sent in 84 % of an Expert's frames and
75 % of a ``linear`` crowd's (whose lapses are seconds of random primitives), this model's
labels agree in 92 % and 93 % (``python studies/which_labels_bco_should_learn_from.py``). Its weak spot is a window
from the very frame a primitive starts, as every self-observed sequence is: read with the
second before it, 79 % of held-out self-observed primitives are named as executed.

>>> import polymimic
>>> model = learn("lego", seed=0, episodes=20)
>>> frames, _ = polymimic.Episode("lego", configuration=1, seed=0).run(["left"] * 30 + ["forward"] * 60)
>>> [PRIMITIVES[i] for i in model.name_windows(polymimic.field.as_frames(frames), [0, 40])]
['left', 'forward']
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Sequence
from typing import Any

import numpy as np
from threadpoolctl import threadpool_limits  # type: ignore[import-untyped, unused-ignore]

from polymimic._native import Episode
from polymimic.baselines.classifiers import make_classifier
from polymimic.baselines.labels import (
    IMITATOR_BODY,
    NO_LABEL,
    WINDOW_FRAMES,
    WINDOW_STRIDE_FRAMES,
    Labelled,
    check_demonstrations,
    observations_of,
)
from polymimic.bodies import Body, BodySpec, WheeledBody, as_body
from polymimic.field import PRIMITIVES, Demonstration, as_frames, primitive_command
from polymimic.window_names import repeat_last_good

__all__ = ["BEFORE_FRAMES", "EXPLORATION_EPISODES", "EXPLORATION_FRAMES", "HORIZONS", "MAX_WINDOW_FRAMES",
           "InverseDynamics", "explore", "horizon_frames", "inverse_dynamics_labels", "learn", "transition_features"]

EXPLORATION_EPISODES = 100
"""Exploration episodes the model learns from by default (about 60 000 frames, 19 000 windows)."""

EXPLORATION_FRAMES = 600
"""The longest exploration episode: 20 s (most run this long; a few end with the ball or the
robot off the field)."""

MAX_WINDOW_FRAMES = EXPLORATION_FRAMES // 4
"""The longest window a model reads: five seconds, so that an exploration episode holds many."""

HORIZONS = (2 / 30, 4 / 30, 7 / 30, 11 / 30, 17 / 30, 29 / 30)
"""Where in a window the displacement is read, as fractions of the window (rounded to frames)."""

BEFORE_FRAMES = 5
"""Frames before a window's first whose motion into it is read: a sixth of a second, the Lego's
motor lag (0.1 s) nearly twice over."""

_HOLD_FRAMES = (1, 60)  # the range of a hold that is not one second, drawn log-uniformly
_ONE_SECOND = 30


@dataclasses.dataclass(frozen=True, eq=False)
class InverseDynamics:
    """A learned inverse dynamics model (:func:`learn`).

    Attributes
    ----------
    imitator : polymimic.Body
        The body whose exploration it learned from.
    window_frames : int
        Frames of motion it reads from a window's first frame.
    classifier : fitted scikit-learn classifier
        Maps :func:`transition_features` to indices into :data:`polymimic.field.PRIMITIVES`.
    """

    imitator: Body
    window_frames: int
    classifier: Any

    def name_windows(self, frames: np.ndarray, starts: Sequence[int] | np.ndarray) -> np.ndarray:
        """The primitive (an index into :data:`~polymimic.field.PRIMITIVES`) the robot of the
        tracker frames ``frames`` executed at each of ``starts``, named from the window from it
        (the last full window where it would run past the end)."""
        return self.predict(self.features(frames, starts))

    def features(self, frames: np.ndarray, starts: Sequence[int] | np.ndarray) -> np.ndarray:
        """:func:`transition_features` of the windows from ``starts`` of the tracker frames ``frames``."""
        poses = _poses(frames)
        return transition_features(poses, _checked_starts(starts, len(poses)), window_frames=self.window_frames)

    def predict(self, features: np.ndarray) -> np.ndarray:
        """The primitive named for each row of :func:`transition_features`."""
        if not len(features):
            return np.empty(0, dtype=np.int64)
        with threadpool_limits(limits=1):  # one batch: threads only contend on a busy node
            return np.asarray(self.classifier.predict(features), dtype=np.int64)


def _check_window(window_frames: Any) -> int:
    if isinstance(window_frames, bool) or not isinstance(window_frames, (int, np.integer)) \
            or not 2 <= window_frames <= MAX_WINDOW_FRAMES:
        raise ValueError(f"window_frames must be an integer in 2..{MAX_WINDOW_FRAMES} (frames of motion a window "
                         f"reads, at most a quarter of an exploration episode), got {window_frames!r}")
    return int(window_frames)


def _check_count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValueError(f"{name} must be an integer ≥ 1, got {value!r}")
    return int(value)


def _check_seed(seed: Any) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2**63:
        raise ValueError(f"seed must be an integer in [0, 2**63) (it draws the exploration), got {seed!r}")
    return int(seed)


def _check_imitator(imitator: Any) -> Body:
    """``imitator`` as a :class:`polymimic.Body`, else a ValueError naming it."""
    if not isinstance(imitator, (str, WheeledBody, Body)):
        raise ValueError(f"imitator must be a body's name, a polymimic.Body or a polymimic.bodies.WheeledBody, got "
                         f"{imitator!r}")
    return as_body(imitator, what="imitator")


def _checked_starts(starts: Sequence[int] | np.ndarray, n_frames: int) -> np.ndarray:
    checked = np.asarray(starts)
    if checked.ndim != 1 or (checked.size and checked.dtype.kind not in "iu"):
        raise ValueError(f"starts must be a sequence of integer frame indices, got {starts!r}")
    outside = np.flatnonzero((checked < 0) | (checked >= n_frames))
    if len(outside):
        raise ValueError(f"starts[{outside[0]}] = {checked[outside[0]]} is not a frame index of these {n_frames} "
                         f"frames (0 to {n_frames - 1})")
    return checked.astype(np.int64)


def _poses(frames: np.ndarray) -> np.ndarray:
    """The robot's ``(n, 3)`` poses (x mm, y mm, θ rad), lost readings repeating the last good one."""
    return repeat_last_good(np.column_stack([np.asarray(frames[c], dtype=np.float64)
                                             for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad")]))


def horizon_frames(window_frames: int) -> np.ndarray:
    """The frames from a window's first at which :func:`transition_features` reads the
    displacement (:data:`HORIZONS` of ``window_frames``, distinct, each within the window).

    >>> horizon_frames(30).tolist(), horizon_frames(2).tolist()
    ([2, 4, 7, 11, 17, 29], [1])
    """
    window_frames = _check_window(window_frames)
    return np.unique(np.clip(np.rint(np.array(HORIZONS) * window_frames), 1, window_frames - 1)).astype(np.int64)


def transition_features(poses: np.ndarray, starts: np.ndarray, *, window_frames: int = WINDOW_FRAMES
                        ) -> np.ndarray:
    """The ``(len(starts), 3 × (horizons + 1))`` features of the windows of ``window_frames``
    frames from ``starts`` over the robot's ``(n, 3)`` poses: at each of :func:`horizon_frames`,
    then :data:`BEFORE_FRAMES` before the window, the robot's displacement from its pose at the
    window's first frame in its own frame there (forward mm, left mm) and its heading change
    (rad, in (−π, π]). A window that would run past the end is moved back to the last full
    one; frames before the first read the first.

    >>> poses = np.column_stack([np.arange(40.0), np.zeros(40), np.zeros(40)])  # 1 mm a frame along +x
    >>> transition_features(poses, np.array([10]))[0, :3].tolist()             # 2 frames on
    [2.0, 0.0, 0.0]
    """
    n = len(poses)
    first = np.minimum(np.asarray(starts, dtype=np.int64), max(n - window_frames, 0))
    x, y, theta = poses[first, 0], poses[first, 1], poses[first, 2]
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    columns = []
    for offset in (*horizon_frames(window_frames), -BEFORE_FRAMES):
        other = np.clip(first + offset, 0, n - 1)
        dx, dy = poses[other, 0] - x, poses[other, 1] - y
        columns += [cos_t * dx + sin_t * dy, -sin_t * dx + cos_t * dy,
                    np.angle(np.exp(1j * (poses[other, 2] - theta)))]
    return np.column_stack(columns)


def explore(imitator: BodySpec = IMITATOR_BODY, *, episodes: int = EXPLORATION_EPISODES,
            seed: int = 0) -> list[tuple[np.ndarray, np.ndarray]]:
    """``episodes`` exploration episodes of body ``imitator`` (see the module's documentation):
    per episode, its tracker frames and the primitive (an index into
    :data:`~polymimic.field.PRIMITIVES`) executed in each. Deterministic given ``seed``."""
    body = _check_imitator(imitator)
    rng = np.random.default_rng(_check_seed(seed))
    commands = [primitive_command(p, body) for p in PRIMITIVES]
    low, high = np.log(_HOLD_FRAMES[0]), np.log(_HOLD_FRAMES[1] + 1)
    explored = []
    for i in range(_check_count("episodes", episodes)):
        episode = Episode(body, configuration=1 + i % 2, seed=int(rng.integers(2**63)))
        executed: list[int] = []
        while len(executed) < EXPLORATION_FRAMES:
            hold = _ONE_SECOND if rng.random() < 0.5 else int(np.exp(rng.uniform(low, high)))
            executed += [int(rng.integers(len(PRIMITIVES)))] * hold
        for primitive in executed[:EXPLORATION_FRAMES]:
            episode.step(commands[primitive])
            if episode.finished:
                break
        frames = as_frames(episode.frames)
        explored.append((frames, np.array(executed[:len(frames)], dtype=np.int64)))
    return explored


def learn(imitator: BodySpec = IMITATOR_BODY, *, seed: int = 0, episodes: int = EXPLORATION_EPISODES,
          window_frames: int = WINDOW_FRAMES) -> InverseDynamics:
    """The inverse dynamics model of body ``imitator`` (the Lego robot by default) reading
    windows of ``window_frames`` frames, learned from ``episodes`` exploration episodes drawn
    with ``seed``. The same arguments give the same model (kept for the process's life: the
    exploration and fit take a few seconds).

    Raises
    ------
    ValueError
        For an unknown body, a window that is not an integer in 2..:data:`MAX_WINDOW_FRAMES`,
        ``episodes`` below 1, or a seed outside [0, 2**63).
    """
    return _learned(_check_imitator(imitator), _check_seed(seed), _check_count("episodes", episodes),
                    _check_window(window_frames))


@functools.lru_cache(maxsize=8)
def _learned(imitator: Body, seed: int, episodes: int, window_frames: int) -> InverseDynamics:
    features, executed = [], []
    for frames, primitives in explore(imitator, episodes=episodes, seed=seed):
        if len(frames) < window_frames + BEFORE_FRAMES:
            continue  # an episode that ended at once shows no window of motion
        starts = np.arange(0, len(frames) - window_frames + 1, WINDOW_STRIDE_FRAMES)
        features.append(transition_features(_poses(frames), starts, window_frames=window_frames))
        executed.append(primitives[starts])
    if not features:
        raise ValueError(f"no exploration episode of {imitator.name!r} lasted a window of {window_frames} frames; "
                         f"explore more episodes")
    model = make_classifier("hist_gradient_boosting", {"max_iter": 100}, seed=seed % 2**32)
    with threadpool_limits(limits=1):  # ten times faster than contending threads on a busy node
        model.fit(np.concatenate(features), np.concatenate(executed))
    return InverseDynamics(imitator=imitator, window_frames=window_frames, classifier=model)


def inverse_dynamics_labels(demonstrations: Sequence[Demonstration], model: InverseDynamics, *,
                            stride_frames: int = WINDOW_STRIDE_FRAMES,
                            frames: Sequence[np.ndarray] | None = None) -> list[Labelled]:
    """Frames labelled with the primitive ``model`` names for the window from them, as
    :func:`polymimic.baselines.labels.window_labels` names them with the recogniser: every
    ``stride_frames``-th frame from the first (the frames between carry the label of the one
    before), or, given ``frames`` (per demonstration, as
    :func:`~polymimic.baselines.training.sample_rows` draws them), those frames alone (every
    other without a label). Observations are on the field of the model's imitator."""
    demos = check_demonstrations(demonstrations)
    if not isinstance(model, InverseDynamics):
        raise ValueError(f"model must be an InverseDynamics (see learn), got {type(model).__name__}")
    stride_frames = _check_count("stride_frames", stride_frames)
    if frames is not None and len(frames) != len(demos):
        raise ValueError(f"frames must list the frames to name for each of the {len(demos)} demonstrations, "
                         f"got {len(frames)}")
    starts = [np.arange(0, len(d.frames), stride_frames) if frames is None
              else _checked_starts(frames[i], len(d.frames)) for i, d in enumerate(demos)]
    features = [model.features(d.frames, s) for d, s in zip(demos, starts)]
    # One prediction for every window: a classifier's call costs more than its rows.
    named = np.split(model.predict(np.concatenate(features)), np.cumsum([len(f) for f in features])[:-1])
    labelled = []
    for demo, rows, names in zip(demos, starts, named):
        n = len(demo.frames)
        if frames is None:
            labels = np.repeat(names, stride_frames)[:n]
        else:
            labels = np.full(n, NO_LABEL, dtype=np.int64)
            labels[rows] = names
        labelled.append(Labelled(demo.demonstrator, observations_of(demo, model.imitator), labels, demo.body,
                                 model.imitator))
    return labelled
