"""``benchmark.md`` and ``benchmark.html``: the benchmark's tables, targets and pictures, in words
a reader can check against ``benchmark.json``."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from polymimic.benchmark.figures import FIGURES
from polymimic.benchmark.targets import check_targets
from polymimic.crowds import FLOOR
from polymimic.runs.markdown import to_html
from polymimic.runs.stats import msd

__all__ = ["benchmark_html", "benchmark_markdown"]


def _verdict(met: bool | None) -> str:
    return {True: "met", False: "**missed**", None: "n/a"}[met]


def _hyperparameters(chosen: Mapping[str, Any]) -> str:
    return ", ".join(f"{k}={v}" for k, v in chosen.items()).replace("|", "/")


def _validation(scored: Mapping[str, Any] | None) -> str:
    """A tuned baseline's validation net goals: the chosen candidate's and the runner-up's."""
    if scored is None:
        return "–"
    runner_up = scored["runner_up"]
    second = "no other candidate" if runner_up is None else f"runner-up {runner_up['net_goals']}"
    return f"{scored['chosen']['net_goals']} ({second}) of {scored['attempts']}"


def _floor(value: float | None, *, signed: bool = False) -> str:
    return "n/a" if value is None else f"{value:+.1f}" if signed else f"{value:.1f}"


def _methods_table(profile: Mapping[str, Any]) -> list[str]:
    rows = ["| method | goals | own goals | net goals | random-crowd floor | gain over floor | evaluated | "
            "validation net goals | chosen on validation |",
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for method, s in profile["methods"].items():
        rows.append(f"| {method} | {msd(s['goals'])} | {msd(s['own_goals'])} | {msd(s['net_goals'])} | "
                    f"{_floor(s.get('floor'))} | {_floor(s.get('gain_over_floor'), signed=True)} | "
                    f"{s['evaluated']} × {s['attempts']} | {_validation(s.get('validation'))} | "
                    f"{_hyperparameters(s['hyperparameters'])} |")
    return rows


def _gain_rows(summary: Mapping[str, Any]) -> list[str]:
    """What the demonstrations add: every method's gain over its own random-crowd floor."""
    profiles = {name: p for name, p in summary["profiles"].items() if name != FLOOR}
    methods = list(dict.fromkeys(m for p in profiles.values() for m in p["methods"]))
    floors = summary["profiles"][FLOOR]["methods"]
    rows = ["## What the demonstrations add", "",
            f"Each method's net goals on the `{FLOOR}` crowd (ten members playing a random primitive every "
            "second: demonstrations that carry no skill) are its floor, what it scores from what it knows of the "
            "task and the field without being shown how; the gain over that floor is what a crowd's demonstrations "
            "add. Mean net goals over the trials or fits evaluated, gain in brackets:", "",
            "| method | floor | " + " | ".join(profiles) + " |", "| --- | --- | " + " | ".join("---" for _ in profiles)
            + " |"]
    for method in methods:
        floor = floors[method]["net_goals"]["mean"] if method in floors else None
        cells = []
        for profile in profiles.values():
            s = profile["methods"].get(method)
            cells.append("n/a" if s is None else f"{s['net_goals']['mean']:.1f} "
                         f"({_floor(s.get('gain_over_floor'), signed=True)})")
        rows.append(f"| {method} | {_floor(floor)} | " + " | ".join(cells) + " |")
    return [*rows, ""]


def _members_table(profile: Mapping[str, Any]) -> list[str]:
    rows = ["| member | controller | body | ε | true skill | goals | own goals | attempts | final LP |",
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name, m in profile["demonstrators"].items():
        skill = m.get("true_skill")
        rows.append(f"| {name} | {m['controller']} | {m['body']} | {m['lapse']:g} | "
                    f"{'n/a' if skill is None else f'{skill:.3f}'} | {m['goals']} | "
                    f"{m['own_goals']} | {m['attempts']} | {msd(m['final_lp'], digits=2)} |")
    return rows


def _recovery_rows(summary: Mapping[str, Any]) -> list[str]:
    rows = ["| profile | estimator | Spearman ρ | Kendall τ | best on top |", "| --- | --- | --- | --- | --- |"]
    for name, profile in summary["profiles"].items():
        for label, key in (("LP", "skill_recovery"), ("own net goals", "skill_by_outcomes")):
            r = profile[key]
            hits = r["best_hits"] if r["best_hits"] is not None else r["top_among_best"]
            top = "n/a" if hits is None else f"{hits} of {profile['trials']}"
            rows.append(f"| {name} | {label} | {msd(r['spearman'], digits=3)} | {msd(r['kendall'], digits=3)} | "
                        f"{top} |")
    return rows


def _ppo_rows(summary: Mapping[str, Any]) -> list[str]:
    """ppo against polymimic: the steps each run took to first score polymimic's net goals."""
    ppo = summary["ppo"]
    budget = ppo["hyperparameters"]["total_timesteps"]
    runs = [r["seed"] for r in ppo["runs"]]
    lines = ["## Reinforcement learning: ppo", "",
             "ppo learns from the reward alone (+1 a goal, −1 an own goal), not from the crowds, with "
             "stable-baselines3's default hyperparameters, untuned, on one torch thread; "
             f"at the first policy update past every {ppo['eval_every']:,} environment steps it plays the same "
             f"evaluation attempts as every method. One step is one primitive, one second of the robot's time. "
             f"Environment steps each run (training seed) took to first score polymimic's mean net goals in a "
             f"profile, or that it did not within {budget:,}:", "",
             "| profile | polymimic's net goals | " + " | ".join(f"ppo seed {s}" for s in runs) + " |",
             "| --- | --- | " + " | ".join("---" for _ in runs) + " |"]
    for name, profile in summary["profiles"].items():
        ours = profile["methods"].get("polymimic")
        reached = profile["methods"]["ppo"]["env_steps_to_polymimic"]
        cells = ["n/a" if ours is None else f"not within {budget:,}" if steps is None else f"{steps:,}"
                 for steps in reached]
        target = "n/a" if ours is None else f"{ours['net_goals']['mean']:.1f}"
        lines.append(f"| {name} | {target} | " + " | ".join(cells) + " |")
    return [*lines, "", f"![ppo's net goals over training](plots/{FIGURES['ppo_curve']})", ""]


def _practice_rows(summary: Mapping[str, Any]) -> list[str]:
    """The practised imitators' curves: mean (sd) net goals at every checkpoint, per profile."""
    profiles = {name: p["practice"] for name, p in summary["profiles"].items() if p.get("practice")}
    marks = next(iter(profiles.values()))["checkpoints"]
    sizes = summary["sizes"]
    lines = ["## Practice", "",
             f"polymimic's imitator after each of the first {sizes['practice_trials']} trials plays attempts of its "
             f"own (from practice seeds, apart from the evaluation's and validation's) for "
             f"{sizes['practice_steps']:,} environment steps, one second of play each, and learns the ball's response "
             "and the states' values from what the tracker showed of them beside the demonstrations "
             "(`polymimic.practice`). Net goals on the evaluation attempts at each checkpoint, mean (sd) over "
             "those trials; attempts the tracker lost are left out and counted. Before any of it, the imitator "
             f"learned its primitives from {next(iter(profiles.values()))['self_observation_steps']:,} seconds of "
             "babbling (its self-observation): steps ppo never takes, to add to practice's for all of its play.", "",
             "| profile | " + " | ".join(f"{m:,} steps" for m in marks) + " | attempts lost |",
             "| --- | " + " | ".join("---" for _ in marks) + " | --- |"]
    for name, practice in profiles.items():
        lines.append(f"| {name} | " + " | ".join(msd(n) for n in practice["net_goals"])
                     + f" | {practice['attempts_lost']} |")
    def steps(reached: list[int | None]) -> str:
        return ", ".join("never" if s is None else f"{s:,}" for s in reached) or "n/a"

    if "ppo" in summary or any(p.get("ppo_bc_steps_to_practice") for p in profiles.values()):
        lines += ["", "Against ppo and ppo_bc: the first practice checkpoint reaching ppo's final net goals, and the "
                      "steps each ppo and ppo_bc run took to first reach the practised net goals (never: not within "
                      "its budget).", "",
                  "| profile | practice to ppo's final | ppo to practice's final | ppo_bc to practice's final |",
                  "| --- | --- | --- | --- |"]
        for name, practice in profiles.items():
            reach = practice["steps_to_ppo"]
            first = "n/a" if "ppo" not in summary else "not within the budget" if reach is None else f"{reach:,}"
            lines.append(f"| {name} | {first} | {steps(practice['ppo_steps_to_practice'])} | "
                         f"{steps(practice.get('ppo_bc_steps_to_practice', []))} |")
    return [*lines, "", f"![Net goals over practice](plots/{FIGURES['practice_curve']})", ""]


def _skills(summary: Mapping[str, Any]) -> str:
    skills = summary.get("controller_skill") or {}
    return ", ".join(f"{name} {value:.2f}" for name, value in skills.items()) or "not measured"


def benchmark_markdown(summary: Mapping[str, Any], *, seconds: Mapping[str, float] | None = None) -> str:
    """The report of a ``benchmark.json``; ``seconds`` are the steps' times, from the manifest."""
    sizes = summary["sizes"]
    lines = ["# polymimic against the baselines", "",
             f"The imitator is the {summary.get('imitator', 'lego')} robot: every method learns to drive it, on its "
             f"own field. {sizes['trials']} trials per profile; every member records "
             f"{sizes['demonstrations_per_configuration']} "
             f"valid demonstrations per field configuration; every method plays the same "
             f"{2 * sizes['attempts_per_configuration']} evaluation attempts (seed {sizes['evaluation_seed']}) after "
             f"every trial. Every baseline's hyperparameters were chosen among {sizes['tuning_budget']} candidates "
             f"on {2 * sizes['validation_attempts_per_configuration']} validation attempts (validation seed "
             f"{sizes['validation_seed']}, disjoint from the evaluation's), each fit on at most "
             f"{sizes['max_decision_samples']} decision samples; bco chose how its frames are labelled too "
             "(labels: the recogniser's steps or the inverse dynamics model learned from the imitator's own "
             "exploration, each with the first half of the candidates); polymimic's methods use the thesis's "
             "constants, untuned. bc, bco, bc_best and random learn the same data in every trial, so each is "
             f"fitted and evaluated {sizes['baseline_fits']} times, every fit under its own seed (which draws its "
             "decision samples and seeds its classifier); bco_lp, which weighs by each trial's LPs, after each of "
             f"the first {sizes['lp_plugin_trials']} trials. Mean (sd) over the trials or fits evaluated (the "
             "column `evaluated`); a baseline's validation net goals are its chosen candidate's and the best other "
             "one's, which says how far the choice stood out.", ""]
    if seconds:
        lines += ["Time: " + ", ".join(f"{k} {v:.0f} s" for k, v in seconds.items())
                  + f"; {sum(seconds.values()):.0f} s in all.", ""]
    lines += ["## Targets", "", "| target | measured | verdict |", "| --- | --- | --- |"]
    lines += [f"| {t['statement']} | {t['measured']} | {_verdict(t['met'])} |" for t in check_targets(summary)]
    lines += ["", "## Net goals", "", f"![Net goals by method and profile](plots/{FIGURES['net_goals']})", "",
              "polymimic chooses, per profile, which parts of its world model its LP weighting reaches "
              "(`world_weighting`: `outcome`, none, each sample counting by the outcome it led to; `intent`, the "
              "push region and the states' values, the ball's response learned from every demonstration at full "
              "weight; `every`, all three), each candidate played after the first trial on the baselines' "
              "validation attempts: its validation net goals are the chosen weighting's and the best other one's. "
              "polymimic_practice keeps the config's weighting.", ""]
    for name, profile in summary["profiles"].items():
        lines += [f"### {name}", "", *_methods_table(profile), ""]
    if FLOOR in summary["profiles"] and len(summary["profiles"]) > 1:
        lines += _gain_rows(summary)
    if "ppo" in summary:
        lines += _ppo_rows(summary)
    if any(p.get("practice") for p in summary["profiles"].values()):
        lines += _practice_rows(summary)
    lines += ["## Skill recovery", "",
              "How well each estimate ranks the members by true skill: the net goals per attempt each member's "
              "controller scores without lapses (" + _skills(summary) + "), times the share of seconds it is in "
              "command, 1 − ε; so a Poor player at ε = 0 ranks below an Expert at ε = 0.05. The estimates: the "
              "members' final LPs, and the plain estimator that ranks them by the net goals of their own "
              "demonstrations.", "",
              *_recovery_rows(summary), "", f"![LP against lapse](plots/{FIGURES['lp_vs_lapse']})", "",
              f"![LP over training](plots/{FIGURES['lp_over_training']})", "", "## The crowds", ""]
    for name, profile in summary["profiles"].items():
        lines += [f"### {name}", "", *_members_table(profile), ""]
    return "\n".join(lines)


def benchmark_html(markdown: str, *, images_from: str) -> str:
    """The report's markdown as one HTML page, its images embedded from ``images_from``."""
    return to_html(markdown, title="polymimic benchmark", images_from=images_from)
