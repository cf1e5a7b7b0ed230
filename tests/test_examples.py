"""The worked examples in examples/ run, and show what their documentation says they show."""

from __future__ import annotations

import importlib.util
import pathlib

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def _load(name: str):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
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
