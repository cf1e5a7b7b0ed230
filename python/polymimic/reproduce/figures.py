"""The report's figures, drawn from ``results.json`` into a run's ``plots/`` folder.

Each figure carries the thesis's number: ``fig_4_5.png``, ``fig_4_7.png`` … ``fig_4_28.png``,
and ``final_lp_heterogeneous.png`` (the heterogeneous experiments' final LPs, which the thesis
shows only as LP over time).

>>> FIGURES["4.13"]
('lp', 'heterogeneous_rcb', 'expert')
>>> FIGURES["4.22"]
('bars', 'varying_skill', 'candidates')
"""

from __future__ import annotations

import os
import pathlib

from polymimic.plots import plot_log_likelihoods, plot_lp_over_time, plot_metric_bars
from polymimic.reproduce.schema import Results
from polymimic.runs.backends import TaskRunner
from polymimic.runs.progress import progress

__all__ = ["FIGURES", "METRIC_LABELS", "draw_figure", "draw_figures"]

METRIC_LABELS = {
    "created": "behaviours created",
    "deleted": "behaviours deleted",
    "permanent": "permanent behaviours",
    "candidates": "candidates moved to the imitator",
    "duplicates": "duplicate candidates (already in the imitator)",
    "candidates_permanent": "candidates made permanent in the imitator",
}



def _numbered() -> dict[str, tuple[str, ...]]:
    figures: dict[str, tuple[str, ...]] = {"4.5": ("log_likelihoods",)}
    for number, metric in zip(range(7, 13), METRIC_LABELS):
        figures[f"4.{number}"] = ("bars", "heterogeneous", metric)
    lp_heterogeneous = [(who, e) for who in ("expert", "tiny", "humanoid")
                        for e in ("heterogeneous_rcb", "heterogeneous_bcr")]
    for number, (who, experiment) in zip(range(13, 19), lp_heterogeneous):
        figures[f"4.{number}"] = ("lp", experiment, who)
    for number, metric in zip(range(19, 25), METRIC_LABELS):
        figures[f"4.{number}"] = ("bars", "varying_skill", metric)
    figures["4.25"] = ("final_lp", "varying_skill")
    for number, who in zip(range(26, 29), ("poor", "average", "expert")):
        figures[f"4.{number}"] = ("lp", "varying_skill", who)
    return figures


FIGURES = _numbered()
"""Thesis figure number → what it shows: ``("bars", experiment, metric)``, ``("lp", experiment,
demonstrator)``, ``("final_lp", experiment)``; ``heterogeneous`` stands for both orderings."""

_GROUPS = {"heterogeneous": {"RCB": "heterogeneous_rcb", "BCR": "heterogeneous_bcr"},
           "varying_skill": {"varying skill": "varying_skill"}}


def figure_file(number: str) -> str:
    """``plots/fig_4_7.png`` for ``"4.7"``: the path the report links, relative to the run."""
    return f"plots/fig_{number.replace('.', '_')}.png"


def draw_figure(inputs: tuple[Results, str], number: str) -> str:
    """Draw figure ``number`` (a key of :data:`FIGURES`, or ``"final_lp_heterogeneous"``) of
    ``inputs = (results, run path)``; return its path relative to the run. A task, so that the
    figures can be drawn side by side."""
    results, run_path = inputs
    experiments = results["experiments"]
    spec = FIGURES.get(number, ("final_lp", "heterogeneous"))
    relative = figure_file(number) if number in FIGURES else f"plots/{number}.png"
    path = pathlib.Path(run_path) / relative
    title = f"Fig {number}: " if number in FIGURES else ""
    if spec[0] == "log_likelihoods":
        plot_log_likelihoods(results["hmm_log_likelihood"], path=path)
    elif spec[0] == "bars":
        _, group, metric = spec
        table = {label: {m: v[metric] for m, v in experiments[e]["behaviours"].items()}
                 for label, e in _GROUPS[group].items()}
        plot_metric_bars(table, ylabel=METRIC_LABELS[metric], path=path,
                         title=f"{title}{METRIC_LABELS[metric]}, mean (sd) over trials")
    elif spec[0] == "final_lp":
        table = {label: experiments[e]["final_lp"] for label, e in _GROUPS[spec[1]].items()}
        plot_metric_bars(table, ylabel="final learning preference", path=path,
                         title=f"{title}final LP of each demonstrator's model, mean (sd)")
    else:
        _, experiment, who = spec
        over_time = experiments[experiment]["lp_over_time"]
        plot_lp_over_time(over_time["trials"][who], stride=over_time["stride"], path=path,
                          title=f"{title}LP of the {who} model, {experiments[experiment]['title']}")
    # Each figure is saved as it is drawn; none is kept in memory.
    return relative


def draw_figures(results: Results, run_path: str | os.PathLike[str], *,
                 runner: TaskRunner | None = None, quiet: bool = False) -> dict[str, str]:
    """Draw every figure, on ``runner``'s workers if given; return each one's path relative to
    ``run_path``, by figure number (``"final_lp_heterogeneous"`` for the extra one)."""
    (pathlib.Path(run_path) / "plots").mkdir(exist_ok=True)
    todo = [*FIGURES, "final_lp_heterogeneous"]
    runner = runner or TaskRunner(workers=1)
    drawn: dict[str, str] = {}
    with progress(total=len(todo), desc="figures", quiet=quiet) as bar:
        for number, relative in runner.map(draw_figure, (results, str(run_path)), todo):
            drawn[number] = relative
            bar.update(1)
    return {number: drawn[number] for number in todo}
