"""Speed of one decision: the imitator's ``act`` against a stable-baselines3 PPO policy's
``predict``, on the same tracker readings, in one run.

The imitator is an improved-control Lego imitator of the Expert's, the Poor player's and the
Tiny's 25 demonstrations per configuration (its behaviours are what each decision chains); the readings are the decision
instants of its own evaluation attempts (every ``act`` timed decides: the costly call; the 29
readings between two decisions only hold a command). The PPO policy is stable-baselines3's
default ``MlpPolicy`` as the ``ppo`` baseline builds it, answering the same readings as
observations one at a time, as a live loop or a Gymnasium loop asks.

Run: ``python benches/act_vs_sb3_predict.py [--decisions 2000]`` (needs ``polymimic[rl]``).
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import polymimic
from polymimic import recognition
from polymimic.baselines import ppo


def decision_readings(policy: polymimic.ImitatorPolicy, n: int) -> list[tuple[float, ...]]:
    """The readings at decision instants of the policy's own attempts (one a second)."""
    readings: list[tuple[float, ...]] = []
    for attempt in polymimic.evaluate(policy, attempts_per_configuration=25, seed=1).attempts:
        frames = attempt.frames[::30]
        readings += [tuple(float(v) for v in (f["t_s"], f["robot_x_mm"], f["robot_y_mm"], f["robot_theta_rad"],
                                              f["ball_x_mm"], f["ball_y_mm"])) for f in frames]
    seen = [r for r in readings if all(math.isfinite(v) for v in r)]  # PPO reads no lost ball
    return (seen * math.ceil(n / len(seen)))[:n]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--decisions", type=int, default=2000)
    args = parser.parse_args()
    recognizer = recognition.train_recognizer(polymimic.self_observation(100, seed=1))
    who = ["expert", "poor", "tiny"]
    demos = [d for name in who for c in (1, 2) for d in polymimic.record(name, configuration=c, n=25, seed=0)]
    trial = polymimic.run_trial(demos, recognizer=recognizer, ordering=who)
    policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos)
    readings = decision_readings(policy, args.decisions)
    player = policy.player()
    act_s = []
    for reading in readings:
        player.reset(start=1, seed=0)  # every act decides
        began = time.perf_counter()
        player.act(reading)
        act_s.append(time.perf_counter() - began)
    model = ppo.new_model(seed=0)
    observations = ppo.scaled(np.array([r[1:] for r in readings]), "goal_relative")
    model.predict(observations[0], deterministic=True)  # warm up
    predict_s = []
    for observation in observations:
        began = time.perf_counter()
        model.predict(observation, deterministic=True)
        predict_s.append(time.perf_counter() - began)
    for name, times in (("imitator act", act_s), ("stable-baselines3 predict", predict_s)):
        ms = np.array(times) * 1000.0
        print(f"{name:>26}: p50 {np.percentile(ms, 50):.3f} ms, p99 {np.percentile(ms, 99):.3f} ms "
              f"({len(ms)} decisions, {len(trial.imitator.behaviours)} behaviours)")
    print(f"{'ratio (predict / act)':>26}: p50 {np.percentile(predict_s, 50) / np.percentile(act_s, 50):.2f}x, "
          f"p99 {np.percentile(predict_s, 99) / np.percentile(act_s, 99):.2f}x")


if __name__ == "__main__":
    main()
