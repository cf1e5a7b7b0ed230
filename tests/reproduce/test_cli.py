"""The command line."""

import subprocess
import sys

from polymimic import cli, demo


def test_demo_recognises_the_primitives_it_was_shown(capsys):
    assert cli.main(["demo", "--train", "60", "--test", "30", "--codebook-size", "32"]) == 0
    out = capsys.readouterr().out
    assert "accuracy" in out and "forward" in out


def test_demo_accuracy_is_high_and_reproducible():
    a = demo.run(n_train=60, n_test=40, codebook_size=32, seed=3)
    b = demo.run(n_train=60, n_test=40, codebook_size=32, seed=3)
    # Chance is 0.25; "left" is the hardest, its turn rate spreading as widely as the thesis's.
    assert min(a.accuracy.values()) > 0.7 and a.accuracy["forward"] > 0.95
    assert a.accuracy == b.accuracy and (a.confusion == b.confusion).all()


def test_module_entry_point_and_version():
    out = subprocess.run([sys.executable, "-m", "polymimic", "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.startswith("polymimic ")
