"""Demonstrations as offline reinforcement learning reads them: transitions between decision
samples, actions as ``bco`` labels them, and rewards read off the frames.

Each demonstration gives one episode: its labelled decision samples in order (the frames a
``bco`` fit of the same seed and size takes, labelled as it labels them:
:func:`polymimic.baselines.bco.labelled`; a frame without a label, a gap, is passed over), each
a state and the action taken there, the next sample's state the state it led to. The commands
the demonstrator sent are never read.

The reward is the outcome, read off the tracker frames as a learner from observation alone
would read it: the demonstration's last reading of the ball (:func:`outcome_read`) past the
target goal's line within its mouth is a goal, +1 on the episode's last transition; past the
own goal's line, an own goal, −1; past a line outside the mouth or over a side line, the ball
out, 0; the robot's last reading over a line, the robot out, 0; any of these ends the episode
(terminal). Elsewhere time ran out: reward 0 and the episode is cut short, not ended (a
timeout), so no value is learned for its last state.

>>> import polymimic
>>> frames = polymimic.record("poor", configuration=1, n=1, seed=0)[0].frames.copy()
>>> last = frames[len(frames) - 1:]
>>> last["ball_x_mm"], last["ball_y_mm"] = -510.4, 30.0   # the ball last seen in the own goal
>>> outcome = outcome_read(frames, body="lego")
>>> outcome, REWARDS[outcome]
('own_goal', -1.0)
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np

from polymimic.baselines.labels import NO_LABEL, Labelled
from polymimic.bodies import BodySpec, as_body
from polymimic.field import Demonstration
from polymimic.window_names import repeat_last_good

__all__ = ["ENDINGS", "LINE_TOLERANCE_MM", "REWARDS", "Transitions", "outcome_read", "transitions"]

REWARDS = {"goal": 1.0, "own_goal": -1.0, "ball_out": 0.0, "robot_out": 0.0, "time_up": 0.0}
"""The reward of each outcome read off the frames, given on an episode's last transition."""

ENDINGS = ("goal", "own_goal", "ball_out", "robot_out")
"""The outcomes that end an episode (terminal); ``time_up`` cuts it short instead."""

LINE_TOLERANCE_MM = 1.0
"""How far short of a line a last reading may lie and still count as past it: a recording
stops at the frame the ball (or the robot) crosses, read with the tracker's noise (on crowds of
every body, the last readings of goals lay from 0.3 mm short of the line to 0.6 mm past it)."""


def outcome_read(frames: np.ndarray, *, body: BodySpec) -> str:
    """The outcome of an episode read off its tracker ``frames`` on the field of ``body`` (the
    last readings of its ball and robot; a lost reading repeats the last good one): ``"goal"``,
    ``"own_goal"``, ``"ball_out"``, ``"robot_out"`` or ``"time_up"`` (both still on the field).

    Raises
    ------
    ValueError
        If ``frames`` holds no frame, or never a reading of the ball.
    """
    if len(frames) == 0:
        raise ValueError("frames is empty: an outcome is read off the ball's last reading")
    ball = repeat_last_good(np.column_stack([frames["ball_x_mm"], frames["ball_y_mm"]]).astype(np.float64))[-1]
    if not np.isfinite(ball).all():
        raise ValueError("frames never read the ball: no outcome can be read off them")
    field = as_body(body).field
    x_mm, y_mm = float(ball[0]), float(ball[1])
    if abs(x_mm) >= field.half_length_mm - LINE_TOLERANCE_MM:
        if abs(y_mm) <= field.goal_half_mouth_mm:
            return "goal" if x_mm > 0 else "own_goal"
        return "ball_out"
    if abs(y_mm) >= field.half_width_mm - LINE_TOLERANCE_MM:
        return "ball_out"
    robot = repeat_last_good(np.column_stack([frames["robot_x_mm"], frames["robot_y_mm"]]).astype(np.float64))[-1]
    if abs(float(robot[0])) >= field.half_length_mm - LINE_TOLERANCE_MM \
            or abs(float(robot[1])) >= field.half_width_mm - LINE_TOLERANCE_MM:
        return "robot_out"
    return "time_up"


@dataclasses.dataclass(frozen=True, eq=False)
class Transitions:
    """Episodes laid end to end, as d3rlpy's ``MDPDataset`` takes them.

    Attributes
    ----------
    observations : ndarray, shape (n, 5)
        Each decision sample's observation, on the imitator's field.
    actions : ndarray of int64, shape (n,)
        The primitive labelled there (an index into :data:`polymimic.field.PRIMITIVES`).
    rewards : ndarray of float64, shape (n,)
        0 but on an episode's last sample: :data:`REWARDS` of its outcome.
    terminals, timeouts : ndarray of float64, shape (n,)
        1 on the last sample of an episode that ended (:data:`ENDINGS`) or was cut short.
    outcomes : list of str
        Each episode's outcome, as read (:func:`outcome_read`).
    """

    observations: np.ndarray
    actions: np.ndarray
    rewards: np.ndarray
    terminals: np.ndarray
    timeouts: np.ndarray
    outcomes: list[str]

    def __post_init__(self) -> None:
        n = len(self.actions)
        for name in ("rewards", "terminals", "timeouts"):
            if getattr(self, name).shape != (n,):
                raise ValueError(f"{name} must be ({n},) for {n} actions, got {getattr(self, name).shape}")
        if self.observations.shape != (n, 5):
            raise ValueError(f"observations must be ({n}, 5) for {n} actions, got {self.observations.shape}")


def transitions(demonstrations: Sequence[Demonstration], labelled: Sequence[Labelled]) -> Transitions:
    """The episodes of ``demonstrations``, each of its labelled samples in ``labelled`` (one per
    demonstration, in the same order, as :func:`polymimic.baselines.bco.labelled` gives them),
    rewarded by the outcome read off its frames. A demonstration with no labelled sample gives
    no episode, nor one cut short with a single sample (it holds no transition).

    Raises
    ------
    ValueError
        If the two sequences differ in length or a pair is of different demonstrators, or no
        episode remains.
    """
    if len(demonstrations) != len(labelled):
        raise ValueError(f"labelled must hold one item per demonstration ({len(demonstrations)}), got {len(labelled)}")
    parts: list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = []
    outcomes: list[str] = []
    for index, (demo, item) in enumerate(zip(demonstrations, labelled)):
        if demo.demonstrator != item.demonstrator or len(demo.frames) != len(item.labels):
            raise ValueError(f"labelled[{index}] is {item.demonstrator!r}'s ({len(item.labels)} frames), not the "
                             f"labelling of demonstrations[{index}] ({demo.demonstrator!r}, {len(demo.frames)} frames)")
        rows = np.flatnonzero(item.labels != NO_LABEL)
        outcome = outcome_read(demo.frames, body=demo.body)
        ends = outcome in ENDINGS
        if len(rows) == 0 or (len(rows) == 1 and not ends):
            continue
        rewards, terminals, timeouts = np.zeros(len(rows)), np.zeros(len(rows)), np.zeros(len(rows))
        rewards[-1] = REWARDS[outcome]
        (terminals if ends else timeouts)[-1] = 1.0
        parts.append((item.observations[rows], item.labels[rows].astype(np.int64), rewards, terminals, timeouts))
        outcomes.append(outcome)
    if not parts:
        raise ValueError("no episode to learn from: no demonstration has a labelled sample (all gaps)")
    observations, actions, rewards, terminals, timeouts = (np.concatenate(column) for column in zip(*parts))
    return Transitions(observations, actions, rewards, terminals, timeouts, outcomes)
