"""The benchmark's pictures: net goals by method and profile, LP against lapse, LP over training,
(where ppo ran) ppo's net goals over its training against polymimic's in every profile, and
(where polymimic_practice ran) the practised imitators' net goals over practice steps, beside
ppo's on the same axes.

>>> import pathlib, tempfile
>>> summary = {"profiles": {"pair": {
...     "demonstrators": {"a": {"lapse": 0.1, "final_lp": {"mean": 0.8, "sd": 0.1}},
...                       "b": {"lapse": 0.9, "final_lp": {"mean": 0.3, "sd": 0.1}}},
...     "skill_recovery": {"spearman": {"mean": 1.0, "sd": 0.0}},
...     "methods": {"bc": {"net_goals": {"mean": 5.0, "sd": 1.0}}},
...     "lp_over_training": {"a": [0.5, 0.7, 0.8], "b": [0.5, 0.4, 0.3]}}}}
>>> sorted(p.name for p in draw_figures(summary, pathlib.Path(tempfile.mkdtemp())))
['benchmark_lp_over_training.png', 'benchmark_lp_vs_lapse.png', 'benchmark_net_goals.png']
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Mapping
from typing import Any

from polymimic.plots import plot_metric_bars, save_figure

__all__ = ["FIGURES", "draw_figures"]

FIGURES = {"net_goals": "benchmark_net_goals.png", "lp_vs_lapse": "benchmark_lp_vs_lapse.png",
           "lp_over_training": "benchmark_lp_over_training.png", "ppo_curve": "benchmark_ppo_curve.png",
           "practice_curve": "benchmark_practice_curve.png"}


def _panels(count: int, *, width_in: float = 3.6, height_in: float = 3.0) -> tuple[Any, list[Any]]:
    from matplotlib.figure import Figure

    columns = min(count, 3)
    rows = math.ceil(count / columns)
    figure = Figure(figsize=(width_in * columns, height_in * rows), layout="constrained")
    axes = figure.subplots(rows, columns, squeeze=False).ravel().tolist()
    for ax in axes[count:]:
        ax.set_visible(False)
    return figure, axes[:count]


def _lp_vs_lapse(profiles: Mapping[str, Any], path: pathlib.Path) -> None:
    figure, axes = _panels(len(profiles))
    for ax, (name, profile) in zip(axes, profiles.items()):
        members = profile["demonstrators"].values()
        lapses = [m["lapse"] for m in members]
        means = [m["final_lp"]["mean"] for m in members]
        sds = [m["final_lp"]["sd"] or 0.0 for m in members]
        ax.errorbar(lapses, means, yerr=sds, fmt="o", capsize=3, markersize=4)
        rho = profile["skill_recovery"]["spearman"]["mean"]
        ax.set_title(f"{name}: ρ = {'n/a' if rho is None else f'{rho:.2f}'}", fontsize="medium")
        ax.set_xlim(-0.05, 1.05)
        ax.set_ylim(0.0, 1.05)
        ax.set_xlabel("lapse ε")
        ax.set_ylabel("final LP")
    save_figure(figure, path)


def _lp_over_training(profiles: Mapping[str, Any], path: pathlib.Path) -> None:
    from matplotlib import colormaps

    colours = colormaps["viridis"]
    figure, axes = _panels(len(profiles))
    for ax, (name, profile) in zip(axes, profiles.items()):
        for member, history in profile["lp_over_training"].items():
            lapse = profile["demonstrators"][member]["lapse"]
            ax.plot(range(len(history)), history, color=colours(lapse), linewidth=0.9, label=f"{member} ε={lapse:g}")
        ax.set_ylim(0.0, 1.05)
        ax.set_xlabel("LP change (resampled)")
        ax.set_ylabel("LP")
        ax.set_title(f"{name}, first trial", fontsize="medium")
        ax.legend(fontsize="xx-small", ncol=2)
    save_figure(figure, path)


def _ppo_curve(summary: Mapping[str, Any], path: pathlib.Path) -> None:
    from matplotlib.figure import Figure
    from matplotlib.ticker import StrMethodFormatter

    figure = Figure(figsize=(7.5, 4.2), layout="constrained")
    ax = figure.add_subplot()
    for run in summary["ppo"]["runs"]:
        points = run["checkpoints"]
        ax.plot([p["env_steps"] for p in points], [p["net_goals"] for p in points], marker="o", markersize=3,
                label=f"ppo, seed {run['seed']}")
    styles = iter(("--", ":", "-.", (0, (5, 1)), (0, (3, 1, 1, 1))) * 4)
    for name, profile in summary["profiles"].items():
        ours = profile["methods"].get("polymimic")
        if ours is not None:
            ax.axhline(ours["net_goals"]["mean"], color="0.35", linestyle=next(styles), linewidth=1.0,
                       label=f"polymimic, {name}")
    attempts = next(iter(summary["profiles"].values()))["methods"]["ppo"]["attempts"]
    ax.set_ylim(-attempts - 1, attempts + 1)
    ax.xaxis.set_major_formatter(StrMethodFormatter("{x:,.0f}"))
    ax.set_xlabel("environment steps (one primitive each)")
    ax.set_ylabel(f"net goals in {attempts} attempts")
    ax.set_title("ppo learning from the reward, against polymimic learning from each crowd", fontsize="medium")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize="x-small")
    save_figure(figure, path)


def _practice_curve(summary: Mapping[str, Any], path: pathlib.Path) -> None:
    """Net goals against environment steps, practice's per profile and ppo's per run, steps on a
    scale linear to 1 000 and logarithmic beyond, so 25 000 steps of practice and a million of
    ppo share the axis."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import StrMethodFormatter

    figure = Figure(figsize=(7.5, 4.2), layout="constrained")
    ax = figure.add_subplot()
    for name, profile in summary["profiles"].items():
        practice = profile.get("practice")
        if practice:
            ax.plot(practice["checkpoints"], [n["mean"] for n in practice["net_goals"]], marker="o", markersize=3,
                    label=f"practice, {name}")
    for run in summary.get("ppo", {}).get("runs", []):
        points = run["checkpoints"]
        ax.plot([p["env_steps"] for p in points], [p["net_goals"] for p in points], color="0.35", linestyle="--",
                linewidth=1.0, label=f"ppo, seed {run['seed']}")
    ax.set_xscale("symlog", linthresh=1_000)
    ax.xaxis.set_major_formatter(StrMethodFormatter("{x:,.0f}"))
    ax.set_xlabel("environment steps (one second of play each)")
    ax.set_ylabel("net goals on the evaluation attempts")
    ax.set_title("polymimic practising after learning from each crowd, and ppo from the reward", fontsize="medium")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize="x-small")
    save_figure(figure, path)


def draw_figures(summary: Mapping[str, Any], folder: str | os.PathLike[str]) -> list[pathlib.Path]:
    """Draw every figure of ``summary`` (a ``benchmark.json``) into ``folder``; their paths."""
    out = pathlib.Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    profiles = summary["profiles"]
    table = {name: {m: s["net_goals"] for m, s in p["methods"].items()} for name, p in profiles.items()}
    figure = plot_metric_bars(table, ylabel="net goals (goals − own goals)", title="Net goals by method and profile")
    figure.set_size_inches(max(7.0, 1.3 * len(next(iter(table.values()), {})) + 2), 4.6)
    axes = figure.axes[0]
    # Long method names would print over each other: break them after their first word.
    axes.set_xticks(axes.get_xticks(), [label.get_text().replace("_", "_\n", 1) if len(label.get_text()) > 12
                                        else label.get_text() for label in axes.get_xticklabels()])
    save_figure(figure, out / FIGURES["net_goals"])
    _lp_vs_lapse(profiles, out / FIGURES["lp_vs_lapse"])
    _lp_over_training(profiles, out / FIGURES["lp_over_training"])
    drawn = [out / FIGURES[k] for k in ("net_goals", "lp_vs_lapse", "lp_over_training")]
    if "ppo" in summary:
        _ppo_curve(summary, out / FIGURES["ppo_curve"])
        drawn.append(out / FIGURES["ppo_curve"])
    if any(p.get("practice") for p in profiles.values()):
        _practice_curve(summary, out / FIGURES["practice_curve"])
        drawn.append(out / FIGURES["practice_curve"])
    return drawn
