"""`polymimic live`: a saved imitator drives a robot from a tracker stream over UDP.

It listens for readings on ``--listen`` and answers each with a command sent to ``--answer``
(the datagrams: :mod:`polymimic.live`), until the stream sends its end or ``--seconds`` pass,
then prints what happened: readings answered, decision latency, and readings lost, stale or
not readings at all.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from typing import Any

from polymimic import live
from polymimic._atomic import atomic_write_text
from polymimic.learning import ImitatorPolicy
from polymimic.runs.config import ConfigError


def add(commands: Any) -> None:
    """The ``live`` command."""
    text = "a saved imitator drives a robot from a live tracker stream (UDP datagrams in, commands out)"
    parser = commands.add_parser("live", help=text, description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("policy", type=pathlib.Path, help="an imitator's policy file (ImitatorPolicy.save)")
    parser.add_argument("--listen", type=_address, default=("127.0.0.1", 0), metavar="HOST:PORT",
                        help="where readings arrive (default 127.0.0.1 and a free port, printed)")
    parser.add_argument("--answer", type=_address, required=True, metavar="HOST:PORT",
                        help="where commands go (the robot's side)")
    parser.add_argument("--seconds", type=float, help="stop after this long (default: when the stream ends)")
    parser.add_argument("--report", type=pathlib.Path, metavar="FILE",
                        help="also write the report as JSON (latencies summarised) to FILE")
    parser.set_defaults(handler=_live)


def _address(text: str) -> tuple[str, int]:
    host, _, port = text.rpartition(":")
    if not host or not port.isdigit() or not 0 <= int(port) < 65536:
        raise argparse.ArgumentTypeError(f"expected HOST:PORT (a port 0..65535), got {text!r}")
    return host, int(port)


def _live(args: argparse.Namespace) -> int:
    if args.seconds is not None and not args.seconds > 0:
        raise ConfigError(f"--seconds must be positive, got {args.seconds}")
    try:
        policy = ImitatorPolicy.load(args.policy)
    except FileNotFoundError:
        raise ConfigError(f"{args.policy}: no such policy file") from None
    try:
        source = live.UdpSource(*args.listen)
    except OSError as error:
        raise ConfigError(f"--listen {args.listen[0]}:{args.listen[1]}: {error.strerror or error}") from None
    sink = live.UdpSink(*args.answer)
    host, port = source.address
    print(f"polymimic live: listening on {host}:{port}, answering {args.answer[0]}:{args.answer[1]}", flush=True)
    report = live.drive(policy.player(), source, sink, duration_s=args.seconds,
                        on_garbage=lambda why: print(f"polymimic live: ignored a datagram: {why}", file=sys.stderr))
    source.close()
    sink.close()
    print(f"polymimic live: {report.summary()}")
    if args.report is not None:
        counts = {key: getattr(report, key) for key in ("answered", "episodes", "lost", "stale", "garbage", "pauses")}
        summary = {**counts, "latency_p50_ms": report.latency_ms(0.5), "latency_p99_ms": report.latency_ms(0.99)}
        atomic_write_text(args.report, json.dumps(summary, indent=2) + "\n")
    return 0
