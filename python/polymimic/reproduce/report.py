"""The report: every table and figure of the thesis's Chapter 4 and Appendix B, ours beside the
thesis's, each with a one-line verdict on whether ours has the thesis's shape.

:func:`render` turns ``results.json`` (and the figures' paths) into Markdown; the verdicts are
plain checks on the numbers, collected at the top of the report.

>>> verdict("the humanoid matches least", True)
'**Shape:** the humanoid matches least — **yes**'
>>> pct(0.9124), pct(None), msd({"mean": 12.0, "sd": 1.5})
('91.2 %', '—', '12.0 (1.5)')
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from typing import Any, Literal

from polymimic._atomic import atomic_write_text
from polymimic.recognition import MOVING
from polymimic.reproduce import thesis
from polymimic.reproduce.figures import METRIC_LABELS, draw_figures
from polymimic.reproduce.results import BEHAVIOUR_COUNTS, gather
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.schema import ExperimentResults, MeanSd, Outcomes, PrimitiveStats, Results
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import RunConfig
from polymimic.runs.markdown import to_html
from polymimic.runs.roster import DEMONSTRATORS, EXPERIMENTS, HETEROGENEOUS, VARYING_SKILL
from polymimic.runs.stats import msd, num, pct

__all__ = ["render", "verdict", "write_report"]



def verdict(claim: str, holds: bool | None) -> str:
    """One line saying whether ours shows the thesis's ``claim``."""
    answer = "n/a (too little data)" if holds is None else ("yes" if holds else "no")
    return f"**Shape:** {claim} — **{answer}**"


def _table(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return [*lines, ""]


def _mean(cell: MeanSd | None) -> float | None:
    return None if not cell else cell["mean"]


def _all_known(*values: Any) -> bool:
    return all(v is not None for v in values)


def _known(values: Mapping[str, float | None]) -> dict[str, float] | None:
    """``values`` where every one is known; None where any is missing."""
    known = {k: v for k, v in values.items() if v is not None}
    return known if len(known) == len(values) else None


def _least(values: Mapping[str, float | None], who: str) -> bool | None:
    """Whether ``who`` has the strictly lowest value (None if any is missing)."""
    known = _known(values)
    return None if known is None else all(known[who] < v for k, v in known.items() if k != who)


def _most(values: Mapping[str, float | None], who: str) -> bool | None:
    """Whether ``who`` has the strictly highest value (None if any is missing)."""
    known = _known(values)
    return None if known is None else all(known[who] > v for k, v in known.items() if k != who)


class _Report:
    """Markdown, section by section, and every verdict given."""

    def __init__(self, results: Results, figures: dict[str, str]) -> None:
        self.r, self.figures = results, figures
        self.lines: list[str] = []
        self.verdicts: list[tuple[str, str, bool | None]] = []
        self.section = ""

    def heading(self, text: str, level: int = 2) -> None:
        self.section = text
        self.lines += [f"{'#' * level} {text}", ""]

    def say(self, *text: str) -> None:
        self.lines += [*text, ""]

    def table(self, header: Sequence[str], rows: Sequence[Sequence[Any]]) -> None:
        self.lines += _table(header, rows)

    def figure(self, number: str, caption: str) -> None:
        if number in self.figures:
            label = f"Fig {number}: " if number[0].isdigit() else ""
            self.lines += [f"![{label}{caption}]({self.figures[number]})", ""]

    def check(self, claim: str, holds: bool | None) -> None:
        self.verdicts.append((self.section, claim, holds))
        self.lines += [verdict(claim, holds), ""]


def render(results: Results, figures: dict[str, str], *, manifest: dict[str, Any] | None = None) -> str:
    """The whole report as Markdown."""
    report = _Report(results, figures)
    imitator = results.get("imitator", "lego")
    if imitator != "lego":
        # The thesis's numbers are a Lego imitator's: beside another body's they would compare nothing.
        _imitator_primitives(report, imitator)
        _experiments_without_thesis(report, list(results["experiments"]))
        head = _header(results, manifest)
        note = [f"The imitator is the {imitator}, not the thesis's Lego robot: the thesis's columns and shape checks "
                "are left out.", ""]
        return "\n".join(head + note + report.lines).rstrip() + "\n"
    for section in (_recognition, _segments, _demonstrators, _heterogeneous, _varying_skill, _own_experiments,
                    _appendix_b):
        section(report)
    head = _header(results, manifest)
    held = [v[2] for v in report.verdicts if v[2] is not None]
    summary = [f"## Shape checks: {sum(held)} of {len(held)} hold", ""]
    summary += _table(["item", "the thesis's shape", "ours"],
                      [(section.split(":")[0], claim, "n/a" if holds is None else ("yes" if holds else "**no**"))
                       for section, claim, holds in report.verdicts])
    return "\n".join(head + summary + report.lines).rstrip() + "\n"


def _header(results: Results, manifest: dict[str, Any] | None) -> list[str]:
    sizes = results["sizes"]
    lines = ["# polymimic: the thesis reproduced", "",
             f"polymimic {results['polymimic_version']}: {sizes['trials']} trials per experiment, "
             f"{sizes['demonstrations_per_configuration']} demonstrations per demonstrator and field configuration, "
             f"{sizes['train_per_primitive']} self-observed sequences per primitive ({sizes['test_per_primitive']} "
             f"held out), a {sizes['codebook_size']}-word codebook, {sizes['evaluated_imitators']} imitators "
             f"evaluated per experiment over {2 * sizes['attempts_per_configuration']} attempts each. "
             "The thesis: 100 trials, 25 demonstrations per configuration, one imitator evaluated per experiment "
             "over 50 attempts. Shares are percentages; mean (sd) over trials.", ""]
    if manifest and manifest.get("stages"):
        rows = [(stage, entry["started"], num(entry.get("seconds"))) for stage, entry in manifest["stages"].items()
                if entry.get("finished")]
        lines += _table(["stage", "started (UTC)", "seconds"], rows)
    return lines


def _recognition(report: _Report) -> None:
    r = report.r
    report.heading("Table 3.1: what each primitive does")
    report.say("Distance travelled (mm) and rotation (deg) in one second of each primitive, over the "
               "self-observation the recogniser learns from.")
    rows = []
    for p in MOVING:
        ours, theirs = r["primitive_stats"][p], thesis.TABLE_3_1.get(p, {})
        rows.append((p, f"{ours['distance_mean_mm']:.2f} ({ours['distance_sd_mm']:.2f})",
                     f"{theirs.get('distance_mean_mm', float('nan')):.2f} ({theirs.get('distance_sd_mm', 0):.2f})",
                     f"{ours['rotation_mean_deg']:.2f} ({ours['rotation_sd_deg']:.2f})",
                     f"{theirs.get('rotation_mean_deg', float('nan')):.2f} ({theirs.get('rotation_sd_deg', 0):.2f})"))
    report.table(["primitive", "distance, ours", "distance, thesis", "rotation, ours", "rotation, thesis"], rows)
    stats = r["primitive_stats"]
    report.check("forward and backward travel that way, left turns positive, right negative, and every mean "
                 "and spread is the thesis's (means within 10 % or two standard errors, spreads within 35 %)",
                 stats["forward"]["distance_mean_mm"] > 0 > stats["backward"]["distance_mean_mm"]
                 and stats["left"]["rotation_mean_deg"] > 0 > stats["right"]["rotation_mean_deg"]
                 and all(_like_table_3_1(stats[p], thesis.TABLE_3_1[p]) for p in MOVING))

    report.heading("Fig 4.5: each HMM on each primitive's held-out sequences")
    report.figure("4.5", "mean log-likelihood of each HMM on each primitive's test set")
    table = r["hmm_log_likelihood"]
    report.table(["HMM \\ test set", *MOVING], [(m, *(num(table[m][p]) for p in MOVING)) for m in MOVING])
    own_best = all((own := table[p][p]) is not None
                   and all((other := table[m][p]) is None or other < own for m in MOVING if m != p) for p in MOVING)
    report.check("every primitive's test set is scored highest by its own HMM", own_best)

    report.heading("Table 4.3: accuracy of each HMM on held-out sequences")
    accuracy = r["hmm_accuracy"]
    report.table(["HMM", "ours", "thesis"], [(p, pct(accuracy[p], 2), pct(thesis.ACCURACY[p], 2)) for p in MOVING])
    report.check("every primitive recognised more than 90 % of the time",
                 all((share := accuracy[p]) is not None and share > 0.9 for p in MOVING))


def _like_table_3_1(ours: PrimitiveStats, theirs: Mapping[str, float]) -> bool:
    """Whether one primitive's row is the thesis's: each spread within 35 % of its spread, each
    mean within 10 % of its mean or within two standard errors of ours (a thousand sequences
    cannot pin backward's 2.29° turn, sd 12.6°, to 10 %)."""
    two_errors_per_sd = 2.0 / math.sqrt(max(ours["count"], 1))
    rows = [(ours["distance_mean_mm"], ours["distance_sd_mm"], theirs["distance_mean_mm"], theirs["distance_sd_mm"]),
            (ours["rotation_mean_deg"], ours["rotation_sd_deg"], theirs["rotation_mean_deg"],
             theirs["rotation_sd_deg"])]
    ok = True
    for mean, sd, their_mean, their_sd in rows:
        ok &= abs(sd - their_sd) <= 0.35 * their_sd
        ok &= abs(mean - their_mean) <= max(0.10 * abs(their_mean), two_errors_per_sd * sd)
    return bool(ok)


def _segments(report: _Report) -> None:
    r = report.r
    report.heading("Table 4.5: segments matching the commands sent, and gaps")
    report.say("Share of classifiable segments named as the primitive equivalent to the commands the "
               "demonstrator sent, and share of all segments that are gaps. The imitator's row is the first "
               "varying-skill imitator's attempts, driven by the thesis's control rule.")
    who_all = [w for w in ("tiny", "expert", "humanoid", "poor", "average", "imitator") if w in r["segments"]]
    rows = [(w, pct(r["segments"][w]["command_match"]), pct(thesis.SEGMENTS[w]["command_match"]),
             pct(r["segments"][w]["gaps"]), pct(thesis.SEGMENTS[w]["gaps"]), r["segments"][w]["segments"])
            for w in who_all]
    report.table(["demonstrator", "matched, ours", "matched, thesis", "gaps, ours", "gaps, thesis", "segments"], rows)
    matches = {w: r["segments"][w]["command_match"] for w in ("tiny", "expert", "humanoid", "poor", "average")}
    report.check("the humanoid's segments match its commands least", _least(matches, "humanoid"))
    gaps = _known({w: r["segments"][w]["gaps"] for w in who_all})
    report.check("gaps are rare (under 5 % for every demonstrator)",
                 None if gaps is None else all(g < 0.05 for g in gaps.values()))


def _goal_rows(ours: Mapping[str, Outcomes], theirs: Mapping[str, Mapping[str, int]],
               names: Sequence[str]) -> list[tuple[Any, ...]]:
    return [(w, ours[w]["goals"], ours[w]["own_goals"], ours[w]["attempts"], theirs[w]["goals"],
             theirs[w]["own_goals"], theirs[w]["attempts"]) for w in names]


_GOALS_HEADER = ["demonstrator", "goals, ours", "own goals, ours", "attempts, ours", "goals, thesis",
                 "own goals, thesis", "attempts, thesis"]


def _demonstrators(report: _Report) -> None:
    d = report.r["demonstrators"]
    report.heading("Tables 4.6 and 4.9: goals and own goals of each demonstrator")
    report.table(_GOALS_HEADER, _goal_rows(d, thesis.DEMONSTRATOR_GOALS, ("expert", "tiny", "humanoid", "poor",
                                                                         "average")))
    # The thesis's claims are about its own five; a user's demonstrators have a section of their own.
    rate = {w: d[w]["goals"] / d[w]["attempts"] for w in DEMONSTRATORS}
    own_rate = {w: d[w]["own_goals"] / d[w]["attempts"] for w in DEMONSTRATORS}
    report.check("the Expert scores the most goals", _most(rate, "expert"))
    report.check("the Poor demonstrator scores the most own goals", _most(own_rate, "poor"))


def _match_rows(experiments: Sequence[ExperimentResults], theses: Sequence[Mapping[str, MeanSd]],
                names: Sequence[str]) -> list[tuple[Any, ...]]:
    rows = []
    for name in names:
        row: list[Any] = [name]
        for ours, theirs in zip(experiments, theses):
            row += [msd(ours["match_rate"].get(name), share=True), msd(theirs.get(name), share=True)]
        rows.append(tuple(row))
    return rows


def _behaviour_figures(report: _Report, numbers: Sequence[int], groups: dict[str, ExperimentResults],
                       names: Sequence[str], claims: dict[str, tuple[str, Any]]) -> None:
    for number, metric in zip(numbers, BEHAVIOUR_COUNTS):
        label = METRIC_LABELS[metric]
        report.heading(f"Fig 4.{number}: {label}", level=3)
        report.figure(f"4.{number}", f"{label}, mean (sd) over trials")
        report.table(["model", *(f"{g}, ours" for g in groups)],
                     [(n, *(msd(e["behaviours"][n][metric]) for e in groups.values())) for n in names])
        claim, test = claims[metric]
        report.check(claim, test({g: {n: _mean(e["behaviours"][n][metric]) for n in names}
                                  for g, e in groups.items()}))


def _each(test: Any) -> Any:
    """A test of one group's values, required of every group."""
    def every(groups: dict[str, dict[str, float | None]]) -> bool | None:
        answers = [test(values) for values in groups.values()]
        return None if None in answers else all(answers)
    return every


def _ordering_changes_little(experiments: Sequence[ExperimentResults], metric: str) -> bool | None:
    rcb, bcr = experiments
    out = []
    for name in HETEROGENEOUS:
        a, b = rcb["behaviours"][name][metric], bcr["behaviours"][name][metric]
        if a["mean"] is None or b["mean"] is None or a["sd"] is None or b["sd"] is None:
            return None
        out.append(abs(a["mean"] - b["mean"]) <= max(a["sd"], b["sd"], 0.5))
    return all(out)


def _heterogeneous(report: _Report) -> None:
    r = report.r
    rcb, bcr = r["experiments"]["heterogeneous_rcb"], r["experiments"]["heterogeneous_bcr"]
    models = ["imitator", *HETEROGENEOUS]
    report.heading("Table 4.7: prediction rounds with a match, heterogeneous bodies")
    report.table(["model", "RCB, ours", "RCB, thesis", "BCR, ours", "BCR, thesis"],
                 _match_rows([rcb, bcr], [thesis.MATCH_RATE["heterogeneous_rcb"],
                                          thesis.MATCH_RATE["heterogeneous_bcr"]], models))
    answers = [_least({n: _mean(e["match_rate"][n]) for n in HETEROGENEOUS}, "humanoid") for e in (rcb, bcr)]
    report.check("the humanoid's model matches least, in both orderings", None if None in answers else all(answers))
    close = [abs(a - b) <= 0.02 for n in models
             if (a := _mean(rcb["match_rate"][n])) is not None and (b := _mean(bcr["match_rate"][n])) is not None]
    report.check("the ordering moves no model's match rate by more than 2 points", all(close) if close else None)

    report.heading("Figs 4.7–4.12: behaviours of each model, heterogeneous bodies")
    groups = {"RCB": rcb, "BCR": bcr}
    pair = [rcb, bcr]
    claims = {
        "created": ("the humanoid's models create the most behaviours", _each(lambda v: _most(v, "humanoid"))),
        "deleted": ("the humanoid's models delete the most behaviours", _each(lambda v: _most(v, "humanoid"))),
        "permanent": ("the ordering changes no model's permanent behaviours by more than an sd",
                      lambda g: _ordering_changes_little(pair, "permanent")),
        "candidates": ("the Expert's models nominate more candidates when first (RCB) than last (BCR)",
                       lambda g: None if None in (g["RCB"]["expert"], g["BCR"]["expert"])
                       else g["RCB"]["expert"] > g["BCR"]["expert"]),
        "duplicates": ("the Expert's models have fewer duplicate candidates when first (RCB)",
                       lambda g: None if None in (g["RCB"]["expert"], g["BCR"]["expert"])
                       else g["RCB"]["expert"] < g["BCR"]["expert"]),
        "candidates_permanent": ("the two-wheeled demonstrators' candidates become permanent more than the "
                                 "humanoid's", _each(lambda v: _least({k: v[k] for k in HETEROGENEOUS}, "humanoid"))),
    }
    _behaviour_figures(report, range(7, 13), groups, models, claims)

    report.heading("Figs 4.13–4.18: learning preference over time, heterogeneous bodies")
    stride = rcb["lp_over_time"]["stride"]
    for number, (who, label) in zip(range(13, 19), [(w, o) for w in HETEROGENEOUS for o in ("RCB", "BCR")]):
        report.figure(f"4.{number}", f"LP of the {who} model ({label}), every {stride}th change, all trials")
    rows = []
    for who in HETEROGENEOUS:
        row: list[Any] = [who]
        for e in (rcb, bcr):
            climb = e["lp_climb"][who]
            row += [msd(e["final_lp"][who], digits=2), msd(climb["changes"], digits=0)]
        rows.append(tuple(row))
    share = pct(rcb["lp_climb"]["expert"]["share"], 0)
    report.say(f"How fast each LP settles: the LP changes it took to cover {share} of the way from 0.5 to its "
               "final value.")
    report.table(["model", "final LP, RCB", "changes to settle, RCB", "final LP, BCR", "changes to settle, BCR"],
                 rows)
    finals = _known({f"{w} {label}": _mean(e["final_lp"][w]) for label, e in groups.items() for w in HETEROGENEOUS})
    report.check("every heterogeneous model's LP climbs high (final mean ≥ 0.8)",
                 None if finals is None else all(f >= 0.8 for f in finals.values()))
    slow = [_most({w: _mean(e["lp_climb"][w]["changes"]) for w in HETEROGENEOUS}, "humanoid") for e in (rcb, bcr)]
    report.check("the humanoid's LP settles slowest, in both orderings", None if None in slow else all(slow))

    _imitator_table(report, "Table 4.8: goals of the trained imitators, heterogeneous bodies",
                    {"RCB": ("heterogeneous_rcb", rcb), "BCR": ("heterogeneous_bcr", bcr)})


def _imitator_table(report: _Report, title: str, groups: dict[str, tuple[str, ExperimentResults]]) -> None:
    report.heading(title)
    report.say("Mean (sd) over the evaluated imitators; the thesis evaluated one. *Improved* is polymimic's "
               "control of the imitator's model; *thesis control* its rule as the thesis gives it.")
    rows = []
    for label, (name, e) in groups.items():
        improved, rule, theirs = e["imitator"], e["imitator_thesis_control"], thesis.IMITATOR_GOALS[name]
        for control, cell in (("improved", improved), ("thesis control", rule)):
            rows.append((label, control, f"{num(cell['goals'])} ({num(cell['goals_sd'])})",
                         f"{num(cell['own_goals'])} ({num(cell['own_goals_sd'])})", cell["attempts"],
                         cell["imitators"], theirs["goals"], theirs["own_goals"], theirs["attempts"]))
    report.table(["experiment", "control", "goals, ours", "own goals, ours", "attempts", "imitators",
                  "goals, thesis", "own goals, thesis", "attempts, thesis"], rows)
    better = []
    for name, e in groups.values():
        cell, theirs = e["imitator"], thesis.IMITATOR_GOALS[name]
        goals, own_goals = cell["goals"], cell["own_goals"]
        if goals is not None and own_goals is not None:
            better.append(goals / cell["attempts"] > theirs["goals"] / theirs["attempts"]
                          and own_goals / cell["attempts"] < theirs["own_goals"] / theirs["attempts"])
    report.check("our imitators score more goals and fewer own goals than the thesis's",
                 all(better) if better else None)


def _varying_skill(report: _Report) -> None:
    e = report.r["experiments"]["varying_skill"]
    models = ["imitator", *VARYING_SKILL]
    report.heading("Table 4.10: prediction rounds with a match, varying skill")
    report.table(["model", "ours", "thesis"], _match_rows([e], [thesis.MATCH_RATE["varying_skill"]], models))
    report.check("the Expert's model matches best of the demonstrators'",
                 _most({n: _mean(e["match_rate"][n]) for n in VARYING_SKILL}, "expert"))

    report.heading("Figs 4.19–4.24: behaviours of each model, varying skill")
    expert_most = _each(lambda v: _most({k: v[k] for k in VARYING_SKILL}, "expert"))
    claims = {
        "created": ("the Expert's models create the fewest behaviours",
                    _each(lambda v: _least({k: v[k] for k in VARYING_SKILL}, "expert"))),
        "deleted": ("the Expert's models delete the fewest behaviours",
                    _each(lambda v: _least({k: v[k] for k in VARYING_SKILL}, "expert"))),
        "permanent": ("the Expert's models keep the most permanent behaviours", expert_most),
        "candidates": ("the Expert's models nominate the most candidates", expert_most),
        "duplicates": ("the Expert's models have the most duplicate candidates", expert_most),
        "candidates_permanent": ("the Expert's candidates become permanent in the imitator most", expert_most),
    }
    _behaviour_figures(report, range(19, 25), {"varying skill": e}, models, claims)

    report.heading("Fig 4.25: final learning preference, varying skill")
    report.figure("4.25", "final LP of each demonstrator's model, mean (sd) over trials")
    report.figure("final_lp_heterogeneous", "final LP, heterogeneous bodies (no figure in the thesis)")
    report.table(["model", "final LP, ours"], [(w, msd(e["final_lp"][w], digits=3)) for w in VARYING_SKILL])
    finals = _known({w: _mean(e["final_lp"][w]) for w in VARYING_SKILL})
    ordered = None if finals is None else finals["expert"] > finals["average"] > finals["poor"]
    report.check("final LPs order Expert > Average > Poor on average", ordered)
    hits = e["lp_order_hits"]
    report.say(f"Trials whose final LPs fell strictly in that order: {hits} of {e['trials']}.")

    report.heading("Figs 4.26–4.28: learning preference over time, varying skill")
    stride = e["lp_over_time"]["stride"]
    for number, who in zip(range(26, 29), VARYING_SKILL):
        report.figure(f"4.{number}", f"LP of the {who} model, every {stride}th change, all trials")
    report.check("the Poor model's LP ends below the starting 0.5, the Expert's near 0.9 or above",
                 None if finals is None else finals["poor"] < 0.5 and finals["expert"] >= 0.85)

    _imitator_table(report, "Table 4.11: goals of the trained imitators, varying skill",
                    {"varying skill": ("varying_skill", e)})
    poor, imitator = report.r["demonstrators"]["poor"], e["imitator"]
    clearly = None
    if (imitator_goals := imitator["goals"]) is not None and poor["attempts"]:
        margin = 2 * (imitator["goals_sd"] or 0.0)
        clearly = (imitator_goals - margin) / imitator["attempts"] > poor["goals"] / poor["attempts"]
    report.check("the improved imitator scores clearly more than the Poor demonstrator (by over two sd)", clearly)


def _own_experiments(report: _Report) -> None:
    """The run config's own experiments: the tables that apply, without thesis columns (the
    thesis has no numbers for them), and no shape checks."""
    _experiments_without_thesis(report, [name for name in report.r["experiments"] if name not in EXPERIMENTS])


def _experiments_without_thesis(report: _Report, names: Sequence[str]) -> None:
    """Each of the experiments ``names``: its demonstrators' goals, final LPs and match rates, and
    its imitators' goals under both controls."""
    d = report.r["demonstrators"]
    for name in names:
        e = report.r["experiments"][name]
        report.heading(f"{'Experiment' if name in EXPERIMENTS else 'Your experiment'}: {e['title']}")
        report.say(f"Phase one {e['phase_one']}, ordering {', '.join(e['ordering'])}; {e['trials']} trials. "
                   "Goals of each demonstrator over its own demonstrations; final LP and match rate mean (sd) "
                   "over trials.")
        report.table(["demonstrator", "goals", "own goals", "attempts", "final LP", "rounds matched"],
                     [(w, d[w]["goals"], d[w]["own_goals"], d[w]["attempts"], msd(e["final_lp"][w], digits=3),
                       msd(e["match_rate"][w], share=True)) for w in e["ordering"]])
        if e["lp_order_hits"] is not None:
            report.say(f"Final LPs in the skill order given: {e['lp_order_hits']} of {e['trials']} trials.")
        report.table(["control", "goals", "own goals", "attempts", "imitators"],
                     [(control, f"{num(cell['goals'])} ({num(cell['goals_sd'])})",
                       f"{num(cell['own_goals'])} ({num(cell['own_goals_sd'])})", cell["attempts"], cell["imitators"])
                      for control, cell in (("improved", e["imitator"]), ("thesis control",
                                                                          e["imitator_thesis_control"]))])


def _imitator_primitives(report: _Report, imitator: str) -> None:
    """The imitator's own Table 3.1 and its recogniser's accuracy, ours alone."""
    r = report.r
    report.heading(f"What each of the {imitator}'s primitives does")
    report.say("Distance travelled (mm) and rotation (deg) in one second of each primitive, over the imitator's "
               "self-observation; share of its held-out sequences each HMM names right.")
    stats = r["primitive_stats"]
    report.table(["primitive", "distance", "rotation", "held-out accuracy"],
                 [(p, f"{stats[p]['distance_mean_mm']:.2f} ({stats[p]['distance_sd_mm']:.2f})",
                   f"{stats[p]['rotation_mean_deg']:.2f} ({stats[p]['rotation_sd_deg']:.2f})",
                   pct(r["hmm_accuracy"].get(p), 2)) for p in MOVING])


def _appendix_b(report: _Report) -> None:
    ours, theirs = report.r["appendix_b"], thesis.APPENDIX_B
    titles: dict[Literal["created", "permanent", "predicting_ball"], str] = {
        "created": "Table B.1: behaviours found in most forward models",
        "permanent": "Table B.2: behaviours made permanent in most forward models",
        "predicting_ball": "Table B.3: behaviours predicting the ball in most forward models"}
    report.heading("Appendix B: the behaviours learned most often")
    report.say(f"Over all {ours['models']} forward models of our trials (the thesis: {theirs['models']}), as a "
               "share of models. Ours counts the models holding a behaviour at the end of their trial; the thesis "
               "counted every creation.")
    for key, title in titles.items():
        report.heading(title, level=3)
        rows = []
        for rank in range(max(len(ours[key]), len(theirs[key]))):
            a = ours[key][rank] if rank < len(ours[key]) else None
            b = theirs[key][rank] if rank < len(theirs[key]) else None
            rows.append((rank + 1, *(_behaviour_cells(a, ours["models"])), *(_behaviour_cells(b, theirs["models"]))))
        cells = ["primitives", "found", "permanent", "predicting ball"]
        report.table(["rank", *(f"{c}, ours" for c in cells), *(f"{c}, thesis" for c in cells)], rows)
        top_ours = {row["primitives"] for row in ours[key][:10]}
        top_theirs = {row["primitives"] for row in theirs[key][:10]}
        shared = len(top_ours & top_theirs)
        report.check(f"most of the thesis's top 10 are in our top 10 ({shared} of 10 are)",
                     shared >= 5 if top_ours else None)


def _behaviour_cells(row: Mapping[str, Any] | None, models: int) -> tuple[str, str, str, str]:
    if row is None:
        return ("", "", "", "")
    return (row["primitives"], pct(row["count"] / models, 0), pct(row["permanent"] / models, 0),
            pct(row["predicting_ball"] / models, 0))


def write_report(run: RunDir, config: RunConfig, *, runner: TaskRunner | None = None,
                 quiet: bool = False) -> Results:
    """Gather ``results.json``, draw the figures (on ``runner``'s workers if given), and write
    ``report.md`` and ``report.html``."""
    results = gather(run, config)
    atomic_write_text(run.results_path, json.dumps(results, indent=1, allow_nan=False) + "\n")
    figures = draw_figures(results, run.path, runner=runner, quiet=quiet)
    markdown = render(results, figures, manifest=run.manifest())
    atomic_write_text(run.report_md_path, markdown)
    atomic_write_text(run.report_html_path, to_html(markdown, title="polymimic: the thesis reproduced",
                                                    images_from=run.path))
    return results
