"""The live loop: a tracker stream over loopback UDP answered reading by reading, whatever the
stream does wrong."""

import json
import math
import socket
import threading

import pytest

import polymimic
from polymimic import live


@pytest.fixture(scope="module")
def policy(expert_imitator):
    return expert_imitator


@pytest.mark.parametrize(("data", "kind"), [
    (b'{"seq": 0, "t_s": 0.0, "robot": [1, 2, 0.5], "ball": [3, 4]}', "reading"),
    (b'{"seq": 1, "t_s": 0.0, "robot": [1, 2, 0.5], "ball": null}', "reading"),
    (b'{"seq": 1, "t_s": 0.0, "robot": [1, 2, 0.5], "ball": [NaN, NaN]}', "reading"),
    (b'{"episode": {"configuration": 2, "seed": 3}}', "episode"),
    (b'{"end": true}', "end"),
    (b'{"seq": 4, "command": "forward"}', "command"),
    (b'{"seq": -1, "t_s": 0.0, "robot": [1, 2, 0.5], "ball": null}', "garbage"),
    (b'{"seq": 1, "t_s": Infinity, "robot": [1, 2, 0.5], "ball": null}', "garbage"),
    (b'{"seq": 1, "t_s": 0.0, "robot": [1, 2], "ball": null}', "garbage"),
    (b'{"seq": true, "t_s": 0.0, "robot": [1, 2, 3], "ball": null}', "garbage"),
    (b'[1, 2, 3]', "garbage"),
    (b'\xff\xfe', "garbage"),
    (b'', "garbage"),
])
def test_datagrams_are_told_apart_and_garbage_is_named_never_raised(data, kind):
    assert live.parse_datagram(data)[0] == kind


def test_a_reading_datagram_round_trips_with_a_lost_ball_as_nan():
    kind, (seq, t_s, x, y, theta, bx, by) = live.parse_datagram(live.reading_datagram(7, 0.25, (1.0, 2.0, 0.5), None))
    assert (kind, seq, t_s, x, y, theta) == ("reading", 7, 0.25, 1.0, 2.0, 0.5)
    assert math.isnan(bx) and math.isnan(by)


def test_the_loop_answers_each_fresh_reading_as_the_player_would_and_counts_what_went_wrong(policy):
    source, answers = live.UdpSource(), live.UdpSource()
    sink = live.UdpSink(*answers.address)
    episode = polymimic.Episode("lego", configuration=1, seed=5)
    readings = []
    for seq in range(70):
        seen = episode.observation()
        readings.append(live.reading_datagram(seq, seen["t_s"], seen["robot"], seen["ball"]))
        episode.step("forward")
    order = [json.dumps({"episode": {"configuration": 1, "seed": 5}}).encode()]
    order += readings[:10] + [b"garbage!"] + readings[10:20] + [readings[15]]  # a repeat: stale
    order += readings[22:40] + [readings[21]]  # 20 and 21 lost; 21 then arrives late: stale
    order += [b'{"seq": 1}'] + readings[40:] + [json.dumps({"end": True}).encode()]
    sender = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    reasons = []
    result = {}
    worker = threading.Thread(target=lambda: result.setdefault(
        "report", live.drive(policy.player(), source, sink, duration_s=20, on_garbage=reasons.append)))
    worker.start()
    for data in order:
        sender.sendto(data, source.address)
    worker.join(timeout=30)
    report = result["report"]
    assert (report.answered, report.episodes, report.lost, report.stale, report.garbage) == (68, 1, 2, 2, 2)
    assert len(reasons) == 2 and "not UTF-8 JSON" in reasons[0] and "not a reading" in reasons[1]
    assert len(report.latencies_ms) == 68 and report.latency_ms(0.99) < 50.0
    got = {}
    while (data := answers.receive(0.5)) is not None:
        _, (seq, command) = live.parse_datagram(data)
        got[seq] = command
    # The same readings, in order and without the lost ones, stepped by a player of its own.
    player = policy.player()
    player.reset(start=1, seed=5)
    expected = {}
    for data in readings:
        _, (seq, *numbers) = live.parse_datagram(data)
        if seq not in (20, 21):
            expected[seq] = player.act(tuple(numbers))
    assert got == expected
    for end in (source, answers, sink, sender):
        end.close()


def test_the_loop_survives_a_silent_source_and_stops_on_time(policy):
    with live.UdpSource() as source, live.UdpSource() as answers, live.UdpSink(*answers.address) as sink:
        report = live.drive(policy.player(), source, sink, duration_s=0.6, pause_s=0.2)
    assert report.answered == 0 and report.pauses >= 2
    assert math.isnan(report.latency_ms(0.5))


def test_the_live_command_answers_bad_input_with_exit_2_and_one_line(tmp_path, capsys):
    from polymimic.cli import main

    assert main(["live", str(tmp_path / "none.zip"), "--answer", "127.0.0.1:9"]) == 2
    assert capsys.readouterr().err.strip() == f"polymimic live: error: {tmp_path / 'none.zip'}: no such policy file"
    (tmp_path / "bad.zip").write_text("not a policy")
    assert main(["live", str(tmp_path / "bad.zip"), "--answer", "127.0.0.1:9"]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    with pytest.raises(SystemExit) as exit_:
        main(["live", str(tmp_path / "bad.zip"), "--answer", "no-port"])
    assert exit_.value.code == 2 and "expected HOST:PORT" in capsys.readouterr().err


def test_the_live_command_drives_and_reports(tmp_path, policy, capsys):
    from polymimic.cli import main

    path = tmp_path / "imitator.policy.zip"
    policy.save(path)
    with live.UdpSource() as answers:
        host, port = answers.address
        assert main(["live", str(path), "--answer", f"{host}:{port}", "--seconds", "0.3",
                     "--report", str(tmp_path / "live.json")]) == 0
    out = capsys.readouterr().out
    assert "listening on 127.0.0.1:" in out and "0 readings answered" in out
    assert json.loads((tmp_path / "live.json").read_text())["answered"] == 0


def test_a_source_asked_to_wait_no_time_answers_none_when_nothing_came():
    with live.UdpSource() as source:
        assert source.receive(0.0) is None and source.receive(-1.0) is None
