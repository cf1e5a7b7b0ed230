"""Atomic file writes: a temporary file beside the target, renamed over it only once complete.

A reader never sees a half-written file, and a failed write leaves the old file (if any) as it
was and no temporary file behind.
"""

from __future__ import annotations

import contextlib
import os
import pathlib
import secrets
from collections.abc import Iterator


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[pathlib.Path]:
    """Yield a temporary path in ``path``'s directory; on success it replaces ``path``.

    The temporary name keeps ``path``'s extension, so writers that pick a format from the
    extension (matplotlib, Pillow) still see it. The file gets the usual permissions (0o666
    less the umask), like any other new file. The directory must exist.
    """
    target = pathlib.Path(path)
    directory = target.parent
    if not directory.is_dir():
        raise FileNotFoundError(f"cannot write {str(target)!r}: directory {str(directory)!r} does not exist")
    while True:
        temporary = directory / f".{target.name}.{secrets.token_hex(4)}.tmp{target.suffix}"
        try:
            os.close(os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            break
        except FileExistsError:
            continue
    try:
        yield temporary
        with open(temporary, "rb+") as written:
            os.fsync(written.fileno())
        os.replace(temporary, target)
    finally:
        temporary.unlink(missing_ok=True)


def atomic_write_text(path: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    with atomic_path(path) as temporary:
        temporary.write_text(text, encoding="utf-8")
