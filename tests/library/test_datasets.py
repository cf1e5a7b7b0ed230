"""Parquet datasets: exact round trips, refusal of files that are not ours, atomic writes."""

import dataclasses
import json
import re

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import polymimic
from polymimic.bodies import THESIS_BODIES, WheeledBody
from polymimic.datasets import (
    load_demonstrations,
    load_self_observation,
    save_demonstrations,
    save_self_observation,
)


@pytest.fixture(scope="module")
def demos():
    return (polymimic.record("expert", configuration=2, n=2, seed=1)
            + polymimic.record("tiny", configuration=1, n=1, seed=2)
            + polymimic.record("humanoid", configuration=1, n=1, seed=3))


@pytest.fixture(scope="module")
def sequences():
    return polymimic.self_observation(2, seed=4)


def assert_same_demonstrations(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert x.frames.dtype == y.frames.dtype
        assert x.frames.tobytes() == y.frames.tobytes()  # bit for bit, NaN and -0.0 included
        assert (x.outcome, x.demonstrator, x.configuration, x.seed) == (y.outcome, y.demonstrator, y.configuration,
                                                                        y.seed)
        assert type(x.seed) is int and type(x.configuration) is int


def test_demonstrations_round_trip_exactly(tmp_path, demos):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos, path)
    assert_same_demonstrations(load_demonstrations(path), demos)
    assert_same_demonstrations(load_demonstrations(str(path)), demos)


def test_special_floats_and_large_seeds_round_trip(tmp_path, demos):
    frames = demos[0].frames.copy()
    frames["ball_x_mm"][:3] = [np.nan, -0.0, np.inf]
    frames["robot_theta_rad"][0] = np.nextafter(np.pi, 0)
    odd = dataclasses.replace(demos[0], frames=frames, seed=2**64 - 1, demonstrator="average")
    save_demonstrations([odd], tmp_path / "odd.parquet")
    assert_same_demonstrations(load_demonstrations(tmp_path / "odd.parquet"), [odd])


def test_another_bodys_self_observation_keeps_its_body_and_an_older_file_is_the_legos(tmp_path):
    import pyarrow.parquet as pq

    tiny = polymimic.self_observation(1, seed=0, body="tiny")
    path = tmp_path / "tiny.parquet"
    save_self_observation(tiny, path)
    again = load_self_observation(path)
    assert [s.body.name for s in again] == ["tiny"] * 5
    assert all(a.frames.tobytes() == s.frames.tobytes() for a, s in zip(again, tiny))
    # A version-2 file, written before self-observation recorded its body, was always the Lego's.
    table = pq.read_table(path)
    header = json.loads(table.schema.metadata[b"polymimic"])
    older = table.drop(["body"]).replace_schema_metadata({"polymimic": json.dumps({**header, "version": 2})})
    pq.write_table(older, tmp_path / "v2.parquet")
    assert {s.body.name for s in load_self_observation(tmp_path / "v2.parquet")} == {"lego"}


ROVER = WheeledBody("rover_on_file", length_mm=200, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=150)


def test_a_body_of_ones_own_is_read_as_the_bodies_given(tmp_path):
    demos = polymimic.record("poor", body=ROVER, configuration=1, n=2, seed=5)
    sequences = polymimic.self_observation(1, seed=5, body=ROVER)
    save_demonstrations(demos, tmp_path / "rover.parquet")
    save_self_observation(sequences, tmp_path / "rover_self.parquet")
    # The file holds the body's name, as before bodies were values.
    assert set(pq.read_table(tmp_path / "rover.parquet").column("body").to_pylist()) == {"rover_on_file"}
    for given in ([ROVER], {"rover_on_file": ROVER}, [polymimic.Body(ROVER)], (ROVER, ROVER)):
        again = load_demonstrations(tmp_path / "rover.parquet", bodies=given)
        assert [d.body for d in again] == [polymimic.Body(ROVER)] * 2
        assert [d.body.field.length_mm for d in again] == [1020.0] * 2
        assert_same_demonstrations(again, demos)
    own = load_self_observation(tmp_path / "rover_self.parquet", bodies=[ROVER])
    assert {s.body.name for s in own} == {"rover_on_file"} and {s.body.kind for s in own} == {"wheeled"}


def test_a_body_not_given_is_refused_naming_the_file_and_how_to_give_it(tmp_path):
    save_demonstrations(polymimic.record("poor", body=ROVER, configuration=1, n=1, seed=5), tmp_path / "rover.parquet")
    save_self_observation(polymimic.self_observation(1, seed=5, body=ROVER), tmp_path / "rover_self.parquet")
    for load, path in ((load_demonstrations, tmp_path / "rover.parquet"),
                       (load_self_observation, tmp_path / "rover_self.parquet")):
        expected = (rf"^{re.escape(str(path))}: body 'rover_on_file' is not built in \(lego, tiny, humanoid\) and "
                    r"was not given: pass its description with bodies=")
        with pytest.raises(ValueError, match=expected):
            load(path)
        with pytest.raises(ValueError, match=r"body 'rover_on_file' is not built in .* \(given: tiny\)"):
            load(path, bodies=[THESIS_BODIES["tiny"]])


def test_two_bodies_of_one_name_are_refused(tmp_path):
    save_demonstrations(polymimic.record("poor", body=ROVER, configuration=1, n=1, seed=5), tmp_path / "rover.parquet")
    other = dataclasses.replace(ROVER, field="small", length_mm=20, width_mm=20)
    with pytest.raises(ValueError, match="bodies: two bodies are named 'rover_on_file', with other constants; give "
                                         "each a name of its own"):
        load_demonstrations(tmp_path / "rover.parquet", bodies=[ROVER, other])
    with pytest.raises(ValueError, match="bodies: key 'rover' holds the body named 'rover_on_file'"):
        load_demonstrations(tmp_path / "rover.parquet", bodies={"rover": ROVER})
    with pytest.raises(TypeError, match="bodies: expected a polymimic.Body or a polymimic.bodies.WheeledBody, got "
                                        "'rover_on_file'"):
        load_demonstrations(tmp_path / "rover.parquet", bodies=["rover_on_file"])


def test_self_observation_round_trips_exactly(tmp_path, sequences):
    path = tmp_path / "self.parquet"
    save_self_observation(sequences, path)
    again = load_self_observation(path)
    assert [s.primitive for s in again] == [s.primitive for s in sequences]
    assert [s.frames.tobytes() for s in again] == [s.frames.tobytes() for s in sequences]


def test_empty_lists_round_trip(tmp_path):
    save_demonstrations([], tmp_path / "none.parquet")
    assert load_demonstrations(tmp_path / "none.parquet") == []
    save_self_observation([], tmp_path / "none-self.parquet")
    assert load_self_observation(tmp_path / "none-self.parquet") == []


def test_file_is_one_row_per_frame_with_versioned_metadata(tmp_path, demos):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos, path)
    table = pq.read_table(path)
    assert table.num_rows == sum(len(d.frames) for d in demos)
    assert table.column_names == ["episode", *polymimic.field.FRAME_DTYPE.names, "demonstrator", "configuration",
                                  "seed", "outcome", "body"]
    header = json.loads(table.schema.metadata[b"polymimic"])
    assert header["format"] == "polymimic.demonstrations" and header["version"] == 3
    assert table.column("episode").to_pylist()[-1] == len(demos) - 1


def test_missing_file_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such dataset file"):
        load_demonstrations(tmp_path / "absent.parquet")
    with pytest.raises(FileNotFoundError):
        load_self_observation(tmp_path / "absent.parquet")


@pytest.mark.parametrize("content", [b"", b"not parquet at all", b"PAR1" + b"\0" * 100 + b"PAR1"])
def test_garbage_is_a_model_file_error(tmp_path, content):
    path = tmp_path / "garbage.parquet"
    path.write_bytes(content)
    with pytest.raises(polymimic.ModelFileError, match=f"{path.name} is not a readable Parquet file"):
        load_demonstrations(path)


def test_truncated_file_is_a_model_file_error(tmp_path, demos):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos, path)
    data = path.read_bytes()
    for cut in (len(data) // 2, len(data) - 10):
        path.write_bytes(data[:cut])
        with pytest.raises(polymimic.ModelFileError, match="demos.parquet"):
            load_demonstrations(path)


def test_damaged_data_pages_are_a_model_file_error(tmp_path, demos):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos, path)
    data = bytearray(path.read_bytes())
    data[100:400] = bytes(300)  # inside the first column chunk; the footer is intact
    path.write_bytes(bytes(data))
    with pytest.raises(polymimic.ModelFileError, match="demos.parquet"):
        load_demonstrations(path)


def test_the_other_kind_is_refused_with_a_hint(tmp_path, demos, sequences):
    save_demonstrations(demos, tmp_path / "demos.parquet")
    save_self_observation(sequences, tmp_path / "self.parquet")
    expected = "holds polymimic.demonstrations, not polymimic.self_observation; load it with load_demonstrations"
    with pytest.raises(polymimic.ModelFileError, match=expected):
        load_self_observation(tmp_path / "demos.parquet")
    with pytest.raises(polymimic.ModelFileError, match="load it with load_self_observation"):
        load_demonstrations(tmp_path / "self.parquet")


def test_foreign_parquet_is_refused(tmp_path):
    path = tmp_path / "foreign.parquet"
    pq.write_table(pa.table({"x": [1.0, 2.0]}), path)
    with pytest.raises(polymimic.ModelFileError, match="foreign.parquet is not a polymimic dataset"):
        load_demonstrations(path)


def rewrite(path, *, header=None, table=None):
    """Rewrite a saved file with another header and/or table (keeping the other)."""
    original = pq.read_table(path)
    table = original if table is None else table
    metadata = dict(original.schema.metadata)
    if header is not None:
        metadata[b"polymimic"] = header if isinstance(header, bytes) else json.dumps(header).encode()
    pq.write_table(table.replace_schema_metadata(metadata), path)


@pytest.mark.parametrize(
    "header, match",
    [
        ({"format": "polymimic.demonstrations", "version": 4}, "is format version 4, written by a newer polymimic"),
        ({"format": "polymimic.demonstrations", "version": 0}, "invalid format version 0"),
        ({"format": "polymimic.demonstrations", "version": "1"}, "invalid format version '1'"),
        ({"format": "polymimic.codebook", "version": 1}, "holds polymimic.codebook, not polymimic.demonstrations$"),
        ({"version": 1}, "unreadable 'polymimic' metadata"),
        (b"{not json", "unreadable 'polymimic' metadata"),
        ([1, 2], "unreadable 'polymimic' metadata"),
    ],
)
def test_bad_headers_are_refused(tmp_path, demos, header, match):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos[:1], path)
    rewrite(path, header=header)
    with pytest.raises(polymimic.ModelFileError, match=match):
        load_demonstrations(path)


def drop(table, name):
    return table.drop_columns([name])


def retype(table, name, type_):
    i = table.column_names.index(name)
    return table.set_column(i, name, table.column(name).cast(type_))


def replace(table, name, values):
    i = table.column_names.index(name)
    return table.set_column(i, pa.field(name, table.schema.field(name).type), pa.array(values,
                                                                                        table.schema.field(name).type))


@pytest.mark.parametrize(
    "change, match",
    [
        (lambda t: drop(t, "ball_y_mm"), r"lacks column\(s\) ball_y_mm"),
        (lambda t: t.append_column("extra", pa.array([0] * t.num_rows)), r"unexpected column\(s\) extra"),
        (lambda t: retype(t, "robot_x_mm", pa.float32()), "column 'robot_x_mm' of type float; expected double"),
        (lambda t: retype(t, "command", pa.int64()), "column 'command' of type int64; expected uint16"),
        (lambda t: replace(t, "episode", [1] * t.num_rows), "episode indices out of order"),
        (lambda t: replace(t, "outcome", ["goal"] * (t.num_rows - 1) + ["own_goal"]),
         "'outcome' that changes within one episode"),
        (lambda t: replace(t, "outcome", ["won"] * t.num_rows), "has outcome 'won'; expected one of goal"),
        (lambda t: replace(t, "configuration", [3] * t.num_rows), "has configuration 3; expected one of 1, 2"),
        (lambda t: t.set_column(1, pa.field("t_s", pa.float64(), nullable=True),
                                pa.array([None] + [0.0] * (t.num_rows - 1), pa.float64())),
         "missing values in column 't_s'"),
    ],
)
def test_foreign_schemas_are_refused(tmp_path, demos, change, match):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos[:1], path)
    rewrite(path, table=change(pq.read_table(path)))
    with pytest.raises(polymimic.ModelFileError, match=match):
        load_demonstrations(path)


def test_a_bad_primitive_is_refused(tmp_path, sequences):
    path = tmp_path / "self.parquet"
    save_self_observation(sequences[:1], path)
    rewrite(path, table=replace(pq.read_table(path), "primitive", ["jump"] * 30))
    with pytest.raises(polymimic.ModelFileError, match="has primitive 'jump'"):
        load_self_observation(path)


def test_a_directory_is_not_a_file(tmp_path):
    with pytest.raises(IsADirectoryError):
        load_demonstrations(tmp_path)


def test_writes_leave_no_temporary_files(tmp_path, demos, sequences):
    save_demonstrations(demos, tmp_path / "demos.parquet")
    save_demonstrations(demos[:1], tmp_path / "demos.parquet")  # replaced
    save_self_observation(sequences, tmp_path / "self.parquet")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["demos.parquet", "self.parquet"]
    assert len(load_demonstrations(tmp_path / "demos.parquet")) == 1


def test_a_failed_write_keeps_the_old_file_and_leaves_nothing(tmp_path, demos, monkeypatch):
    path = tmp_path / "demos.parquet"
    save_demonstrations(demos, path)
    before = path.read_bytes()

    def crash(table, where, **kwargs):
        with open(where, "wb") as half:
            half.write(b"PAR1 half written")
        raise OSError("disk full")

    monkeypatch.setattr(pq, "write_table", crash)
    with pytest.raises(OSError, match="disk full"):
        save_demonstrations(demos[:1], path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["demos.parquet"]


def test_a_missing_directory_is_named(tmp_path, demos):
    with pytest.raises(FileNotFoundError, match="does not exist"):
        save_demonstrations(demos, tmp_path / "no" / "such" / "demos.parquet")


def bad_frames(demo, frames):
    return dataclasses.replace(demo, frames=frames)


@pytest.mark.parametrize(
    "make_input, error, match",
    [
        (lambda d: d[0], TypeError, "got a single Demonstration; wrap it in a list"),
        (lambda d: "demos", TypeError, "expected a list of Demonstration, got str"),
        (lambda d: [d[0], "x"], TypeError, "demonstrations item 1 is a str, not a Demonstration"),
        (lambda d: [bad_frames(d[0], d[0].frames[:0])], ValueError, "demonstration 0 has no frames"),
        (lambda d: [d[0], bad_frames(d[0], np.zeros((3, 7)))], TypeError,
         "demonstration 1 has frames of float64; expected a structured array"),
        (lambda d: [bad_frames(d[0], d[0].frames.reshape(1, -1))], ValueError, r"frames of shape \(1, \d+\)"),
        (lambda d: [dataclasses.replace(d[0], outcome="won")], ValueError, "outcome 'won'"),
        (lambda d: [dataclasses.replace(d[0], configuration=3)], ValueError, "configuration 3; expected 1 or 2"),
        (lambda d: [dataclasses.replace(d[0], seed=-1)], ValueError, "seed -1"),
        (lambda d: [dataclasses.replace(d[0], demonstrator="")], ValueError, "demonstrator ''"),
    ],
)
def test_bad_demonstrations_write_nothing(tmp_path, demos, make_input, error, match):
    path = tmp_path / "demos.parquet"
    with pytest.raises(error, match=match):
        save_demonstrations(make_input(demos), path)
    assert list(tmp_path.iterdir()) == []


def test_bad_sequences_write_nothing(tmp_path, sequences, demos):
    path = tmp_path / "self.parquet"
    with pytest.raises(TypeError, match="self-observation sequences item 0 is a Demonstration"):
        save_self_observation(demos, path)
    with pytest.raises(ValueError, match="sequence 0 has primitive 'jump'"):
        save_self_observation([dataclasses.replace(sequences[0], primitive="jump")], path)
    assert list(tmp_path.iterdir()) == []
