"""The benchmark's targets (issues "Crowds and baselines" and "What the demonstrations add"), each
checked against a summary with the measured numbers beside it: met, missed, or not applicable
where a profile or method was not run.

>>> summary = {"profiles": {"linear": {"skill_recovery": {"spearman": {"mean": 0.95}},
...                                    "skill_by_outcomes": {"spearman": {"mean": 0.97}}, "methods": {}}}}
>>> [(t["statement"][:24], t["met"]) for t in check_targets(summary)]
[('linear: Spearman ρ(LP, s', True), ('linear: ρ(LP) within 0.0', True)]
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypedDict

__all__ = ["LEARN_FROM_DEMONSTRATIONS", "Target", "check_targets"]

LEARN_FROM_DEMONSTRATIONS = ("bco", "bco_lp", "bc", "bc_best")
"""The baselines polymimic must beat: those that learn from the same demonstrations."""


class Target(TypedDict):
    statement: str
    measured: str
    met: bool | None


def _net(profile: Mapping[str, Any], method: str) -> float | None:
    entry = profile["methods"].get(method)
    return None if entry is None else entry["net_goals"]["mean"]


def _ratio_met(value: float, reference: float) -> bool:
    """``value`` ≥ 1.2 × ``reference`` where the reference is positive; else just above it."""
    return value >= 1.2 * reference if reference > 0 else value > reference


def _beats_baselines(name: str, profile: Mapping[str, Any]) -> list[Target]:
    ours = _net(profile, "polymimic")
    rivals = {m: _net(profile, m) for m in LEARN_FROM_DEMONSTRATIONS}
    present = {m: v for m, v in rivals.items() if v is not None}
    if ours is None or not present:
        return []
    best = max(present, key=lambda m: present[m])
    measured = f"polymimic {ours:.1f}, best baseline {best} {present[best]:.1f}"
    out = [Target(statement=f"{name}: polymimic scores the most net goals of the methods learning from "
                            f"demonstrations", measured=measured, met=ours >= present[best])]
    if present[best] > 0:
        out.append(Target(statement=f"{name}: polymimic ≥ 1.2 × the best baseline's net goals",
                          measured=f"{ours:.1f} vs 1.2 × {present[best]:.1f} = {1.2 * present[best]:.1f}",
                          met=ours >= 1.2 * present[best]))
    return out


def _skill(name: str, profile: Mapping[str, Any]) -> list[Target]:
    lp, outcomes = profile["skill_recovery"]["spearman"]["mean"], profile["skill_by_outcomes"]["spearman"]["mean"]
    out = [Target(statement=f"{name}: Spearman ρ(LP, skill) ≥ 0.9", measured="n/a" if lp is None else f"{lp:.3f}",
                  met=None if lp is None else lp >= 0.9)]
    if name == "linear":
        out.append(Target(statement=f"{name}: ρ(LP) within 0.05 of the net-goal ranking's ρ (or above it)",
                          measured="n/a" if lp is None or outcomes is None else f"{lp:.3f} vs {outcomes:.3f}",
                          met=None if lp is None or outcomes is None else lp >= outcomes - 0.05))
    return out


def _what_lp_buys(name: str, profile: Mapping[str, Any]) -> list[Target]:
    out = []
    trials, recovery = profile.get("trials", 0), profile["skill_recovery"]
    hits = recovery.get("top_among_best")
    if hits is not None and trials:
        out.append(Target(statement=f"{name}: a member of the highest true skill has the highest LP in ≥ 95 % of "
                                    "trials",
                          measured=f"{hits} of {trials} trials", met=hits >= 0.95 * trials))
    ours, uniform = _net(profile, "polymimic"), _net(profile, "polymimic_uniform_lp")
    if ours is not None and uniform is not None:
        out.append(Target(statement=f"{name}: polymimic − polymimic_uniform_lp ≥ 3 net goals",
                          measured=f"{ours:.1f} − {uniform:.1f} = {ours - uniform:.1f}", met=ours - uniform >= 3))
    bco, bco_lp = _net(profile, "bco"), _net(profile, "bco_lp")
    if bco is not None and bco_lp is not None:
        out.append(Target(statement=f"{name}: bco_lp ≥ 1.2 × bco in net goals (above it where bco ≤ 0)",
                          measured=f"{bco_lp:.1f} vs {bco:.1f}", met=_ratio_met(bco_lp, bco)))
    return out


PRACTICE_HORIZON = 25_000
"""The practice targets are read at this checkpoint (issue "Practice")."""


def _practice(name: str, profile: Mapping[str, Any]) -> list[Target]:
    """Practice gains at least 3 net goals by 25 000 steps and never loses more than 1; on
    ``one_good`` and ``half`` it reaches 47; ppo needs at least 20 times its steps for its score."""
    practice = profile.get("practice")
    if not practice:
        return []
    marks, net = practice["checkpoints"], [n["mean"] for n in practice["net_goals"]]
    worst = min(n - net[0] for n in net)
    out = [Target(statement=f"{name}: practice never loses more than 1 net goal at a checkpoint",
                  measured=f"worst {worst:+.1f}", met=worst >= -1)]
    if PRACTICE_HORIZON in marks:
        at = net[marks.index(PRACTICE_HORIZON)]
        out.append(Target(statement=f"{name}: practice gains ≥ 3 net goals by {PRACTICE_HORIZON:,} steps",
                          measured=f"{net[0]:.1f} → {at:.1f}", met=at - net[0] >= 3))
        if name in ("one_good", "half"):
            out.append(Target(statement=f"{name}: ≥ 47 net goals within {PRACTICE_HORIZON:,} practice steps",
                              measured=f"{at:.1f}", met=at >= 47))
    cloned = practice.get("ppo_bc_steps_to_practice", [])
    if cloned and PRACTICE_HORIZON in marks:
        shown = ", ".join("never" if s is None else f"{s:,}" for s in cloned)
        out.append(Target(statement=f"{name}: ppo_bc needs ≥ 10 × {PRACTICE_HORIZON:,} steps for the net goals "
                                    f"practice has after {PRACTICE_HORIZON:,}",
                          measured=f"ppo_bc: {shown}",
                          met=all(s is None or s >= 10 * PRACTICE_HORIZON for s in cloned)))
    reached = practice.get("ppo_steps_to_practice", [])
    if reached:
        shown = ", ".join("never" if s is None else f"{s:,}" for s in reached)
        out.append(Target(statement=f"{name}: ppo needs ≥ 20 × the practice's {marks[-1]:,} steps for its "
                                    f"{net[-1]:.1f} net goals",
                          measured=f"ppo: {shown}", met=all(s is None or s >= 20 * marks[-1] for s in reached)))
    return out


def _weighting_pays(name: str, profile: Mapping[str, Any]) -> list[Target]:
    """The LP-weighted imitator loses at most 1 net goal to the uniform-LP one; on ``one_good``
    and ``half`` it nets at least 45 of 50 from the demonstrations alone."""
    ours, uniform = _net(profile, "polymimic"), _net(profile, "polymimic_uniform_lp")
    out = []
    if ours is not None and uniform is not None:
        out.append(Target(statement=f"{name}: polymimic ≥ polymimic_uniform_lp − 1 net goal",
                          measured=f"{ours:.1f} vs {uniform:.1f} ({ours - uniform:+.1f})", met=ours >= uniform - 1))
    if ours is not None and name in ("one_good", "half"):
        out.append(Target(statement=f"{name}: polymimic ≥ 45 net goals with no environment step",
                          measured=f"{ours:.1f}", met=ours >= 45))
    return out


def check_targets(summary: Mapping[str, Any]) -> list[Target]:
    """Every target that applies to the profiles and methods of ``summary``."""
    out: list[Target] = []
    for name, profile in summary["profiles"].items():
        out += _beats_baselines(name, profile)
        out += _weighting_pays(name, profile)
        if name in ("linear", "mixed_bodies"):
            out += _skill(name, profile)
        if name in ("one_good", "mixed_bodies"):
            out += _what_lp_buys(name, profile)
        out += _practice(name, profile)
    return out
