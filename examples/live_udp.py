"""A trained imitator driving a robot from a live tracker stream, in real time, over loopback UDP
between two processes.

This process plays the robot and its overhead tracker: the field, stepped at the tracker's 30
readings a second in real time, sends each reading as a datagram and waits for the command
that answers it until the next reading is due; a command that has not come by then is late,
and the robot keeps the one it had. The other process is the imitator, ``polymimic
live`` (:func:`polymimic.live.drive`): it reads the stream, steps an
:class:`polymimic.ImitatorPlayer` and sends back commands. With ``--chaos`` the stream
misbehaves as networks do: garbage datagrams, repeated and out-of-order readings, readings
dropped, and the stream pausing for
half a second; the imitator names and counts each and goes on.

Run: ``python examples/live_udp.py [--seconds 20] [--chaos] [--policy FILE]`` (without
``--policy`` an imitator is trained first, in about ten seconds). It prints both sides'
reports: episodes and their outcomes, late decisions, and the decision latency (p50, p99).
"""

from __future__ import annotations

import argparse
import json
import pathlib
import random
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from typing import Any

import polymimic
from polymimic import live, recognition

READINGS_PER_S = 30


def field_side(to: tuple[str, int], commands: live.UdpSource, body: polymimic.Body, *, seconds: float,
               chaos: bool) -> dict[str, Any]:
    """Play episodes in real time for ``seconds``, one reading every 1/30 s."""
    send = live.UdpSink(*to)
    rng = random.Random(7)
    outcomes: list[str] = []
    late = readings = dropped_readings = 0
    tick_s = 1.0 / READINGS_PER_S
    ends = time.perf_counter() + seconds
    episode_index = 0
    while time.perf_counter() < ends:
        configuration, seed = 1 + episode_index % 2, 1000 + episode_index
        episode = polymimic.Episode(body, configuration=configuration, seed=seed)
        send.send_datagram(json.dumps({"episode": {"configuration": configuration, "seed": seed}}).encode())
        command, seq, next_tick = "stop", 0, time.perf_counter()
        while not episode.finished and time.perf_counter() < ends:
            seen = episode.observation()
            wire = live.reading_datagram(seq, seen["t_s"], seen["robot"], seen["ball"])
            if chaos and rng.random() < 0.02:
                send.send_datagram(b"\x00not a reading\xff")
            if chaos and seq == 45:
                time.sleep(0.6)  # the tracker stalls; the robot holds its command
                next_tick = time.perf_counter()
            dropped = chaos and rng.random() < 0.01
            if not dropped:
                send.send_datagram(wire)
                if chaos and rng.random() < 0.02:
                    send.send_datagram(wire)  # a duplicate: stale to the imitator
            readings += 1
            dropped_readings += dropped
            next_tick += tick_s
            answered = dropped
            while not answered:
                data = commands.receive(max(0.0, next_tick - time.perf_counter()))
                if data is None:
                    break
                kind, body_ = live.parse_datagram(data)
                if kind == "command" and body_[0] == seq:
                    command, answered = body_[1], True
            late += not answered
            episode.step(command)
            seq += 1
            time.sleep(max(0.0, next_tick - time.perf_counter()))
        outcomes.append(episode.outcome or "stopped")
        episode_index += 1
    for _ in range(3):  # datagrams may be lost: say it more than once
        send.send_datagram(json.dumps({"end": True}).encode())
    send.close()
    return {"episodes": len(outcomes), "outcomes": outcomes, "readings": readings, "late": late,
            "dropped": dropped_readings}


def trained_policy(directory: pathlib.Path) -> pathlib.Path:
    """A small improved imitator of the Expert, saved to a file the other process loads."""
    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
    demos = [d for c in (1, 2) for d in polymimic.record("expert", configuration=c, n=3, seed=0)]
    trial = polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert"])
    policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos)
    path = directory / "imitator.policy.zip"
    policy.save(path)
    return path


def main(argv: Sequence[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=20.0, help="how long the field plays (default 20)")
    parser.add_argument("--chaos", action="store_true", help="garbage, repeats, drops and a pause in the stream")
    parser.add_argument("--policy", type=pathlib.Path, help="a saved imitator (default: train a small one)")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as scratch, live.UdpSource() as commands:
        policy_path = args.policy or trained_policy(pathlib.Path(scratch))
        body = polymimic.ImitatorPolicy.load(policy_path).body
        report_path = pathlib.Path(scratch) / "live.json"
        host, port = commands.address
        # The imitator's process: `polymimic live`, listening on a free port it prints.
        with subprocess.Popen(
                [sys.executable, "-m", "polymimic", "live", str(policy_path), "--answer", f"{host}:{port}",
                 "--seconds", str(args.seconds + 30.0), "--report", str(report_path)],
                stdout=subprocess.PIPE, text=True) as imitator:
            assert imitator.stdout is not None
            listening = imitator.stdout.readline()  # "polymimic live: listening on HOST:PORT, answering …"
            listen_host, _, listen_port = listening.split("listening on ")[1].split(",")[0].rpartition(":")
            field = field_side((listen_host, int(listen_port)), commands, body, seconds=args.seconds,
                               chaos=args.chaos)
            imitator.communicate(timeout=60)
        imitator_report = json.loads(report_path.read_text())
    goals = field["outcomes"].count("goal")
    print(f"field: {field['readings']} readings in {field['episodes']} episodes ({goals} goals), "
          f"{field['late']} decisions late ({field['dropped']} readings dropped on the way, the robot holding its "
          f"command)")
    print(f"imitator: {imitator_report['answered']} answered; decision latency p50 "
          f"{imitator_report['latency_p50_ms']:.3f} ms, p99 {imitator_report['latency_p99_ms']:.3f} ms; lost "
          f"{imitator_report['lost']}, stale {imitator_report['stale']}, garbage {imitator_report['garbage']}, "
          f"pauses {imitator_report['pauses']}")
    return {"field": field, "imitator": imitator_report}


if __name__ == "__main__":
    main()
