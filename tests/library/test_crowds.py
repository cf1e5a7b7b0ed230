"""Crowds: the profiles as docs/guides/crowd.md and the floors and misleading crowds list them, true skill,
crowds from data, and their recordings."""

import dataclasses
import json

import numpy as np
import pyarrow.parquet as pq
import pytest

import polymimic
from polymimic import recognition
from polymimic.bodies import WheeledBody
from polymimic.crowds import PROFILES, Crowd, Member, controller_skill, member_seed, profile, record_crowd
from polymimic.field import FRAME_DTYPE, Demonstration
from polymimic.learning import segmented


def test_the_five_profiles_are_the_specs():
    lapses = {name: sorted(c.lapses().values()) for name, c in PROFILES.items()}
    assert lapses["one_good"] == [0.05] + [0.9] * 9
    assert lapses["half"] == [0.05] * 5 + [0.9] * 5
    assert lapses["equal"] == [0.5] * 10
    assert lapses["linear"] == pytest.approx([0.05 + 0.1 * k for k in range(10)])
    mixed = PROFILES["mixed_bodies"]
    assert sorted((m.controller, m.lapse) for m in mixed.members) == sorted(
        (c, e) for c in ("expert", "tiny", "humanoid") for e in (0.05, 0.5, 0.9))
    assert {m.body for m in mixed.members} == {"lego", "tiny", "humanoid"}
    assert PROFILES["one_good"].best() == ("expert_00",)
    assert len(PROFILES["half"].best()) == 5


def test_the_floor_and_the_misleading_crowds():
    members = {name: sorted((m.controller, m.lapse) for m in PROFILES[name].members)
               for name in ("random", "all_poor", "half_poor", "one_good_poor")}
    assert members["random"] == [("expert", 1.0)] * 10
    assert members["all_poor"] == [("poor", 0.0)] * 10
    assert members["half_poor"] == [("expert", 0.05)] * 5 + [("poor", 0.0)] * 5
    assert members["one_good_poor"] == [("expert", 0.05)] + [("poor", 0.0)] * 9
    assert all(len(PROFILES[name]) == 10 for name in members)


def test_true_skill_is_the_controllers_net_goals_while_it_is_in_command():
    crowd = PROFILES["one_good_poor"]
    # By ε alone the nine Poor players, who never lapse, are the best…
    assert set(crowd.best()) == {f"poor_{i:02d}" for i in range(1, 10)}
    # …by what their controllers score, the Expert is.
    controllers = {"expert": 0.96, "poor": -0.02}
    skill = crowd.skill(controllers)
    assert skill["expert_00"] == pytest.approx(0.96 * 0.95) and skill["poor_03"] == pytest.approx(-0.02)
    assert crowd.best(controllers) == ("expert_00",)
    # Within one controller, lower ε ranks higher, as before.
    linear = PROFILES["linear"].skill({"expert": 1.0})
    assert sorted(linear, key=linear.__getitem__, reverse=True) == list(PROFILES["linear"].names)
    with pytest.raises(ValueError, match="no measured skill for controller 'poor'"):
        crowd.skill({"expert": 1.0})


def test_a_controllers_skill_is_its_net_goals_per_attempt_without_lapses():
    demos = [d for c in (1, 2) for d in polymimic.record("poor", configuration=c, n=3, seed=4)]
    net = sum(d.outcome == "goal" for d in demos) - sum(d.outcome == "own_goal" for d in demos)
    assert controller_skill(["poor"], n=3, seed=4) == {"poor": net / 6}


def test_a_crowd_round_trips_as_data():
    crowd = PROFILES["mixed_bodies"]
    assert Crowd.from_members(crowd.name, crowd.to_members()) == crowd
    counted = Crowd.from_members("c", [{"controller": "poor", "lapse": 0.2, "count": 3},
                                       {"controller": "expert", "lapse": 0, "name": "star"}])
    assert counted.names == ("poor_00", "poor_01", "poor_02", "star")
    assert counted.members[-1] == Member("star", "expert", 0.0)


@pytest.mark.parametrize(("members", "match"), [
    ([{"controller": "expert", "lapse": 0.1}], "at least two"),
    ([{"controller": "expert", "lapse": 1.5}, {"controller": "poor", "lapse": 0.1}], r"lapse 1\.5.*\[0, 1\]"),
    ([{"controller": "expert", "lapse": float("nan")}, {"controller": "poor", "lapse": 0.1}], "lapse nan"),
    ([{"controller": "expert", "lapse": True}, {"controller": "poor", "lapse": 0.1}], "lapse True"),
    ([{"controller": "experts", "lapse": 0.1}, {"controller": "poor", "lapse": 0.1}], "controller 'experts'"),
    ([{"controller": "expert"}, {"controller": "poor", "lapse": 0.1}], "missing key 'lapse'"),
    ([{"controller": "expert", "lapse": 0.1, "lapes": 2}, {"controller": "poor", "lapse": 0.1}],
     "unknown key 'lapes'"),
    ([{"controller": "expert", "lapse": 0.1, "name": "a"}, {"controller": "poor", "lapse": 0.1, "name": "a"}],
     "names member 'a' twice"),
    ([{"controller": "expert", "lapse": 0.1, "count": 0}, {"controller": "poor", "lapse": 0.1}], "count"),
    ("expert", "a list of tables"),
])
def test_bad_crowds_are_refused_by_name(members, match):
    with pytest.raises(ValueError, match=match):
        Crowd.from_members("mine", members)


def test_unknown_profiles_are_named():
    with pytest.raises(ValueError, match="unknown profile 'one_goood'; expected one of one_good"):
        profile("one_goood")


def test_members_of_one_controller_and_lapse_record_different_demonstrations():
    assert len({member_seed(0, i) for i in range(10)}) == 10
    assert member_seed(3, 1) == member_seed(3, 1) != member_seed(4, 1)
    demos = record_crowd(PROFILES["half"], n=1, seed=2)
    assert [d.demonstrator for d in demos[:4]] == ["expert_00", "expert_00", "expert_01", "expert_01"]
    assert [d.configuration for d in demos[:2]] == [1, 2]
    assert demos[0].frames.tobytes() != demos[2].frames.tobytes()


def test_a_crowd_of_lapse_zero_records_its_controllers_own_demonstrations():
    crowd = Crowd.from_members("pure", [{"controller": "expert", "lapse": 0.0}, {"controller": "tiny", "lapse": 0.0}])
    demos = record_crowd(crowd, n=2, seed=5)
    own = polymimic.record("tiny", configuration=1, n=2, seed=member_seed(5, 1))
    mine = [d for d in demos if d.demonstrator == "tiny_01" and d.configuration == 1]
    assert [d.frames.tobytes() for d in mine] == [d.frames.tobytes() for d in own]
    assert {d.body.name for d in mine} == {"tiny"}


def test_a_demonstration_of_an_unknown_demonstrator_names_its_body():
    frames = np.zeros(3, dtype=FRAME_DTYPE)
    assert Demonstration(frames, "goal", "alice", 1, 0, body="tiny").body.name == "tiny"
    with pytest.raises(ValueError, match="give its body"):
        Demonstration(frames, "goal", "alice", 1, 0)
    with pytest.raises(ValueError, match="demonstration of 'alice': unknown body \"two wheels\""):
        Demonstration(frames, "goal", "alice", 1, 0, body="two wheels")
    # A body of one's own is given as itself: its name alone says nothing of its field.
    with pytest.raises(ValueError, match="unknown body \"wheels\": the built-in bodies are lego, tiny, humanoid; "
                                         "describe a body of your own"):
        Demonstration(frames, "goal", "alice", 1, 0, body="wheels")
    wheels = WheeledBody("wheels", length_mm=100, width_mm=100, wheel_base_mm=90, top_wheel_speed_mm_s=100)
    assert Demonstration(frames, "goal", "alice", 1, 0, body=wheels).body == polymimic.Body(wheels)


def test_a_crowds_bodies_survive_a_dataset_round_trip(tmp_path):
    demos = record_crowd(PROFILES["mixed_bodies"], n=1, seed=1)
    polymimic.save_demonstrations(demos, tmp_path / "crowd.parquet")
    again = polymimic.load_demonstrations(tmp_path / "crowd.parquet")
    assert [(d.demonstrator, d.body.name) for d in again] == [(d.demonstrator, d.body.name) for d in demos]


def test_a_version_1_dataset_without_bodies_reads_with_the_known_ones(tmp_path):
    path = tmp_path / "old.parquet"
    polymimic.save_demonstrations(polymimic.record("tiny", configuration=1, n=1, seed=0), path)
    table = pq.read_table(path).drop_columns(["body"])
    header = json.loads(table.schema.metadata[b"polymimic"])
    header["version"] = 1
    pq.write_table(table.replace_schema_metadata({b"polymimic": json.dumps(header).encode()}), path)
    assert [d.body.name for d in polymimic.load_demonstrations(path)] == ["tiny"]


def test_the_small_field_follows_the_body_not_the_name():
    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=8)
    tiny = polymimic.record("tiny", configuration=1, n=1, seed=0)[0]
    renamed = [dataclasses.replace(tiny, demonstrator="tiny_07"), dataclasses.replace(tiny, demonstrator="t",
                                                                                      body="lego")]
    assert segmented(renamed, recognizer).pitches == ["small", "large"]
