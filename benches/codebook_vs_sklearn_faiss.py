"""A 512-codeword codebook on 125 000 three-dimensional points: polymimic.Codebook (LBG)
against scikit-learn KMeans (k-means++, Lloyd) and faiss Kmeans run for as many Lloyd
iterations as LBG used in all, every library on one thread.
Run: ``python benches/codebook_vs_sklearn_faiss.py [--rounds 5]``.

The machine may be shared, so ours and faiss run alternately, round after round, and the
ratio reported is the median of the per-round ratios (each round's two runs saw about the
same load). Wall-clock and CPU times are both shown; on one thread they should agree unless
the machine is oversubscribed.
"""

import os

# One thread everywhere, before numpy, scikit-learn, faiss or polymimic load their pools.
for _variable in ("RAYON_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                  "BLIS_NUM_THREADS", "VECLIB_MAXIMUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_variable] = "1"

import argparse  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from sklearn.cluster import KMeans  # noqa: E402

import polymimic  # noqa: E402
from _data import tracker_like_points  # noqa: E402


def timed(function):
    """The result, the wall-clock seconds and the CPU seconds of this process."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = function()
    return result, time.perf_counter() - wall, time.process_time() - cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--points", type=int, default=125_000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--no-sklearn", action="store_true", help="skip scikit-learn")
    args = parser.parse_args()

    try:
        import faiss
    except ImportError:
        faiss = None
        print("faiss-cpu is not installed: pip install faiss-cpu")
    else:
        faiss.omp_set_num_threads(1)
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # scikit-learn depends on it, so this is a safeguard only
        threadpool_limits = None

    points = tracker_like_points(args.points)
    as_float32 = np.ascontiguousarray(points, dtype=np.float32)
    print(f"{len(points)} points × 3 → {args.size} codewords, one thread, {args.rounds} rounds")

    fits, ours_wall, ours_cpu, faiss_wall, faiss_cpu = [], [], [], [], []
    for round_ in range(args.rounds):
        ours, wall, cpu = timed(lambda: polymimic.Codebook.fit(points, size=args.size, seed=0))
        fits.append(ours)
        ours_wall.append(wall)
        ours_cpu.append(cpu)
        line = f"round {round_ + 1}: polymimic {wall:6.2f} s (cpu {cpu:6.2f} s)"
        if faiss is not None:
            kmeans = faiss.Kmeans(3, args.size, niter=ours.n_iter_, seed=0, max_points_per_centroid=10**9)
            _, wall, cpu = timed(lambda kmeans=kmeans: kmeans.train(as_float32))
            faiss_wall.append(wall)
            faiss_cpu.append(cpu)
            line += f"  faiss {wall:6.2f} s (cpu {cpu:6.2f} s)  ratio {ours_wall[-1] / wall:.3f}"
        print(line, flush=True)

    ours = fits[0]
    if any(not np.array_equal(fit.centroids, ours.centroids) for fit in fits):
        raise SystemExit("polymimic's codebook differed between rounds")
    ours_distortion = ours.distortion(points)
    print(f"\npolymimic LBG       median {statistics.median(ours_wall):6.2f} s "
          f"(cpu {statistics.median(ours_cpu):6.2f} s)"
          f"  distortion {ours_distortion:.4f}  ({ours.n_iter_} Lloyd iterations)")
    if faiss is not None:
        faiss_distortion = float(kmeans.index.search(as_float32, 1)[0].mean())
        print(f"faiss Kmeans        median {statistics.median(faiss_wall):6.2f} s "
              f"(cpu {statistics.median(faiss_cpu):6.2f} s)"
              f"  distortion {faiss_distortion:.4f}  ({ours.n_iter_} Lloyd iterations, float32)")

    if not args.no_sklearn:
        def sklearn_fit():
            if threadpool_limits is None:
                return KMeans(args.size, n_init=1, random_state=0).fit(points)
            with threadpool_limits(limits=1):
                return KMeans(args.size, n_init=1, random_state=0).fit(points)

        peer, peer_wall, peer_cpu = timed(sklearn_fit)
        peer_distortion = peer.inertia_ / len(points)
        print(f"scikit-learn KMeans once   {peer_wall:6.2f} s (cpu {peer_cpu:6.2f} s)  distortion {peer_distortion:.4f}"
              f"  ({peer.n_iter_} Lloyd iterations)")
        print(f"\nspeed-up over scikit-learn: {peer_wall / statistics.median(ours_wall):.2f}x; "
              f"distortion ours/scikit-learn: {ours_distortion / peer_distortion:.4f}")
    if faiss is not None:
        ratios = [o / f for o, f in zip(ours_wall, faiss_wall)]
        cpu_ratios = [o / f for o, f in zip(ours_cpu, faiss_cpu)]
        print(f"time ours/faiss for the same Lloyd iterations, one thread: median of per-round ratios "
              f"{statistics.median(ratios):.3f} (cpu {statistics.median(cpu_ratios):.3f}; "
              f"ratio of medians {statistics.median(ours_wall) / statistics.median(faiss_wall):.3f}; target ≤ 1.2)")


if __name__ == "__main__":
    main()
