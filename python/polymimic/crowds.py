"""Crowds of demonstrators of graded skill and mixed bodies (docs/guides/crowd.md).

A crowd **member** is a built-in controller degraded by a lapse ε: at the start of every second
of an episode, with probability ε, it executes one random imitator primitive for that second
instead of what its controller commands (:func:`polymimic.record`'s ``lapse``). A member's
**true skill** is the net goals its controller scores without lapses (:func:`controller_skill`)
times the share of seconds that controller is in command, 1 − ε (:meth:`Crowd.skill`), so a
Poor player at ε = 0 does not outrank an Expert at ε = 0.05; without measured skills, ε alone
ranks (lower is more skill). The benchmark's
profiles are :data:`PROFILES`; a crowd of your own is plain data (:meth:`Crowd.from_members`).

>>> crowd = PROFILES["linear"]
>>> len(crowd), crowd.members[0]
(10, Member(name='expert_00', controller='expert', lapse=0.05))
>>> crowd.best()
('expert_00',)
>>> PROFILES["one_good_poor"].best(), PROFILES["one_good_poor"].best({"expert": 0.9, "poor": 0.0})
(('poor_01', 'poor_02', 'poor_03', 'poor_04', 'poor_05', 'poor_06', 'poor_07', 'poor_08', 'poor_09'), ('expert_00',))
>>> Crowd.from_members("pair", [{"controller": "tiny", "lapse": 0.1}, {"controller": "poor", "lapse": 0.0}]).names
('tiny_00', 'poor_01')
>>> Crowd.from_members("solo", [{"controller": "expert", "lapse": 0.1}])
Traceback (most recent call last):
...
ValueError: crowd 'solo' has 1 member; a crowd needs at least two
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from polymimic.bodies import Body
from polymimic.field import BODIES, DEMONSTRATORS, Demonstration, record

__all__ = ["FLOOR", "PROFILES", "Crowd", "Member", "controller_skill", "member_seed", "profile", "record_crowd"]


@dataclasses.dataclass(frozen=True)
class Member:
    """One demonstrator of a crowd: a built-in ``controller`` with lapse ``lapse``."""

    name: str
    controller: str
    lapse: float

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise ValueError(f"a member's name must be a non-empty string, got {self.name!r}")
        if self.controller not in DEMONSTRATORS:
            raise ValueError(f"member {self.name!r} has controller {self.controller!r}; expected one of "
                             f"{', '.join(DEMONSTRATORS)}")
        lapse = self.lapse
        if isinstance(lapse, bool) or not isinstance(lapse, (int, float)) or not 0.0 <= lapse <= 1.0:
            raise ValueError(f"member {self.name!r} has lapse {lapse!r}; a lapse is a probability in [0, 1]")
        object.__setattr__(self, "lapse", float(lapse))

    @property
    def body(self) -> str:
        """The name of the body the member's controller drives."""
        return BODIES[self.controller]


@dataclasses.dataclass(frozen=True)
class Crowd:
    """A named crowd of at least two members with distinct names."""

    name: str
    members: tuple[Member, ...]

    def __post_init__(self) -> None:
        if len(self.members) < 2:
            raise ValueError(f"crowd {self.name!r} has {len(self.members)} member"
                             f"{'' if len(self.members) == 1 else 's'}; a crowd needs at least two")
        seen: set[str] = set()
        for member in self.members:
            if member.name in seen:
                raise ValueError(f"crowd {self.name!r} names member {member.name!r} twice")
            seen.add(member.name)

    def __len__(self) -> int:
        return len(self.members)

    @property
    def names(self) -> tuple[str, ...]:
        """The members' names, in order."""
        return tuple(m.name for m in self.members)

    def lapses(self) -> dict[str, float]:
        """Each member's lapse rate ε, by name."""
        return {m.name: m.lapse for m in self.members}

    def skill(self, controllers: Mapping[str, float] | None = None) -> dict[str, float]:
        """Every member's true skill, higher is better: the net goals per attempt its controller
        scores without lapses (``controllers[controller]``, :func:`controller_skill`) times the
        share of seconds that controller is in command, 1 − ε; without ``controllers``, −ε
        (lower ε is better). A ``ValueError`` names a member's controller missing from
        ``controllers``.

        >>> PROFILES["half_poor"].skill({"expert": 0.96, "poor": 0.02})["expert_00"]
        0.912
        """
        if controllers is None:
            return {m.name: -m.lapse for m in self.members}
        missing = sorted({m.controller for m in self.members} - set(controllers))
        if missing:
            raise ValueError(f"crowd {self.name!r}: no measured skill for controller {missing[0]!r}; "
                             f"controllers has {', '.join(sorted(controllers)) or 'none'}")
        return {m.name: round(float(controllers[m.controller]) * (1.0 - m.lapse), 12) for m in self.members}

    def best(self, controllers: Mapping[str, float] | None = None) -> tuple[str, ...]:
        """The members of the highest true skill (several if they tie; see :meth:`skill`)."""
        skill = self.skill(controllers)
        top = max(skill.values())
        return tuple(name for name, value in skill.items() if value == top)

    def to_members(self) -> list[dict[str, Any]]:
        """The crowd as plain data, one table per member (what :meth:`from_members` reads)."""
        return [dataclasses.asdict(m) for m in self.members]

    @classmethod
    def from_members(cls, name: str, members: Sequence[Mapping[str, Any]]) -> Crowd:
        """A crowd from tables of ``controller`` and ``lapse``, with an optional ``name`` and
        ``count`` (that many such members, default 1). Unnamed members are called
        ``<controller>_<index in the crowd>``."""
        if isinstance(members, (str, bytes)) or not isinstance(members, Sequence):
            raise ValueError(f"crowd {name!r}: members must be a list of tables, got {members!r}")
        built: list[Member] = []
        for i, entry in enumerate(members):
            if not isinstance(entry, Mapping):
                raise ValueError(f"crowd {name!r} member {i}: expected a table of controller and lapse, got {entry!r}")
            unknown = sorted(set(entry) - {"name", "controller", "lapse", "count"})
            if unknown:
                raise ValueError(f"crowd {name!r} member {i}: unknown key {unknown[0]!r}; expected controller, "
                                 f"lapse, and optionally name and count")
            for key in ("controller", "lapse"):
                if key not in entry:
                    raise ValueError(f"crowd {name!r} member {i}: missing key {key!r}")
            count = entry.get("count", 1)
            if isinstance(count, bool) or not isinstance(count, int) or count < 1:
                raise ValueError(f"crowd {name!r} member {i}: count must be an integer ≥ 1, got {count!r}")
            if "name" in entry and count != 1:
                raise ValueError(f"crowd {name!r} member {i}: a named member stands for one (count = 1)")
            for _ in range(count):
                given = entry.get("name", f"{entry['controller']}_{len(built):02d}")
                built.append(Member(name=given, controller=entry["controller"], lapse=entry["lapse"]))
        return cls(name=name, members=tuple(built))


def _profile(name: str, members: Sequence[tuple[str, float]]) -> Crowd:
    return Crowd.from_members(name, [{"controller": c, "lapse": e} for c, e in members])


PROFILES: dict[str, Crowd] = {
    "one_good": _profile("one_good", [("expert", 0.05)] + [("expert", 0.9)] * 9),
    "half": _profile("half", [("expert", 0.05)] * 5 + [("expert", 0.9)] * 5),
    "equal": _profile("equal", [("expert", 0.5)] * 10),
    "linear": _profile("linear", [("expert", round(0.05 + 0.1 * k, 2)) for k in range(10)]),
    "mixed_bodies": _profile("mixed_bodies", [(c, e) for c in ("expert", "tiny", "humanoid")
                                              for e in (0.05, 0.5, 0.9)]),
    "random": _profile("random", [("expert", 1.0)] * 10),
    "all_poor": _profile("all_poor", [("poor", 0.0)] * 10),
    "half_poor": _profile("half_poor", [("expert", 0.05)] * 5 + [("poor", 0.0)] * 5),
    "one_good_poor": _profile("one_good_poor", [("expert", 0.05)] + [("poor", 0.0)] * 9),
}
"""The benchmark's crowds: five of graded skill and mixed bodies (docs/guides/crowd.md); ``random``, ten
members who play a random primitive every second (ε = 1), the floor of what any method learns
from demonstrations that carry no skill; ``all_poor``, ten Poor players at ε = 0, who score about
as many own goals as goals; and two crowds that mislead a ranking by ε, whose Poor members never
lapse: ``half_poor`` (five Experts at ε = 0.05, five Poor) and ``one_good_poor`` (one Expert at
ε = 0.05, nine Poor)."""

FLOOR = "random"
"""The profile whose demonstrations carry no skill: each method's floor."""


def profile(name: str) -> Crowd:
    """The built-in crowd ``name``; a ``ValueError`` listing them for any other."""
    try:
        return PROFILES[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown profile {name!r}; expected one of {', '.join(PROFILES)}") from None


def controller_skill(controllers: Iterable[str], *, n: int = 25, seed: int = 0,
                     config: dict[str, Any] | str | None = None) -> dict[str, float]:
    """Each of ``controllers``' net goals per attempt without lapses, on its own body and field:
    ``n`` valid demonstrations per field configuration under ``seed``, (goals − own goals) / 2n.

    >>> skill = controller_skill(["expert", "poor"], n=2, seed=0)
    >>> skill["expert"] > skill["poor"]
    True
    """
    out: dict[str, float] = {}
    for controller in dict.fromkeys(controllers):
        demos = [d for configuration in (1, 2)
                 for d in record(controller, configuration=configuration, n=n, seed=seed, config=config)]
        out[controller] = (sum(d.outcome == "goal" for d in demos) - sum(d.outcome == "own_goal" for d in demos)) \
            / len(demos)
    return out


def member_seed(seed: int, index: int) -> int:
    """The recording seed of a crowd's member ``index`` under the crowd's ``seed``: members of
    the same controller and lapse record different demonstrations."""
    state = np.random.SeedSequence([seed, index]).generate_state(1, dtype=np.uint64)
    return int(state[0])


def record_crowd(crowd: Crowd, *, n: int = 25, seed: int = 0,
                 config: dict[str, Any] | str | None = None) -> list[Demonstration]:
    """``n`` valid demonstrations per field configuration of every member, in member order (the
    configuration-1 ones first), each under the member's name and body.

    >>> demos = record_crowd(PROFILES["half"], n=1, seed=3)
    >>> len(demos), demos[0].demonstrator, demos[-1].body.name
    (20, 'expert_00', 'lego')
    """
    out: list[Demonstration] = []
    for index, member in enumerate(crowd.members):
        for configuration in (1, 2):
            for demo in record(member.controller, configuration=configuration, n=n,
                               seed=member_seed(seed, index), config=config, lapse=member.lapse):
                out.append(dataclasses.replace(demo, demonstrator=member.name, body=Body(member.body)))
    return out
