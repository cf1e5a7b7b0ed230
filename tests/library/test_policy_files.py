"""A policy saves to one versioned file and loads back playing the same episodes, bit for bit;
a file that is not one, or is damaged, is refused with an error naming it."""

import dataclasses
import hashlib
import json
import os
import subprocess
import sys
import zipfile

import pytest

import polymimic
from polymimic import imitator_file, learning, recognition
from polymimic.bodies import THESIS_BODIES
from polymimic.segments import load_segments


def _learned(body, demonstrators):
    """A small recogniser of ``body``'s own primitives, two demonstrations per configuration of
    each demonstrator segmented by it, and a trial on them."""
    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1, body=body), codebook_size=32)
    demos = [d for who in demonstrators for c in (1, 2) for d in polymimic.record(who, configuration=c, n=2, seed=0)]
    batch = learning.segmented(demos, recognizer)
    return recognizer, batch, learning.run_trial(batch, recognizer=recognizer, ordering=list(demonstrators), seed=0)


@pytest.fixture(scope="module")
def lego():
    return _learned("lego", ("expert", "poor"))


@pytest.fixture(scope="module")
def tiny():
    return _learned("tiny", ("tiny",))


@pytest.fixture(scope="module")
def saved(lego, tmp_path_factory):
    """A saved improved-control policy, for the tests that damage a copy of its file."""
    recognizer, batch, trial = lego
    path = tmp_path_factory.mktemp("saved") / "imitator.zip"
    learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch).save(path)
    return path


def _played(policy, seed=11):
    return learning.evaluate(policy, attempts_per_configuration=2, seed=seed)


def _assert_same_play(first, second):
    a, b = _played(first), _played(second)
    assert len(a.attempts) == len(b.attempts) == 4
    for x, y in zip(a.attempts, b.attempts):
        assert x.frames.tobytes() == y.frames.tobytes()
        assert (x.outcome, x.configuration, x.seed, x.body) == (y.outcome, y.configuration, y.seed, y.body)
    assert a.behaviours == b.behaviours


def _round_trip(policy, path):
    policy.save(path)
    again = learning.ImitatorPolicy.load(path)
    assert type(again) is learning.ImitatorPolicy
    assert (again.control, again.body, len(again)) == (policy.control, policy.body, len(policy))
    return again


@pytest.mark.parametrize("control", ["thesis", "improved"])
def test_a_lego_policy_plays_the_same_episodes_once_loaded(lego, tmp_path, control):
    recognizer, batch, trial = lego
    # A changed constant, and one that makes the improved control read the trial's LPs.
    config = polymimic.LearningConfig(imitator_weighting="lp", push_heading_tail=0.2)
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, config=config, control=control,
                                     demonstrations=batch)
    again = _round_trip(policy, tmp_path / "imitator.zip")
    _assert_same_play(policy, again)
    inputs = imitator_file.read_policy_file(tmp_path / "imitator.zip")
    assert inputs.config == config and inputs.trial == trial
    assert (inputs.demonstrations == batch) if control == "improved" else inputs.demonstrations is None


@pytest.mark.parametrize("control", ["thesis", "improved"])
def test_a_tiny_policy_plays_the_same_episodes_once_loaded(tiny, tmp_path, control):
    recognizer, batch, trial = tiny
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control=control, demonstrations=batch, body="tiny")
    again = _round_trip(policy, tmp_path / "tiny.zip")
    assert again.body.name == "tiny"
    _assert_same_play(policy, again)
    with zipfile.ZipFile(tmp_path / "tiny.zip") as archive:
        assert "body.toml" not in archive.namelist()  # a thesis body is named, not described


def test_the_same_policy_writes_the_same_bytes(lego, tmp_path):
    recognizer, batch, trial = lego
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch)
    policy.save(tmp_path / "first.zip")
    learning.ImitatorPolicy.load(tmp_path / "first.zip").save(tmp_path / "second.zip")
    assert (tmp_path / "first.zip").read_bytes() == (tmp_path / "second.zip").read_bytes()


def test_the_file_records_its_format_version_and_writer(saved):
    with zipfile.ZipFile(saved) as archive:
        names = archive.namelist()
        header = json.loads(archive.read("policy.json"))
    assert names == ["policy.json", "trial.json", "recognizer.json", "learning.toml", "demonstrations.parquet"]
    assert header == {"format": "polymimic.imitator_policy", "version": imitator_file.FORMAT_VERSION,
                      "writer": f"polymimic {polymimic.__version__}", "control": "improved", "body": "lego"}


def test_each_part_loads_on_its_own(saved, tmp_path):
    with zipfile.ZipFile(saved) as archive:
        archive.extractall(tmp_path)
    inputs = imitator_file.read_policy_file(saved)
    assert polymimic.TrialResult.load(tmp_path / "trial.json") == inputs.trial
    assert polymimic.LearningConfig.load(tmp_path / "learning.toml") == inputs.config
    assert load_segments(tmp_path / "demonstrations.parquet") == inputs.demonstrations
    recognizer = polymimic.PrimitiveRecognizer.load(tmp_path / "recognizer.json")
    assert recognizer.motion_stats() == inputs.recognizer.motion_stats()


@pytest.fixture(scope="module")
def own_body():
    """The tiny robot's constants (slip by primitive) under a name of its own."""
    return dataclasses.replace(THESIS_BODIES["tiny"], name="tiny_on_file")


def test_a_wheeled_body_round_trips(tiny, own_body, tmp_path):
    recognizer, batch, trial = tiny
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch,
                                     body=own_body)
    again = _round_trip(policy, tmp_path / "own.zip")
    assert again.body.name == "tiny_on_file" and again.body.description == own_body
    assert policy.body.description is own_body
    assert imitator_file.read_policy_file(tmp_path / "own.zip").body.description == own_body
    _assert_same_play(policy, again)


def test_a_wheeled_body_loads_in_a_process_that_never_described_it(tiny, own_body, tmp_path):
    recognizer, batch, trial = tiny
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="thesis", body=own_body)
    policy.save(tmp_path / "own.zip")
    digest = ("import hashlib, sys; from polymimic import learning; "
              "p = learning.ImitatorPolicy.load(sys.argv[1]); "
              "a = learning.evaluate(p, attempts_per_configuration=2, seed=11).attempts; "
              "print(p.body.name, hashlib.sha256(b''.join(x.frames.tobytes() for x in a)).hexdigest())")
    out = subprocess.run([sys.executable, "-c", digest, str(tmp_path / "own.zip")], capture_output=True, text=True,
                         check=True, env={**os.environ, "PYTHONWARNINGS": "error"}).stdout.split()
    here = hashlib.sha256(b"".join(x.frames.tobytes() for x in _played(policy).attempts)).hexdigest()
    assert out == ["tiny_on_file", here]


def test_a_failed_save_leaves_the_old_file_and_nothing_else(lego, saved, tmp_path, monkeypatch):
    recognizer, batch, trial = lego
    path = tmp_path / "imitator.zip"
    path.write_bytes(saved.read_bytes())
    written = []

    def fail_after_first(self, info, data, *args, **kwargs):
        if written:
            raise OSError("disk full")
        written.append(info)
        return original(self, info, data, *args, **kwargs)

    original = zipfile.ZipFile.writestr
    monkeypatch.setattr(zipfile.ZipFile, "writestr", fail_after_first)
    with pytest.raises(OSError, match="disk full"):
        learning.ImitatorPolicy(trial, recognizer=recognizer).save(path)
    assert path.read_bytes() == saved.read_bytes()
    assert [p.name for p in tmp_path.iterdir()] == ["imitator.zip"]


def _rewritten(source, target, *, drop=(), replace=None):
    """A copy of the archive ``source`` without the parts ``drop``, ``replace`` giving new contents."""
    replace = replace or {}
    with zipfile.ZipFile(source) as old, zipfile.ZipFile(target, "w") as new:
        for info in old.infolist():
            if info.filename not in drop:
                new.writestr(info.filename, replace.get(info.filename, old.read(info.filename)))
    return target


def _header_with(saved, **changes):
    with zipfile.ZipFile(saved) as archive:
        return json.dumps({**json.loads(archive.read("policy.json")), **changes})


def _refused(path, match):
    with pytest.raises(polymimic.ModelFileError, match=match) as caught:
        learning.ImitatorPolicy.load(path)
    assert str(caught.value).startswith(str(path)), caught.value
    return str(caught.value)


def test_a_later_format_version_is_refused(saved, tmp_path):
    path = _rewritten(saved, tmp_path / "later.zip", replace={"policy.json": _header_with(saved, version=3)})
    _refused(path, r"is format version 3, written by polymimic .*reads versions up to 2 \(upgrade polymimic\)")


def test_a_version_1_file_loads_as_a_policy_that_never_practised(saved, tmp_path):
    path = _rewritten(saved, tmp_path / "first.zip", replace={"policy.json": _header_with(saved, version=1)})
    policy = learning.ImitatorPolicy.load(path)
    assert policy.made_from.practice is None
    _assert_same_play(policy, learning.ImitatorPolicy.load(saved))


@pytest.mark.parametrize("weight", [-1, "1", None, float("nan")])
def test_a_bad_practice_weight_is_refused(saved, tmp_path, weight):
    header = _header_with(saved, practice_weight=weight)
    path = _rewritten(saved, tmp_path / "weight.zip", replace={"policy.json": header})
    _refused(path, "has practice_weight")


@pytest.mark.parametrize("version", [0, "1", None, True])
def test_an_invalid_format_version_is_refused(saved, tmp_path, version):
    path = _rewritten(saved, tmp_path / "invalid.zip", replace={"policy.json": _header_with(saved, version=version)})
    _refused(path, "has an invalid format version")


def test_a_file_without_its_writer_is_refused(saved, tmp_path):
    path = _rewritten(saved, tmp_path / "anonymous.zip", replace={"policy.json": _header_with(saved, writer=None)})
    _refused(path, "does not say which polymimic wrote it")


@pytest.mark.parametrize("cut", [1, 100, 1000])
def test_a_truncated_file_is_refused(saved, tmp_path, cut):
    path = tmp_path / "cut.zip"
    path.write_bytes(saved.read_bytes()[:-cut])
    _refused(path, "not a polymimic.imitator_policy file: not a zip archive, or one cut short")


def test_a_damaged_part_is_refused(saved, tmp_path):
    data = bytearray(saved.read_bytes())
    with zipfile.ZipFile(saved) as archive:
        info = archive.getinfo("trial.json")
    # The part's data starts after its 30-byte local header, its name and its extra field.
    start = info.header_offset + 30 + len(info.filename) + len(info.extra)
    data[start + info.compress_size // 2] ^= 0xFF
    path = tmp_path / "damaged.zip"
    path.write_bytes(bytes(data))
    _refused(path, "part trial.json is damaged")


@pytest.mark.parametrize("part", ["trial.json", "recognizer.json", "learning.toml", "demonstrations.parquet"])
def test_a_missing_part_is_refused(saved, tmp_path, part):
    _refused(_rewritten(saved, tmp_path / "short.zip", drop=[part]), f"part {part} is missing")


@pytest.mark.parametrize("part, content, match", [
    ("trial.json", "{}", "trial.json: not a saved trial result"),
    ("recognizer.json", '{"format": "polymimic.Codebook"}', "recognizer.json: saved recogniser"),
    ("learning.toml", "decay_step = -1\n", "learning.toml: .*decay_step = -1"),
    ("learning.toml", "speed = 3\n", "learning.toml: .*speed"),
    ("demonstrations.parquet", b"PAR1", "demonstrations.parquet: not a readable Parquet file"),
    ("policy.json", "{", "policy.json is damaged"),
])
def test_a_part_that_does_not_read_is_named(saved, tmp_path, part, content, match):
    _refused(_rewritten(saved, tmp_path / "bad.zip", replace={part: content}), match)


def test_a_body_table_that_is_not_the_bodys_is_refused(tiny, own_body, tmp_path):
    recognizer, _, trial = tiny
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, body=own_body)
    policy.save(tmp_path / "own.zip")
    bodiless = _rewritten(tmp_path / "own.zip", tmp_path / "bodiless.zip", drop=["body.toml"])
    _refused(bodiless, "part body.toml is missing")
    other = "[bodies.other]\nlength_mm = 90\nwidth_mm = 80\nwheel_base_mm = 70\ntop_wheel_speed_mm_s = 60\n"
    _refused(_rewritten(tmp_path / "own.zip", tmp_path / "other.zip", replace={"body.toml": other}),
             r"body.toml: expected the table \[bodies.tiny_on_file\] alone, found other")


def test_files_that_are_not_policies_are_refused(lego, tmp_path):
    _, _, trial = lego
    trial.save(tmp_path / "trial.json")
    _refused(tmp_path / "trial.json", "not a polymimic.imitator_policy file: not a zip archive")
    (tmp_path / "empty.zip").write_bytes(b"")
    _refused(tmp_path / "empty.zip", "not a zip archive")
    with zipfile.ZipFile(tmp_path / "notes.zip", "w") as archive:
        archive.writestr("notes.txt", "hello")
    _refused(tmp_path / "notes.zip", "not a polymimic.imitator_policy file: the zip archive has no policy.json")
    with zipfile.ZipFile(tmp_path / "other.zip", "w") as archive:
        archive.writestr("policy.json", json.dumps({"format": "polymimic.baselines.policy", "version": 1}))
    _refused(tmp_path / "other.zip", "holds polymimic.baselines.policy, not polymimic.imitator_policy")


@pytest.mark.parametrize("change, match", [
    (dict(control="best"), "has control 'best'; expected one of thesis, improved"),
    (dict(body=3), "has body 3; expected a body's name"),
])
def test_a_header_that_names_no_policy_is_refused(saved, tmp_path, change, match):
    _refused(_rewritten(saved, tmp_path / "odd.zip", replace={"policy.json": _header_with(saved, **change)}), match)


def test_a_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(FileNotFoundError):
        learning.ImitatorPolicy.load(tmp_path / "nowhere.zip")


def test_for_trial_still_shares_what_the_policy_learned(lego):
    recognizer, batch, trial = lego
    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch)
    shared = policy.for_trial(trial)
    _assert_same_play(policy, shared)
