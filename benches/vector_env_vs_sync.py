"""Environment steps per second at 32 sub-environments: PenaltyKickVectorEnv (every episode
stepped together in Rust) against Gymnasium's SyncVectorEnv over single PenaltyKickEnvs, both
in one run, alternating, on the same seeded random actions (the target: at least 3×).
Run: ``python benches/vector_env_vs_sync.py``.
"""

import argparse
import time

import gymnasium
import numpy as np

from _rounds import alternate
from polymimic.env import PenaltyKickEnv
from polymimic.vector_env import PenaltyKickVectorEnv


def steps_per_second(envs, n_envs, steps, seed):
    actions = np.random.default_rng(seed).integers(0, 5, size=(steps, n_envs))
    envs.reset(seed=seed)
    start = time.perf_counter()
    for row in actions:
        envs.step(row)
    return steps * n_envs / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envs", type=int, default=32)
    parser.add_argument("--steps", type=int, default=200, help="vector steps per measurement")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    ours = PenaltyKickVectorEnv(args.envs)
    sync = gymnasium.vector.SyncVectorEnv([PenaltyKickEnv for _ in range(args.envs)])
    ours_rate, sync_rate, ratio = alternate(
        args.rounds, lambda round_: steps_per_second(ours, args.envs, args.steps, round_),
        lambda round_: steps_per_second(sync, args.envs, args.steps, round_), names=("vector", "sync"),
        unit="env steps/s")
    print(f"\n{args.envs} envs: PenaltyKickVectorEnv {ours_rate:.0f} env steps/s, "
          f"SyncVectorEnv {sync_rate:.0f}; median ratio {ratio:.2f} (target ≥ 3)")


if __name__ == "__main__":
    main()
