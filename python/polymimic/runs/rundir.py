"""A run's directory, as every application keeps it: a manifest (format, version, config, the
start and finish of every stage), a lock that one process holds at a time, and the datasets,
models and plots folders. Each application names its own outputs in a subclass of
:class:`RunHouse` (``polymimic.reproduce.rundir.RunDir``, ``polymimic.benchmark.rundir.BenchmarkDir``).
"""

from __future__ import annotations

import contextlib
import datetime
import json
import os
import pathlib
import re
import socket
import sys
from collections.abc import Callable, Iterator
from typing import Any, Generic, Protocol, TypeVar

from polymimic._atomic import atomic_write_text
from polymimic._native import ModelFileError, PolymimicError, __version__
from polymimic.runs.config import ConfigError

if sys.platform != "win32":
    import fcntl

__all__ = ["MANIFEST_VERSION", "MissingInputError", "RunError", "RunHouse", "latest_run_path", "new_run_path"]

MANIFEST_VERSION = 1


class RunError(PolymimicError):
    """A stage cannot run: its inputs are missing, the run directory is damaged, in use, or
    disagrees with the config."""


class MissingInputError(RunError):
    """A stage's input is not in the run directory: an earlier stage has not run."""


def new_run_path(root: str | os.PathLike[str] = "runs") -> pathlib.Path:
    """``runs/<UTC timestamp>``, e.g. ``runs/20250101-120000``; a suffix keeps it new."""
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y%m%d-%H%M%S")
    path = pathlib.Path(root) / stamp
    suffix = 1
    while path.exists():
        suffix += 1
        path = pathlib.Path(root) / f"{stamp}-{suffix}"
    return path


def latest_run_path(root: str | os.PathLike[str] = "runs") -> pathlib.Path | None:
    """The newest run directory under ``root`` (by name: names are timestamps), if any."""
    runs = sorted(p for p in pathlib.Path(root).glob("*") if (p / "manifest.json").is_file())
    return runs[-1] if runs else None


_TEMPORARY = re.compile(r"^\..+\.[0-9a-f]{8}\.tmp(\.[^.]*)?$")
"""The name :func:`polymimic._atomic.atomic_path` gives a file while it is being written."""

_LOCK_NAME = ".lock"

Loaded = TypeVar("Loaded")


def _warn(message: str) -> None:
    print(f"warning: {message}", file=sys.stderr)


def _now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="milliseconds")


_Stored = TypeVar("_Stored")


class StoredConfig(Protocol):
    """What a run keeps in its manifest: a config that is plain data and back."""

    def to_dict(self) -> dict[str, Any]: ...

    @classmethod
    def from_dict(cls: type[_Stored], data: dict[str, Any]) -> _Stored: ...


ConfigT = TypeVar("ConfigT", bound=StoredConfig)


class RunHouse(Generic[ConfigT]):
    """A directory of one run: its manifest (of ``manifest_format``, holding a config of
    ``config_type``), a lock, its datasets, models and plots, and the self-observation and
    recogniser every kind of run starts from."""

    manifest_format: str
    config_type: type[ConfigT]
    results_name: str
    """The stem of the run's results file (``<results_name>.json``)."""
    report_name: str
    """The stem of its report (``<report_name>.md``, ``.html``)."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = pathlib.Path(path)
        if self.path.exists() and not self.path.is_dir():
            raise RunError(f"{self.path} is a file, not a run directory: name a directory with --run-dir")
        self._lock_depth = 0
        self.datasets = self.path / "datasets"
        self.models = self.path / "models"
        self.plots = self.path / "plots"
        self.manifest_path = self.path / "manifest.json"
        self.recognizer_path = self.models / "recognizer.json"
        self.results_path = self.path / f"{self.results_name}.json"
        self.report_md_path = self.path / f"{self.report_name}.md"
        self.report_html_path = self.path / f"{self.report_name}.html"

    def __repr__(self) -> str:
        return f"{type(self).__name__}({str(self.path)!r})"

    def self_observation_path(self, split: str) -> pathlib.Path:
        """``split`` is ``"train"`` or ``"test"``."""
        return self.datasets / f"self_observation_{split}.parquet"

    def require(self, path: pathlib.Path, stage: str) -> pathlib.Path:
        """``path`` if it exists; else a :class:`MissingInputError` naming the stage that makes it."""
        if not path.exists():
            raise MissingInputError(f"{path} is missing: run `polymimic {stage} --run-dir {self.path}` first")
        return path

    def finished(self, path: pathlib.Path, load: Callable[[pathlib.Path], Loaded], *,
                 say: Callable[[str], None] | None = None) -> bool:
        """Whether a stage's output at ``path`` is there and whole: ``load`` reads it without
        error. A damaged one is reported through ``say`` (a warning on stderr, shown even in a
        quiet run), removed, and counts as not finished, so that the stage makes it again."""
        return self._read_whole(path, load, say)[0]

    def loaded(self, path: pathlib.Path, load: Callable[[pathlib.Path], Loaded], *,
               say: Callable[[str], None] | None = None) -> Loaded | None:
        """What ``load`` reads from a finished output at ``path`` (see :meth:`finished`), or
        ``None`` where it is not finished: one read where a caller also looks inside."""
        return self._read_whole(path, load, say)[1]

    def _read_whole(self, path: pathlib.Path, load: Callable[[pathlib.Path], Loaded],
                    say: Callable[[str], None] | None) -> tuple[bool, Loaded | None]:
        if not path.exists():
            return False, None
        try:
            value = load(path)
        except (ModelFileError, RunError, ValueError, OSError) as error:
            (say or _warn)(f"{path} is damaged ({error}): making it again")
            path.unlink(missing_ok=True)
            return False, None
        return True, value

    # Exclusive use, and what an interrupted writer left behind.

    @contextlib.contextmanager
    def lock(self, command: str) -> Iterator[None]:
        """Hold the run directory for ``command`` while it writes; another process asking for
        it meanwhile gets a :class:`RunError` naming the holder. The holder may take it again
        (a stage within ``reproduce``). On entry, temporary files an interrupted writer left
        are removed: no one else is writing. Where the platform has no ``fcntl`` (Windows),
        the directory is not locked."""
        if self._lock_depth:
            self._lock_depth += 1
            try:
                yield
            finally:
                self._lock_depth -= 1
            return
        self.path.mkdir(parents=True, exist_ok=True)
        with open(self.path / _LOCK_NAME, "a+", encoding="utf-8") as handle:
            _acquire(handle, self.path)
            handle.seek(0)
            handle.truncate()
            handle.write(f"pid {os.getpid()} on {socket.gethostname()}, {command}, since {_now()}\n")
            handle.flush()
            self._lock_depth = 1
            try:
                self.remove_temporaries()
                yield
            finally:
                self._lock_depth = 0
                handle.seek(0)
                handle.truncate()

    def remove_temporaries(self) -> list[pathlib.Path]:
        """Remove the half-written files an interrupted stage left behind; return them."""
        stale = [p for p in self.path.rglob(".*") if p.is_file() and _TEMPORARY.match(p.name)]
        for path in stale:
            path.unlink(missing_ok=True)
        return stale

    # The manifest.

    def open(self, config: ConfigT | None) -> ConfigT:
        """Create the directory (with its manifest) or open it, and return the run's config.

        An existing run keeps the config it was made with: ``config`` may be None (use it) or
        equal to it; a different one is refused, since finished stages would not match it.
        """
        if self.manifest_path.exists():
            stored = self.config_type.from_dict(self.manifest()["config"])
            if config is not None and config != stored:
                raise RunError(f"{self.path} was made with a different config; start a new --run-dir, or leave "
                               f"out --config/--quick to go on with its own (`polymimic config --run-dir "
                               f"{self.path}` prints it)")
            return stored
        if self.path.exists() and any(p.name != _LOCK_NAME for p in self.path.iterdir()):
            raise RunError(f"{self.path} exists, is not empty and holds no manifest.json: not a run directory")
        config = config or self.config_type()
        # The manifest first: a run stopped before it is an empty directory, one stopped after it a run.
        self.path.mkdir(parents=True, exist_ok=True)
        self._write({"format": self.manifest_format, "version": MANIFEST_VERSION, "polymimic_version": __version__,
                     "created": _now(), "config": config.to_dict(), "seeds": config.to_dict()["seeds"],
                     "stages": {}})
        for folder in (self.datasets, self.models, self.plots):
            folder.mkdir(parents=True, exist_ok=True)
        return config

    def manifest(self) -> dict[str, Any]:
        """The run's ``manifest.json``.

        Raises
        ------
        MissingInputError
            If the folder is not a run directory.
        RunError
            If the manifest cannot be read.
        """
        try:
            data = json.loads(self.manifest_path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise MissingInputError(f"{self.path} is not a run directory (no manifest.json)") from None
        except (OSError, ValueError) as error:
            raise RunError(f"{self.manifest_path}: not a readable manifest ({error})") from error
        if not isinstance(data, dict):
            raise RunError(f"{self.manifest_path}: not a polymimic run manifest (a JSON object is expected, got "
                           f"{type(data).__name__})")
        version = data.get("version")
        known = data.get("format") == self.manifest_format
        if not known or type(version) is not int or not 1 <= version <= MANIFEST_VERSION:
            raise RunError(f"{self.manifest_path}: not a polymimic run manifest of version ≤ {MANIFEST_VERSION} "
                           f"(format {data.get('format')!r}, version {version!r})")
        if not isinstance(data.get("stages"), dict):
            raise RunError(f"{self.manifest_path}: key 'stages' must be an object, got {data.get('stages')!r}")
        if not isinstance(data.get("config"), dict):
            raise RunError(f"{self.manifest_path}: key 'config' must be an object, got {data.get('config')!r}")
        try:
            self.config_type.from_dict(data["config"])
        except ConfigError as error:
            raise RunError(f"{self.manifest_path}: its config cannot be read ({error})") from error
        manifest: dict[str, Any] = data
        return manifest

    def stage_started(self, stage: str, **details: Any) -> None:
        """Records in the manifest that ``stage`` started now, with ``details``."""
        manifest = self.manifest()
        manifest["stages"][stage] = {"started": _now(), "finished": None, **details}
        self._write(manifest)

    def stage_finished(self, stage: str, seconds: float, **details: Any) -> None:
        """Records in the manifest that ``stage`` finished now, after ``seconds``, with ``details``."""
        manifest = self.manifest()
        entry = manifest["stages"].setdefault(stage, {})
        entry.update(finished=_now(), seconds=round(seconds, 3), **details)
        self._write(manifest)

    def stage_restored(self, stage: str, entry: dict[str, Any]) -> None:
        """Put back a stage's earlier entry (a rerun found nothing to do), noting when it checked."""
        manifest = self.manifest()
        manifest["stages"][stage] = {**entry, "checked": _now()}
        self._write(manifest)

    def _write(self, manifest: dict[str, Any]) -> None:
        atomic_write_text(self.manifest_path, json.dumps(manifest, indent=1) + "\n")


def _acquire(handle: Any, path: pathlib.Path) -> None:
    """Lock ``handle``'s file without waiting; a :class:`RunError` naming the holder if taken."""
    if sys.platform == "win32":  # no fcntl: the directory is not locked
        return
    try:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        handle.seek(0)
        holder = handle.read().strip() or "another process"
        raise RunError(f"{path} is in use by {holder}: wait for it to finish, or stop it") from None
