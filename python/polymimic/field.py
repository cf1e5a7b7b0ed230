"""The simulated field: demonstrations, self-observation and the commands of every controller.

Frames are numpy structured arrays with one named column per tracker value
(:data:`FRAME_DTYPE`), so ``frames["ball_x_mm"]`` reads a column and
``pandas.DataFrame(frames)`` makes a table. The field's configuration (:func:`check_config`,
:func:`default_config`) is :mod:`polymimic.field_config`'s, re-exported here.

>>> demos = record("expert", configuration=1, n=2, seed=7)
>>> demos[0].frames.dtype.names[:3]
('t_s', 'robot_x_mm', 'robot_y_mm')
>>> demos[0].outcome in {"goal", "own_goal", "ball_out", "robot_out", "time_up"}
True
>>> sequences = self_observation(3, seed=1)
>>> len(sequences), sequences[0].frames.shape
(15, (30,))
"""

from __future__ import annotations

import dataclasses
import numbers
from collections.abc import Sequence
from typing import Any, Literal

import numpy as np

from polymimic import _native
from polymimic._arguments import integer, probability
from polymimic.bodies import Body, BodySpec, WheeledBody, as_body
from polymimic.field_config import check_config as check_config
from polymimic.field_config import default_config as default_config
from polymimic.field_config import native_field_config
from polymimic.policies import policy_parts

FRAME_DTYPE = np.dtype([
    ("t_s", "f8"),
    ("robot_x_mm", "f8"),
    ("robot_y_mm", "f8"),
    ("robot_theta_rad", "f8"),
    ("ball_x_mm", "f8"),
    ("ball_y_mm", "f8"),
    ("command", "u2"),
])
"""Tracker frames: time, robot pose, ball position (NaN when none), and the id of the command
being sent (for evaluation only; see :func:`command_table`)."""

DEMONSTRATORS = ("expert", "poor", "tiny", "humanoid")
BODIES = {"expert": "lego", "poor": "lego", "tiny": "tiny", "humanoid": "humanoid", "average": "lego",
          "imitator": "lego"}
"""The body of every demonstrator polymimic knows, by name: ``lego`` (the imitator's own),
``tiny`` or ``humanoid``."""
PRIMITIVES = ("forward", "backward", "left", "right", "stop")
PRIMITIVE_SETS = {"wheeled": PRIMITIVES,
                  "humanoid": (*PRIMITIVES, "sidestep_left", "sidestep_right", "kick")}
"""A body's own primitives, by set: every wheeled body's five, and the humanoid's eight (its
walks, turns and standing still, its side-steps and its kick; a left and a right kick look
alike from above, and so do waiting and scanning)."""
WHEELED_EQUIVALENT = {"sidestep_left": "left", "sidestep_right": "right", "kick": "backward"}
"""The wheeled primitive each of the humanoid's own looks most like, as Table 4.4 has its
commands: a shuffle turns the body's outline the way a spin does, a kick leans it back."""
OUTCOMES = ("goal", "own_goal", "ball_out", "robot_out", "time_up")
OUTCOME_REWARDS = {"goal": 1.0, "own_goal": -1.0}
"""An attempt's return by its outcome (every other outcome 0): net goals, one attempt at a time."""
UNKNOWN_COMMAND = 65535
"""The ``command`` of a frame whose command was never recorded (a tracker log without a command
column): the largest ``u2``, far from every real id, so it is never read as a command. Whatever
needs the commands sent (:func:`primitives_sent`) refuses such frames."""

assert tuple(_native.FRAME_COLUMNS) == FRAME_DTYPE.names


def as_frames(array: np.ndarray) -> np.ndarray:
    """A ``(k, 7)`` float array in :data:`FRAME_DTYPE` column order, as structured frames."""
    frames = np.empty(len(array), dtype=FRAME_DTYPE)
    for i, name in enumerate(FRAME_DTYPE.fields or {}):
        frames[name] = array[:, i]
    return frames


BODY_NAMES = ("lego", "tiny", "humanoid")
"""The bodies of the simulated field; the small field is the ``tiny`` body's."""


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class Demonstration:
    """One recorded attempt at a penalty kick.

    ``body`` is the demonstrator's :class:`polymimic.Body`, given as one, as a built-in body's
    name (one of :data:`BODY_NAMES`) or as a :class:`polymimic.bodies.WheeledBody`; left empty,
    it is the body :func:`body_of` knows for ``demonstrator``, so a demonstrator of another name
    (a crowd's member, your own) names its body.

    >>> import numpy as np
    >>> frames = np.zeros(2, dtype=FRAME_DTYPE)
    >>> Demonstration(frames, "goal", "tiny", 1, 0).body
    Body('tiny')
    >>> Demonstration(frames, "goal", "tiny_03", 1, 0, body="tiny").demonstrator
    'tiny_03'
    >>> Demonstration(frames, "goal", "alice", 1, 0)
    Traceback (most recent call last):
    ...
    ValueError: unknown demonstrator 'alice': give its body (one of lego, tiny, humanoid) with body=
    """

    frames: np.ndarray
    outcome: str
    demonstrator: str
    configuration: int
    seed: int
    body: Body

    def __init__(self, frames: np.ndarray, outcome: str, demonstrator: str, configuration: int, seed: int,
                 body: BodySpec = "") -> None:
        if body == "":
            if demonstrator not in BODIES:
                raise ValueError(f"unknown demonstrator {demonstrator!r}: give its body (one of "
                                 f"{', '.join(BODY_NAMES)}) with body=")
            body = BODIES[demonstrator]
        for name, value in (("frames", frames), ("outcome", outcome), ("demonstrator", demonstrator),
                            ("configuration", configuration), ("seed", seed),
                            ("body", as_body(body, what=f"demonstration of {demonstrator!r}"))):
            object.__setattr__(self, name, value)

    def __repr__(self) -> str:
        return (f"Demonstration({self.demonstrator}, configuration={self.configuration}, "
                f"{len(self.frames)} frames, {self.outcome}, seed={self.seed})")

    @property
    def tracked_throughout(self) -> bool:
        """Whether the tracker saw the robot and the ball in every frame (what a recording
        needs to count as a demonstration)."""
        return all(bool(np.isfinite(self.frames[c]).all())
                   for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"))


@dataclasses.dataclass(frozen=True, eq=False, init=False)
class PrimitiveSequence:
    """One second of an imitator executing one primitive, as the tracker saw it, and the body
    that executed it.

    Attributes
    ----------
    primitive : str
        The primitive executed (``"forward"``, ``"backward"``, ``"left"``, ``"right"``,
        ``"stop"``, or one of the humanoid's own).
    frames : numpy structured array of shape (30,)
        The tracker's frames in :data:`FRAME_DTYPE`: ``t_s``, ``robot_x_mm``, ``robot_y_mm``,
        ``robot_theta_rad``, ``ball_x_mm``, ``ball_y_mm`` and ``command``.
    body : polymimic.Body
        The body that executed it (given as a Body, a built-in body's name or a
        :class:`polymimic.bodies.WheeledBody`; the Lego robot by default).
    """

    primitive: str
    frames: np.ndarray
    body: Body

    def __init__(self, primitive: str, frames: np.ndarray, body: BodySpec = "lego") -> None:
        object.__setattr__(self, "primitive", primitive)
        object.__setattr__(self, "frames", frames)
        object.__setattr__(self, "body", as_body(body, what=f"sequence of {primitive!r}"))


def body_of(demonstrator: str) -> str:
    """The body ``demonstrator`` has (see :data:`BODIES`); a ``ValueError`` for a name polymimic
    does not know.

    >>> body_of("poor"), body_of("tiny")
    ('lego', 'tiny')
    """
    try:
        return BODIES[demonstrator]
    except (KeyError, TypeError):
        raise ValueError(f"unknown demonstrator {demonstrator!r}: polymimic knows the bodies of "
                         f"{', '.join(BODIES)}") from None


def record(demonstrator: str | Any, *, configuration: int, n: int, seed: int = 0, lapse: float = 0.0,
           config: dict[str, Any] | str | None = None, body: BodySpec | None = None, name: str | None = None,
           decision_hz: float | None = None, timeout_s: float | None = 10.0) -> list[Demonstration]:
    """``n`` valid demonstrations of ``demonstrator`` from field ``configuration`` (1 or 2).

    A demonstration whose tracking was lost is discarded and replaced, deterministically.
    Built-in demonstrators run in parallel in Rust with the GIL released; a Python policy drives
    ``body`` on the Rust field, its episodes one after the other, the GIL held only while it is
    called.

    Parameters
    ----------
    demonstrator : str, ImitatorPolicy or policy
        A built-in's name (one of :data:`DEMONSTRATORS`); a trained imitator (a
        :class:`polymimic.ImitatorPolicy`, practised or not: it plays its own body, its
        demonstrations named ``name``, ``"imitator"`` by default); or a Python policy of your
        own: a callable ``policy(reading) -> command`` or an object with ``act`` (see
        :mod:`polymimic.policies`; an :class:`polymimic.ImitatorPlayer` is one).
    configuration : {1, 2}
        The field configuration every episode starts from (thesis Fig. 4.4).
    n : int
        Valid demonstrations to return, at least 1.
    seed : int
        Any integer in ``[0, 2**64)``; the same seed gives the same demonstrations.
    lapse : float
        A built-in's lapse rate ε in [0, 1] (docs/guides/crowd.md), a skill set by design: at
        the start of every second of an episode (tracker frames 0, 30, 60, …), with probability
        ε, the demonstrator spends that second on one uniformly random primitive instead of its
        controller's commands (on the humanoid, which takes no primitives, the equivalent walk
        forward or backward, turn left or right, or wait). The frames record the commands
        actually sent. The lapses are drawn from a random stream of their own under each
        episode's seed, so the episodes keep their seeds at every ε, and ``lapse=0.0`` is the
        controller's own demonstrations, bit for bit.
    config : dict or str, optional
        Field parameters laid over the default world (see :func:`default_config`).
    body : polymimic.Body, str or polymimic.bodies.WheeledBody, optional
        Puts a built-in controller on another body (a :class:`polymimic.Body`, one of
        :data:`BODY_NAMES` or a :class:`polymimic.bodies.WheeledBody`: Poor's and Tiny's
        primitives drive any wheeled body, the Expert's wheel speeds one that takes them, the
        humanoid's only the humanoid); a policy's body, required.
    name : str, optional
        The name the demonstrations carry (a built-in's own by default; required for a policy).
    decision_hz : float, optional
        How often a policy decides (a divisor of 30; its own ``decision_hz`` attribute by
        default, else every frame).
    timeout_s : float or None
        The longest a policy may take over one decision before it is interrupted (None: no
        limit).

    Returns
    -------
    list of Demonstration
        The demonstrations, each with its frames (30 a second), outcome, configuration, seed,
        demonstrator and body (a :class:`polymimic.Body`).

    Raises
    ------
    ValueError
        For an unknown demonstrator, a configuration other than 1 or 2, ``n`` below 1, a seed
        outside ``[0, 2**64)``, a ``lapse`` that is not a number in [0, 1]; for a policy, a
        missing body or name, or a ``decision_hz`` that does not divide 30.
    TypeError
        For a configuration, ``n`` or seed that is not an integer, or a demonstrator that is
        neither a name nor a policy.
    polymimic.PolicyError
        When a policy raises (its exception is the cause), answers with something that is not a
        command its body executes, or does not answer within ``timeout_s``; the message names
        the policy, the attempt, its seed and the episode time.

    Examples
    --------
    >>> sloppy = record("expert", configuration=1, n=1, seed=3, lapse=1.0)
    >>> bool((sloppy[0].frames["command"] <= 4).all())  # primitives only; the Expert's own are 100 up
    True

    A policy of your own:

    >>> import math
    >>> def chase(reading):  # turn toward the ball, then drive at it
    ...     bearing = math.atan2(reading.ball_y_mm - reading.robot_y_mm, reading.ball_x_mm - reading.robot_x_mm)
    ...     error = math.remainder(bearing - reading.robot_theta_rad, math.tau)
    ...     return "forward" if abs(error) < 0.3 else ("left" if error > 0 else "right")
    >>> mine = record(chase, body="lego", name="chaser", configuration=1, n=2, seed=3, decision_hz=10)
    >>> [(d.demonstrator, d.body.name) for d in mine]
    [('chaser', 'lego'), ('chaser', 'lego')]
    """
    configuration, n = integer("configuration", configuration, 1, 2), integer("n", n, 1)
    seed, lapse = integer("seed", seed, 0, 2**64 - 1), probability("lapse", lapse)
    if isinstance(demonstrator, _native.ImitatorPolicy):
        return _record_imitator(demonstrator, configuration=configuration, n=n, seed=seed, lapse=lapse,
                                config=config, body=body, name=name, decision_hz=decision_hz)
    if not isinstance(demonstrator, str):
        return _record_policy(demonstrator, configuration=configuration, n=n, seed=seed, lapse=lapse, config=config,
                              body=body, name=name, decision_hz=decision_hz, timeout_s=timeout_s)
    if demonstrator not in DEMONSTRATORS:
        raise ValueError(f"unknown demonstrator {demonstrator!r}; expected one of {', '.join(DEMONSTRATORS)} "
                         f"or a Python policy")
    if decision_hz is not None:
        raise ValueError(f"decision_hz= is for a Python policy; the built-in {demonstrator!r} decides every frame")
    driven = None if body is None else _checked_body(body)
    raw = _native.record_demonstrations(demonstrator, configuration=configuration, n=n, seed=seed, lapse=lapse,
                                        config=native_field_config(config), body=driven)
    who = demonstrator if name is None else _own_name(name, demonstrator)
    return _demonstrations(raw, who, BODIES[demonstrator] if driven is None else driven)


def _demonstrations(raw: list[dict[str, Any]], demonstrator: str, body: BodySpec) -> list[Demonstration]:
    """What the native recorders return, as demonstrations of ``demonstrator`` on ``body``."""
    body = as_body(body)
    return [Demonstration(frames=as_frames(d["frames"]), outcome=d["outcome"], demonstrator=demonstrator,
                          configuration=d["configuration"], seed=d["seed"], body=body) for d in raw]


def _checked_body(body: Any) -> Body:
    if not isinstance(body, (Body, WheeledBody)) and body not in BODY_NAMES:
        raise ValueError(f"body must be one of {', '.join(BODY_NAMES)} (built in), a polymimic.Body or a "
                         f"polymimic.bodies.WheeledBody; got {body!r}")
    return as_body(body)


def _own_name(name: Any, demonstrator: str) -> str:
    """A name for a built-in's demonstrations: a word, and no other built-in's."""
    if not isinstance(name, str) or not name.isidentifier():
        raise ValueError(f"name must be a word of letters, digits and _, got {name!r}")
    if name != demonstrator and name in BODIES:
        raise ValueError(f"name {name!r} is another demonstrator's; the {demonstrator}'s demonstrations need a name "
                         f"of their own")
    return name


def _record_imitator(policy: _native.ImitatorPolicy, *, configuration: int, n: int, seed: int, lapse: float,
                     config: dict[str, Any] | str | None, body: BodySpec | None, name: str | None,
                     decision_hz: float | None) -> list[Demonstration]:
    """A trained imitator's attempts, recorded in Rust as a demonstrator's (its own body)."""
    if lapse != 0.0:
        raise ValueError("lapse= is for the built-in demonstrators; an imitator plays as it learned to")
    if decision_hz is not None:
        raise ValueError("decision_hz= is for a Python policy; an imitator holds each primitive for a second")
    if body is not None and as_body(body) != policy.body:
        raise ValueError(f"body={as_body(body).name!r}, but the imitator drives the {policy.body.name!r} body; leave "
                         f"body= out")
    who = "imitator" if name is None else _own_name(name, "imitator")
    raw = policy.record(configuration=configuration, n=n, seed=seed, field_config=native_field_config(config))
    return _demonstrations(raw, who, policy.body)


def _record_policy(policy: Any, *, configuration: int, n: int, seed: int, lapse: float,
                   config: dict[str, Any] | str | None, body: BodySpec | None, name: str | None,
                   decision_hz: float | None, timeout_s: float | None) -> list[Demonstration]:
    parts = policy_parts(policy, decision_hz=decision_hz, name=name, reserved=tuple(BODIES))
    if body is None:
        raise ValueError(f"a Python demonstrator needs its body: body= one of {', '.join(BODY_NAMES)} or a "
                         f"polymimic.bodies.WheeledBody")
    driven = _checked_body(body)
    if lapse != 0.0:
        raise ValueError("lapse= is for the built-in demonstrators; a Python policy lapses as it is written to")
    if timeout_s is not None and (isinstance(timeout_s, bool) or not isinstance(timeout_s, numbers.Real)):
        raise TypeError(f"timeout_s must be a number of seconds or None, got {timeout_s!r}")
    raw = _native.record_python_policy(parts.act, parts.reset, name=parts.name, body=driven,
                                       configuration=configuration,
                                       n=n, seed=seed, decision_hz=parts.decision_hz,
                                       timeout_s=None if timeout_s is None else float(timeout_s),
                                       config=native_field_config(config))
    return _demonstrations(raw, parts.name, driven)


def self_observation(n_per_primitive: int, *, seed: int = 0, config: dict[str, Any] | str | None = None,
                     body: BodySpec = "lego",
                     primitives: Literal["wheeled", "own"] = "wheeled") -> list[PrimitiveSequence]:
    """An imitator alone on its body's field executing random one-second primitives: exactly
    ``n_per_primitive`` valid sequences of each of forward, backward, left, right and stop.

    ``body`` is the imitator's: the Lego robot by default (the thesis's), the ``"tiny"`` on the
    small field, a :class:`polymimic.bodies.WheeledBody`, or the ``"humanoid"``, which executes
    each primitive as its walking, turning or waiting equivalent.

    ``primitives="own"`` babbles the body's own primitives instead (:data:`PRIMITIVE_SETS`):
    a wheeled body's are the five, the humanoid's add ``sidestep_left``, ``sidestep_right``
    and ``kick``, the classes of its commands an overhead tracker tells apart. A kick shows
    only with a ball: before each one the experimenter puts a ball before the kicking foot,
    and only a kick's frames hold a ball. This is the thesis's self-observation (thesis §3.1.1).

    Parameters
    ----------
    n_per_primitive : int
        Valid sequences of each primitive, at least 1 (the thesis trains on 1000).
    seed : int
        Any integer in ``[0, 2**64)``.
    config : dict or str, optional
        Field parameters laid over the default world (see :func:`default_config`).
    body : polymimic.Body, str or polymimic.bodies.WheeledBody
        The imitator's body.
    primitives : {"wheeled", "own"}
        The wheeled five, or the body's own set.

    Returns
    -------
    list of PrimitiveSequence
        Each sequence's frames (one second: 30 tracker frames), its primitive and body.

    Examples
    --------
    >>> sequences = self_observation(1, seed=0, body="tiny")
    >>> sorted(s.primitive for s in sequences), sequences[0].body.name
    (['backward', 'forward', 'left', 'right', 'stop'], 'tiny')
    >>> own = self_observation(1, seed=0, body="humanoid", primitives="own")
    >>> sorted(s.primitive for s in own)
    ['backward', 'forward', 'kick', 'left', 'right', 'sidestep_left', 'sidestep_right', 'stop']
    """
    driven = _checked_body(body)
    if primitives not in ("wheeled", "own"):
        raise ValueError(f"primitives must be 'wheeled' or 'own', got {primitives!r}")
    frames, primitives_run = _native.record_self_observation(integer("n_per_primitive", n_per_primitive, 1),
                                                             seed=integer("seed", seed, 0, 2**64 - 1),
                                                             config=native_field_config(config), body=driven,
                                                             primitives=primitives)
    return [PrimitiveSequence(primitive=p, frames=as_frames(f), body=driven)
            for f, p in zip(frames, primitives_run)]


def primitive_set_of(sequences: Sequence[PrimitiveSequence]) -> Literal["wheeled", "humanoid"]:
    """The set of primitives ``sequences`` were babbled over: the humanoid's when they hold one
    of its own (a side-step or a kick), else the wheeled five.

    >>> primitive_set_of(self_observation(1, body="humanoid", primitives="own"))
    'humanoid'
    """
    wheeled = set(PRIMITIVE_SETS["wheeled"])
    return "humanoid" if any(s.primitive not in wheeled for s in sequences) else "wheeled"


def command_table() -> list[dict[str, Any]]:
    """Every command of every controller (id, name, language) with its equivalent primitive.

    Returns
    -------
    list of dict
        One ``{"id", "name", "language", "primitive"}`` per command: the five primitives
        (language ``"primitive"``), the Expert's named wheel-speed pairs (``"expert"``), the
        wheel-speed pairs a Python policy sends, by the primitive they resemble (``"wheels"``),
        and the humanoid's commands (``"humanoid"``), each with the primitive it resembles
        (thesis Table 4.4 for the humanoid's).
    """
    return list(_native.commands())


def primitive_command(primitive: str, body: BodySpec = "lego") -> str:
    """The name of the command that has ``body`` execute ``primitive``: the primitive itself on
    a wheeled body, its walking, turning or waiting equivalent on the humanoid.

    >>> primitive_command("left"), primitive_command("left", "humanoid"), primitive_command("stop", "humanoid")
    ('left', 'Turn Left', 'Wait')
    """
    return _native.primitive_command(primitive, as_body(body))


def command_primitives() -> np.ndarray:
    """A lookup array: ``command_primitives()[frames["command"]]`` names each frame's primitive.

    It has no entry for :data:`UNKNOWN_COMMAND`; :func:`primitives_sent` checks for it first."""
    table = command_table()
    lookup = np.full(max(row["id"] for row in table) + 1, "", dtype=object)
    for row in table:
        lookup[row["id"]] = row["primitive"]
    return lookup


def commands_recorded(demonstration: Demonstration) -> bool:
    """Whether every frame of ``demonstration`` records the command sent (a tracker log without
    a command column records none: :data:`UNKNOWN_COMMAND`)."""
    return not bool((demonstration.frames["command"] == UNKNOWN_COMMAND).any())


def primitives_sent(demonstration: Demonstration) -> np.ndarray:
    """The equivalent primitive of the command sent in each of ``demonstration``'s frames; a
    ``ValueError`` for a demonstration whose commands were not recorded (:data:`UNKNOWN_COMMAND`,
    as in a tracker log without a command column), so that nothing is measured against
    commands nobody knows.

    >>> demo = record("poor", configuration=1, n=1, seed=2)[0]
    >>> set(primitives_sent(demo)) <= set(PRIMITIVES)
    True
    >>> demo.frames["command"] = UNKNOWN_COMMAND
    >>> primitives_sent(demo)
    Traceback (most recent call last):
    ...
    ValueError: demonstration of 'poor' (seed ...) has no recorded commands ...
    """
    commands = demonstration.frames["command"].astype(np.int64)
    if not commands_recorded(demonstration):
        unknown = np.flatnonzero(commands == UNKNOWN_COMMAND)
        raise ValueError(f"demonstration of {demonstration.demonstrator!r} (seed {demonstration.seed}) has no "
                         f"recorded commands (frame {int(unknown[0])} on, {unknown.size} frames in all): it was "
                         "imported without a command column; measures against the commands sent (command "
                         "match, behavioural cloning on commands) need a log that has one")
    lookup = command_primitives()
    beyond = np.flatnonzero(commands >= len(lookup))
    if beyond.size:
        raise ValueError(f"demonstration of {demonstration.demonstrator!r} (seed {demonstration.seed}) has command "
                         f"id {int(commands[beyond[0]])} in frame {int(beyond[0])}, which no controller has; see "
                         "polymimic.command_table()")
    sent: np.ndarray = lookup[commands]
    return sent
