"""The imitator driving a robot from a live tracker stream, over UDP datagrams.

A tracker (or the field playing one, :func:`serve_field`) sends one datagram per reading, and
the imitator answers each with the command to send the robot until the next: :func:`drive`
reads from a :class:`UdpSource`, steps an :class:`polymimic.ImitatorPlayer` and writes to a
:class:`UdpSink`. The stream is what a network gives: readings may be lost, late, duplicated,
out of order or not readings at all, and the source may pause. None of it stops the loop; each
is counted in the :class:`LiveReport`.

Datagrams are UTF-8 JSON objects:

- a reading: ``{"seq": 12, "t_s": 0.4, "robot": [x_mm, y_mm, theta_rad], "ball": [x_mm, y_mm]}``
  (``"ball": null`` or NaNs when the tracker lost it; ``seq`` counts readings from 0 within an
  episode);
- a new episode: ``{"episode": {"configuration": 1, "seed": 7}}`` (or ``"start": {...}``
  instead of the configuration): the player starts afresh (without one, it starts from the
  first reading it gets, from what that reading shows);
- the end: ``{"end": true}``;
- a command, from the imitator: ``{"seq": 12, "command": "forward"}``, answering reading 12.

>>> wire = reading_datagram(3, 0.1, (-170.0, 0.0, 0.0), None)
>>> parse_datagram(wire)
('reading', (3, 0.1, -170.0, 0.0, 0.0, nan, nan))
>>> parse_datagram(b"\\xff garbage")
('garbage', "not UTF-8 JSON: b'\\\\xff garbage'")
"""

from __future__ import annotations

import dataclasses
import json
import math
import socket
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from polymimic._native import ImitatorPlayer

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["LiveReport", "UdpSink", "UdpSource", "drive", "parse_datagram", "reading_datagram"]

_MAX_DATAGRAM = 65_507


def reading_datagram(seq: int, t_s: float, robot: tuple[float, float, float],
                     ball: tuple[float, float] | None) -> bytes:
    """One reading as the wire carries it."""
    return json.dumps({"seq": seq, "t_s": t_s, "robot": list(robot), "ball": None if ball is None else list(ball)},
                      allow_nan=True).encode()


def parse_datagram(data: bytes) -> tuple[str, Any]:
    """What a datagram holds: ``("reading", (seq, t_s, x, y, θ, ball_x, ball_y))``,
    ``("episode", {...})``, ``("end", None)``, ``("command", (seq, name))`` or ``("garbage",
    why)``; never raises."""
    try:
        message = json.loads(data.decode())
    except (UnicodeDecodeError, ValueError):
        return "garbage", f"not UTF-8 JSON: {data[:40]!r}"
    if not isinstance(message, dict):
        return "garbage", f"not a JSON object: {data[:40]!r}"
    if message.get("end") is True:
        return "end", None
    if isinstance(message.get("episode"), dict):
        return "episode", message["episode"]
    if "command" in message:
        if isinstance(message["command"], str) and _whole(message.get("seq")):
            return "command", (message["seq"], message["command"])
        return "garbage", f"a command needs a whole seq and a name: {data[:60]!r}"
    robot, ball = message.get("robot"), message.get("ball")
    if not (_whole(message.get("seq")) and _number(message.get("t_s")) and _numbers(robot, 3)
            and (ball is None or _numbers(ball, 2))):
        return "garbage", f"not a reading (seq, t_s, robot [x, y, θ], ball [x, y] or null): {data[:60]!r}"
    bx, by = (math.nan, math.nan) if ball is None else (float(ball[0]), float(ball[1]))
    x, y, theta = (float(v) for v in robot) if isinstance(robot, list) else (math.nan,) * 3
    return "reading", (message["seq"], float(message["t_s"]), x, y, theta, bx, by)


def _whole(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and value >= 0


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _numbers(value: Any, n: int) -> bool:
    return isinstance(value, list) and len(value) == n and all(
        isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)


class _Socket:
    """A UDP socket that closes on leaving a ``with`` block."""

    _socket: socket.socket

    def close(self) -> None:
        """Let the socket go (also on leaving a ``with`` block)."""
        self._socket.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class UdpSource(_Socket):
    """Datagrams arriving at ``host:port`` (bound here; port 0 picks a free one: see
    :attr:`address`). :meth:`receive` waits at most ``timeout_s`` for one."""

    def __init__(self, host: str = "127.0.0.1", port: int = 0) -> None:
        self._socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._socket.bind((host, port))

    @property
    def address(self) -> tuple[str, int]:
        """Where to send readings."""
        host, port = self._socket.getsockname()[:2]
        return str(host), int(port)

    def receive(self, timeout_s: float) -> bytes | None:
        """The next datagram, or None if none came within ``timeout_s``."""
        self._socket.settimeout(max(timeout_s, 1e-6))  # 0 would make the socket non-blocking
        try:
            data, _ = self._socket.recvfrom(_MAX_DATAGRAM)
        except (TimeoutError, BlockingIOError):
            return None
        return data



class UdpSink(_Socket):
    """Commands sent to ``host:port``."""

    def __init__(self, host: str, port: int) -> None:
        self._socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._to = (host, port)

    def send(self, seq: int, command: str) -> None:
        """The command answering reading ``seq``."""
        self.send_datagram(json.dumps({"seq": seq, "command": command}).encode())

    def send_datagram(self, data: bytes) -> None:
        """Any datagram (a tracker's side sends its readings so)."""
        self._socket.sendto(data, self._to)



@dataclasses.dataclass
class LiveReport:
    """What a live run did: readings answered, each decision's latency (from the datagram's
    arrival to the command's sending), and what the stream did wrong."""

    answered: int = 0
    episodes: int = 0
    lost: int = 0
    """Readings never received (gaps in ``seq``)."""
    stale: int = 0
    """Readings that came after a later one (late, out of order or duplicated): dropped."""
    garbage: int = 0
    """Datagrams that were not readings, episodes or the end."""
    pauses: int = 0
    """Times the source went quiet for longer than ``pause_s``."""
    latencies_ms: list[float] = dataclasses.field(default_factory=list)

    def latency_ms(self, quantile: float) -> float:
        """A quantile of the decision latency, ms (NaN before any decision)."""
        return float(np.quantile(self.latencies_ms, quantile)) if self.latencies_ms else math.nan

    def summary(self) -> str:
        """One line: readings answered, latency p50 and p99, and the stream's faults."""
        return (f"{self.answered} readings answered in {self.episodes} episode(s); decision latency p50 "
                f"{self.latency_ms(0.5):.3f} ms, p99 {self.latency_ms(0.99):.3f} ms; lost {self.lost}, stale "
                f"{self.stale}, garbage {self.garbage}, pauses {self.pauses}")


def drive(player: ImitatorPlayer, source: UdpSource, sink: UdpSink, *, duration_s: float | None = None,
          pause_s: float = 0.5, on_garbage: Callable[[str], None] | None = None) -> LiveReport:
    """Answer every reading from ``source`` with ``player``'s command, sent to ``sink``, until
    the stream ends or ``duration_s`` seconds pass; returns what happened."""
    report, last_seq, started = LiveReport(), -1, False
    deadline = math.inf if duration_s is None else time.monotonic() + duration_s
    while (now := time.monotonic()) < deadline:
        data = source.receive(min(pause_s, deadline - now))
        if data is None:
            report.pauses += 1
            continue
        arrived = time.perf_counter()
        kind, body = parse_datagram(data)
        if kind == "end":
            break
        if kind == "episode":
            try:
                player.reset(dict(body))
            except (ValueError, TypeError) as error:
                report.garbage += 1
                if on_garbage is not None:
                    on_garbage(f"an episode the player cannot start: {error}")
                continue
            report.episodes, last_seq, started = report.episodes + 1, -1, True
            continue
        if kind != "reading":
            report.garbage += 1
            if on_garbage is not None:
                on_garbage(str(body))
            continue
        seq, *numbers = body
        if seq <= last_seq:
            report.stale += 1
            continue
        report.lost += seq - last_seq - 1
        last_seq = seq
        if not started:
            _, x, y, theta, bx, by = numbers
            try:
                player.reset(start={"robot": (x, y, theta), "ball": (bx, by)})
            except ValueError as error:  # a first reading no episode can start from (the ball lost, …)
                report.garbage += 1
                if on_garbage is not None:
                    on_garbage(f"no episode starts from reading {seq}: {error}")
                continue
            report.episodes, started = report.episodes + 1, True
        sink.send(seq, player.act(tuple(numbers)))
        report.latencies_ms.append((time.perf_counter() - arrived) * 1000.0)
        report.answered += 1
    return report
