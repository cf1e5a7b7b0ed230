"""A 512-codeword codebook on 125 000 three-dimensional points: polymimic.Codebook (LBG)
against scikit-learn KMeans (k-means++, Lloyd) and faiss Kmeans run for as many Lloyd
iterations as LBG used in all. Run: ``python benches/codebook_vs_sklearn_faiss.py``.
"""

import argparse
import time

import numpy as np
from sklearn.cluster import KMeans

import polymimic
from _data import tracker_like_points


def timed(function):
    start = time.perf_counter()
    result = function()
    return result, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--points", type=int, default=125_000)
    args = parser.parse_args()

    points = tracker_like_points(args.points)
    print(f"{len(points)} points × 3 → {args.size} codewords")

    ours, ours_s = timed(lambda: polymimic.Codebook.fit(points, size=args.size, seed=0))
    ours_distortion = ours.distortion(points)
    print(f"polymimic LBG      {ours_s:7.2f} s  distortion {ours_distortion:.4f}  ({ours.n_iter_} Lloyd iterations)")

    peer, peer_s = timed(lambda: KMeans(args.size, n_init=1, random_state=0).fit(points))
    peer_distortion = peer.inertia_ / len(points)
    print(f"scikit-learn KMeans {peer_s:6.2f} s  distortion {peer_distortion:.4f}  ({peer.n_iter_} Lloyd iterations)")

    try:
        import faiss
    except ImportError:
        faiss = None
        print("faiss-cpu is not installed: pip install faiss-cpu")
    if faiss is not None:
        as_float32 = np.ascontiguousarray(points, dtype=np.float32)
        kmeans = faiss.Kmeans(3, args.size, niter=ours.n_iter_, seed=0, max_points_per_centroid=10**9)
        _, faiss_s = timed(lambda: kmeans.train(as_float32))
        faiss_distortion = float(kmeans.index.search(as_float32, 1)[0].mean())
        print(f"faiss Kmeans        {faiss_s:6.2f} s  distortion {faiss_distortion:.4f}  "
              f"({ours.n_iter_} Lloyd iterations, float32)")

    print(f"\nspeed-up over scikit-learn: {peer_s / ours_s:.2f}x; "
          f"distortion ours/scikit-learn: {ours_distortion / peer_distortion:.4f}")
    if faiss is not None:
        print(f"time ours/faiss for the same Lloyd iterations: {ours_s / faiss_s:.2f} (target ≤ 2)")


if __name__ == "__main__":
    main()
