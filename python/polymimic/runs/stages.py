"""How an application runs its stages: each one timed into the run's manifest and said when it
ends, and a finished output recognised by how many items it holds.

>>> counted([1, 2, 3], 3)
[1, 2, 3]
>>> counted([1, 2], 3)
Traceback (most recent call last):
...
ValueError: it holds 2 items where the config asks for 3
"""

from __future__ import annotations

import pathlib
import sys
import time
from collections.abc import Callable, Sequence, Sized
from typing import Any, TypeVar

from polymimic.bodies import BodiesGiven
from polymimic.datasets import load_demonstrations
from polymimic.field import Demonstration
from polymimic.runs.rundir import RunHouse

__all__ = ["Staged", "counted", "each_member_recorded"]

Items = TypeVar("Items", bound=Sized)


def counted(items: Items, count: int) -> Items:
    """``items``, if there are ``count`` of them: a whole output, not one cut short."""
    if len(items) != count:
        raise ValueError(f"it holds {len(items)} items where the config asks for {count}")
    return items


def each_member_recorded(path: pathlib.Path, *, names: Sequence[str], n: int,
                         bodies: BodiesGiven = ()) -> list[Demonstration]:
    """The demonstrations at ``path`` (a body of one's own read as ``bodies`` describes it), if
    they are ``n`` per configuration of each member named."""
    demos = counted(load_demonstrations(path, bodies=bodies), 2 * n * len(names))
    found = [d.demonstrator for d in demos]
    for name in names:
        if found.count(name) != 2 * n:
            raise ValueError(f"it holds {found.count(name)} demonstrations of {name!r}, not {2 * n}")
    return demos


class Staged:
    """What an application's run shares: saying what it does (unless ``quiet``) and running a
    stage timed into its run directory's manifest. Subclasses give ``run`` and ``quiet``."""

    run: RunHouse[Any]
    quiet: bool

    def say(self, message: str) -> None:
        """Prints a stage message to stderr, unless quiet."""
        if not self.quiet:
            print(message, file=sys.stderr)

    def _stage(self, name: str, work: Callable[[], int]) -> int:
        started = time.perf_counter()
        self.run.stage_started(name)
        made = work()
        self.run.stage_finished(name, time.perf_counter() - started, made=made)
        self.say(f"{name}: {made} made in {time.perf_counter() - started:.1f} s")
        return made
