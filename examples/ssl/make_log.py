"""Makes ``ssl_vision.csv``, the SSL-Vision-style log of docs/guides/ssl.md: three penalty kicks of
the ``ssl_bot`` of ``ssl.toml`` on a 9 × 6 m field, as the vision system of a RoboCup Small Size
League team would log them, lapses included.

    python examples/ssl/make_log.py            # rewrites examples/ssl/ssl_vision.csv

The kicks are the built-in Tiny controller's, driving the team's robot (the log must come from
somewhere; the guide reads it as any team's). The log is what SSL-Vision's detection frames give:
a capture time in seconds since the epoch (``t_capture``), a frame number, the camera, the robot's
position (mm) and orientation (rad) and the ball's position, 30 frames a second, one kick after
another with the ball put back between them. Three lapses are written in: a single frame dropped
twice in the first kick, and the ball unseen for 0.3 s (its columns empty) in the second.
"""

from __future__ import annotations

import csv
import pathlib
import sys
import tempfile

import polymimic
from polymimic.runs.config import RunConfig

HERE = pathlib.Path(__file__).resolve().parent
LOG = HERE / "ssl_vision.csv"
EPOCH_S = 1_700_000_000.0
"""The capture clock's start: seconds since 1970, as SSL-Vision stamps its frames."""
DROPPED = {0: (40, 95)}
"""Kick → the frames (counted from its first) the log lost, one at a time."""
BALL_UNSEEN = {1: range(60, 69)}
"""Kick → the frames in which the vision saw no ball: 9 frames, 0.3 s between the sightings."""
COLUMNS = {"t": "t_capture", "robot_x": "robot_x", "robot_y": "robot_y", "robot_theta": "robot_orientation",
           "ball_x": "ball_x", "ball_y": "ball_y"}


def kicks() -> list[polymimic.Demonstration]:
    """The three kicks: the Tiny controller on the team's robot, from both configurations."""
    config = RunConfig.load(HERE / "ssl.toml")
    robot = config.bodies["ssl_bot"]
    return [*polymimic.record("tiny", body=robot, configuration=1, n=2, seed=3, name="ssl"),
            *polymimic.record("tiny", body=robot, configuration=2, n=1, seed=3, name="ssl")]


def _mm(value: str) -> str:
    """A position to a tenth of a millimetre, as the vision's detections are precise."""
    return f"{float(value):.1f}"


def write(path: pathlib.Path = LOG) -> None:
    """The log, lapses and SSL-Vision's columns written in."""
    demos = kicks()
    with tempfile.TemporaryDirectory() as folder:
        plain = pathlib.Path(folder) / "plain.csv"
        polymimic.write_tracks(demos, plain, rate_hz=30, columns=COLUMNS, include=("episode",))
        with open(plain, newline="") as handle:
            rows = list(csv.DictReader(handle))
    lines, frame_number, start_s = [], 0, 0.0
    for kick in range(len(demos)):
        readings = [r for r in rows if r["episode"] == str(kick)]
        for i, reading in enumerate(readings):
            frame_number += 1
            if i in DROPPED.get(kick, ()):
                continue
            unseen = i in BALL_UNSEEN.get(kick, ())
            ball = ("", "") if unseen else (_mm(reading["ball_x"]), _mm(reading["ball_y"]))
            lines.append([f"{EPOCH_S + start_s + float(reading['t_capture']):.4f}", frame_number, 0,
                          _mm(reading["robot_x"]), _mm(reading["robot_y"]),
                          f"{float(reading['robot_orientation']):.4f}", *ball])
        # The ball put back by hand: two seconds (60 frames) before the next kick.
        start_s += float(readings[-1]["t_capture"]) + 2.0
        frame_number += 60
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t_capture", "frame_number", "camera_id", "robot_x", "robot_y", "robot_orientation",
                         "ball_x", "ball_y"])
        writer.writerows(lines)


if __name__ == "__main__":
    write(pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else LOG)
