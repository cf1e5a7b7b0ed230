"""Draws the README's pictures: an Expert demonstration, and from a full run
(``polymimic reproduce --run-dir runs/full``) the learning preference of the varying-skill
experiment and a goal the improved imitator scored from configuration 2.

    python docs/make_images.py runs/full
"""

import json
import pathlib
import sys

from matplotlib.figure import Figure

import polymimic
from polymimic.datasets import load_demonstrations
from polymimic.plots import plot_lp_over_time

HERE = pathlib.Path(__file__).parent


def main(run_dir: str) -> None:
    demo = polymimic.record("expert", configuration=2, n=1, seed=0)[0]
    polymimic.plot_demonstration(demo, path=HERE / "expert_demonstration.png")
    results = json.loads((pathlib.Path(run_dir) / "results.json").read_text(encoding="utf-8"))
    lp = results["experiments"]["varying_skill"]["lp_over_time"]
    figure = Figure(figsize=(12.0, 3.4), layout="constrained")
    for ax, who in zip(figure.subplots(1, 3, sharey=True), ("poor", "average", "expert")):
        plot_lp_over_time(lp["trials"][who], stride=lp["stride"], title=f"{who}: LP over training", ax=ax)
    figure.savefig(HERE / "lp_varying_skill.png", dpi=110)
    attempts = load_demonstrations(pathlib.Path(run_dir) / "datasets" / "attempts_varying_skill_improved.parquet")
    goal = next(a for a in attempts if a.configuration == 2 and a.outcome == "goal")
    polymimic.plot_demonstration(goal, path=HERE / "improved_imitator_configuration_2.png")


if __name__ == "__main__":
    main(sys.argv[1])
