"""Demonstrations and self-observation sequences saved to, and loaded from, Parquet files.

One row per tracker frame: the :data:`~polymimic.field.FRAME_DTYPE` columns (``t_s``,
``robot_x_mm``, ``robot_y_mm``, ``robot_theta_rad``, ``ball_x_mm``, ``ball_y_mm``,
``command``), the index of the frame's demonstration (``episode``) or sequence (``sequence``),
counted from 0 in file order, and that demonstration's ``demonstrator``, ``configuration``,
``seed``, ``outcome`` and ``body`` (or the sequence's ``primitive``) repeated on each of its rows. The
schema metadata key ``polymimic`` holds JSON ``{"format": "polymimic.demonstrations"`` (or
``"polymimic.self_observation"``) ``, "version": 1, "writer": ...}``, checked on load. The
files are plain Parquet: ``pandas.read_parquet(path)`` or ``polars.read_parquet(path)`` reads
them as one table.

Files are written atomically (a temporary file in the same directory, renamed over the target),
and a round trip is exact: the frames come back bit for bit.

>>> import pathlib, tempfile
>>> from polymimic.field import record
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> demos = record("poor", configuration=1, n=2, seed=3)
>>> save_demonstrations(demos, folder / "poor.parquet")
>>> again = load_demonstrations(folder / "poor.parquet")
>>> all(a.frames.tobytes() == d.frames.tobytes() and a.outcome == d.outcome for a, d in zip(again, demos))
True
>>> load_self_observation(folder / "poor.parquet")
Traceback (most recent call last):
...
polymimic.ModelFileError: .../poor.parquet holds polymimic.demonstrations, not ...; load it with load_demonstrations
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic import _native
from polymimic._atomic import atomic_path
from polymimic._native import ModelFileError
from polymimic.bodies import BodiesGiven, Body, bodies_by_name, body_named
from polymimic.field import FRAME_DTYPE, OUTCOMES, PRIMITIVE_SETS, Demonstration, PrimitiveSequence

__all__ = ["load_demonstrations", "load_self_observation", "save_demonstrations", "save_self_observation"]

FORMAT_VERSION = 3
"""The version written; files of a later version are refused. Version 2 added the demonstrations'
``body`` column (a version-1 file is read with each demonstrator's known body), version 3 the
self-observation's (an earlier one is the Lego imitator's, the only body it then recorded)."""

DEMONSTRATIONS = "polymimic.demonstrations"
SELF_OBSERVATION = "polymimic.self_observation"
_LOADERS = {DEMONSTRATIONS: "load_demonstrations", SELF_OBSERVATION: "load_self_observation"}
_METADATA_KEY = b"polymimic"
_FRAME_COLUMNS: tuple[str, ...] = FRAME_DTYPE.names or ()
_FRAME_TYPES = {name: ("uint16" if name == "command" else "double") for name in _FRAME_COLUMNS}
_DEMONSTRATION_TYPES = {"episode": "int32", **_FRAME_TYPES, "demonstrator": "string", "configuration": "int8",
                        "seed": "uint64", "outcome": "string", "body": "string"}
_DEMONSTRATION_TYPES_V1 = {k: v for k, v in _DEMONSTRATION_TYPES.items() if k != "body"}
_SELF_OBSERVATION_TYPES = {"sequence": "int32", **_FRAME_TYPES, "primitive": "string", "body": "string"}
_SELF_OBSERVATION_TYPES_V2 = {k: v for k, v in _SELF_OBSERVATION_TYPES.items() if k != "body"}


def save_demonstrations(demos: Sequence[Demonstration], path: str | os.PathLike[str]) -> None:
    """Write demonstrations to a Parquet file, atomically.

    Parameters
    ----------
    demos : list of Demonstration
        As :func:`polymimic.record` returns them; each needs at least one frame.
    path : str or path-like
        The file to write (replaced if it exists). Its directory must exist.

    Raises
    ------
    TypeError, ValueError
        For anything that is not a list of valid demonstrations; nothing is written then.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from polymimic.field import record
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "expert.parquet"
    >>> save_demonstrations(record("expert", configuration=1, n=1, seed=0), path)
    >>> import pyarrow.parquet as pq
    >>> pq.read_schema(path).names[:3]
    ['episode', 't_s', 'robot_x_mm']
    """
    items = _checked_items(demos, Demonstration, "demonstrations", "Demonstration")
    for i, demo in enumerate(items):
        _check_frames(demo.frames, f"demonstration {i}")
        if demo.outcome not in OUTCOMES:
            raise ValueError(f"demonstration {i} has outcome {demo.outcome!r}; expected one of {', '.join(OUTCOMES)}")
        if not isinstance(demo.demonstrator, str) or not demo.demonstrator:
            raise ValueError(f"demonstration {i} has demonstrator {demo.demonstrator!r}; expected a non-empty name")
        if not _is_int(demo.configuration) or demo.configuration not in (1, 2):
            raise ValueError(f"demonstration {i} has configuration {demo.configuration!r}; expected 1 or 2")
        if not _is_int(demo.seed) or not 0 <= demo.seed < 2**64:
            raise ValueError(f"demonstration {i} has seed {demo.seed!r}; expected an integer in 0..2**64")
    lengths = [len(d.frames) for d in items]
    columns = {
        "episode": _repeat(np.arange(len(items)), lengths, "int32"),
        **_frame_columns([d.frames for d in items]),
        "demonstrator": _repeat([d.demonstrator for d in items], lengths, object),
        "configuration": _repeat([d.configuration for d in items], lengths, "int8"),
        "seed": _repeat([d.seed for d in items], lengths, "uint64"),
        "outcome": _repeat([d.outcome for d in items], lengths, object),
        "body": _repeat([d.body.name for d in items], lengths, object),
    }
    _write(columns, _DEMONSTRATION_TYPES, DEMONSTRATIONS, path)


def load_demonstrations(path: str | os.PathLike[str], *, bodies: BodiesGiven = ()) -> list[Demonstration]:
    """Read the demonstrations that :func:`save_demonstrations` wrote, in their order.

    The file names each demonstration's body; a built-in body is known by its name, a body of
    your own must be given in ``bodies`` (:class:`polymimic.Body` or
    :class:`polymimic.bodies.WheeledBody` values, or a mapping from their names to them, as a
    run config's ``bodies``).

    Raises
    ------
    FileNotFoundError
        If there is no file at ``path``.
    ValueError
        If the file names a body neither built in nor in ``bodies`` (the message names the file,
        the body and how to give it), or ``bodies`` holds two bodies of one name.
    polymimic.ModelFileError
        If the file is not Parquet, is damaged, holds another kind of data or a foreign schema,
        or was written by a later format version; the message names the file and the problem.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from polymimic.field import record
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "tiny.parquet"
    >>> save_demonstrations(record("tiny", configuration=2, n=2, seed=5), path)
    >>> [(d.demonstrator, d.configuration, d.seed) for d in load_demonstrations(path)][0][:2]
    ('tiny', 2)
    """
    columns, starts, stops = _read(path, DEMONSTRATIONS, {3: _DEMONSTRATION_TYPES, 2: _DEMONSTRATION_TYPES,
                                                         1: _DEMONSTRATION_TYPES_V1},
                                   "episode")
    names = ("demonstrator", "configuration", "seed", "outcome") + (("body",) if "body" in columns else ())
    meta = {name: _per_group(columns, name, starts, stops, path, "episode") for name in names}
    _check_values(meta["outcome"], OUTCOMES, "outcome", path)
    _check_values(meta["configuration"], (1, 2), "configuration", path)
    body_of: dict[str, Body] = {}
    if "body" in meta:
        _check_names(meta["body"], "body", path)
        body_of = _bodies_named(meta["body"], bodies, path)
    frames = _frames(columns)
    try:
        return [Demonstration(frames=frames[a:b].copy(), outcome=str(meta["outcome"][i]),
                              demonstrator=str(meta["demonstrator"][i]), configuration=int(meta["configuration"][i]),
                              seed=int(meta["seed"][i]), body=body_of[str(meta["body"][i])] if "body" in meta else "")
                for i, (a, b) in enumerate(zip(starts, stops))]
    except ValueError as error:
        raise ModelFileError(f"{os.fspath(path)}: {error}") from None


def save_self_observation(seqs: Sequence[PrimitiveSequence], path: str | os.PathLike[str]) -> None:
    """Write self-observation sequences (as :func:`polymimic.self_observation` returns them, each
    with at least one frame) to a Parquet file, atomically; the path and the errors are as for
    :func:`save_demonstrations`.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from polymimic.field import self_observation
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "self.parquet"
    >>> save_self_observation(self_observation(2, seed=1), path)
    >>> sorted({s.primitive for s in load_self_observation(path)})
    ['backward', 'forward', 'left', 'right', 'stop']
    """
    items = _checked_items(seqs, PrimitiveSequence, "self-observation sequences", "PrimitiveSequence")
    for i, seq in enumerate(items):
        _check_frames(seq.frames, f"sequence {i}")
        own = PRIMITIVE_SETS[seq.body.primitive_set]
        if seq.primitive not in own:
            raise ValueError(f"sequence {i} has primitive {seq.primitive!r}; a {seq.body.name} body's are "
                             f"{', '.join(own)}")
    lengths = [len(s.frames) for s in items]
    columns = {
        "sequence": _repeat(np.arange(len(items)), lengths, "int32"),
        **_frame_columns([s.frames for s in items]),
        "primitive": _repeat([s.primitive for s in items], lengths, object),
        "body": _repeat([s.body.name for s in items], lengths, object),
    }
    _write(columns, _SELF_OBSERVATION_TYPES, SELF_OBSERVATION, path)


def load_self_observation(path: str | os.PathLike[str], *, bodies: BodiesGiven = ()) -> list[PrimitiveSequence]:
    """Read the sequences that :func:`save_self_observation` wrote, in their order; a body of
    your own is given in ``bodies``, and a missing or damaged file or a body not given raises,
    as in :func:`load_demonstrations`.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from polymimic.field import self_observation
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "self.parquet"
    >>> save_self_observation(self_observation(1, seed=2), path)
    >>> [len(s.frames) for s in load_self_observation(path)]
    [30, 30, 30, 30, 30]
    """
    columns, starts, stops = _read(path, SELF_OBSERVATION, {1: _SELF_OBSERVATION_TYPES_V2,
                                                            2: _SELF_OBSERVATION_TYPES_V2, 3: _SELF_OBSERVATION_TYPES},
                                   "sequence")
    primitives = _per_group(columns, "primitive", starts, stops, path, "sequence")
    _check_values(primitives, PRIMITIVE_SETS["humanoid"], "primitive", path)
    names = _per_group(columns, "body", starts, stops, path, "sequence") if "body" in columns else None
    body_of: dict[str, Body] = {}
    if names is not None:
        _check_names(names, "body", path)
        body_of = _bodies_named(names, bodies, path)
    frames = _frames(columns)
    return [PrimitiveSequence(primitive=str(p), frames=frames[a:b].copy(),
                              body=body_of[str(names[i])] if names is not None else "lego")
            for i, (p, a, b) in enumerate(zip(primitives, starts, stops))]


# Saving.

def _checked_items(items: Any, kind: type, what: str, name: str) -> list[Any]:
    if isinstance(items, kind):
        raise TypeError(f"expected a list of {name}, got a single {name}; wrap it in a list")
    if isinstance(items, (str, bytes)) or not isinstance(items, Sequence):
        raise TypeError(f"expected a list of {name}, got {type(items).__name__}")
    for i, item in enumerate(items):
        if not isinstance(item, kind):
            raise TypeError(f"{what} item {i} is a {type(item).__name__}, not a {name}")
    return list(items)


def _check_frames(frames: Any, what: str) -> None:
    if not isinstance(frames, np.ndarray) or frames.dtype != FRAME_DTYPE:
        got = frames.dtype if isinstance(frames, np.ndarray) else type(frames).__name__
        raise TypeError(f"{what} has frames of {got}; expected a structured array of polymimic.field.FRAME_DTYPE")
    if frames.ndim != 1:
        raise ValueError(f"{what} has frames of shape {frames.shape}; expected a 1-D array of frames")
    if len(frames) == 0:
        raise ValueError(f"{what} has no frames")


def _is_int(value: Any) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _repeat(values: Any, lengths: list[int], dtype: Any) -> np.ndarray:
    return np.repeat(np.asarray(values, dtype=dtype), lengths) if lengths else np.empty(0, dtype=dtype)


def _frame_columns(frames: list[np.ndarray]) -> dict[str, np.ndarray]:
    stacked = np.concatenate(frames) if frames else np.empty(0, dtype=FRAME_DTYPE)
    return {name: np.ascontiguousarray(stacked[name]) for name in _FRAME_COLUMNS}


def _write(columns: dict[str, np.ndarray], types: dict[str, str], kind: str, path: str | os.PathLike[str]) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    schema = pa.schema([pa.field(name, pa.type_for_alias(t), nullable=False) for name, t in types.items()],
                       metadata={_METADATA_KEY: json.dumps({"format": kind, "version": FORMAT_VERSION,
                                                            "writer": f"polymimic {_native.__version__}"})})
    table = pa.Table.from_arrays([pa.array(columns[name], type=schema.field(name).type) for name in types],
                                 schema=schema)
    strings = [name for name, t in types.items() if t == "string"]
    with atomic_path(path) as temporary:
        # Dictionary encoding only for the repeated names: floats are kept as written, bit for bit.
        # Page checksums let a damaged file be told from a good one on load.
        pq.write_table(table, temporary, compression="zstd", use_dictionary=strings, write_page_checksum=True)


# Loading.

def _read(path: str | os.PathLike[str], kind: str, columns_of: Mapping[int, dict[str, str]],
          group: str) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray]:
    """The checked columns of a file of ``kind``, and where each group starts and stops;
    ``columns_of`` gives the columns of each format version."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    where = os.fspath(path)
    if not os.path.exists(where):
        raise FileNotFoundError(2, "no such dataset file", where)
    if os.path.isdir(where):
        raise IsADirectoryError(21, "expected a Parquet file, got a directory", where)
    try:
        parquet = pq.ParquetFile(where, page_checksum_verification=True)
        schema = parquet.schema_arrow
    except (pa.ArrowException, OSError) as e:
        raise ModelFileError(f"{where} is not a readable Parquet file ({e})") from e
    types = columns_of[_check_header(schema.metadata or {}, kind, where)]
    _check_schema(schema, types, where)
    try:
        table = parquet.read()
    except (pa.ArrowException, OSError) as e:
        raise ModelFileError(f"{where} is damaged: its data cannot be read ({e})") from e
    for name in types:
        if table.column(name).null_count:
            raise ModelFileError(f"{where} has missing values in column {name!r}")
    columns = {name: table.column(name).to_numpy() for name in types}
    groups = columns[group].astype(np.int64)
    if len(groups) and (groups[0] != 0 or not np.isin(np.diff(groups), (0, 1)).all()):
        raise ModelFileError(f"{where} has {group} indices out of order; they must count up from 0 in file order")
    bounds = np.flatnonzero(np.diff(groups)) + 1
    starts = np.concatenate([[0], bounds]) if len(groups) else np.empty(0, dtype=np.int64)
    stops = np.concatenate([bounds, [len(groups)]]) if len(groups) else np.empty(0, dtype=np.int64)
    return columns, starts, stops


def _check_header(metadata: dict[bytes, bytes], kind: str, where: str) -> int:
    """The file's format version, once its header is checked."""
    raw = metadata.get(_METADATA_KEY)
    if raw is None:
        raise ModelFileError(f"{where} is not a polymimic dataset: its schema has no 'polymimic' metadata")
    try:
        header = json.loads(raw)
        found, version = header["format"], header["version"]
    except (ValueError, TypeError, KeyError) as e:
        raise ModelFileError(f"{where} has unreadable 'polymimic' metadata ({e!r})") from e
    if found != kind:
        hint = f"; load it with {_LOADERS[found]}" if isinstance(found, str) and found in _LOADERS else ""
        raise ModelFileError(f"{where} holds {found}, not {kind}{hint}")
    if not _is_int(version) or version < 1:
        raise ModelFileError(f"{where} has an invalid format version {version!r}")
    if version > FORMAT_VERSION:
        raise ModelFileError(f"{where} is format version {version}, written by a newer polymimic; "
                             f"this one reads versions up to {FORMAT_VERSION} (upgrade polymimic)")
    return int(version)


def _check_schema(schema: Any, types: dict[str, str], where: str) -> None:
    import pyarrow as pa

    missing = [name for name in types if name not in schema.names]
    if missing:
        raise ModelFileError(f"{where} lacks column(s) {', '.join(missing)}")
    extra = [name for name in schema.names if name not in types]
    if extra:
        raise ModelFileError(f"{where} has unexpected column(s) {', '.join(extra)}")
    for name, alias in types.items():
        found = schema.field(name).type
        if found != pa.type_for_alias(alias):
            raise ModelFileError(f"{where} has column {name!r} of type {found}; expected {alias}")


def _per_group(columns: dict[str, np.ndarray], name: str, starts: np.ndarray, stops: np.ndarray,
               where: str | os.PathLike[str], group: str) -> np.ndarray:
    """The value of a per-group column for each group, checked to be the same on all its rows."""
    values = columns[name]
    first: np.ndarray = values[starts]
    if len(values) and not (values == np.repeat(first, stops - starts)).all():
        raise ModelFileError(f"{os.fspath(where)} has a {name!r} that changes within one {group}")
    return first


def _check_names(values: np.ndarray, name: str, where: str | os.PathLike[str]) -> None:
    """Every value a name (a word of letters, digits and _): a body's, a demonstrator's."""
    for value in values:
        if not isinstance(value, str) or not value.isidentifier():
            raise ModelFileError(f"{os.fspath(where)}: column {name!r} holds {value!r}; expected a name")


def _bodies_named(names: np.ndarray, bodies: BodiesGiven, where: str | os.PathLike[str]) -> dict[str, Body]:
    """The body each name of the file's ``body`` column names: a built-in body, or one of
    ``bodies``; a ``ValueError`` naming the file for any other."""
    given = bodies_by_name(bodies)
    return {name: body_named(name, given, where=os.fspath(where)) for name in dict.fromkeys(map(str, names))}


def _check_values(values: np.ndarray, allowed: tuple[Any, ...], name: str, where: str | os.PathLike[str]) -> None:
    bad = [v for v in dict.fromkeys(values.tolist()) if v not in allowed]
    if bad:
        raise ModelFileError(f"{os.fspath(where)} has {name} {bad[0]!r}; expected one of "
                             f"{', '.join(map(str, allowed))}")


def _frames(columns: dict[str, np.ndarray]) -> np.ndarray:
    frames = np.empty(len(columns["t_s"]), dtype=FRAME_DTYPE)
    for name in _FRAME_COLUMNS:
        frames[name] = columns[name]
    return frames
