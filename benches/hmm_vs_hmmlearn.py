"""Baum-Welch per iteration, one thread: polymimic.DiscreteHMM against hmmlearn.

Both start from the same parameters on the same 5000 sequences of 25–30 symbols over 512
symbols (the thesis's size), left-right topology. The time of one iteration is the
difference between fits of more and fewer iterations, divided by the difference in
iterations, so that what each library does once per fit (input conversion, checks) is not
counted as iteration time for either. Run: ``python benches/hmm_vs_hmmlearn.py``.
"""

import os

os.environ["RAYON_NUM_THREADS"] = "1"  # one thread for ours; must be set before the import
os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402
from hmmlearn import hmm  # noqa: E402

import polymimic  # noqa: E402
from _data import best_of, thesis_sequences  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--states", type=int, nargs="+", default=[1, 5, 20])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    sequences = thesis_sequences()
    stacked = np.concatenate(sequences)[:, None]
    lengths = [len(s) for s in sequences]
    print(f"{len(sequences)} sequences, {len(stacked)} symbols, 512 symbols, left-right, one thread")
    print(f"{'states':>6} {'ours ms':>9} {'scaling ms':>11} {'log ms':>9} {'vs scaling':>11} {'vs log':>8}")
    for n_states in args.states:
        start = polymimic.DiscreteHMM(n_states, 512, max_iter=0, seed=0).fit(sequences)
        params = (start.startprob_, start.transmat_, start.emissionprob_)

        def ours_fit(iterations, params=params):
            model = polymimic.DiscreteHMM.from_params(*params, max_iter=iterations, tol=float("-inf"))
            return best_of(lambda: model.fit(sequences, init="given"), args.repeats)

        ours_s = (ours_fit(21) - ours_fit(1)) / 20

        peer_s = {}
        for implementation in ("scaling", "log"):
            def peer_fit(iterations, n_states=n_states, implementation=implementation, params=params):
                peer = hmm.CategoricalHMM(n_components=n_states, n_features=512, implementation=implementation,
                                          init_params="", params="ste", n_iter=iterations, tol=-np.inf)

                def fit(peer=peer, params=params):
                    peer.startprob_, peer.transmat_, peer.emissionprob_ = (p.copy() for p in params)
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        peer.fit(stacked, lengths=lengths)

                return best_of(fit, args.repeats)

            peer_s[implementation] = (peer_fit(3) - peer_fit(1)) / 2
        print(f"{n_states:>6} {ours_s * 1e3:>9.2f} {peer_s['scaling'] * 1e3:>11.1f} {peer_s['log'] * 1e3:>9.1f} "
              f"{peer_s['scaling'] / ours_s:>10.1f}x {peer_s['log'] / ours_s:>7.1f}x")


if __name__ == "__main__":
    main()
