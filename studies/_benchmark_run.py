"""A finished ``polymimic benchmark`` run, as the scripts that play its attempts again read it."""

import argparse
import dataclasses
from collections.abc import Iterator

from polymimic._native import PrimitiveRecognizer, TrialResult
from polymimic.baselines.evaluation import attempts_of
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.datasets import load_demonstrations
from polymimic.learning import ImitatorPolicy, segmented


def arguments(doc: str, *, fits: int, one_profile: bool = False) -> argparse.Namespace:
    """The command line: the run directory, its profiles (or one, ``mixed_bodies`` by default)
    and how many fit seeds."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    if one_profile:
        parser.add_argument("--profile", default="mixed_bodies")
    else:
        parser.add_argument("--profiles", nargs="+", help="default: every profile of the run")
    parser.add_argument("--fits", type=int, default=fits, help="fit seeds 0, 1, …")
    return parser.parse_args()


def opened(run_dir: str):
    """The run, its config and its evaluation attempts (configuration, episode seed)."""
    run = BenchmarkDir(run_dir)
    config = run.open(None)
    return run, config, attempts_of(config.benchmark.sizes.attempts_per_configuration, seed=config.seeds.evaluation)


def imitators(run: BenchmarkDir, config, profile: str, trials: int) -> Iterator[tuple[int, ImitatorPolicy]]:
    """The ``polymimic`` imitators of a profile's first ``trials`` trials, with their seeds, as
    the run learned them (the improved control, the crowd's segmented demonstrations)."""
    recognizer = PrimitiveRecognizer.load(run.recognizer_path)
    batch = segmented(load_demonstrations(run.crowd_path(profile)), recognizer, **dataclasses.asdict(config.segmenter))
    for trial_seed in range(trials):
        trial = TrialResult.from_json(run.trial_path(profile, trial_seed).read_text())
        yield trial_seed, ImitatorPolicy(trial, recognizer=recognizer, config=config.learning, control="improved",
                                         demonstrations=batch, body=config.imitator_body())
