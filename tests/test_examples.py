"""The worked examples in examples/ run, and show what their documentation says they show."""

from __future__ import annotations

import csv
import importlib.util
import pathlib
import sys

import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def _load(name: str):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # as an import would: dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_own_data_learns_from_a_python_controller_a_new_body_and_a_tracker_log(tmp_path, capsys):
    example = _load("own_data")
    text = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "report.md").read_text() == text
    assert "20 episodes from overhead_camera.csv: 20 demonstrations, 0 invalid" in capsys.readouterr().out
    # The log was another program's: metres, degrees, 15 readings a second, its own column names.
    header, first = (tmp_path / "overhead_camera.csv").read_text().splitlines()[:2]
    assert header == "run,time,x,y,heading,ball_x,ball_y"
    assert abs(float(first.split(",")[2])) < 1.0, "metres"
    rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
            for line in text.splitlines() if line.startswith("| ") and "---" not in line and "demonstrator" not in line}
    assert set(rows) == {"expert", "buggy_chaser", "logged"}
    assert rows["buggy_chaser"][0] == "buggy" and rows["logged"][0] == "lego"
    assert all(row[1] == "20" for row in rows.values())
    lps = {who: float(row[4]) for who, row in rows.items()}
    assert all(0.0 <= lp <= 1.0 for lp in lps.values())
    # The Expert scores every kick and owns no goal; the LP puts it first.
    assert rows["expert"][2:4] == ["20", "0"]
    assert max(lps, key=lps.get) == "expert"
    assert "scored" in text and "in 20 attempts" in text


def test_ppo_penalty_kick_learns_plays_the_imitators_attempts_and_writes_its_curve(tmp_path, capsys):
    pytest.importorskip("stable_baselines3")
    from polymimic import baselines

    example = _load("ppo_penalty_kick")
    result = example.main(["--timesteps", "8192", "--eval-every", "4096", "--attempts", "3", "--out", str(tmp_path)])
    settings, checkpoints = result["settings"], result["checkpoints"]
    assert settings["timesteps"] == 8192 and settings["attempts_per_configuration"] == 3
    # Before training, then at every policy update past a multiple of --eval-every, and at the end.
    policy = baselines.load_policy(tmp_path / "ppo.pmp")
    update = policy.model.n_steps * policy.model.n_envs
    steps = [c["env_steps"] for c in checkpoints]
    assert steps[0] == 0 and steps == sorted(set(steps)) and steps[-1] >= 8192
    assert all(s % update == 0 for s in steps) and all(b - a <= 4096 + update for a, b in zip(steps, steps[1:]))
    for c in checkpoints:
        assert c["attempts"] == 6
        assert 0 <= c["goals"] and 0 <= c["own_goals"] and c["goals"] + c["own_goals"] <= 6
        assert c["net_goals"] == c["goals"] - c["own_goals"]
    assert [c["wall_s"] for c in checkpoints] == sorted(c["wall_s"] for c in checkpoints)
    with (tmp_path / "curve.csv").open() as file:
        rows = list(csv.DictReader(file))
    assert [{k: float(v) for k, v in row.items()} for row in rows] == checkpoints
    for picture in ("curve.png", "play.png"):
        assert (tmp_path / picture).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # The saved policy is the last checkpoint's: on the same attempts it scores the same.
    again = baselines.evaluate_policy(policy, attempts_per_configuration=3, seed=settings["eval_seed"])
    assert (again.goals, again.own_goals) == (checkpoints[-1]["goals"], checkpoints[-1]["own_goals"])
    progress = [line for line in capsys.readouterr().out.splitlines() if " env steps: " in line]
    assert len(progress) == len(checkpoints)


def test_ppo_penalty_kick_without_stable_baselines3_names_the_extra(monkeypatch):
    from polymimic.baselines import ppo

    example = _load("ppo_penalty_kick")
    monkeypatch.setattr(ppo, "available", lambda: False)
    with pytest.raises(SystemExit, match=r"pip install \"polymimic\[rl\]\""):
        example.main(["--timesteps", "10"])


def test_live_udp_closes_the_loop_between_two_processes_through_a_misbehaving_stream(capsys):
    example = _load("live_udp")
    result = example.main(["--seconds", "4", "--chaos"])
    field, imitator = result["field"], result["imitator"]
    # About 30 readings a second for 4 s, less the half-second stall.
    assert 90 <= field["readings"] <= 125, field["readings"]
    # Every reading the imitator received was answered before the next was due, or nearly all
    # on a loaded machine; the chaos was named and counted, none of it stopped the loop.
    assert field["late"] <= max(2, field["readings"] // 50), field
    assert imitator["answered"] == field["readings"] - field["dropped"]
    assert imitator["garbage"] >= 1 and imitator["stale"] >= 1 and imitator["pauses"] >= 1
    assert imitator["lost"] == field["dropped"]
    assert imitator["latency_p99_ms"] < 33.0
    assert "decision latency p50" in capsys.readouterr().out
