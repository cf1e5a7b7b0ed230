"""Bodies as data (docs/guides/own-data.md): a two-wheeled robot of your own, described by its constants.

A :class:`WheeledBody` is a robot's size, wheel base, top wheel speed, motor lag and slip, and
the field it plays on (``"large"``, 1020 × 810 mm with a 100 mm ball, or ``"small"``, 560 × 345
mm with a 25 mm ball). It drives with the imitator's five primitives, whose wheel speeds you may
give or leave to be derived from the top speed. Pass it wherever a body is asked for:
:func:`polymimic.record` (a Python policy, or the built-in Poor, Tiny and, on a body that takes
its wheel speeds, Expert controllers) and :class:`polymimic.Episode`. The thesis's Lego and tiny
robots are two entries of :data:`THESIS_BODIES`, with the constants the field was calibrated
with: a body equal to one of them is that body, bit for bit.

>>> import polymimic
>>> rover = WheeledBody("rover", length_mm=200, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=150)
>>> rover.primitives_mm_s["forward"], rover.primitives_mm_s["left"]
((60.0, 60.0), (-52.5, 52.5))
>>> demos = polymimic.record("poor", body=rover, configuration=1, n=1, seed=0)
>>> demos[0].demonstrator, demos[0].body.name, demos[0].body.description is rover
('poor', 'rover', True)

In a TOML file, each body is a table (see :func:`bodies_from_tables`)::

    [bodies.rover]
    length_mm = 200
    width_mm = 180
    wheel_base_mm = 160
    top_wheel_speed_mm_s = 150
    motor_lag_s = 0.1
    slip = { common_sd = 0.2, differential_sd = 0.04 }
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Iterable, Mapping
from typing import Any, Union

import numpy as np
import numpy.typing as npt

from polymimic import _native
from polymimic.body_parts import Field, Slip
from polymimic.body_parts import number_in as _number_in

__all__ = ["FIELDS", "THESIS_BODIES", "THESIS_BODY_FIELDS", "BodiesGiven", "Body", "BodySpec", "Field", "Slip",
           "WheeledBody", "as_body", "bodies_by_name", "bodies_from_tables", "body_named", "onto_field"]

Body = _native.Body

PRIMITIVE_NAMES = ("forward", "backward", "left", "right", "stop")
FIELDS = ("large", "small")
"""The fields a body may play on: the thesis's large field (Lego, humanoid) and small one (tiny)."""

DRIVE_FRACTION = 0.4
"""Derived primitives: forward and backward run both wheels at this fraction of the top speed,"""
SPIN_FRACTION = 0.35
"""and left and right spin on the spot with the wheels at this fraction, opposite ways (the Lego's
calibrated primitives run at 0.37–0.47 and 0.33–0.41 of its top speed)."""

THESIS_BODY_FIELDS = {"lego": "large", "tiny": "small", "humanoid": "large"}
"""The thesis's bodies and the fields they play on."""


def _known_keys(what: str, mapping: Mapping[str, Any], known: tuple[str, ...]) -> None:
    for key in mapping:
        if key not in known:
            raise ValueError(f"unknown key {what}.{key}; known: {', '.join(known)}")


SlipSpec = Union[Slip, Mapping[str, Slip]]
FieldSpec = Union[str, Field]


@dataclasses.dataclass(frozen=True)
class WheeledBody:
    """A two-wheeled robot: every length in mm, speed in mm/s, lag in s.

    ``motor_lag_s`` and ``turn_lag_s`` are the time constants with which the robot's forward
    speed and turn rate follow its wheels (its mass, its yaw inertia). ``slip`` is one
    :class:`Slip` for every primitive or a mapping from primitive name to one.
    ``primitives_mm_s`` maps each primitive to its (left, right) wheel speeds, every one within
    the top speed and ``stop`` at rest; left out, they are derived (:data:`DRIVE_FRACTION`,
    :data:`SPIN_FRACTION`). ``expert_commands`` lets the Expert's wheel-speed language drive
    the body (it needs a top speed of at least 130 mm/s, the Expert's sprint).

    Every value is checked when the body is made: a ``ValueError`` names the constant and what
    is allowed.

    >>> WheeledBody("flat", length_mm=0, width_mm=10, wheel_base_mm=8, top_wheel_speed_mm_s=20)
    Traceback (most recent call last):
    ...
    ValueError: body 'flat': length_mm must be a positive number, got 0
    """

    name: str
    length_mm: float
    width_mm: float
    wheel_base_mm: float
    top_wheel_speed_mm_s: float
    motor_lag_s: float = 0.1
    turn_lag_s: float = 0.03
    slip: SlipSpec = Slip()
    primitives_mm_s: Mapping[str, tuple[float, float]] = dataclasses.field(default_factory=dict)
    field: FieldSpec = "large"
    expert_commands: bool = False
    fresh_slip_frames: int = 30

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.isidentifier():
            raise ValueError(f"a body's name must be a word of letters, digits and _, got {self.name!r}")
        try:
            for key in ("length_mm", "width_mm", "wheel_base_mm", "top_wheel_speed_mm_s", "motor_lag_s",
                        "turn_lag_s"):
                _number_in(key, getattr(self, key), 0.0, 1e6, open_low=True)
            if not isinstance(self.field, Field) and self.field not in FIELDS:
                raise ValueError(f"field must be one of {', '.join(FIELDS)} or a polymimic.bodies.Field, got "
                                 f"{self.field!r}")
            if not isinstance(self.expert_commands, bool):
                raise ValueError(f"expert_commands must be true or false, got {self.expert_commands!r}")
            if self.expert_commands and self.top_wheel_speed_mm_s < 130:
                raise ValueError(f"expert_commands needs a top_wheel_speed_mm_s of at least 130 (the Expert's "
                                 f"sprint), got {self.top_wheel_speed_mm_s}")
            if isinstance(self.fresh_slip_frames, bool) or not isinstance(self.fresh_slip_frames, int) or \
                    self.fresh_slip_frames < 1:
                raise ValueError(f"fresh_slip_frames must be a whole number ≥ 1, got {self.fresh_slip_frames!r}")
            self._check_fits_its_field()
            object.__setattr__(self, "primitives_mm_s", self._checked_primitives())
            object.__setattr__(self, "slip", self._checked_slip())
        except ValueError as error:
            raise ValueError(f"body {self.name!r}: {error}") from None
        self._check_not_a_thesis_body_renamed()

    def _check_not_a_thesis_body_renamed(self) -> None:
        """A thesis body's name stands for the thesis's constants alone: were it to stand for
        others too, what a file of that body's demonstrations holds would depend on who reads it."""
        if _building_thesis_bodies or self.name not in THESIS_BODY_FIELDS:
            return
        thesis = THESIS_BODIES.get(self.name)
        if thesis is None:
            raise ValueError(f"body name {self.name!r} is the thesis's; give your body a name of its own")
        if thesis != self:
            raise ValueError(f"body {self.name!r} is already described with other constants; give this one "
                             f"another name")

    def _check_fits_its_field(self) -> None:
        """The robot must fit between its start and the ball: a third of the field's length
        apart in both configurations."""
        field = _field_of(self)
        room_mm = field.length_mm / 3 - field.ball_diameter_mm / 2
        if self.length_mm / 2 >= room_mm or self.width_mm >= field.width_mm:
            raise ValueError(f"a {self.length_mm:g} × {self.width_mm:g} mm body does not fit the {field.length_mm:g} × "
                             f"{field.width_mm:g} mm field: half its length must be under {room_mm:g} mm (a third of "
                             f"the field's length, less the ball's radius) and its width under the field's")

    def __hash__(self) -> int:
        return hash(self._native_body())

    def _checked_primitives(self) -> dict[str, tuple[float, float]]:
        given = dict(self.primitives_mm_s)
        _known_keys("primitives_mm_s", given, PRIMITIVE_NAMES)
        top = float(self.top_wheel_speed_mm_s)
        drive, spin = DRIVE_FRACTION * top, SPIN_FRACTION * top
        derived = {"forward": (drive, drive), "backward": (-drive, -drive), "left": (-spin, spin),
                   "right": (spin, -spin), "stop": (0.0, 0.0)}
        out = {}
        for name in PRIMITIVE_NAMES:
            pair = given.get(name, derived[name])
            if not isinstance(pair, (tuple, list)) or len(pair) != 2:
                raise ValueError(f"primitives_mm_s.{name} must be a (left, right) pair of wheel speeds, got {pair!r}")
            left, right = (_number_in(f"primitives_mm_s.{name}", v, -top, top) for v in pair)
            out[name] = (left, right)
        if out["stop"] != (0.0, 0.0):
            raise ValueError(f"primitives_mm_s.stop must be (0, 0), got {out['stop']}")
        # An imitator names what it sees by its own primitives, so no two may move alike.
        moving = [name for name in PRIMITIVE_NAMES if name != "stop"]
        for i, name in enumerate(moving):
            for other in [*moving[i + 1:], "stop"]:
                if out[name] == out[other]:
                    raise ValueError(f"primitives_mm_s.{name} and primitives_mm_s.{other} are both {out[name]}: a "
                                     f"recogniser cannot tell them apart, so every moving primitive needs wheel "
                                     f"speeds of its own")
        return out

    def _checked_slip(self) -> SlipSpec:
        if isinstance(self.slip, Slip):
            return self.slip
        if not isinstance(self.slip, Mapping):
            raise ValueError(f"slip must be a Slip or a mapping from primitive name to one, got {self.slip!r}")
        _known_keys("slip", self.slip, PRIMITIVE_NAMES)
        missing = [p for p in PRIMITIVE_NAMES if p not in self.slip]
        if missing:
            raise ValueError(f"slip by primitive lacks {', '.join(missing)}")
        for name, value in self.slip.items():
            if not isinstance(value, Slip):
                raise ValueError(f"slip.{name} must be a Slip, got {value!r}")
        return dict(self.slip)

    def slip_of(self, primitive: str) -> Slip:
        """The slip of one primitive."""
        return self.slip if isinstance(self.slip, Slip) else self.slip[primitive]

    def _native_body(self) -> tuple[str, str]:
        """The constants as the field reads them, and the field's name."""
        constants = {
            "name": self.name,
            "length_mm": float(self.length_mm),
            "width_mm": float(self.width_mm),
            "wheel_base_mm": float(self.wheel_base_mm),
            "primitive_wheels_mm_s": [list(self.primitives_mm_s[p]) for p in PRIMITIVE_NAMES],
            "traction": [{"common_sd": float(self.slip_of(p).common_sd),
                          "differential_sd": float(self.slip_of(p).differential_sd)} for p in PRIMITIVE_NAMES],
            "tau_linear_s": float(self.motor_lag_s),
            "tau_angular_s": float(self.turn_lag_s),
            "traction_refresh_frames": self.fresh_slip_frames,
            "accepts_expert_commands": self.expert_commands,
            "top_wheel_speed_mm_s": float(self.top_wheel_speed_mm_s),
        }
        field = self.field if isinstance(self.field, str) else json.dumps(self.field.sizes())
        return json.dumps(constants), field

    def to_table(self) -> dict[str, Any]:
        """The body as a TOML table (:meth:`from_table` reads it back equal).

        >>> cart = WheeledBody("cart", length_mm=90, width_mm=80, wheel_base_mm=70, top_wheel_speed_mm_s=60)
        >>> WheeledBody.from_table("cart", cart.to_table()) == cart
        True
        """
        slip: Any = (dataclasses.asdict(self.slip) if isinstance(self.slip, Slip)
                     else {p: dataclasses.asdict(s) for p, s in self.slip.items()})
        table = {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.name not in ("name", "slip",
                                                                                                   "primitives_mm_s")}
        if isinstance(self.field, Field):
            table["field"] = self.field.sizes()
        return {**table, "slip": slip, "primitives_mm_s": {p: list(w) for p, w in self.primitives_mm_s.items()}}

    @classmethod
    def from_table(cls, name: str, table: Mapping[str, Any], *, where: str = "") -> WheeledBody:
        """A body from a TOML table (``[bodies.<name>]``): the constructor's keywords, ``slip``
        as ``{common_sd, differential_sd}`` (or one such table per primitive) and
        ``primitives_mm_s`` as ``{forward = [l, r], …}``. A ``ValueError`` names ``where`` and
        the key for anything unknown or out of range.

        >>> WheeledBody.from_table("cart", {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70,
        ...                                 "top_wheel_speed_mm_s": 60, "colour": "red"}, where="[bodies.cart]")
        Traceback (most recent call last):
        ...
        ValueError: [bodies.cart]: unknown key 'colour'; known keys: length_mm, width_mm, ...
        """
        where = where or f"[bodies.{name}]"
        if not isinstance(table, Mapping):
            raise ValueError(f"{where} must be a table, got {table!r}")
        known = [f.name for f in dataclasses.fields(cls) if f.name != "name"]
        for key in table:
            if key not in known:
                raise ValueError(f"{where}: unknown key {key!r}; known keys: {', '.join(known)}")
        values = dict(table)
        if "slip" in values:
            values["slip"] = _slip_from(values["slip"], where)
        if isinstance(values.get("field"), Mapping):
            sizes = values["field"]
            unknown = [k for k in sizes if k not in ("length_mm", "width_mm", "goal_mouth_mm", "ball_diameter_mm")]
            if unknown:
                raise ValueError(f"{where}: unknown key field.{unknown[0]!r}; known keys: length_mm, width_mm, "
                                 f"goal_mouth_mm, ball_diameter_mm")
            try:
                values["field"] = Field(**sizes)
            except (TypeError, ValueError) as error:
                raise ValueError(f"{where}: {error}") from None
        if "primitives_mm_s" in values:
            primitives = values["primitives_mm_s"]
            if not isinstance(primitives, Mapping):
                raise ValueError(f"{where}: primitives_mm_s must be a table of (left, right) pairs, got {primitives!r}")
            values["primitives_mm_s"] = {k: tuple(v) if isinstance(v, list) else v for k, v in primitives.items()}
        try:
            return cls(name, **values)
        except TypeError as error:
            raise ValueError(f"{where}: {error}") from None
        except ValueError as error:
            raise ValueError(f"{where}: {error}") from None


    @classmethod
    def _from_native(cls, constants: str, field_sizes: str) -> WheeledBody:
        """The description of a body the native side hands back: its constants and its field's
        sizes as JSON (a thesis field's by its name)."""
        c, sizes = json.loads(constants), Field(**json.loads(field_sizes))
        field: FieldSpec = next((name for name in FIELDS if _thesis_field(name) == sizes), sizes)
        return cls(c["name"], length_mm=c["length_mm"], width_mm=c["width_mm"], wheel_base_mm=c["wheel_base_mm"],
                   top_wheel_speed_mm_s=c["top_wheel_speed_mm_s"], motor_lag_s=c["tau_linear_s"],
                   turn_lag_s=c["tau_angular_s"],
                   slip={p: Slip(**t) for p, t in zip(PRIMITIVE_NAMES, c["traction"])},
                   primitives_mm_s={p: tuple(w) for p, w in zip(PRIMITIVE_NAMES, c["primitive_wheels_mm_s"])},
                   field=field, expert_commands=c["accepts_expert_commands"],
                   fresh_slip_frames=c["traction_refresh_frames"])


BodySpec = Union[str, WheeledBody, Body]
"""A body as every function asks for one: a :class:`polymimic.Body`, a built-in body's name, or
a :class:`WheeledBody`."""
BodiesGiven = Union[Iterable[Union[WheeledBody, Body]], Mapping[str, Union[WheeledBody, Body]]]
"""The bodies of one's own a reader of files is given: the bodies, or a mapping from their
names to them (as a run config's ``bodies``)."""


def _thesis_field(name: str) -> Field:
    """A thesis field's sizes (``"large"`` or ``"small"``): the field its body plays on."""
    return Body("lego" if name == "large" else "tiny").field


def _field_of(body: WheeledBody) -> Field:
    """The sizes of the field ``body`` plays on."""
    return body.field if isinstance(body.field, Field) else _thesis_field(body.field)


def _slip_from(value: Any, where: str) -> SlipSpec:
    def one(table: Any, key: str) -> Slip:
        if not isinstance(table, Mapping):
            raise ValueError(f"{where}: {key} must be a table {{common_sd, differential_sd}}, got {table!r}")
        unknown = [k for k in table if k not in ("common_sd", "differential_sd")]
        if unknown:
            raise ValueError(f"{where}: unknown key {key}.{unknown[0]!r}; known keys: common_sd, differential_sd")
        try:
            return Slip(**table)
        except ValueError as error:
            raise ValueError(f"{where}: {error}") from None
    if isinstance(value, Mapping) and set(value) <= set(PRIMITIVE_NAMES) and value:
        return {name: one(table, f"slip.{name}") for name, table in value.items()}
    return one(value, "slip")


def bodies_from_tables(tables: Mapping[str, Any]) -> dict[str, WheeledBody]:
    """Every ``[bodies.<name>]`` table of a parsed TOML file (the ``bodies`` table itself) as a
    body. A thesis body's name may be used only for the thesis's own constants.

    >>> import tomllib
    >>> text = '[bodies.cart]\\nlength_mm = 90\\nwidth_mm = 80\\nwheel_base_mm = 70\\ntop_wheel_speed_mm_s = 60\\n'
    >>> bodies_from_tables(tomllib.loads(text)["bodies"])["cart"].primitives_mm_s["forward"]
    (24.0, 24.0)
    """
    if not isinstance(tables, Mapping):
        raise ValueError(f"[bodies] must hold one table per body, got {tables!r}")
    return {name: WheeledBody.from_table(name, table) for name, table in tables.items()}


def _thesis_bodies() -> dict[str, WheeledBody]:
    out = {}
    for name, text in _native.thesis_wheeled_bodies():
        c = json.loads(text)
        out[name] = WheeledBody(
            name, length_mm=c["length_mm"], width_mm=c["width_mm"], wheel_base_mm=c["wheel_base_mm"],
            top_wheel_speed_mm_s=c["top_wheel_speed_mm_s"], motor_lag_s=c["tau_linear_s"],
            turn_lag_s=c["tau_angular_s"],
            slip={p: Slip(**t) for p, t in zip(PRIMITIVE_NAMES, c["traction"])},
            primitives_mm_s={p: tuple(w) for p, w in zip(PRIMITIVE_NAMES, c["primitive_wheels_mm_s"])},
            field=THESIS_BODY_FIELDS[name], expert_commands=c["accepts_expert_commands"],
            fresh_slip_frames=c["traction_refresh_frames"])
    return out


_building_thesis_bodies = True  # while THESIS_BODIES are made, the check of a thesis body's name waits for them

THESIS_BODIES: dict[str, WheeledBody] = _thesis_bodies()
"""The thesis's two wheeled bodies, ``lego`` and ``tiny``, as data."""
_building_thesis_bodies = False


def onto_field(observations: npt.ArrayLike, *, recorded_by: BodySpec,
               imitator: BodySpec = "lego") -> npt.NDArray[np.float64]:
    """Observations ``(n, 5)`` (robot x, y (mm), heading (rad), ball x, y (mm)) of a demonstration
    by the body ``recorded_by`` on its field, as an imitator of body ``imitator`` sees them on its
    own: the learner's one correspondence, which every part of polymimic that learns from a
    demonstration applies (the learning trial, the improved control, the cloning baselines).

    The ball carries the field: along it, its position scales with the fields' lengths (goal
    line onto goal line); across it, the goal mouth maps onto the goal mouth and the rest of each
    half onto the rest, so a goal stays a goal, an own goal an own goal and a ball in play in
    play, whatever the mouths' share of the widths. The robot keeps its heading and its bearing
    from the ball; its distance from the ball maps by the bodies' reach (``Body.reach_mm``, the
    demonstrator's as it played, the imitator's as it imitates) up to the demonstrator's reach,
    so a touch stays a touch, and beyond it at the fields' scale. Without the ball (NaN) the
    robot maps as a point of the field. Mapped back, a frame is itself (to rounding); in its own
    setting (the same field and reach), it is itself exactly.

    >>> import numpy as np
    >>> seen = np.array([[260.0, -86.25, 0.3, 280.0, -86.25]])  # the tiny touching the ball on the far post
    >>> onto_field(seen, recorded_by="tiny").tolist()           # the Lego's touch, on the large field's post
    [[390.0, -202.5, 0.3, 510.0, -202.5]]
    """
    return _native.observations_onto(observations, as_body(recorded_by, what="recorded_by"),
                                     as_body(imitator, what="imitator"))


def as_body(body: BodySpec, *, what: str = "body") -> Body:
    """``body`` as a :class:`polymimic.Body`: itself, a built-in body by its name, or a
    :class:`WheeledBody` made one. Any other name is a ``ValueError`` naming ``what``, listing
    the built-in bodies and how to describe a body of one's own.

    >>> as_body("tiny").field.length_mm
    560.0
    >>> as_body("rover_17", what="imitator")
    Traceback (most recent call last):
    ...
    ValueError: imitator: unknown body "rover_17": the built-in bodies are lego, tiny, humanoid; describe a body of ...
    """
    if isinstance(body, Body):
        return body
    try:
        return Body(body)
    except (TypeError, ValueError) as error:
        raise type(error)(f"{what}: {error}") from None


def bodies_by_name(bodies: BodiesGiven, *, what: str = "bodies") -> dict[str, Body]:
    """``bodies`` (each a :class:`polymimic.Body` or a :class:`WheeledBody`; or a mapping from
    each one's name to it) by name. Two bodies under one name must be the same body: a
    ``ValueError`` naming ``what`` otherwise, or for a mapping's key that is not its body's name.

    >>> twin = WheeledBody("twin", length_mm=50, width_mm=50, wheel_base_mm=40, top_wheel_speed_mm_s=50)
    >>> sorted(bodies_by_name([twin, THESIS_BODIES["tiny"]]))
    ['tiny', 'twin']
    >>> bodies_by_name([twin, dataclasses.replace(twin, field="small")])
    Traceback (most recent call last):
    ...
    ValueError: bodies: two bodies are named 'twin', with other constants; give each a name of its own
    """
    if isinstance(bodies, (str, bytes)):
        raise TypeError(f"{what} must be bodies (polymimic.Body or polymimic.bodies.WheeledBody) or a mapping "
                        f"from their names to them, got {bodies!r}")
    pairs = bodies.items() if isinstance(bodies, Mapping) else ((None, body) for body in bodies)
    out: dict[str, Body] = {}
    for key, given in pairs:
        if not isinstance(given, (Body, WheeledBody)):
            raise TypeError(f"{what}: expected a polymimic.Body or a polymimic.bodies.WheeledBody, got {given!r}")
        body = as_body(given, what=what)
        if key is not None and key != body.name:
            raise ValueError(f"{what}: key {key!r} holds the body named {body.name!r}; a body is given under its "
                             f"own name")
        if out.get(body.name, body) != body:
            raise ValueError(f"{what}: two bodies are named {body.name!r}, with other constants; give each a name of "
                             f"its own")
        out[body.name] = body
    return out


def body_named(name: str, bodies: Mapping[str, Body], *, where: str) -> Body:
    """The body ``name`` names: a built-in body, or one of ``bodies`` (the bodies of one's own
    given, by name, as :func:`bodies_by_name` gives them). A ``ValueError`` names ``where`` and
    the body, and says how to give it.

    >>> body_named("tiny", {}, where="demos.parquet").field.length_mm
    560.0
    >>> body_named("rover", {}, where="demos.parquet")
    Traceback (most recent call last):
    ...
    ValueError: demos.parquet: body 'rover' is not built in (lego, tiny, humanoid) and was not given: pass its ...
    """
    if name in THESIS_BODY_FIELDS:
        return Body(name)
    known = bodies.get(name)
    if known is None:
        given = f" (given: {', '.join(sorted(bodies))})" if bodies else ""
        raise ValueError(f"{where}: body {name!r} is not built in ({', '.join(THESIS_BODY_FIELDS)}) and was not "
                         f"given{given}: pass its description with bodies= (a polymimic.bodies.WheeledBody or a "
                         f"polymimic.Body, or a run config's [bodies.{name}] table)")
    return known
