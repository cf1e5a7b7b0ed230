"""``matrix.json``: every cell's net goals, polymimic's and bco's, mean and sd over trials or fits,
polymimic's weighting of the members and bco's hyperparameters as chosen on validation, and its
transfer ratio (the cell over its row's own-body cell, docs/results/matrix.md), and the heat map.

>>> transfer(30.0, 40.0), transfer(30.0, 0.0), transfer(None, 40.0)
(0.75, None, None)
"""

from __future__ import annotations

import dataclasses
import json
import pathlib
from collections.abc import Mapping, Sequence
from typing import Any

from polymimic import __version__
from polymimic.bodies import Field, as_body
from polymimic.matrix.cell_files import load_cell_evaluation, load_cell_tuning
from polymimic.matrix.config import MatrixConfig, demonstrator_sets, stored_column
from polymimic.matrix.rundir import MatrixDir
from polymimic.matrix.weighing import chosen_weighting
from polymimic.runs.stats import mean_sd

__all__ = ["FORMAT", "HEAT_MAP", "VERSION", "draw_heat_map", "gather", "transfer"]

FORMAT, VERSION = "polymimic.matrix", 1
HEAT_MAP = "matrix_heat_map.png"


def _pitch(field: Field) -> str:
    """The field as ``matrix.json`` names it: ``"large"`` (the Lego's and the humanoid's),
    ``"small"`` (the tiny's) or its sizes as JSON."""
    for name, body in (("large", "lego"), ("small", "tiny")):
        if field == as_body(body).field:
            return name
    sizes = field.sizes()
    return json.dumps({k: sizes[k] for k in ("length_mm", "width_mm", "goal_mouth_mm")})


def transfer(cell: float | None, own: float | None) -> float | None:
    """A cell's net goals over its row's own-body cell's: none where either is missing or the
    own-body cell nets nothing."""
    if cell is None or own is None or own <= 0:
        return None
    return round(cell / own, 4)


def _scores(evaluations: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    nets = [e["goals"] - e["own_goals"] for e in evaluations]
    return {"net_goals": mean_sd(nets), "goals": mean_sd(e["goals"] for e in evaluations),
            "own_goals": mean_sd(e["own_goals"] for e in evaluations), "per_seed": nets,
            "evaluated": len(evaluations), "attempts": evaluations[0]["attempts"] if evaluations else None}


def _cell(run: MatrixDir, config: MatrixConfig, row: str, column: str) -> dict[str, Any]:
    sets = demonstrator_sets(row, config.run.demonstrators)
    chosen = sets[column]
    # A built-in body's own-body cell is its own controller's column: read there.
    stored = stored_column(sets, column)
    polymimic = [load_cell_evaluation(run.require(run.evaluation_path(row, stored, "polymimic", s), "matrix"))
                 for s in config.trial_seeds()]
    bco = [load_cell_evaluation(run.require(run.evaluation_path(row, stored, "bco", s), "matrix"))
           for s in config.fit_seeds()]
    tuning = load_cell_tuning(run.require(run.tuning_path(row, stored), "matrix"))
    weighting, weighing = chosen_weighting(run, config, row, stored)
    return {"set": chosen.name, "demonstrators": list(chosen.names),
            "polymimic": {**_scores(polymimic), "weighting": weighting, "weighing": weighing},
            "bco": {**_scores(bco), "hyperparameters": tuning["hyperparameters"]}}


def gather(run: MatrixDir, config: MatrixConfig) -> dict[str, Any]:
    """The whole ``matrix.json`` of a finished run (the same seeds give the same bytes)."""
    settings, tuning = config.matrix, config.matrix.tuning
    sizes = {**dataclasses.asdict(settings.sizes), "bco_fits": settings.bco_fits, "tuning_budget": tuning.tuning_budget,
             "validation_attempts_per_configuration": tuning.validation_attempts_per_configuration,
             "evaluation_seed": config.seeds.evaluation, "validation_seed": tuning.validation_seed}
    own_set = "humanoid" if settings.primitives == "own" else "wheeled"
    imitators = {}
    cells: dict[str, dict[str, Any]] = {}
    for row in settings.imitators:
        body = config.body(row)
        field = body.field
        imitators[row] = {"field": {"length_mm": field.length_mm, "width_mm": field.width_mm,
                                    "goal_mouth_mm": field.goal_mouth_mm, "ball_diameter_mm": field.ball_diameter_mm},
                          "pitch": _pitch(field), "reach_mm": body.imitating_reach_mm,
                          "primitives": own_set if body.kind == "humanoid" else "wheeled"}
        cells[row] = {column: _cell(run, config, row, column) for column in config.columns()}
        own_cell = cells[row].get("own_body")  # no transfer ratio where the own-body column is left out
        own = {m: None if own_cell is None else own_cell[m]["net_goals"]["mean"] for m in ("polymimic", "bco")}
        for cell in cells[row].values():
            ours, theirs = cell["polymimic"]["net_goals"]["mean"], cell["bco"]["net_goals"]["mean"]
            cell["transfer"] = {m: transfer(cell[m]["net_goals"]["mean"], own[m]) for m in ("polymimic", "bco")}
            cell["polymimic_over_bco"] = None if theirs is None or theirs <= 0 else round(ours / theirs, 4)
    return {"format": FORMAT, "version": VERSION, "polymimic_version": __version__, "sizes": sizes,
            "imitators": imitators, "columns": list(config.columns()), "cells": cells}


def draw_heat_map(summary: Mapping[str, Any], folder: pathlib.Path) -> pathlib.Path:
    """Net goals of every cell, polymimic's and bco's side by side, on one colour scale."""
    import numpy as np
    from matplotlib.figure import Figure

    from polymimic.plots import save_figure

    rows, columns = list(summary["cells"]), summary["columns"]
    attempts = 2 * summary["sizes"]["attempts_per_configuration"]
    figure = Figure(figsize=(4.2 + 1.3 * len(columns), 1.2 + 0.75 * len(rows)), layout="constrained")
    axes = figure.subplots(1, 2, sharey=True)
    images = []
    for ax, method in zip(axes, ("polymimic", "bco")):
        values = np.array([[_mean(summary["cells"][r][c][method]) for c in columns] for r in rows], dtype=float)
        images.append(ax.imshow(values, cmap="RdYlGn", vmin=-attempts, vmax=attempts, aspect="auto"))
        for (i, j), value in np.ndenumerate(values):
            ratio = summary["cells"][rows[i]][columns[j]]["transfer"][method]
            text = "—" if np.isnan(value) else f"{value:.1f}" + ("" if ratio is None else f"\n×{ratio:.2f}")
            ax.text(j, i, text, ha="center", va="center", fontsize="small")
        ax.set_xticks(range(len(columns)), [c.replace("_", " ") for c in columns], rotation=30, ha="right")
        ax.set_yticks(range(len(rows)), rows)
        ax.set_title(f"{method}: net goals per {attempts} (× transfer)", fontsize="medium")
    axes[0].set_ylabel("imitator body")
    figure.colorbar(images[0], ax=axes, shrink=0.8, label="net goals")
    path = folder / HEAT_MAP
    save_figure(figure, path)
    return path


def _mean(method: Mapping[str, Any]) -> float:
    mean = method["net_goals"]["mean"]
    return float("nan") if mean is None else float(mean)
