"""A finished ``polymimic benchmark`` run, as the scripts that play its attempts again read it."""

import argparse

from polymimic.baselines.evaluation import attempts_of
from polymimic.benchmark.rundir import BenchmarkDir


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
    return run, config, attempts_of(config.benchmark.attempts_per_configuration, seed=config.seeds.evaluation)
