"""Writes the results pages' main tables, and the README's summary of them, from the result files
committed under ``docs/results/``.

Each table sits in its page between ``<!-- table:NAME -->`` and ``<!-- /table:NAME -->``; this
script rewrites what lies between from the files, so every number of those tables has one
source. ``docs/results/provenance.json`` says, for each file, the command that made it, the
world it was measured in and the machine. ``tests/test_results_pages.py`` fails when a page's
table is not what this script writes. Run::

    python docs/write_results.py            # rewrite the tables
    python docs/write_results.py --check    # exit 1 if a page is stale
    python docs/write_results.py --take RUN_DIR/benchmark.json   # commit a run's file, then rewrite

``--take`` copies a run's result file under ``docs/results/``; a benchmark's LP histories are
kept at every tenth point there (the report's plots are drawn from the run's own file), which
keeps the file under 300 kB.

A table whose result file is not committed yet is left as it is (and said so by ``--check``).
"""

from __future__ import annotations

import argparse
import json
import pathlib
import re
import statistics
import sys
from collections.abc import Callable
from typing import Any

DOCS = pathlib.Path(__file__).resolve().parent
RESULTS = DOCS / "results"


def load(name: str) -> dict[str, Any] | None:
    """A committed result file, or None if it is not there."""
    path = RESULTS / name
    return json.loads(path.read_text()) if path.is_file() else None


def provenance(name: str) -> dict[str, str]:
    """The command, world and machine of a result file."""
    entry: dict[str, str] = json.loads((RESULTS / "provenance.json").read_text())[name]
    return entry


def measured_by(*names: str) -> str:
    """The line under a table: where each of its files comes from."""
    parts = []
    for name in names:
        p = provenance(name)
        parts.append(f"`docs/results/{name}`: `{p['command']}`, {p['world']}, on {p['machine']}")
    return "Written by `docs/write_results.py` from " + "; ".join(parts) + "."


def signed(value: float, digits: int) -> str:
    return f"{value:.{digits}f}".replace("-", "−")


def percent(share: float) -> str:
    return f"{100 * share:.1f}"


# ---------------------------------------------------------------------------------------------
# The thesis reproduced (results/thesis.md)

THESIS_COLUMN = [
    "−1.15° (0.57°)", "31.4 / 35.5 / 11.6 %", "2.8 %", "89.4 / 91.6 / 81.3 %", "the most / the most",
    "the humanoid slowest", "27 / 15 / 12", "≈ 0.3 / — / ≈ 0.9", "11 / 7 / 11 (9, 13, 13)", "",
]
"""The thesis's own figures (thesis Tables 3.1, 4.5, 4.6, 4.7, 4.8, 4.11, Figs. 4.7–4.8,
4.13–4.18, 4.25), as the reproduction's report sets them."""

ROWS = [
    "forward's rotation over a second, mean (sd)",
    "segments matching the commands: Tiny / Expert / humanoid",
    "the humanoid's gaps",
    "prediction rounds with a match, RCB: Expert / Tiny / humanoid",
    "behaviours the humanoid's models create / delete, RCB",
    "LP changes to settle, RCB: Expert / Tiny / humanoid",
    "goals in 50: Expert / Tiny / humanoid",
    "final LP, varying skill: Poor / Average / Expert",
    "improved imitators' goals: RCB / BCR / varying skill (own goals)",
    "shape checks that hold",
]


def shape_checks(results: dict[str, Any]) -> str:
    """How many of the report's shape checks hold, as the report counts them."""
    from polymimic.reproduce.report import render

    found = re.search(r"Shape checks: (\d+) of (\d+) hold", render(results, {}))
    assert found is not None, "the report counts its shape checks"
    return f"{found.group(1)} of {found.group(2)}"


def reproduction_column(r: dict[str, Any]) -> list[str]:
    """One world's column of the reproduction table."""
    forward = r["primitive_stats"]["forward"]
    seg = r["segments"]
    rcb = r["experiments"]["heterogeneous_rcb"]
    who = ("expert", "tiny", "humanoid")
    behaviours = rcb["behaviours"]
    imitators = [r["experiments"][e]["imitator"] for e in ("heterogeneous_rcb", "heterogeneous_bcr", "varying_skill")]
    own = [i["own_goals"] for i in imitators]
    own_text = "0" if not any(own) else ", ".join(f"{o:.1f}" for o in own)
    lp = r["experiments"]["varying_skill"]["final_lp"]
    return [
        f"{signed(forward['rotation_mean_deg'], 2)}° ({forward['rotation_sd_deg']:.2f}°)",
        " / ".join(percent(seg[d]["command_match"]) for d in ("tiny", "expert", "humanoid")) + " %",
        f"{percent(seg['humanoid']['gaps'])} % of {seg['humanoid']['segments']}",
        " / ".join(percent(rcb["match_rate"][d]["mean"]) for d in who) + " %",
        f"{behaviours['humanoid']['created']['mean']:.1f} / {behaviours['humanoid']['deleted']['mean']:.1f} "
        f"(the Expert's {behaviours['expert']['created']['mean']:.1f} / {behaviours['expert']['deleted']['mean']:.1f})",
        " / ".join(f"{rcb['lp_climb'][d]['changes']['mean']:.0f}" for d in who),
        " / ".join(str(r["demonstrators"][d]["goals"]) for d in who),
        " / ".join(f"{lp[d]['mean']:.2f}" for d in ("poor", "average", "expert")),
        " / ".join(f"{i['goals']:.1f}" for i in imitators) + f" ({own_text})",
        shape_checks(r),
    ]


def reproduction_table() -> str | None:
    default, before = load("results.json"), load("results_before_calibration.json")
    if default is None or before is None:
        return None
    rows = zip(ROWS, reproduction_column(before), reproduction_column(default), THESIS_COLUMN)
    lines = ["| | before the calibration | the default world | thesis |", "| --- | --- | --- | --- |"]
    lines += [f"| {label} | {b} | {d} | {t} |" for label, b, d, t in rows]
    return "\n".join(lines) + "\n\n" + measured_by("results.json", "results_before_calibration.json")


# ---------------------------------------------------------------------------------------------
# The matrix (results/matrix.md)

COLUMNS = ("expert", "tiny", "humanoid", "own_body", "mixed_bodies")
HEADINGS = ("expert", "tiny", "humanoid", "own body", "mixed bodies")


def matrix_table(method: str) -> str | None:
    matrix = load("matrix.json")
    if matrix is None:
        return None
    lines = ["| imitator | " + " | ".join(HEADINGS) + " |", "| --- " * (len(COLUMNS) + 1) + "|"]
    for row, cells in matrix["cells"].items():
        entries = []
        for column in COLUMNS:
            cell = cells[column]
            net = cell[method]["net_goals"]
            ratio = cell["transfer"][method]
            text = f"{net['mean']:.1f} ({net['sd']:.1f})"
            entries.append(text if ratio is None else f"{text} ×{ratio:.2f}")
        lines.append(f"| {row} | " + " | ".join(entries) + " |")
    return "\n".join(lines) + "\n\n" + measured_by("matrix.json")


# ---------------------------------------------------------------------------------------------
# The benchmark (results/benchmark.md)

README_PROFILES = ("one_good", "half", "equal", "linear", "mixed_bodies", "random")
"""The README's columns: the five built-in crowds and the random crowd, every method's floor."""
METHOD_ORDER = ("polymimic", "polymimic_thesis_control", "polymimic_uniform_lp", "polymimic_practice", "offline_rl",
                "bco", "bco_lp", "bc", "bc_best", "ppo", "ppo_bc", "random")


def methods_of(benchmark: dict[str, Any]) -> list[str]:
    """The methods the run compared, in the pages' order."""
    present = {m for p in benchmark["profiles"].values() for m in p["methods"]}
    return [m for m in METHOD_ORDER if m in present] + sorted(present - set(METHOD_ORDER))


def net_goals_table(benchmark: dict[str, Any], profiles: list[str], cell: Callable[[dict[str, Any]], str]) -> str:
    lines = ["| method | " + " | ".join(profiles) + " |", "| --- " * (len(profiles) + 1) + "|"]
    for method in methods_of(benchmark):
        entries = [benchmark["profiles"][p]["methods"].get(method) for p in profiles]
        lines.append(f"| `{method}` | " + " | ".join("—" if m is None else cell(m) for m in entries) + " |")
    return "\n".join(lines)


def benchmark_table() -> str | None:
    """Net goals ± sd (goals / own goals) of every method in every profile, then each method's
    gain over its own random-crowd floor."""
    benchmark = load("benchmark.json")
    if benchmark is None:
        return None
    profiles = list(benchmark["profiles"])
    scores = net_goals_table(benchmark, profiles,
                             lambda m: f"{m['net_goals']['mean']:.1f} ± {m['net_goals']['sd']:.1f} "
                                       f"({m['goals']['mean']:.1f} / {m['own_goals']['mean']:.1f})")
    crowds = [p for p in profiles if p != "random"]
    gains = net_goals_table(benchmark, crowds, lambda m: "—" if m.get("gain_over_floor") is None
                            else f"{m['gain_over_floor']:+.1f}".replace("-", "−"))
    return (scores + "\n\nWhat the demonstrations add — each method's net goals less its own net goals from "
            "the `random` crowd (ten members at ε = 1, no skill shown):\n\n" + gains + "\n\n"
            + measured_by("benchmark.json"))


def skill_table() -> str | None:
    """How the LP ranks each crowd's members against their true skill, per profile."""
    benchmark = load("benchmark.json")
    if benchmark is None:
        return None

    def mean(value: dict[str, float | None], digits: int = 2) -> str:
        return "–" if value["mean"] is None else f"{value['mean']:.{digits}f}"

    lines = ["| profile | ρ(LP, true skill) | τ(LP, true skill) | ρ(own net goals, true skill) | "
             "a member of the highest true skill on top (LP) |", "| --- | --- | --- | --- | --- |"]
    for name, profile in benchmark["profiles"].items():
        recovery, trials = profile["skill_recovery"], profile["trials"]
        top = recovery["top_among_best"]
        lines.append(f"| {name} | {mean(recovery['spearman'])} | {mean(recovery['kendall'])} | "
                     f"{mean(profile['skill_by_outcomes']['spearman'])} | "
                     f"{'–' if top is None else f'{top} of {trials}'} |")
    return "\n".join(lines) + "\n\n" + measured_by("benchmark.json")


def benchmark_targets() -> str | None:
    """The benchmark's targets, checked on the committed file as the run's report checks them."""
    benchmark = load("benchmark.json")
    if benchmark is None:
        return None
    from polymimic.benchmark.targets import check_targets

    verdict = {True: "met", False: "**missed**", None: "n/a"}
    lines = ["| target | measured | verdict |", "| --- | --- | --- |"]
    lines += [f"| {t['statement']} | {t['measured']} | {verdict[t['met']]} |" for t in check_targets(benchmark)]
    return "\n".join(lines) + "\n\n" + measured_by("benchmark.json")


COMPARED_AT = (0, 10_000, 25_000, 50_000, 100_000, 250_000, 500_000)
"""The checkpoints the practice-against-RL table shows (environment steps)."""


def _at(curve: list[list[float]], steps: int) -> float | None:
    """A curve's net goals at ``steps``: its last point played within them (None before its first)."""
    points = [p[2] for p in curve if p[1] <= steps]
    return points[-1] if points else None


def _curves_by_method(compared: dict[str, Any]) -> dict[tuple[str, str], list[list[list[float]]]]:
    """Per (method, profile): the seeds' curves, each ``[checkpoint, steps played, net goals]``."""
    out: dict[tuple[str, str], list[list[list[float]]]] = {}
    for key, entry in compared.items():
        method, profile = key.split("/")[:2]
        out.setdefault((method, profile), []).append(entry["curve"])
    return out


def first_reaching(curves: list[list[list[float]]], score: float) -> int | None:
    """The fewest environment steps at which the seeds' mean (each seed's latest point) reaches
    ``score`` (None: never within the curves).

    >>> first_reaching([[[0, 0, 30], [10, 10, 40]], [[0, 0, 36], [10, 10, 46]]], 43)
    10
    """
    marks = sorted({int(p[1]) for c in curves for p in c})
    for mark in marks:
        values = [_at(c, mark) for c in curves]
        if all(v is not None for v in values) and statistics.fmean(v for v in values if v is not None) >= score:
            return mark
    return None


def practice_vs_ppo_table() -> str | None:
    """Mean net goals over seeds at the compared checkpoints, a row per method and profile, and
    the comparison's targets."""
    compared = load("practice_vs_ppo.json")
    if compared is None:
        return None
    curves = _curves_by_method(compared)
    header = ["0 steps" if c == 0 else f"{c:,}".replace(",", " ") for c in COMPARED_AT]
    lines = ["| profile | method | seeds | " + " | ".join(header) + " |", "| --- " * (len(header) + 3) + "|"]
    for (method, profile), runs in sorted(curves.items(), key=lambda kv: (kv[0][1], kv[0][0])):
        cells = []
        for mark in COMPARED_AT:
            values = [_at(run, mark) for run in runs]
            cells.append("—" if any(v is None for v in values)
                         else f"{statistics.fmean(v for v in values if v is not None):.1f}")
        lines.append(f"| {profile} | `{method}` | {len(runs)} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n\n" + measured_by("practice_vs_ppo.json")


def practice_targets() -> str | None:
    """The comparison's targets, each with its measured figure and verdict (mean of the seeds)."""
    compared = load("practice_vs_ppo.json")
    if compared is None:
        return None
    curves = _curves_by_method(compared)
    methods = sorted({m for m, _ in curves} - {"ppo", "ppo_bc"})
    verdict = {True: "met", False: "**missed**", None: "n/a"}
    lines = ["| profile | target | measured | verdict |", "| --- | --- | --- | --- |"]
    for method in methods:
        for profile in sorted({p for m, p in curves if m == method}):
            ours, theirs = curves[(method, profile)], curves.get(("ppo_bc", profile))
            at_50k = [_at(c, 50_000) for c in ours]
            reached = statistics.fmean(v for v in at_50k if v is not None) if None not in at_50k else None
            dip = min(min(p[2] for p in c) - c[0][2] for c in ours)
            rows = [(f"`{method}` nets ≥ 47 within 50 000 steps",
                     "—" if reached is None else f"{reached:.1f}", None if reached is None else reached >= 47),
                    (f"`{method}` never more than 1 below its start (any seed, any checkpoint)", signed(dip, 0),
                     dip >= -1)]
            if theirs is not None:
                rows += _against_ppo_bc(ours, theirs)
            lines += [f"| {profile} | {t} | {m} | {verdict[v]} |" for t, m, v in rows]
    return "\n".join(lines) + "\n\n" + measured_by("practice_vs_ppo.json")


STUDIES = DOCS.parent / "studies"
PRACTICE_STUDY = STUDIES / "which_practice_wins_on_validation.json"
"""The study that chose practice's default: its curves on validation attempts, per method,
profile and trial (``studies/which_practice_wins_on_validation.py``)."""
CHECK_STUDY = STUDIES / "which_check_keeps_distil_safe.json"
"""The study that chose ``distil``'s check, on the same validation attempts
(``studies/which_check_keeps_distil_safe.py``)."""

Curves = dict[str, dict[tuple[str, int], list[list[float]]]]
"""A study's curves: per variant (a method, a check), per (profile, trial), ``[checkpoint, steps,
net goals]`` at each checkpoint."""


def study_curves(path: pathlib.Path) -> Curves | None:
    """A practice study's file (keys ``variant/profile/trial/steps``) as curves, or None if it is
    not there; a file of more than one budget is refused (a table compares one)."""
    if not path.is_file():
        return None
    done: dict[str, Any] = json.loads(path.read_text())
    budgets = {key.split("/")[3] for key in done}
    if len(budgets) != 1:
        raise SystemExit(f"{path.name} holds practices of {len(budgets)} budgets ({sorted(budgets)}); "
                         f"the table compares one")
    curves: Curves = {}
    for key, value in done.items():
        variant, profile, trial, _steps = key.split("/")
        curves.setdefault(variant, {})[(profile, int(trial))] = value["curve"]
    return curves


def _deepest_dip(curves: Curves, variant: str) -> str:
    dip = min(min(point[2] for point in c) - c[0][2] for c in curves[variant].values())
    return signed(dip, 0) if dip else "0"


def _means_after(curves: Curves) -> dict[str, float]:
    return {v: statistics.fmean(c[-1][2] for c in by_trial.values()) for v, by_trial in curves.items()}


def practice_validation_table() -> str | None:
    """Each practice method's net goals before → after per profile and trial, its mean after, and
    its deepest dip below the start; the highest mean after is in bold (the default)."""
    curves = study_curves(PRACTICE_STUDY)
    if curves is None:
        return None
    columns = sorted({column for by_trial in curves.values() for column in by_trial},
                     key=lambda c: (c[0] != "one_good", c))
    means = _means_after(curves)
    best = max(means.values())
    lines = ["| method | " + " | ".join(f"`{p}` trial {t}" for p, t in columns) + " | mean after | deepest dip |",
             "| --- " * (len(columns) + 3) + "|"]
    for method, by_trial in curves.items():
        cells = [f"{by_trial[c][0][2]:.0f} → {by_trial[c][-1][2]:.0f}" if c in by_trial else "—" for c in columns]
        mean = f"{means[method]:.2f}"  # two profiles of two trials: quarters, shown exactly
        lines.append(f"| `{method}` | " + " | ".join(cells)
                     + f" | {f'**{mean}**' if means[method] == best else mean} | {_deepest_dip(curves, method)} |")
    return "\n".join(lines) + ("\n\nWritten by `docs/write_results.py` from "
                               "`studies/which_practice_wins_on_validation.json`.")


def practice_checks_table() -> str | None:
    """Each check's mean net goals before and after, how many practices ended above, at and below
    their teacher, and the deepest dip below the start."""
    curves = study_curves(CHECK_STUDY)
    if curves is None:
        return None
    means = _means_after(curves)
    lines = ["| check | practices | mean before | mean after | above the teacher | level with it | below it "
             "| deepest dip |", "| --- " * 8 + "|"]
    for check, by_trial in curves.items():
        ends = [c[-1][2] - c[0][2] for c in by_trial.values()]
        before = statistics.fmean(c[0][2] for c in by_trial.values())
        lines.append(f"| `{check}` | {len(ends)} | {before:.2f} | {means[check]:.2f} | {sum(e > 0 for e in ends)} | "
                     f"{sum(e == 0 for e in ends)} | {sum(e < 0 for e in ends)} | {_deepest_dip(curves, check)} |")
    return "\n".join(lines) + ("\n\nWritten by `docs/write_results.py` from "
                               "`studies/which_check_keeps_distil_safe.json`.")


def _thousands(steps: int | None) -> str:
    return "never" if steps is None else f"{steps:,}".replace(",", " ")


def _against_ppo_bc(ours: list[list[list[float]]],
                    theirs: list[list[list[float]]]) -> list[tuple[str, str, bool | None]]:
    """The targets that set practice beside ``ppo_bc``: sooner to every score it reaches, five
    times sooner to 47 (or its best), and at 250 000 steps at least its last figure."""
    marks = sorted({int(p[1]) for c in theirs for p in c})
    means = [statistics.fmean(v for v in (_at(c, mark) for c in theirs) if v is not None) for mark in marks]
    last, best = marks[-1], max(means)
    scores = sorted(set(means))
    # Sooner, or both from the start: a score ppo_bc's cloning already reaches at 0 steps is no race.
    sooner = [s for s in scores if (steps := first_reaching(ours, s)) is not None
              and (steps < (first_reaching(theirs, s) or 0) or steps == first_reaching(theirs, s) == 0)]
    goal = min(47.0, best)
    ours_to, theirs_to = first_reaching(ours, goal), first_reaching(theirs, goal)
    ratio = None if ours_to is None or theirs_to is None else (theirs_to / ours_to if ours_to else float("inf"))
    at_250k = [_at(c, 250_000) for c in ours]
    mine = statistics.fmean(v for v in at_250k if v is not None) if None not in at_250k else None
    return [
        ("fewer steps than `ppo_bc` to every score `ppo_bc` reaches", f"{len(sooner)} of its {len(scores)} scores",
         len(sooner) == len(scores)),
        (f"≥ 5× fewer steps than `ppo_bc` to {goal:.1f} (47, or `ppo_bc`'s best mean)",
         f"{_thousands(ours_to)} against {_thousands(theirs_to)}"
         + ("" if ratio is None else " (from the start)" if ratio == float("inf") else f" ({ratio:.1f}×)"),
         None if theirs_to is None else ratio is not None and ratio >= 5),
        (f"at 250 000 steps at least `ppo_bc`'s {means[-1]:.1f} at {_thousands(last)}",
         "—" if mine is None else f"{mine:.1f}", None if mine is None else mine >= means[-1]),
    ]


def practice_summary() -> str | None:
    """The README's line on practice."""
    compared = load("practice_vs_ppo.json")
    if compared is None:
        return None
    curves = _curves_by_method(compared)
    made = provenance("practice_vs_ppo.json")
    method = next(m for m, _ in curves if m not in ("ppo", "ppo_bc"))
    parts = []
    for profile in sorted({p for m, p in curves if m == method}):
        ours = curves[(method, profile)]
        start, end = statistics.fmean(c[0][2] for c in ours), max(int(p[1]) for c in ours for p in c)
        at = {mark: [_at(c, mark) for c in ours] for mark in (50_000, end)}
        shown = "; ".join(f"{statistics.fmean(v for v in values if v is not None):.1f} at {mark:,}".replace(",", " ")
                          for mark, values in at.items() if None not in values)
        theirs = curves.get(("ppo_bc", profile))
        beside = "" if theirs is None else (
            f" (`ppo_bc` {statistics.fmean(v for v in (_at(c, end) for c in theirs) if v is not None):.1f})")
        parts.append(f"`{profile}` {start:.1f} → {shown}{beside}")
    return (f"**Practice** (`{made['command']}`, {made['world']}): practising by `{method}`, the imitator's "
            f"net goals per 50, mean of {len(next(iter(curves.values())))} seeds: " + "; ".join(parts)
            + " ([practice](docs/results/practice.md)).")


def benchmark_summary() -> str | None:
    """The README's table: net goals alone, mean ± sd, every method, the five crowds and the floor."""
    benchmark = load("benchmark.json")
    if benchmark is None:
        return None
    profiles = [p for p in README_PROFILES if p in benchmark["profiles"]]
    return (net_goals_table(benchmark, profiles, lambda m: f"{m['net_goals']['mean']:.1f} ± {m['net_goals']['sd']:.1f}")
            + "\n\n" + measured_by("benchmark.json"))


WHEELED_FROM_OTHER = {"lego": "tiny", "tiny": "expert", "wagon": "expert"}
"""Each wheeled learner and the other wheeled body's built-in demonstrator it learns from."""


def matrix_summary() -> str | None:
    """The README's line on the matrix."""
    matrix = load("matrix.json")
    if matrix is None:
        return None
    cells = matrix["cells"]
    transfers = [cells[row][column]["transfer"]["polymimic"] for row, column in WHEELED_FROM_OTHER.items()
                 if row in cells]
    beaten = [(row, column) for row, columns in cells.items() for column, cell in columns.items()
              if cell["polymimic"]["net_goals"]["mean"] <= cell["bco"]["net_goals"]["mean"]]
    rows = ", ".join(cells)
    lead = ("polymimic nets more than `bco` in every cell" if not beaten
            else f"polymimic nets more than `bco` in all but {len(beaten)} of the cells")
    made = provenance("matrix.json")
    return (f"**Who learns from whom** (`{made['command']}`, {made['world']}): "
            f"each wheeled imitator learns from another wheeled body's demonstrator at least "
            f"{min(transfers):.2f} × as well as from its own body, and {lead} ({rows} learning from the "
            "Expert, the Tiny, the Humanoid, their own body and the `mixed_bodies` crowd; "
            "[the matrix](docs/results/matrix.md)).")


def thesis_summary() -> str | None:
    """The README's line on the reproduction."""
    results = load("results.json")
    if results is None:
        return None
    goals = [results["experiments"][e]["imitator"] for e in ("heterogeneous_rcb", "heterogeneous_bcr", "varying_skill")]
    own = "without an own goal" if not any(g["own_goals"] for g in goals) else "with own goals"
    made = provenance("results.json")
    return (f"**The thesis side by side** (`{made['command']}`): the report's shape checks hold, "
            f"{shape_checks(results)}, in {made['world']}, calibrated against the "
            f"thesis's own numbers; the improved imitators score {min(g['goals'] for g in goals):.1f} to "
            f"{max(g['goals'] for g in goals):.1f} goals of 50 {own}, where the thesis's scored 7 to 11 "
            "([the thesis side by side](docs/results/thesis.md)).")


TABLES: dict[str, tuple[str, Callable[[], str | None]]] = {
    "readme_benchmark": ("../README.md", benchmark_summary),
    "readme_matrix": ("../README.md", matrix_summary),
    "readme_thesis": ("../README.md", thesis_summary),
    "readme_practice": ("../README.md", practice_summary),
    "reproduction": ("results/thesis.md", reproduction_table),
    "matrix_polymimic": ("results/matrix.md", lambda: matrix_table("polymimic")),
    "matrix_bco": ("results/matrix.md", lambda: matrix_table("bco")),
    "benchmark": ("results/benchmark.md", benchmark_table),
    "benchmark_targets": ("results/benchmark.md", benchmark_targets),
    "benchmark_skill": ("results/benchmark.md", skill_table),
    "practice_vs_ppo": ("results/practice.md", practice_vs_ppo_table),
    "practice_targets": ("results/practice.md", practice_targets),
    "practice_validation": ("guides/practice.md", practice_validation_table),
    "practice_checks": ("guides/practice.md", practice_checks_table),
}
"""Each table's name, the page it sits in, and what writes it."""


def marked(name: str) -> re.Pattern[str]:
    return re.compile(rf"(<!-- table:{name} -->\n)(.*?)(\n<!-- /table:{name} -->)", re.S)


def page_with_table(name: str) -> tuple[pathlib.Path, str, str | None]:
    """The page, its text, and its text with the table rewritten (None: no result file yet)."""
    page, write = TABLES[name]
    path = DOCS / page
    text = path.read_text()
    pattern = marked(name)
    if not pattern.search(text):
        raise SystemExit(f"{page} has no <!-- table:{name} --> marks")
    table = write()
    if table is None:
        return path, text, None
    return path, text, pattern.sub(lambda m: m.group(1) + table + m.group(3), text)


LP_HISTORY_STRIDE = 10
"""Every how many points a taken benchmark file keeps of each member's LP history."""


def take(path: pathlib.Path) -> None:
    """Copies a run's result file under docs/results/, a benchmark's LP histories thinned."""
    data = json.loads(path.read_text())
    if path.name == "benchmark.json":
        for profile in data["profiles"].values():
            histories = profile.get("lp_over_training") or {}
            for member, history in histories.items():
                histories[member] = history[::LP_HISTORY_STRIDE]
    (RESULTS / path.name).write_text(json.dumps(data, indent=1) + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 if a page is not what the files give")
    parser.add_argument("--tables", nargs="+", choices=sorted(TABLES), default=list(TABLES), help="only these")
    parser.add_argument("--take", type=pathlib.Path, nargs="+", default=[], help="run result files to commit first")
    args = parser.parse_args(argv)
    for path in args.take:
        take(path)
    stale = []
    for name in args.tables:
        path, text, new = page_with_table(name)
        if new is None:
            print(f"{name}: no result file committed yet; {path.name} left as it is")
        elif new != text:
            stale.append(name)
            if not args.check:
                path.write_text(new)
                print(f"{name}: written to {path.name}")
    if args.check and stale:
        print("stale: " + ", ".join(stale), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
