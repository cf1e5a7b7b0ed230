"""The ``polymimic`` command."""

from __future__ import annotations

import argparse
import sys


def _demo(args: argparse.Namespace) -> int:
    from polymimic import demo

    print(demo.report(demo.run(n_train=args.train, n_test=args.test, codebook_size=args.codebook_size,
                               n_states=args.states, seed=args.seed)))
    return 0


def build_parser() -> argparse.ArgumentParser:
    from polymimic import __version__

    parser = argparse.ArgumentParser(prog="polymimic", description=__doc__)
    parser.add_argument("--version", action="version", version=f"polymimic {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)
    demo = commands.add_parser("demo", help="train an HMM bank on synthetic motion primitives and recognise them")
    demo.add_argument("--train", type=int, default=200, help="training sequences per primitive")
    demo.add_argument("--test", type=int, default=100, help="held-out sequences per primitive")
    demo.add_argument("--codebook-size", type=int, default=64)
    demo.add_argument("--states", type=int, default=3)
    demo.add_argument("--seed", type=int, default=0)
    demo.set_defaults(handler=_demo)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    return args.handler(args)


if __name__ == "__main__":
    sys.exit(main())
