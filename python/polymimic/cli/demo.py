"""`polymimic demo`: the HMMs and codebooks alone, on synthetic motion, in a minute."""

from __future__ import annotations

import argparse
from typing import Any

from polymimic import demo


def add(commands: Any) -> None:
    """The ``demo`` command."""
    parser = commands.add_parser("demo", help="train an HMM bank on synthetic motion primitives and recognise them")
    parser.add_argument("--train", type=int, default=200, help="training sequences per primitive")
    parser.add_argument("--test", type=int, default=100, help="held-out sequences per primitive")
    parser.add_argument("--codebook-size", type=int, default=64)
    parser.add_argument("--states", type=int, default=3)
    parser.add_argument("--seed", type=int, default=0)
    parser.set_defaults(handler=_demo)


def _demo(args: argparse.Namespace) -> int:
    print(demo.report(demo.run(n_train=args.train, n_test=args.test, codebook_size=args.codebook_size,
                               n_states=args.states, seed=args.seed)))
    return 0
