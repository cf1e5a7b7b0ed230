"""The file of a saved :class:`polymimic.ImitatorPolicy`: a zip archive of what the policy is
made from, each part in the format polymimic already gives it.

==========================  ==========================================================================
``policy.json``             the header: ``{"format": "polymimic.imitator_policy", "version": 1,
                            "writer": "polymimic <version>", "control": "thesis" or "improved",
                            "body": <the body's name>}``
``trial.json``              the trial whose imitator plays (:meth:`polymimic.TrialResult.save`'s JSON)
``recognizer.json``         the recogniser of the body's primitives
                            (:meth:`polymimic.PrimitiveRecognizer.save`'s JSON)
``learning.toml``           every learning constant (:meth:`polymimic.LearningConfig.save`'s TOML)
``body.toml``               only for a body of your own: its ``[bodies.<name>]`` table
                            (:func:`polymimic.bodies.bodies_from_tables`)
``demonstrations.parquet``  only for the improved control: the segmented demonstrations it learns
                            from (:func:`polymimic.segments.load_segments`' Parquet)
``practice.parquet``        only for a policy that practised (:func:`polymimic.practice`): its own
                            attempts, segmented, in the same Parquet; the header then also holds
                            ``"practice_weight"`` (version 2)
==========================  ==========================================================================

Unzipped, each part loads on its own with the function named. Loading a policy makes it again
from its parts, so it plays exactly as the saved one did. Writing is atomic (a reader sees the
old file or the whole new one), and the same policy always writes the same bytes. Reading
checks the header and every part: anything wrong (not a zip archive, or one cut short; a part
missing or damaged; another format; a later format version) is a
:class:`polymimic.ModelFileError` naming the file and the problem.

>>> import pathlib, tempfile, zipfile
>>> import polymimic
>>> from polymimic import learning, recognition
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
>>> trial = learning.run_trial(polymimic.record("expert", configuration=1, n=2, seed=0), recognizer=recognizer,
...                            ordering=["expert"])
>>> path = pathlib.Path(tempfile.mkdtemp()) / "imitator.zip"
>>> learning.ImitatorPolicy(trial, recognizer=recognizer).save(path)
>>> zipfile.ZipFile(path).namelist()
['policy.json', 'trial.json', 'recognizer.json', 'learning.toml']
>>> read_policy_file(path).control
'thesis'
>>> _ = path.write_bytes(path.read_bytes()[:-100])
>>> read_policy_file(path)
Traceback (most recent call last):
...
polymimic.ModelFileError: .../imitator.zip: not a polymimic.imitator_policy file: not a zip archive, or one cut short...
"""

from __future__ import annotations

import dataclasses
import io
import json
import os
import zipfile
import zlib
from collections.abc import Callable
from typing import Any, TypeVar

from polymimic import _native
from polymimic._atomic import atomic_path
from polymimic._native import ModelFileError, PrimitiveRecognizer, SegmentedDemonstrations, TrialResult
from polymimic._segments_parquet import read_segments, write_segments
from polymimic._toml import dumps, loads, write_table
from polymimic.bodies import THESIS_BODY_FIELDS, Body, WheeledBody, bodies_from_tables

__all__ = ["CONTROLS", "FORMAT", "FORMAT_VERSION", "PolicyInputs", "read_policy_file", "write_policy_file"]

FORMAT = "polymimic.imitator_policy"
FORMAT_VERSION = 2
"""The version written; files of a later version are refused. Version 2 added the practised
policy's own attempts; version 1 files read as policies that never practised."""

CONTROLS = ("thesis", "improved")

HEADER, TRIAL, RECOGNIZER, LEARNING, BODY, DEMONSTRATIONS, PRACTICE = (
    "policy.json", "trial.json", "recognizer.json", "learning.toml", "body.toml", "demonstrations.parquet",
    "practice.parquet")

T = TypeVar("T")

_WRITTEN_AT = (1980, 1, 1, 0, 0, 0)
"""Every part's zip timestamp: the earliest a zip records, so the same policy writes the same bytes."""


@dataclasses.dataclass(frozen=True)
class PolicyInputs:
    """What an :class:`~polymimic.ImitatorPolicy` is made from, as its file keeps it: the
    constructor's arguments, ``body`` the :class:`polymimic.Body` it drives,
    ``demonstrations`` (segmented) only for the improved control, and ``practice`` (its own
    attempts, segmented) only for a policy that practised."""

    trial: TrialResult
    recognizer: PrimitiveRecognizer
    config: _native.LearningConfig
    control: str
    body: Body
    demonstrations: SegmentedDemonstrations | None = None
    practice: SegmentedDemonstrations | None = None
    practice_weight: float = 1.0
    practice_refines: tuple[str, ...] | None = None
    """The world model's parts its own attempts refine (None: the ball's response and the
    states' values)."""


def write_policy_file(path: str | os.PathLike[str], inputs: PolicyInputs) -> None:
    """Write ``inputs`` to ``path`` as one policy file, atomically."""
    body = inputs.body
    header = {"format": FORMAT, "version": FORMAT_VERSION, "writer": f"polymimic {_native.__version__}",
              "control": inputs.control, "body": body.name}
    if inputs.practice is not None:
        header["practice_weight"] = inputs.practice_weight
        if inputs.practice_refines is not None:
            header["practice_refines"] = list(inputs.practice_refines)
    # The recogniser pickles as the JSON its save writes.
    parts: dict[str, str | bytes] = {HEADER: json.dumps(header, indent=2) + "\n", TRIAL: inputs.trial.to_json(),
                                     RECOGNIZER: inputs.recognizer.__reduce__()[1][0],
                                     LEARNING: dumps(inputs.config.to_dict())}
    if body.kind == "wheeled" and (description := body.description) is not None:
        lines: list[str] = []
        write_table(lines, f"bodies.{body.name}", description.to_table(), {})
        parts[BODY] = "\n".join(lines)
    for name, batch in ((DEMONSTRATIONS, inputs.demonstrations), (PRACTICE, inputs.practice)):
        if batch is not None:
            buffer = io.BytesIO()
            write_segments(batch, buffer)
            parts[name] = buffer.getvalue()
    with atomic_path(path) as temporary, zipfile.ZipFile(temporary, "w") as archive:
        for name, data in parts.items():
            archive.writestr(zipfile.ZipInfo(name, _WRITTEN_AT), data, compress_type=zipfile.ZIP_DEFLATED)


def read_policy_file(path: str | os.PathLike[str]) -> PolicyInputs:
    """The inputs :func:`write_policy_file` wrote to ``path``, every part checked.

    Raises
    ------
    polymimic.ModelFileError
        If ``path`` is not a policy file, is damaged or cut short, lacks a part, or was written
        in a later format version; the message names the file and the problem.
    """
    where = os.fspath(path)
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, EOFError) as error:
        raise ModelFileError(f"{where}: not a {FORMAT} file: not a zip archive, or one cut short ({error})") from None
    with archive:
        header = _header(archive, where)
        control, body_name = header["control"], header["body"]

        def part(name: str) -> str:
            return _part(archive, name, where).decode("utf-8")

        trial = _checked(where, TRIAL, lambda: TrialResult.from_json(part(TRIAL)))
        recognizer = _checked(where, RECOGNIZER, lambda: PrimitiveRecognizer._from_json(part(RECOGNIZER)))
        config = _checked(where, LEARNING, lambda: _native.LearningConfig(**loads(part(LEARNING))))
        body = (Body(body_name) if body_name in THESIS_BODY_FIELDS
                else _checked(where, BODY, lambda: Body(_body(loads(part(BODY)), body_name))))
        demonstrations = practice = None
        if control == "improved":
            demonstrations = read_segments(io.BytesIO(_part(archive, DEMONSTRATIONS, where)),
                                           f"{where}: {DEMONSTRATIONS}")
        if "practice_weight" in header:
            practice = read_segments(io.BytesIO(_part(archive, PRACTICE, where)), f"{where}: {PRACTICE}")
    return PolicyInputs(trial=trial, recognizer=recognizer, config=config, control=control, body=body,
                        demonstrations=demonstrations, practice=practice,
                        practice_weight=header.get("practice_weight", 1.0),
                        practice_refines=_refines(header, where))


def _refines(header: dict[str, Any], where: str) -> tuple[str, ...] | None:
    refines = header.get("practice_refines")
    if refines is None:
        return None
    if not isinstance(refines, list) or not all(isinstance(r, str) for r in refines):
        raise ModelFileError(f"{where}: {HEADER} has practice_refines {refines!r}; expected a list of part names")
    return tuple(refines)


def _header(archive: zipfile.ZipFile, where: str) -> dict[str, Any]:
    """The checked header: this format, a version this polymimic reads, a control and a body."""
    if HEADER not in archive.namelist():
        raise ModelFileError(f"{where}: not a {FORMAT} file: the zip archive has no {HEADER}")
    try:
        header = json.loads(_part(archive, HEADER, where))
    except ValueError as error:
        raise ModelFileError(f"{where}: {HEADER} is damaged ({error})") from None
    if not isinstance(header, dict):
        raise ModelFileError(f"{where}: {HEADER} is damaged: it holds {type(header).__name__}, not an object")
    found, version, writer = header.get("format"), header.get("version"), header.get("writer")
    if found != FORMAT:
        raise ModelFileError(f"{where} holds {found or 'no format'}, not {FORMAT}")
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise ModelFileError(f"{where} has an invalid format version {version!r}")
    if not isinstance(writer, str) or not writer.startswith("polymimic "):
        raise ModelFileError(f"{where} does not say which polymimic wrote it (writer {writer!r})")
    if version > FORMAT_VERSION:
        raise ModelFileError(f"{where} is format version {version}, written by {writer}; this one "
                             f"(polymimic {_native.__version__}) reads versions up to {FORMAT_VERSION} "
                             f"(upgrade polymimic)")
    if header.get("control") not in CONTROLS:
        raise ModelFileError(f"{where}: {HEADER} has control {header.get('control')!r}; expected one of "
                             f"{', '.join(CONTROLS)}")
    if not isinstance(header.get("body"), str):
        raise ModelFileError(f"{where}: {HEADER} has body {header.get('body')!r}; expected a body's name")
    weight = header.get("practice_weight", 1.0)
    if isinstance(weight, bool) or not isinstance(weight, (int, float)) or not 0 <= weight < float("inf"):
        raise ModelFileError(f"{where}: {HEADER} has practice_weight {weight!r}; expected a number of at least 0")
    if "practice_weight" in header and header["control"] != "improved":
        raise ModelFileError(f"{where}: {HEADER} holds practice, which only the improved control learns from")
    return header


def _part(archive: zipfile.ZipFile, name: str, where: str) -> bytes:
    """Part ``name``'s bytes, their checksum checked."""
    try:
        return archive.read(name)
    except KeyError:
        raise ModelFileError(f"{where}: part {name} is missing") from None
    except (zipfile.BadZipFile, zlib.error, EOFError, OSError) as error:
        raise ModelFileError(f"{where}: part {name} is damaged ({error})") from None


def _checked(where: str, name: str, read: Callable[[], T]) -> T:
    """``read()``, any error it raises reading part ``name`` a :class:`ModelFileError` naming the file."""
    try:
        return read()
    except ModelFileError as error:
        message = str(error)
        raise ModelFileError(message if message.startswith(where) else f"{where}: {name}: {message}") from None
    except (ValueError, TypeError, KeyError) as error:
        raise ModelFileError(f"{where}: {name}: {error}") from None


def _body(tables: dict[str, Any], name: str) -> WheeledBody:
    """The body ``name`` of ``body.toml``'s tables, and no other."""
    bodies = bodies_from_tables(tables.get("bodies", {}))
    if list(bodies) != [name]:
        raise ValueError(f"expected the table [bodies.{name}] alone, found {', '.join(bodies) or 'none'}")
    return bodies[name]
