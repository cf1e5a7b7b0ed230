"""Crowds of demonstrators of graded skill and mixed bodies (docs/guides/crowd.md).

A crowd **member** is a built-in controller degraded by a lapse ε: at the start of every second
of an episode, with probability ε, it executes one random imitator primitive for that second
instead of what its controller commands (:func:`polymimic.record`'s ``lapse``). Lower ε is
more skill; a crowd's **true skill** is that design rank. The five profiles of the benchmark
are :data:`PROFILES`; a crowd of your own is plain data (:meth:`Crowd.from_members`).

>>> crowd = PROFILES["linear"]
>>> len(crowd), crowd.members[0]
(10, Member(name='expert_00', controller='expert', lapse=0.05))
>>> crowd.best()
('expert_00',)
>>> Crowd.from_members("pair", [{"controller": "tiny", "lapse": 0.1}, {"controller": "poor", "lapse": 0.0}]).names
('tiny_00', 'poor_01')
>>> Crowd.from_members("solo", [{"controller": "expert", "lapse": 0.1}])
Traceback (most recent call last):
...
ValueError: crowd 'solo' has 1 member; a crowd needs at least two
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic.field import BODIES, DEMONSTRATORS, Demonstration, record

__all__ = ["PROFILES", "Crowd", "Member", "member_seed", "profile", "record_crowd"]


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
        """The body the member's controller drives."""
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

    def best(self) -> tuple[str, ...]:
        """The members of the lowest lapse (several if they tie)."""
        lowest = min(m.lapse for m in self.members)
        return tuple(m.name for m in self.members if m.lapse == lowest)

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
}
"""The benchmark's five crowds (docs/guides/crowd.md)."""


def profile(name: str) -> Crowd:
    """The built-in crowd ``name``; a ``ValueError`` listing them for any other."""
    try:
        return PROFILES[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown profile {name!r}; expected one of {', '.join(PROFILES)}") from None


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
    >>> len(demos), demos[0].demonstrator, demos[-1].body
    (20, 'expert_00', 'lego')
    """
    out: list[Demonstration] = []
    for index, member in enumerate(crowd.members):
        for configuration in (1, 2):
            for demo in record(member.controller, configuration=configuration, n=n,
                               seed=member_seed(seed, index), config=config, lapse=member.lapse):
                out.append(dataclasses.replace(demo, demonstrator=member.name, body=member.body))
    return out
