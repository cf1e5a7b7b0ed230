"""Practice curves a study keeps in one JSON file, keyed ``variant/profile/trial/steps`` (the
variant a method or a check): each curve is written the moment it is finished, so a rerun goes
on where the last one stopped."""

import argparse
import json
import os
import pathlib
import statistics
import time
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from _benchmark_run import imitators
from polymimic import Attempts
from polymimic._atomic import atomic_write_text
from polymimic.baselines.tuning import VALIDATION_SEED_BASE
from polymimic.benchmark.rundir import BenchmarkDir


def on_validation(doc: str, *, variants: str, choices: Sequence[str],
                  out: pathlib.Path) -> tuple[argparse.Namespace, Any, Any]:
    """The command line of a study that practises a run's imitators on its validation attempts,
    one curve per ``variants`` choice (``--<variants>``), profile and trial, kept in ``out`` by
    default (the study's committed file, so that a rerun goes on from it); then the run and its
    config."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", default=["one_good", "half"])
    parser.add_argument(f"--{variants}", nargs="+", default=list(choices), choices=choices)
    parser.add_argument("--trials", type=int, default=2)
    parser.add_argument("--steps", type=int, default=50_000)
    parser.add_argument("--out", type=pathlib.Path, default=out, help=f"default: {out.name} beside the study")
    options = parser.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")  # torch on a small machine: one thread learns fastest
    run = BenchmarkDir(options.run_dir)
    return options, run, run.open(None)


def validation_attempts(config: Any) -> Attempts:
    """A benchmark run's validation attempts, drawn as tuning draws them: apart from the
    evaluation's."""
    tuning = config.benchmark.tuning
    return Attempts(per_configuration=tuning.validation_attempts_per_configuration,
                    seed=VALIDATION_SEED_BASE + tuning.validation_seed)


class CurveFile:
    """The finished curves of a study at ``path`` (none where it is not there yet)."""

    def __init__(self, path: pathlib.Path) -> None:
        self.path = path
        self.done: dict[str, Any] = json.loads(path.read_text()) if path.exists() else {}

    def __contains__(self, key: str) -> bool:
        return key in self.done

    def pending(self, options: argparse.Namespace, run: Any, config: Any,
                variants: Sequence[str]) -> Iterator[tuple[str, str, int, Any]]:
        """``(key, variant, trial seed, imitator)`` for each curve of ``options``' profiles and
        trials and of ``variants`` not kept yet."""
        for profile in options.profiles:
            for trial_seed, policy in imitators(run, config, profile, options.trials):
                for variant in variants:
                    key = f"{variant}/{profile}/{trial_seed}/{options.steps}"
                    if key not in self.done:
                        yield key, variant, trial_seed, policy

    def practise(self, key: str, practice: Callable[[], Any], *, scored_on: int) -> None:
        """Runs ``practice`` (a practice result with a ``curve``), keeps its curve and time under
        ``key`` at once, and prints where it started and ended of the ``scored_on`` attempts."""
        started = time.perf_counter()
        curve = [[p.checkpoint, p.steps, p.net_goals] for p in practice().curve]
        self.done[key] = {"curve": curve, "seconds": round(time.perf_counter() - started, 1)}
        atomic_write_text(self.path, json.dumps(self.done, indent=1) + "\n")
        print(f"{key}: {curve[0][2]:+.0f} -> {curve[-1][2]:+.0f} of {scored_on} ({self.done[key]['seconds']:.0f} s)",
              flush=True)

    def summary(self, variant: str, steps: int, profile: str | None = None) -> dict[str, Any] | None:
        """The mean net goals at each checkpoint over a variant's curves of ``steps`` (on one
        ``profile``, or all), its gain and its deepest dip below the start; None without curves."""
        prefix = f"{variant}/{profile}/" if profile else f"{variant}/"
        curves = [v["curve"] for k, v in self.done.items() if k.startswith(prefix) and k.endswith(f"/{steps}")]
        if not curves:
            return None
        means = [round(statistics.fmean(c[i][2] for c in curves), 2) for i in range(len(curves[0]))]
        return {"variant": variant, "profile": profile or "all", "curves": len(curves),
                "checkpoints": [p[0] for p in curves[0]], "mean_net_goals": means,
                "gain": round(means[-1] - means[0], 2),
                "deepest_dip": min(min(p[2] for p in c) - c[0][2] for c in curves)}
