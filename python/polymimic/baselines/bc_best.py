"""``bc_best``: :mod:`~polymimic.baselines.bc` on one named member's demonstrations only (an
oracle of who is best: the benchmark names the member of lowest lapse ε), or on those of several
named members where several share the lowest ε.

>>> import polymimic
>>> from polymimic.baselines import bc_best
>>> demos = polymimic.record("poor", configuration=1, n=1, seed=0) + polymimic.record("expert", configuration=1, n=1)
>>> bc_best.fit(demos, member="expert").method
'bc_best'
"""

from __future__ import annotations

from collections.abc import Sequence

from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters
from polymimic.baselines.labels import IMITATOR_BODY, Labelled, check_demonstrations, command_labels
from polymimic.baselines.policy import ClonedPolicy
from polymimic.baselines.training import train
from polymimic.bodies import BodySpec
from polymimic.field import Demonstration

__all__ = ["fit", "labelled", "member_demonstrations"]


def member_demonstrations(demonstrations: Sequence[Demonstration], member: str | Sequence[str]) -> list[Demonstration]:
    """The demonstrations of ``member`` (a name, or several), or a ValueError naming the members
    there are."""
    demos = check_demonstrations(demonstrations)
    names = (member,) if isinstance(member, str) else tuple(member)
    present = {d.demonstrator for d in demos}
    missing = [n for n in names if n not in present]
    if missing or not names:
        raise ValueError(f"unknown member {missing[0] if missing else member!r}: the demonstrations are by "
                         f"{', '.join(map(repr, sorted(present)))}")
    return [d for d in demos if d.demonstrator in names]


def labelled(demonstrations: Sequence[Demonstration], *, member: str | Sequence[str],
             imitator: BodySpec = IMITATOR_BODY) -> list[Labelled]:
    """``member``'s demonstrations with every frame labelled by its command's primitive, seen
    on the field of body ``imitator``."""
    return command_labels(member_demonstrations(demonstrations, member), imitator=imitator)


def fit(demonstrations: Sequence[Demonstration], *, member: str | Sequence[str],
        hyperparameters: Hyperparameters = DEFAULT, seed: int = 0) -> ClonedPolicy:
    """:func:`polymimic.baselines.bc.fit` on ``member``'s demonstrations alone.

    Raises
    ------
    ValueError
        If ``demonstrations`` is empty or holds none by ``member``.
    """
    return train("bc_best", labelled(demonstrations, member=member), hyperparameters=hyperparameters, seed=seed)
