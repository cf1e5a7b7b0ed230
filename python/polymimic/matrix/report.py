"""``matrix.md`` and ``matrix.html``: the matrix's tables, its targets, its heat map, and its
pictures of each set's demonstration and each row's attempt on their own fields, in words a reader
can check against ``matrix.json``."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from polymimic.matrix.pictures import Picture
from polymimic.matrix.summary import HEAT_MAP
from polymimic.runs.markdown import to_html
from polymimic.runs.stats import msd

__all__ = ["matrix_html", "matrix_markdown", "matrix_targets"]

TRANSFER_PAIRS = (("lego", "tiny"), ("tiny", "expert"), ("wagon", "expert"))
"""Wheeled imitators learning from the other wheeled body's built-in demonstrator."""


def matrix_targets(summary: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The issue's targets, each with what was measured and whether it holds (None: no data)."""
    cells, targets = summary["cells"], []
    for row, column in TRANSFER_PAIRS:
        if row in cells and column in cells[row] and "own_body" in cells[row]:
            ratio = cells[row][column]["transfer"]["polymimic"]
            targets.append({"statement": f"{row} ← {column}: transfer ≥ 0.8 × the own-body cell",
                            "measured": "—" if ratio is None else f"{ratio:.2f}",
                            "met": None if ratio is None else ratio >= 0.8})
    misses = []
    for row, columns in cells.items():
        for column, cell in columns.items():
            ours, theirs = cell["polymimic"]["net_goals"]["mean"], cell["bco"]["net_goals"]["mean"]
            if ours is not None and theirs is not None and (ours <= theirs or (theirs > 0 and ours < 1.5 * theirs)):
                misses.append(f"{row} ← {column} ({ours:.1f} vs {theirs:.1f})")
    targets.append({"statement": "polymimic ≥ 1.5 × bco where bco's are positive, and above it everywhere",
                    "measured": "every cell" if not misses else "missed in " + ", ".join(misses),
                    "met": not misses})
    if "humanoid" in cells and "expert" in cells["humanoid"]:
        # The target is per 50 attempts, the thesis's evaluation: a smaller run's figure is scaled to it.
        attempts = 2 * summary["sizes"]["attempts_per_configuration"]
        net = cells["humanoid"]["expert"]["polymimic"]["net_goals"]["mean"]
        per_50 = None if net is None else net * 50 / attempts
        targets.append({"statement": "the humanoid learning from the Lego Expert nets ≥ 20 goals per 50",
                        "measured": "—" if per_50 is None else f"{per_50:.1f}",
                        "met": None if per_50 is None else per_50 >= 20})
    return targets


def _table(summary: Mapping[str, Any], method: str) -> list[str]:
    columns = summary["columns"]
    lines = ["| imitator | " + " | ".join(c.replace("_", " ") for c in columns) + " |",
             "| --- |" + " --- |" * len(columns)]
    for row, cells in summary["cells"].items():
        entries = []
        for column in columns:
            cell = cells[column]
            ratio = cell["transfer"][method]
            entries.append(msd(cell[method]["net_goals"]) + ("" if ratio is None else f" ×{ratio:.2f}"))
        lines.append(f"| {row} | " + " | ".join(entries) + " |")
    return lines


def _weighing(summary: Mapping[str, Any]) -> list[str]:
    """polymimic's weighting of each crowd's members, and every candidate's validation net goals."""
    rows = [(row, column, cell["polymimic"]) for row, cells in summary["cells"].items()
            for column, cell in cells.items() if cell["polymimic"].get("weighing")]
    if not rows:
        return []
    lines = ["polymimic's weighting of the members, chosen on validation (net goals per candidate):", "",
             "| cell | chosen | validation |", "| --- | --- | --- |"]
    for row, column, method in rows:
        tried = ", ".join(f"{w['weighting']} {w['goals'] - w['own_goals']} of {w['attempts']}"
                          for w in method["weighing"])
        lines.append(f"| {row} ← {column.replace('_', ' ')} | {method['weighting']} | {tried} |")
    return [*lines, ""]


def _pictures(pictures: Sequence[Picture]) -> list[str]:
    """The pictures' two sections: each set's demonstration, each row's attempt."""
    intros = {"demonstrators": ("The demonstrators, each on its own field", "Each set of demonstrators' first "
                                "demonstration (its first member's first in configuration 1; a log's first episode), "
                                "drawn on its demonstrator's body's own field, to scale."),
              "attempts": ("The imitators, each on its own field", "Each row's imitator after its first trial in the "
                           "pictured column: the first of its evaluation attempts, drawn on the row's own field.")}
    lines: list[str] = []
    for section, (heading, intro) in intros.items():
        shown = [p for p in pictures if p.section == section]
        if shown:
            lines += [f"## {heading}", "", intro, ""]
            lines += [line for p in shown for line in (f"![{p.caption}]({p.file})", "")]
    return lines


def matrix_markdown(summary: Mapping[str, Any], *, seconds: Mapping[str, float] | None = None,
                    pictures: Sequence[Picture] = ()) -> str:
    """The report of a ``matrix.json``; ``seconds`` are the steps' times, from the manifest;
    ``pictures`` the demonstrations and attempts drawn (:func:`polymimic.matrix.pictures.draw_pictures`)."""
    sizes, attempts = summary["sizes"], 2 * summary["sizes"]["attempts_per_configuration"]
    verdict = {True: "met", False: "**missed**", None: "n/a"}
    lines = ["# Who learns what from whom", "",
             f"Rows are imitator bodies, each learning on its own field from its own self-observation; columns are "
             f"sets of demonstrators, {sizes['demonstrations_per_configuration']} valid demonstrations per member and "
             f"field configuration, brought into the imitator's setting by polymimic's one correspondence. A cell is "
             f"the net goals per {attempts} evaluation attempts on the row's field (seed {sizes['evaluation_seed']}), "
             f"mean (sd) over {sizes['trials']} trials for polymimic (the improved control) and over "
             f"{sizes['bco_fits']} fits for bco (its labels from the row's own recogniser, its hyperparameters "
             f"chosen among {sizes['tuning_budget']} candidates on validation attempts of its own), and ×r its "
             "transfer ratio: the cell over the row's own-body cell (none where that nets nothing). Each trial "
             "(and fit) learns from demonstrations of its own, every member recorded afresh under seeds of its "
             "own (a log's episodes resampled with replacement), so a cell's sd says how much its answer depends "
             "on what was demonstrated as well as on the learner's seed. In a cell of "
             "more than one demonstrator polymimic's weighting of the members is chosen with bco's effort: each "
             "candidate learns one trial and plays the same validation attempts.", ""]
    if seconds:
        lines += ["Time: " + ", ".join(f"{k} {v:.0f} s" for k, v in seconds.items())
                  + f"; {sum(seconds.values()):.0f} s in all.", ""]
    lines += ["## Targets", "", "| target | measured | verdict |", "| --- | --- | --- |"]
    lines += [f"| {t['statement']} | {t['measured']} | {verdict[t['met']]} |" for t in matrix_targets(summary)]
    lines += ["", f"![Net goals of every cell](plots/{HEAT_MAP})", "", "## polymimic", "",
              *_table(summary, "polymimic"), "", *_weighing(summary), "## bco", "", *_table(summary, "bco"), "",
              "## The imitators", "",
              "| imitator | field (mm) | goal mouth (mm) | reach (mm) |", "| --- | --- | --- | --- |"]
    for row, imitator in summary["imitators"].items():
        field = imitator["field"]
        lines.append(f"| {row} | {field['length_mm']:g} × {field['width_mm']:g} | {field['goal_mouth_mm']:g} | "
                     f"{imitator['reach_mm']:g} |")
    if pictures:
        lines += ["", *_pictures(pictures)]
    return "\n".join(lines).rstrip("\n")


def matrix_html(markdown: str, *, images_from: str) -> str:
    """The report's markdown as one HTML page, its images embedded from ``images_from``."""
    return to_html(markdown, title="polymimic matrix", images_from=images_from)
