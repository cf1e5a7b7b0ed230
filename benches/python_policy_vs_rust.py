"""Recording cost per decision of a Python demonstrator against the same controller in Rust, at
10 decisions a second (the target: under 3×). The Python policy is the Poor demonstrator's rule
written in Python (drive at the ball, turning with hysteresis); the Rust one is the built-in
Poor controller deciding through the same policy path, on the same episodes and seeds. Both in
one run, alternating. Run: ``python benches/python_policy_vs_rust.py``.
"""

import argparse
import math
import statistics
import time

import polymimic
from polymimic import _native

DECISION_HZ = 10
FRAMES_PER_DECISION = 30 // DECISION_HZ


class PoorInPython:
    """The Poor demonstrator's controller (crates/polymimic-field/src/controller/poor.rs)."""

    name = "poor_in_python"
    decision_hz = DECISION_HZ

    def __init__(self):
        self.turning = None

    def reset(self, episode):
        self.turning = None

    def act(self, reading):
        if not reading.ball_seen:
            return "stop"
        bearing = math.atan2(reading.ball_y_mm - reading.robot_y_mm, reading.ball_x_mm - reading.robot_x_mm)
        error = math.remainder(bearing - reading.robot_theta_rad, math.tau)
        limit = math.radians(8.0 if self.turning else 20.0)
        self.turning = ("left" if error > 0 else "right") if abs(error) > limit else None
        return self.turning or "forward"


def decisions(frame_counts):
    """Decisions made over episodes of these lengths (the final frame takes none)."""
    return sum(math.ceil((k - 1) / FRAMES_PER_DECISION) for k in frame_counts)


def per_decision_us(record, n, seed):
    start = time.perf_counter()
    counts = [count for configuration in (1, 2) for count in record(configuration, n, seed)]
    return (time.perf_counter() - start) / decisions(counts) * 1e6, decisions(counts)


def python_policy(configuration, n, seed):
    demos = polymimic.record(PoorInPython(), body="lego", configuration=configuration, n=n, seed=seed)
    return [len(d.frames) for d in demos]


def rust_controller(configuration, n, seed):
    return _native.record_builtin_at_rate("poor", configuration=configuration, n=n, seed=seed,
                                          decision_hz=DECISION_HZ)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=20, help="episodes per configuration and measurement")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    ratios = []
    for round_ in range(args.rounds):
        python_us, python_n = per_decision_us(python_policy, args.episodes, round_)
        rust_us, rust_n = per_decision_us(rust_controller, args.episodes, round_)
        ratios.append(python_us / rust_us)
        print(f"round {round_}: Python policy {python_us:6.1f} µs/decision ({python_n} decisions), "
              f"Rust controller {rust_us:6.1f} µs/decision ({rust_n}); ratio {ratios[-1]:.2f}")
    print(f"\nmedian ratio {statistics.median(ratios):.2f} at {DECISION_HZ} decisions/s (target < 3)")


if __name__ == "__main__":
    main()
