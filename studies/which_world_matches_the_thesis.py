"""Calibrate the simulated world against the thesis's own numbers: search the tracker's noise and
the humanoid's constants together (Optuna, TPE sampler, seeded) for the world in which a
reproduction measures most nearly what the thesis published. Run:
``python studies/which_world_matches_the_thesis.py [--hours 2] [--trials N]`` (``pip install optuna``
first; it is not a dependency of polymimic). Linux or macOS.

Each trial writes a run config (the sizes ``--size`` names, the trial's ``[field.tracker]`` and
``[field.humanoid]``, the config's default seeds), runs ``polymimic reproduce`` on it in a
temporary run directory of its own (under ``$TMPDIR``), reads ``results.json`` and removes the
directory. Every finished trial is appended to a JSON-lines log (its constants, distance, each
group's term, each item's error, seconds); the study (``thesis_world``) lives in SQLite beside the
log, so the same command goes on with it. The best constants so far are written, after each new
best and at the end, as a TOML file in the form of ``docs/configs`` (``[field.tracker]`` and
``[field.humanoid]``); use it with ``polymimic reproduce --config docs/configs/thesis_world.toml``.
The first trials are the known points: the world that was the default before this calibration
(``docs/configs/world_before_calibration.toml``; the calibrated world is the default now), both
presets of ``docs/configs`` together, then each alone. A trial's LP shaping is the default's:
``lp_own_goal_weight`` became 3 with the calibrated world, which leaves the heterogeneous
experiments as they were (no demonstrator there concedes) but can move the varying-skill imitator's
row of Table 4.5 slightly against the study's first 112 trials. The search stops when ``--trials``
have run, before a trial could outlast ``--hours`` (a trial still running at the deadline is
stopped and counted as failed), or after three failed trials in a row (the reproduction itself is
then broken). One search at a time writes a log (it is locked); Ctrl-C or SIGTERM ends the trial's
reproduction with it and marks the trial failed.

Sizes: ``thesis`` (the default) is the thesis's (1000 self-observed sequences per primitive, a
512-word codebook, 25 demonstrations per configuration, 100 trials per experiment) with one
evaluated imitator per experiment instead of 100: the distance uses only the first varying-skill
imitator's attempts (Table 4.5's imitator row), and driving the other 99 is most of a full
reproduction's time. These are the most informative sizes there are, and still take well under
the minute or two a trial could afford. ``quick`` is ``polymimic reproduce --quick``'s, for a
smoke test. Measured on a shared two-core node while other work kept its load near 6: 35 s per
trial at ``thesis`` (the default world), so about 200 trials in two hours; 9 to 13 s at ``quick``
(the four known worlds).

The distance
------------
Every thesis number the reproduction measures a counterpart of is an item, with an error e:

* a mean the thesis gives an sd for (Table 3.1): |ours − thesis| / thesis's sd;
* a spread (Table 3.1's sds): |ln(ours / thesis)|;
* a share (Table 4.5's command matches and gaps, Table 4.7's match rates, and the 12 % of the
  imitator's permanent behaviours that came from the humanoid's models, §4.5): the log-odds ratio
  |logit(ours) − logit(thesis)|, shares clipped to [0.005, 0.995] (97 % against 81 % misses a sixth
  as often, which a relative error of 19 % would hide);
* what the thesis states in words only (Figs 4.7–4.18 are pictures; their bars and curves are not
  in its text), as how far ours falls short, zero once it holds; counts c compared as
  ln((c + 1) / (c' + 1)), so that a count of none is not infinitely far from a count of one:
  the humanoid's models create and delete the most behaviours (ln of the others' most over the
  humanoid's), keep about as many permanent ones (|ln| against the two-wheeled
  models' mean), the imitator's model fewer (ln of the imitator's over the demonstrators' mean);
  every heterogeneous LP rises to the maximum 1 ((1 − final LP) / 0.5), within the first half of
  training ((changes to cover 90 % of its way / all its changes − 0.5) / 0.5, the changes read
  off ``lp_over_time``), the humanoid's slowest (ln of the others' most changes over its own).

Each e is bounded smoothly by 3 as 3·tanh(e / 3), which leaves small errors almost as they are and
keeps one figure that is simply wrong from outweighing the rest, yet still tells a search that it
is getting less wrong; a number the results lack counts as 3. Each group's term is the mean of its
items: ``table_3_1`` (16 items), ``table_4_5`` (12), ``table_4_7`` (8), ``figs_4_7_4_12`` (10)
and ``figs_4_13_4_18`` (14), over both orderings for the figures. The distance is the mean of the
five terms weighted 2, 2, 2, 1, 1 (the tables give numbers, the figures only words). The report's
pass/fail shape checks play no part. The thesis's numbers come from ``polymimic.reproduce.thesis``;
the 12 % and the words are quoted below where they are used.

The search space
----------------
``[field.tracker]``: position_sigma_mm 0.05–2 (log), heading_sigma_rad 0.001–0.1 (log),
spike_probability 1e-4–0.03 (log), spike_max_rad 0.05–0.35. ``[field.humanoid]``: turn_pivot_mm
0–40, sway_rad 0.02–0.25 (log), step_yaw_sd_rad 0.005–0.1 (log), foot_aim_sd_mm 0–40, the end of
foot_window_s 0.4–1.0 (its start stays 0.3; kick_s is 1), spot_tolerance_mm 20–150 (log),
lineup_side_mm 50–300, lineup_ahead_mm 200–550: the constants the two presets set, each range
holding the default and the preset's value. The tracker's loss_probability stays at its default:
it only discards demonstrations, which no figure counts.
"""

from __future__ import annotations

import argparse
import dataclasses
import datetime
import json
import math
import os
import pathlib
import shlex
import signal
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from collections.abc import Iterable, Mapping
from typing import Any

from polymimic._atomic import atomic_path
from polymimic.reproduce import thesis
from polymimic.runs.config import ConfigError, RunConfig
from polymimic.runs.roster import HETEROGENEOUS

ROOT = pathlib.Path(__file__).resolve().parent.parent
PRESETS = {"tracker_table_3_1": ROOT / "docs/configs/tracker_table_3_1.toml",
           "humanoid_thesis_like": ROOT / "docs/configs/humanoid_thesis_like.toml"}
WORLD_BEFORE_CALIBRATION = ROOT / "docs/configs/world_before_calibration.toml"
DEFAULT_LOG = ROOT / "studies/calibration/thesis_world.jsonl"
DEFAULT_BEST = ROOT / "docs/configs/thesis_world.toml"
STUDY = "thesis_world"
DISTANCE_VERSION = 1
"""Kept with the study: distances of another version are not comparable."""

SIZES = {"thesis": RunConfig, "quick": RunConfig.quick}
FAILURES_IN_A_ROW = 3
"""The search stops after this many failed trials in a row: the reproduction itself is broken."""
LP_STRIDE = 10
"""``lp_over_time`` every 10th change rather than 200th: the figures' terms read the number of
changes off it, and sampling does not change learning."""

CAP = 3.0
SHARE_CLIP = 0.005
WEIGHTS = {"table_3_1": 2.0, "table_4_5": 2.0, "table_4_7": 2.0, "figs_4_7_4_12": 1.0, "figs_4_13_4_18": 1.0}
IMITATOR_PERMANENT_FROM_HUMANOID = 0.12
"""§4.5: about 12 % of the imitator's permanent behaviours still came from the Bioloid (Figs 4.9
and 4.12; not among polymimic.reproduce.thesis's numbers)."""
TWO_WHEELED = ("expert", "tiny")
HETEROGENEOUS_EXPERIMENTS = {"rcb": "heterogeneous_rcb", "bcr": "heterogeneous_bcr"}


@dataclasses.dataclass(frozen=True)
class Constant:
    """One searched constant: ``section.key`` of ``[field]``, or ``section.key[i]`` for an element."""

    name: str
    low: float
    high: float
    log: bool = False

    @property
    def path(self) -> tuple[str, str, int | None]:
        section, key = self.name.split(".")
        if key.endswith("]"):
            key, index = key[:-1].split("[")
            return section, key, int(index)
        return section, key, None


SPACE = (
    Constant("tracker.position_sigma_mm", 0.05, 2.0, log=True),
    Constant("tracker.heading_sigma_rad", 0.001, 0.1, log=True),
    Constant("tracker.spike_probability", 1e-4, 0.03, log=True),
    Constant("tracker.spike_max_rad", 0.05, 0.35),
    Constant("humanoid.turn_pivot_mm", 0.0, 40.0),
    Constant("humanoid.sway_rad", 0.02, 0.25, log=True),
    Constant("humanoid.step_yaw_sd_rad", 0.005, 0.1, log=True),
    Constant("humanoid.foot_aim_sd_mm", 0.0, 40.0),
    Constant("humanoid.foot_window_s[1]", 0.4, 1.0),
    Constant("humanoid.spot_tolerance_mm", 20.0, 150.0, log=True),
    Constant("humanoid.lineup_side_mm", 50.0, 300.0),
    Constant("humanoid.lineup_ahead_mm", 200.0, 550.0),
)


class Refused(Exception):
    """A reason to stop before searching, said in one line (exit code 2)."""


class TrialFailed(Exception):
    """A trial's reproduction could not run or did not finish."""


# The world: constants in and out of a field config.

def field_of(values: Mapping[str, float]) -> dict[str, Any]:
    """The ``[field]`` tables that set ``values`` over the default field."""
    full = RunConfig().field
    tables: dict[str, dict[str, Any]] = {}
    for constant in SPACE:
        section, key, index = constant.path
        table = tables.setdefault(section, {})
        if index is None:
            table[key] = float(values[constant.name])
        else:
            table[key] = [*full[section][key]]
            table[key][index] = float(values[constant.name])
    return tables


def constants_of(field: Mapping[str, Any]) -> dict[str, float]:
    """The searched constants of a whole field config."""
    values = {}
    for constant in SPACE:
        section, key, index = constant.path
        value = field[section][key]
        values[constant.name] = float(value if index is None else value[index])
    return values


def start_points() -> dict[str, dict[str, float]]:
    """The known worlds, first to be tried: the default before the calibration (named
    ``default`` in the study, which began before the calibrated world became the default), both
    presets together, each alone. A
    preset that sets anything the search does not vary, or a value outside its range, is refused
    (the enqueued trial would not be the preset's world)."""
    loaded = {name: RunConfig.load(path) for name, path in PRESETS.items()}
    both = RunConfig.load(PRESETS["humanoid_thesis_like"], base=loaded["tracker_table_3_1"])
    fields = {"default": RunConfig.load(WORLD_BEFORE_CALIBRATION).field, "both_presets": both.field,
              **{name: config.field for name, config in loaded.items()}}
    points = {}
    for name, field in fields.items():
        values = constants_of(field)
        outside = [c.name for c in SPACE if not c.low <= values[c.name] <= c.high]
        if outside:
            raise Refused(f"{name}: {outside[0]} = {values[outside[0]]} is outside the search space")
        if RunConfig.from_dict({"field": field_of(values)}).field != field:
            raise Refused(f"{name} sets a [field] constant the search does not vary")
        points[name] = values
    return points


# One trial: a reproduction in a temporary run directory.

def trial_config(size: str, values: Mapping[str, float]) -> RunConfig:
    """The run config of a trial: ``size``'s sizes, one evaluated imitator, the trial's world."""
    base = SIZES[size]()
    experiments = dataclasses.replace(base.experiments, evaluated_imitators=1, lp_stride=LP_STRIDE)
    return RunConfig.from_dict({"field": field_of(values)}, base=dataclasses.replace(base, experiments=experiments))


def _stop(process: subprocess.Popen[bytes]) -> None:
    """End the reproduction and every worker it started (its own process group)."""
    for sig, wait in ((signal.SIGTERM, 10.0), (signal.SIGKILL, None)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            continue


def reproduce(config: RunConfig, *, workers: int, timeout: float) -> dict[str, Any]:
    """``results.json`` of a reproduction with ``config``, its run directory removed after."""
    with tempfile.TemporaryDirectory(prefix="calibrate-thesis-world-") as scratch:
        folder = pathlib.Path(scratch)
        (folder / "config.toml").write_text(config.to_toml(), encoding="utf-8")
        command = [sys.executable, "-m", "polymimic", "reproduce", "--config", str(folder / "config.toml"),
                   "--run-dir", str(folder / "run"), "--quiet", "--workers", str(workers)]
        with open(folder / "stderr.txt", "wb") as stderr:
            process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=stderr, start_new_session=True)
            try:
                code = process.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                raise TrialFailed(f"stopped at the deadline, after {timeout:.0f} s") from None
            finally:
                _stop(process)  # its pool's workers too, whatever happened
        if code != 0:
            said = [line for line in (folder / "stderr.txt").read_text(errors="replace").splitlines() if line.strip()]
            raise TrialFailed(f"polymimic reproduce exited with {code}: {said[-1] if said else 'no message'}")
        try:
            results: dict[str, Any] = json.loads((folder / "run/results.json").read_text(encoding="utf-8"))
        except (OSError, ValueError) as error:
            raise TrialFailed(f"no results.json to read: {error}") from None
        return results


# The distance.

def _logit(share: float) -> float:
    share = min(max(share, SHARE_CLIP), 1.0 - SHARE_CLIP)
    return math.log(share / (1.0 - share))


def _share_error(ours: float | None, theirs: float) -> float | None:
    return None if ours is None else abs(_logit(ours) - _logit(theirs))


def _count_ratio(a: float | None, b: float | None) -> float | None:
    """ln((a + 1) / (b + 1)): counts of a handful compared without infinities."""
    return None if a is None or b is None else math.log((a + 1.0) / (b + 1.0))


def _short_by(x: float | None) -> float | None:
    """How far a stated order falls short: nothing once it holds."""
    return None if x is None else max(0.0, x)


def _mean(values: Iterable[float | None]) -> float | None:
    known = list(values)
    return None if not known or None in known else statistics.fmean(v for v in known if v is not None)


def _max(values: Iterable[float | None]) -> float | None:
    known = list(values)
    return None if not known or None in known else max(v for v in known if v is not None)


def table_3_1_items(results: Mapping[str, Any]) -> dict[str, float | None]:
    """Each moving primitive's distance and rotation, mean and sd, against Table 3.1."""
    items: dict[str, float | None] = {}
    for primitive, theirs in thesis.TABLE_3_1.items():
        ours = results["primitive_stats"].get(primitive, {})
        for motion, unit in (("distance", "mm"), ("rotation", "deg")):
            mean, sd = f"{motion}_mean_{unit}", f"{motion}_sd_{unit}"
            our_mean, our_sd = ours.get(mean), ours.get(sd)
            items[f"{primitive}.{mean}"] = (None if our_mean is None
                                            else abs(our_mean - theirs[mean]) / theirs[sd])
            items[f"{primitive}.{sd}"] = (None if our_sd is None
                                          else abs(math.log(max(our_sd, 1e-9) / theirs[sd])))
    return items


def table_4_5_items(results: Mapping[str, Any]) -> dict[str, float | None]:
    """Each demonstrator's (and the imitator's) command matches and gaps, against Table 4.5."""
    items: dict[str, float | None] = {}
    for who, theirs in thesis.SEGMENTS.items():
        ours = results["segments"].get(who, {})
        for key in ("command_match", "gaps"):
            items[f"{who}.{key}"] = _share_error(ours.get(key), theirs[key])
    return items


def table_4_7_items(results: Mapping[str, Any]) -> dict[str, float | None]:
    """Each model's share of prediction rounds with a match, both orderings, against Table 4.7."""
    items: dict[str, float | None] = {}
    for label, experiment in HETEROGENEOUS_EXPERIMENTS.items():
        ours = results["experiments"][experiment]["match_rate"]
        for model, theirs in thesis.MATCH_RATE[experiment].items():
            items[f"{label}.{model}"] = _share_error((ours.get(model) or {}).get("mean"), theirs["mean"])
    return items


def figs_4_7_4_12_items(results: Mapping[str, Any]) -> dict[str, float | None]:
    """What §4.4.1 says of the behaviour counts, per ordering: the Bioloid's models create far
    more behaviours than the others and delete far more, yet keep about as many permanent ones;
    the imitator's model keeps fewer permanent behaviours; and the 12 % of §4.5."""
    items: dict[str, float | None] = {}
    for label, experiment in HETEROGENEOUS_EXPERIMENTS.items():
        counts = results["experiments"][experiment]["behaviours"]

        def mean(model: str, count: str, counts: Mapping[str, Any] = counts) -> float | None:
            return counts[model][count]["mean"]

        for count in ("created", "deleted"):
            most_other = _max(mean(m, count) for m in TWO_WHEELED)
            items[f"{label}.humanoid_{count}_most"] = _short_by(_count_ratio(most_other, mean("humanoid", count)))
        wheeled = _mean(mean(m, "permanent") for m in TWO_WHEELED)
        ratio = _count_ratio(mean("humanoid", "permanent"), wheeled)
        items[f"{label}.humanoid_permanent_like_wheeled"] = None if ratio is None else abs(ratio)
        demonstrators = _mean(mean(m, "permanent") for m in HETEROGENEOUS)
        items[f"{label}.imitator_permanent_fewer"] = _short_by(_count_ratio(mean("imitator", "permanent"),
                                                                            demonstrators))
        from_humanoid, imitator = mean("humanoid", "candidates_permanent"), mean("imitator", "permanent")
        share = None if from_humanoid is None or not imitator else min(from_humanoid / imitator, 1.0)
        items[f"{label}.imitator_permanent_from_humanoid"] = _share_error(share, IMITATOR_PERMANENT_FROM_HUMANOID)
    return items


def figs_4_13_4_18_items(results: Mapping[str, Any]) -> dict[str, float | None]:
    """What §4.4.1 says of the LP over time, per ordering: every forward model's LP climbs fast
    to the maximum of 1, within the first half of training at the latest, and the Bioloid's
    models are the slowest to get there."""
    items: dict[str, float | None] = {}
    for label, experiment in HETEROGENEOUS_EXPERIMENTS.items():
        e = results["experiments"][experiment]
        stride, curves = e["lp_over_time"]["stride"], e["lp_over_time"]["trials"]
        climbs = {}
        for who in HETEROGENEOUS:
            final = e["final_lp"][who]["mean"]
            items[f"{label}.{who}_final_lp"] = None if final is None else max(0.0, 1.0 - final) / 0.5
            climbs[who] = e["lp_climb"][who]["changes"]["mean"]
            changes = _mean(stride * len(curve) for curve in curves[who])  # to within a stride
            late = None if climbs[who] is None or not changes else (climbs[who] / changes - 0.5) / 0.5
            items[f"{label}.{who}_lp_climbs_in_first_half"] = _short_by(late)
        slowest_other = _max(climbs[w] for w in TWO_WHEELED)
        items[f"{label}.humanoid_lp_slowest"] = _short_by(_count_ratio(slowest_other, climbs["humanoid"]))
    return items


GROUPS = {"table_3_1": table_3_1_items, "table_4_5": table_4_5_items, "table_4_7": table_4_7_items,
          "figs_4_7_4_12": figs_4_7_4_12_items, "figs_4_13_4_18": figs_4_13_4_18_items}


def _bounded(error: float | None) -> float:
    return CAP if error is None or not math.isfinite(error) else CAP * math.tanh(error / CAP)


def distance(results: Mapping[str, Any]) -> tuple[float, dict[str, float], dict[str, float]]:
    """The distance, each group's term, and every item's bounded error (``group.item``)."""
    try:
        items = {f"{group}.{name}": _bounded(error) for group, measure in GROUPS.items()
                 for name, error in measure(results).items()}
    except (KeyError, TypeError) as error:  # a results.json of another shape than this distance reads
        raise TrialFailed(f"results.json lacks what the distance reads: {error!r}") from None
    terms = {group: statistics.fmean(v for k, v in items.items() if k.startswith(f"{group}.")) for group in GROUPS}
    total = sum(WEIGHTS[g] * terms[g] for g in GROUPS) / sum(WEIGHTS.values())
    return total, terms, items


# Output: progress, the log, the best world as TOML.

def _degrees(constant: Constant, value: float) -> str:
    return f" ({math.degrees(value):.2f}°)" if constant.name.endswith("_rad") else ""


def describe(values: Mapping[str, float]) -> str:
    """The constants, one line per section."""
    lines = []
    for section in ("tracker", "humanoid"):
        cells = [f"{c.name.split('.', 1)[1]} {values[c.name]:.4g}{_degrees(c, values[c.name])}"
                 for c in SPACE if c.name.startswith(f"{section}.")]
        lines.append(f"  {section}: " + ", ".join(cells))
    return "\n".join(lines)


def terms_text(value: float, terms: Mapping[str, float]) -> str:
    return f"distance {value:.4f} = " + ", ".join(f"{g} {t:.3f}" for g, t in terms.items())


def shown(path: str | os.PathLike[str]) -> str:
    """A path as the repository names it, where it is inside the repository."""
    resolved = pathlib.Path(path).resolve()
    return str(resolved.relative_to(ROOT)) if resolved.is_relative_to(ROOT) else str(path)


def best_toml(trial: Any, *, size: str, storage: str, command: str, path: pathlib.Path) -> str:
    """The best trial's world, as ``docs/configs``' presets are written."""
    about = (f"The simulated world calibrated against the thesis's own numbers: the tracker's noise and the "
             f"humanoid's constants searched together (Optuna TPE) for the reproduction whose Table 3.1, Table 4.5, "
             f"Table 4.7 and Figs 4.7-4.18 lie nearest the thesis's (the distance is defined in "
             f"studies/which_world_matches_the_thesis.py). The best trial so far of the study {STUDY!r} in {storage}: "
             f"trial {trial.number}, measured at size {size!r} with the run config's default seeds, "
             f"{terms_text(trial.value, trial.user_attrs['terms'])}.")
    lines = [f"# {line}" for line in textwrap.wrap(about, 96)]
    lines += [f"# Made by: {command}", f"# Use it with `polymimic reproduce --config {shown(path)}`."]
    values, tables = trial.params, field_of(trial.params)
    for section in ("tracker", "humanoid"):
        rows = []
        for constant in (c for c in SPACE if c.path[0] == section):
            key = constant.path[1]
            value = tables[section][key]
            text = "[" + ", ".join(repr(v) for v in value) + "]" if isinstance(value, list) else repr(value)
            rows.append((f"{key} = {text}", _degrees(constant, values[constant.name]).strip(" ()")))
        width = max(len(row) for row, _ in rows) + 3
        lines += ["", f"[field.{section}]", *(f"{row:<{width}}# {note}" if note else row for row, note in rows)]
    return "\n".join(lines) + "\n"


def write_best(study: Any, *, size: str, storage: str, command: str, path: pathlib.Path) -> None:
    """The study's best world to ``path`` (atomically), checked to read back as the trial's."""
    import optuna

    complete = study.get_trials(deepcopy=False, states=(optuna.trial.TrialState.COMPLETE,))
    if not complete:
        return
    best = study.best_trial
    text = best_toml(best, size=size, storage=storage, command=command, path=path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as temporary:  # left as it was if the check below refuses
        temporary.write_text(text, encoding="utf-8")
        if constants_of(RunConfig.load(temporary).field) != best.params:
            raise RuntimeError(f"{path} would not read back as trial {best.number}'s world")


def log_line(log: Any, record: Mapping[str, Any]) -> None:
    log.write(json.dumps(record) + "\n")
    log.flush()


# The search.

def open_study(storage: str, *, size: str, seed: int, shown_as: str) -> Any:
    """The study in ``storage``, made if new; one made at another size or by another distance is
    refused, and trials a stopped run left running are marked failed. The sampler's seed is
    ``seed`` plus the trials the study holds, so that a continued study does not draw the points
    of its first run again."""
    import optuna

    optuna.logging.set_verbosity(optuna.logging.WARNING)
    study = optuna.create_study(study_name=STUDY, storage=storage, direction="minimize", load_if_exists=True)
    made = study.user_attrs
    if made.get("size", size) != size:
        raise Refused(f"the study in {shown_as} measures at size {made['size']!r}: pass --size {made['size']} "
                      "or another --storage")
    if made.get("distance_version", DISTANCE_VERSION) != DISTANCE_VERSION:
        raise Refused(f"the study in {shown_as} measured another distance (version {made['distance_version']}): "
                      "pass another --storage")
    study.set_user_attr("size", size)
    study.set_user_attr("distance_version", DISTANCE_VERSION)
    # The log is locked, so a trial still running is one a killed run left.
    for stale in study.get_trials(deepcopy=False, states=(optuna.trial.TrialState.RUNNING,)):
        study.tell(stale.number, state=optuna.trial.TrialState.FAIL)
    sampler = optuna.samplers.TPESampler(seed=seed + len(study.get_trials(deepcopy=False)), multivariate=True)
    return optuna.load_study(study_name=STUDY, storage=storage, sampler=sampler)


def enqueue_start_points(study: Any, points: Mapping[str, Mapping[str, float]]) -> None:
    """Queue every known world not measured yet; one whose trial failed or was interrupted is
    queued again (a known world fails only where the reproduction itself does)."""
    import optuna

    states = optuna.trial.TrialState
    trials = study.get_trials(deepcopy=False)
    for name, values in points.items():
        done = [t for t in trials if t.user_attrs.get("start_point") == name
                and t.state in (states.COMPLETE, states.WAITING)]
        if not done:
            study.enqueue_trial(dict(values), user_attrs={"start_point": name})


def run_one(study: Any, args: argparse.Namespace, deadline: float) -> dict[str, Any]:
    """Ask for a world, measure it, tell the study; the log's record of it."""
    import optuna

    trial = study.ask()
    values = {c.name: trial.suggest_float(c.name, c.low, c.high, log=c.log) for c in SPACE}
    started = time.monotonic()
    record: dict[str, Any] = {"trial": trial.number, "start_point": trial.user_attrs.get("start_point"),
                              "size": args.size, "constants": values}
    try:
        results = reproduce(trial_config(args.size, values), workers=args.workers,
                            timeout=max(deadline - time.monotonic(), 1.0))
        value, terms, items = distance(results)
    except (TrialFailed, ConfigError) as error:
        trial.set_user_attr("error", str(error))
        study.tell(trial, state=optuna.trial.TrialState.FAIL)
        return {**record, "state": "fail", "error": str(error), "seconds": round(time.monotonic() - started, 1),
                "finished": _now()}
    except BaseException:
        study.tell(trial, state=optuna.trial.TrialState.FAIL)
        raise
    seconds = round(time.monotonic() - started, 1)
    for key, attr in (("terms", terms), ("items", items), ("seconds", seconds)):
        trial.set_user_attr(key, attr)
    study.tell(trial, value)
    return {**record, "state": "complete", "distance": value, "terms": terms, "items": items, "seconds": seconds,
            "finished": _now()}


def _now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")


def report(record: Mapping[str, Any], study: Any) -> str:
    """What a trial printed: its world, its distance and each group's term, the best so far."""
    start = f" ({record['start_point']})" if record["start_point"] else ""
    head = f"trial {record['trial']}{start}, {record['seconds']:.0f} s: "
    if record["state"] != "complete":
        return head + f"failed: {record['error']}\n" + describe(record["constants"])
    best = study.best_trial
    return (head + terms_text(record["distance"], record["terms"]) + "\n" + describe(record["constants"])
            + f"\n  best so far: trial {best.number}, distance {best.value:.4f}")


def search(args: argparse.Namespace) -> int:
    started = time.monotonic()
    deadline = started + args.hours * 3600.0
    try:
        import optuna
    except ImportError:
        raise Refused("optuna is not installed: pip install optuna") from None
    import fcntl

    points = start_points()
    args.log.parent.mkdir(parents=True, exist_ok=True)
    storage = args.storage if "://" in args.storage else f"sqlite:///{pathlib.Path(args.storage).resolve()}"
    if "://" not in args.storage:
        pathlib.Path(args.storage).resolve().parent.mkdir(parents=True, exist_ok=True)
    command = shlex.join(["python", *sys.argv])
    with open(args.log, "a", encoding="utf-8") as log:
        try:
            fcntl.flock(log, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise Refused(f"another calibration is writing {args.log}") from None
        study = open_study(storage, size=args.size, seed=args.seed, shown_as=args.storage)
        enqueue_start_points(study, points)
        print(f"study {STUDY!r} in {args.storage}: {len(study.trials)} trials so far (queued ones included); "
              f"log {args.log}", flush=True)

        def best() -> None:
            where = args.storage if "://" in args.storage else shown(args.storage)
            write_best(study, size=args.size, storage=where, command=command, path=args.best)

        ran, longest, failed = 0, 0.0, 0
        try:
            while args.trials is None or ran < args.trials:
                left = deadline - time.monotonic()
                if left <= longest:
                    print(f"stopping: {left:.0f} s left of --hours, and a trial has taken {longest:.0f} s", flush=True)
                    break
                record = run_one(study, args, deadline)
                log_line(log, record)
                ran, longest = ran + 1, max(longest, record["seconds"])
                print(report(record, study), flush=True)
                failed = failed + 1 if record["state"] != "complete" else 0
                if failed == FAILURES_IN_A_ROW:
                    print(f"stopping: {failed} trials in a row failed; see the log", flush=True)
                    break
                if record["state"] == "complete" and study.best_trial.number == record["trial"]:
                    best()
        except KeyboardInterrupt:
            print("interrupted: the trial under way is marked failed", flush=True)
            best()
            return 130
        best()
    if study.get_trials(deepcopy=False, states=(optuna.trial.TrialState.COMPLETE,)):
        minutes = (time.monotonic() - started) / 60
        print(f"{ran} trial{'s' if ran != 1 else ''} in {minutes:.1f} min; best: trial {study.best_trial.number}, "
              f"distance {study.best_value:.4f}, written to {args.best}", flush=True)
    return 0


# The command line.

class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> Any:
        self.exit(2, f"{self.prog}: error: {message}\n")  # one line, no usage


def _number(kind: type, *, least: float, strictly: bool = False) -> Any:
    def parse(text: str) -> Any:
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not {'an integer' if kind is int else 'a number'}") from None
        if not math.isfinite(value) or value < least or (strictly and value == least):
            raise argparse.ArgumentTypeError(f"must be {'above' if strictly else 'at least'} {least:g}, got {text}")
        return value
    return parse


def arguments(argv: list[str] | None = None) -> argparse.Namespace:
    parser = _Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hours", type=_number(float, least=0.0, strictly=True), default=2.0,
                        help="the most the search may run, in hours; no trial is started that could outlast it "
                             "(default: 2)")
    parser.add_argument("--trials", type=_number(int, least=1),
                        help="at most this many trials in this run; the study keeps the earlier ones "
                             "(default: as many as --hours allows)")
    parser.add_argument("--size", choices=SIZES, default="thesis",
                        help="reproduction sizes of each trial: 'thesis' (the thesis's, one evaluated imitator per "
                             "experiment; under a minute) or 'quick' (--quick's; seconds, for a smoke test). A study "
                             "keeps one size (default: thesis)")
    parser.add_argument("--log", type=pathlib.Path, default=DEFAULT_LOG,
                        help="JSON-lines log, one record per trial, appended to (default: "
                             f"{DEFAULT_LOG.relative_to(ROOT)})")
    parser.add_argument("--storage",
                        help="Optuna storage: a file for SQLite or a database URL; the same storage continues the "
                             "same study (default: the log's path with the suffix .sqlite3)")
    parser.add_argument("--best", type=pathlib.Path, default=DEFAULT_BEST,
                        help="where the best world so far is written as TOML, [field.tracker] and [field.humanoid] "
                             f"(default: {DEFAULT_BEST.relative_to(ROOT)})")
    parser.add_argument("--workers", type=_number(int, least=1), default=os.cpu_count() or 1,
                        help="processes each reproduction runs its trials and evaluations on (default: one per "
                             "core)")
    parser.add_argument("--seed", type=_number(int, least=0), default=0,
                        help="seed of the TPE sampler, plus the trials the study holds when a run starts; the "
                             "reproductions always use the run config's seeds (default: 0)")
    args = parser.parse_args(argv)
    if args.storage is None:
        args.storage = str(args.log.with_suffix(".sqlite3"))
    return args


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


def main() -> int:
    args = arguments()
    signal.signal(signal.SIGTERM, _interrupt)  # stopped from outside: end the trial's processes too
    try:
        return search(args)
    except Refused as refusal:
        print(f"{pathlib.Path(sys.argv[0]).name}: error: {refusal}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
