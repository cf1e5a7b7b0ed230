"""How much a tracker log loses: demonstrations written as logs in metres and degrees at other
rates (polymimic.write_tracks), imported back (polymimic.import_tracks, outcomes derived from the
field), and compared frame by frame with the originals; then the recogniser's segments of the
Expert's imported demonstrations against those of the originals. Run:
``python studies/what_a_tracker_log_loses.py [--per-case 8]``.

Every demonstrator, both configurations, and lapses 0 and 0.9 (for outcomes other than goals);
errors are the largest over all frames (positions in mm; headings in degrees along the shorter
arc).
"""

import argparse
import pathlib
import tempfile
import time

import numpy as np

import polymimic
from polymimic import recognition
from polymimic.field import BODY_NAMES, DEMONSTRATORS

UNITS = {"length": "m", "angle": "deg"}
POSITIONS = ("robot_x_mm", "robot_y_mm", "ball_x_mm", "ball_y_mm")


def round_trip(demos, path, rate_hz, include=()):
    polymimic.write_tracks(demos, path, units=UNITS, rate_hz=rate_hz, include=include)
    return polymimic.import_tracks(path, demonstrator="tracked", body=demos[0].body, units=UNITS,
                                   rate_hz=rate_hz).demonstrations


def errors(a, b):
    position_mm = max(float(np.abs(a.frames[c] - b.frames[c]).max()) for c in POSITIONS)
    turn = np.angle(np.exp(1j * (a.frames["robot_theta_rad"] - b.frames["robot_theta_rad"])))
    return position_mm, float(np.degrees(np.abs(turn).max()))


def frame_labels(recognizer, demos):
    """Each frame's segment label ("" outside every segment)."""
    out = []
    for d, seg in zip(demos, recognizer.segment_many([d.frames for d in demos])):
        labels = np.full(len(d.frames), "", dtype=object)
        for label, first, last in zip(seg["label"], seg["first_frame"], seg["last_frame"]):
            labels[first:last + 1] = label
        out.append(labels)
    return np.concatenate(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--per-case", type=int, default=8, help="demonstrations per demonstrator, configuration, lapse")
    args = parser.parse_args()
    started = time.perf_counter()
    demos = [d for i, who in enumerate(DEMONSTRATORS) for c in (1, 2) for lapse in (0.0, 0.9)
             for d in polymimic.record(who, configuration=c, n=args.per_case, seed=1000 + 10 * i + c, lapse=lapse)]
    outcomes = {o: sum(d.outcome == o for d in demos) for o in polymimic.field.OUTCOMES}
    print(f"{len(demos)} demonstrations: {outcomes}")
    recognizer = recognition.train_recognizer(polymimic.self_observation(60, seed=1), codebook_size=64)
    experts = [d for d in demos if d.demonstrator == "expert"]
    folder = pathlib.Path(tempfile.mkdtemp())
    print("rate_hz  max_mm  p95_mm  max_deg  p95_deg  same_frames  same_outcome  expert_segments_same  "
          "expert_frame_labels_same")
    for rate_hz in (60, 45, 20):
        found, frames_same, outcome_same = [], 0, 0
        for body in BODY_NAMES:
            group = [d for d in demos if d.body.name == body]
            for a, b in zip(group, round_trip(group, folder / f"{body}_{rate_hz}.csv", rate_hz)):
                frames_same += len(a.frames) == len(b.frames)
                outcome_same += a.outcome == b.outcome
                found.append(errors(a, b))
        e = np.array(found)
        imported = round_trip(experts, folder / f"expert_{rate_hz}.csv", rate_hz)
        same, total = recognition.matching_segments(recognizer, experts, imported)
        labels_same = float(np.mean(frame_labels(recognizer, experts) == frame_labels(recognizer, imported)))
        print(f"{rate_hz:7d}  {e[:, 0].max():6.3g}  {np.percentile(e[:, 0], 95):6.3g}  {e[:, 1].max():7.3g}  "
              f"{np.percentile(e[:, 1], 95):7.3g}  {frames_same:5d}/{len(demos)}  {outcome_same:6d}/{len(demos)}  "
              f"{same}/{total} = {same / total:.2%}  {labels_same:.2%}")
    print(f"{time.perf_counter() - started:.1f} s")


if __name__ == "__main__":
    main()
