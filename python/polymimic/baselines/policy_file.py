"""The file format of a saved baseline policy: a versioned header, then a pickle.

Line 1 is ``polymimic.baselines.policy <version>``; line 2 is JSON (the policy's kind, its
hyperparameters, the scikit-learn version that fitted it, and the SHA-256 of the payload);
the rest is the policy pickled. A pickle is what scikit-learn offers for its estimators;
**loading a pickle runs code, so load only files you trust.** The header is checked before
anything is unpickled, and a truncated or altered payload fails its checksum.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "policy.pmp"
>>> write_policy_file(path, {"kind": "example"}, [1, 2, 3])
>>> read_policy_file(path)
({'kind': 'example', 'sha256': '...', 'sklearn': '...'}, [1, 2, 3])
>>> _ = path.write_bytes(path.read_bytes()[:-3])
>>> read_policy_file(path)
Traceback (most recent call last):
...
polymimic.ModelFileError: .../policy.pmp: the policy's payload is damaged (checksum mismatch)
"""

from __future__ import annotations

import hashlib
import json
import os
import pickle
from typing import Any

import sklearn  # type: ignore[import-untyped, unused-ignore]

from polymimic._atomic import atomic_path
from polymimic._native import ModelFileError

__all__ = ["FORMAT", "FORMAT_VERSION", "read_policy_file", "write_policy_file"]

FORMAT = "polymimic.baselines.policy"
FORMAT_VERSION = 1


def write_policy_file(path: str | os.PathLike[str], meta: dict[str, Any], policy: Any) -> None:
    """Write ``policy`` to ``path`` atomically, with ``meta`` in its header."""
    payload = pickle.dumps(policy, protocol=pickle.HIGHEST_PROTOCOL)
    header = {**meta, "sklearn": sklearn.__version__, "sha256": hashlib.sha256(payload).hexdigest()}
    with atomic_path(path) as temporary, open(temporary, "wb") as file:
        file.write(f"{FORMAT} {FORMAT_VERSION}\n".encode())
        file.write(json.dumps(header, sort_keys=True).encode() + b"\n")
        file.write(payload)


def read_policy_file(path: str | os.PathLike[str]) -> tuple[dict[str, Any], Any]:
    """The header and the policy :func:`write_policy_file` wrote, or a
    :class:`polymimic.ModelFileError` naming ``path`` and what is wrong."""
    name = os.fspath(path)
    try:
        with open(path, "rb") as file:
            data = file.read()
    except OSError as error:
        raise ModelFileError(f"{name}: cannot read the policy file ({error})") from error
    first, _, rest = data.partition(b"\n")
    header_line, _, payload = rest.partition(b"\n")
    parts = first.decode("utf-8", "replace").split(" ")
    if len(parts) != 2 or parts[0] != FORMAT or not parts[1].isdigit():
        raise ModelFileError(f"{name}: not a {FORMAT} file")
    if int(parts[1]) > FORMAT_VERSION:
        raise ModelFileError(f"{name}: {FORMAT} version {parts[1]} is newer than this polymimic reads "
                             f"(≤ {FORMAT_VERSION})")
    try:
        header = json.loads(header_line)
    except ValueError as error:
        raise ModelFileError(f"{name}: the policy's header is damaged ({error})") from error
    if not isinstance(header, dict) or hashlib.sha256(payload).hexdigest() != header.get("sha256"):
        raise ModelFileError(f"{name}: the policy's payload is damaged (checksum mismatch)")
    try:
        policy = pickle.loads(payload)
    except Exception as error:  # any unpickling failure is a bad file
        raise ModelFileError(f"{name}: the policy cannot be unpickled ({error})") from error
    return header, policy
