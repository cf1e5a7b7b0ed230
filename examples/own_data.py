"""Learning from your own demonstrators: a controller you wrote, on a robot of your own, and the
log of a tracker you run, learned from together with polymimic's Expert.

Three demonstrators take penalty kicks:

- ``buggy_chaser``: a Python controller of the user's own (``Chaser``), driving a new wheeled
  body (``BUGGY``: bigger and faster than the thesis's Lego robot, with more motor lag);
- ``logged``: a robot watched by another program's overhead tracker, whose log is a CSV in
  metres and degrees at 15 readings a second, with the program's own column names
  (``overhead_camera_log`` stands in for that program);
- ``expert``: polymimic's built-in Expert.

The imitator (the thesis's Lego robot) recognises its own primitives, segments every
demonstration, learns one forward model per demonstrator weighted by each one's learning
preference, and then plays; the report gives what each demonstrator scored, its final learning
preference and the imitator's goals.

Run: ``python examples/own_data.py [--out DIR]`` (about half a minute).
"""

from __future__ import annotations

import argparse
import csv
import math
import pathlib
import tempfile
from collections.abc import Sequence

import polymimic
from polymimic import recognition
from polymimic.bodies import Slip, WheeledBody

BUGGY = WheeledBody("buggy", length_mm=180, width_mm=170, wheel_base_mm=150, top_wheel_speed_mm_s=140,
                    motor_lag_s=0.2, turn_lag_s=0.04, slip=Slip(common_sd=0.15, differential_sd=0.03))
"""The user's robot: a body described by its constants (see polymimic.bodies)."""

DEMONSTRATIONS_PER_CONFIGURATION = 10
ATTEMPTS_PER_CONFIGURATION = 10


class Chaser:
    """The user's controller: face the ball, drive at it, and come round behind it first when it
    lies between the robot and the target goal's far side (a simple approach a student might
    write). Decides five times a second."""

    decision_hz = 5

    def reset(self, episode: dict) -> None:
        self.behind = False

    def act(self, reading: polymimic.Reading) -> str:
        if not reading.ball_seen:
            return "stop"
        goal_x = reading.field_length_mm / 2
        # Aim at a point behind the ball on the goal's line until there, then at the ball.
        to_goal = math.atan2(-reading.ball_y_mm, goal_x - reading.ball_x_mm)
        aim_x = reading.ball_x_mm - 150 * math.cos(to_goal)
        aim_y = reading.ball_y_mm - 150 * math.sin(to_goal)
        if math.hypot(aim_x - reading.robot_x_mm, aim_y - reading.robot_y_mm) < 60:
            self.behind = True
        target = (reading.ball_x_mm, reading.ball_y_mm) if self.behind else (aim_x, aim_y)
        bearing = math.atan2(target[1] - reading.robot_y_mm, target[0] - reading.robot_x_mm)
        error = math.remainder(bearing - reading.robot_theta_rad, math.tau)
        if abs(error) < math.radians(15):
            return "forward"
        return "left" if error > 0 else "right"


def overhead_camera_log(path: pathlib.Path, *, episodes: int, seed: int) -> None:
    """Another program's tracker: it watches a robot (here the Poor controller on the Lego body,
    on polymimic's field standing in for the lab) and logs every other frame, 15 a second, in
    metres and degrees, under column names of its own, one run after another."""
    per_configuration = episodes // 2
    runs = [d for c in (1, 2) for d in polymimic.record("poor", configuration=c, n=per_configuration, seed=seed)]
    with path.open("w", newline="") as file:
        out = csv.writer(file)
        out.writerow(["run", "time", "x", "y", "heading", "ball_x", "ball_y"])
        for run, demo in enumerate(runs):
            frames = demo.frames[::2]
            for f in frames:
                out.writerow([run, f"{f['t_s']:.4f}", f"{f['robot_x_mm'] / 1000:.6f}", f"{f['robot_y_mm'] / 1000:.6f}",
                              f"{math.degrees(f['robot_theta_rad']):.4f}", f"{f['ball_x_mm'] / 1000:.6f}",
                              f"{f['ball_y_mm'] / 1000:.6f}"])


def gather(folder: pathlib.Path, *, seed: int) -> dict[str, list[polymimic.Demonstration]]:
    """Every demonstrator's demonstrations: recorded, imported, built in."""
    n = DEMONSTRATIONS_PER_CONFIGURATION
    chaser = [d for c in (1, 2) for d in polymimic.record(Chaser(), body=BUGGY, name="buggy_chaser",
                                                          configuration=c, n=n, seed=seed)]
    log = folder / "overhead_camera.csv"
    overhead_camera_log(log, episodes=2 * n, seed=seed)
    imported = polymimic.import_tracks(
        log, demonstrator="logged", body="lego", rate_hz=15, units={"length": "m", "angle": "deg"},
        columns={"episode": "run", "t": "time", "robot_x": "x", "robot_y": "y", "robot_theta": "heading",
                 "ball_x": "ball_x", "ball_y": "ball_y"})
    print(imported.summary())
    expert = [d for c in (1, 2) for d in polymimic.record("expert", configuration=c, n=n, seed=seed)]
    return {"expert": expert, "buggy_chaser": chaser, "logged": imported.demonstrations}


def learn_and_play(demonstrations: dict[str, list[polymimic.Demonstration]], *, seed: int):
    """The imitator's recogniser, one learning trial over every demonstration, and its play."""
    recognizer = recognition.train_recognizer(polymimic.self_observation(60, seed=seed), codebook_size=64, seed=seed)
    everyone = [d for who in demonstrations for d in demonstrations[who]]
    batch = polymimic.learning.segmented(everyone, recognizer)
    trial = polymimic.run_trial(batch, recognizer=recognizer, ordering=list(demonstrations), seed=seed)
    policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch)
    played = polymimic.evaluate(policy, attempts_per_configuration=ATTEMPTS_PER_CONFIGURATION, seed=seed)
    return trial, played


def report(demonstrations: dict[str, list[polymimic.Demonstration]], trial, played) -> str:
    """A Markdown report: every demonstrator's record and final learning preference, and the
    imitator's goals."""
    lines = ["# Learning from your own demonstrators", "",
             "| demonstrator | body | demonstrations | goals | own goals | final LP |",
             "| --- | --- | ---: | ---: | ---: | ---: |"]
    for who, demos in demonstrations.items():
        lines.append(f"| {who} | {demos[0].body.name} | {len(demos)} | {_count(demos, 'goal')} | "
                     f"{_count(demos, 'own_goal')} | {trial.models[who].lp:.2f} |")
    attempts = len(played.attempts)
    lines += ["", f"The imitator (Lego body, improved control) scored {played.goals} goals and "
                  f"{played.own_goals} own goals in {attempts} attempts.", ""]
    return "\n".join(lines)


def _count(demos: Sequence[polymimic.Demonstration], outcome: str) -> int:
    return sum(d.outcome == outcome for d in demos)


def main(argv: Sequence[str] | None = None) -> str:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=None, help="folder for the log and report.md")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    folder = args.out or pathlib.Path(tempfile.mkdtemp(prefix="polymimic-own-data-"))
    folder.mkdir(parents=True, exist_ok=True)
    demonstrations = gather(folder, seed=args.seed)
    trial, played = learn_and_play(demonstrations, seed=args.seed)
    text = report(demonstrations, trial, played)
    (folder / "report.md").write_text(text)
    print(text)
    print(f"written to {folder / 'report.md'}")
    return text


if __name__ == "__main__":
    main()
