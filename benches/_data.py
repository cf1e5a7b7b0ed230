"""Inputs shared by the peer comparisons: thesis-sized and reproducible."""

import numpy as np


def thesis_sequences(n_sequences=5000, n_symbols=512, seed=1):
    """5000 sequences of 25–30 symbols that drift through the alphabet, as quantised motion does."""
    rng = np.random.default_rng(seed)
    sequences = []
    for _ in range(n_sequences):
        length = int(rng.integers(25, 31))
        offset = int(rng.integers(0, n_symbols))
        t = np.arange(length)
        sequences.append((offset + 7 * t + rng.integers(0, 16, size=length)) % n_symbols)
    return sequences


def tracker_like_points(n_points=125_000, seed=2):
    """(n, 3) points along short random arcs: (dx mm, dy mm, 16·dθ rad), like tracker frames."""
    rng = np.random.default_rng(seed)
    arcs = []
    for _ in range(-(-n_points // 25)):
        speed_mm, turn_rad = rng.uniform(-50, 50), rng.uniform(-0.6, 0.6)
        s = np.arange(25) / 25
        heading = turn_rad * s
        arcs.append(np.stack([
            speed_mm * s * np.cos(heading) + rng.uniform(-1, 1, 25),
            speed_mm * s * np.sin(heading) + rng.uniform(-1, 1, 25),
            16 * heading + rng.uniform(-0.8, 0.8, 25),
        ], axis=1))
    return np.concatenate(arcs)[:n_points]


def best_of(function, repeats):
    """The fastest of several runs, in seconds (the least disturbed by other work)."""
    import time

    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best
