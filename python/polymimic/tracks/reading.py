"""Reading a tracker log (CSV or Parquet) into columns in polymimic's units, with every bad
value named by file, row and column."""

from __future__ import annotations

import csv
import dataclasses
import os
from collections.abc import Collection, Mapping
from typing import Any

import numpy as np

from polymimic.tracks.errors import TrackLogError
from polymimic.tracks.units import (
    OPTIONAL,
    REQUIRED,
    Units,
    checked_columns,
    default_name,
    factor,
    no_such_column,
)

__all__ = ["Log", "read_log"]

SUFFIXES = (".csv", ".parquet")


@dataclasses.dataclass(frozen=True)
class Log:
    """A log's columns by polymimic's names.

    ``measured`` holds the required columns as floats in mm, rad and s (NaN where the tracker
    saw nothing); ``labels`` the optional columns the file has, as read (``None`` where empty).
    Row ``i`` of every column is the file's data row ``i + 1``.
    """

    path: str
    is_csv: bool
    file_names: dict[str, str]
    measured: dict[str, np.ndarray]
    labels: dict[str, list[Any]]

    @property
    def n_rows(self) -> int:
        """Readings in the log."""
        return len(self.measured["t"])

    def where(self, row: int, name: str | None = None) -> str:
        """``path: data row N (line M)[, column 'c']`` for row index ``row`` (from 0)."""
        line = f" (line {row + 2})" if self.is_csv else ""
        column = f", column {self.file_names[name]!r}" if name is not None else ""
        return f"{self.path}: data row {row + 1}{line}{column}"


def read_log(path: str | os.PathLike[str], *, columns: Mapping[str, str] | None, units: Units,
             ignore: Collection[str] = ()) -> Log:
    """The log at ``path``, its columns found by ``columns`` (polymimic's name → the file's)
    or by their default names, converted from ``units``; ``ignore`` names file columns to skip."""
    where = os.fspath(path)
    suffix = os.path.splitext(where)[1].lower()
    if suffix not in SUFFIXES:
        kind = suffix or "a file without an extension"
        raise TrackLogError(f"{where}: a tracker log is a .csv or a .parquet file, not {kind}")
    if not os.path.exists(where):
        raise FileNotFoundError(2, "no such tracker log", where)
    if os.path.isdir(where):
        raise IsADirectoryError(21, "expected a tracker log file, got a directory", where)
    found, raw = _read_csv(where) if suffix == ".csv" else _read_parquet(where)
    names = _match_columns(where, found, checked_columns(columns), units, ignore)
    log = Log(path=where, is_csv=suffix == ".csv", file_names=names, measured={}, labels={})
    n_rows = len(raw[found[0]]) if found else 0
    if n_rows == 0:
        raise TrackLogError(f"{where}: the log has columns but no data rows")
    for name in REQUIRED:
        log.measured[name] = _numbers(log, name, raw[names[name]]) * factor(name, units)
    for name in OPTIONAL:
        if name in names:
            log.labels[name] = _labels(raw[names[name]])
    return log


def _read_csv(where: str) -> tuple[list[str], dict[str, Any]]:
    import pyarrow as pa
    import pyarrow.csv as pacsv

    try:
        with open(where, newline="", encoding="utf-8-sig") as handle:  # as Arrow, past a byte-order mark
            header = next(csv.reader(handle), None)
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise TrackLogError(f"{where} is not a readable CSV file ({error})") from error
    if header is None or not any(h.strip() for h in header):
        raise TrackLogError(f"{where} is empty: a tracker log needs a header row and data rows")
    duplicated = sorted({h for h in header if header.count(h) > 1})
    if duplicated:
        raise TrackLogError(f"{where}: the header names column(s) {', '.join(map(repr, duplicated))} more than once")
    # Every column read as text, so that a value that is not a number is reported, not guessed.
    options = pacsv.ConvertOptions(column_types={h: pa.string() for h in header}, strings_can_be_null=True)
    try:
        table = pacsv.read_csv(where, convert_options=options)
    except (pa.ArrowException, OSError) as error:
        raise TrackLogError(f"{where} is not a readable CSV file ({error})") from error
    return list(table.column_names), {name: table.column(name).to_pylist() for name in table.column_names}


def _read_parquet(where: str) -> tuple[list[str], dict[str, Any]]:
    import pyarrow as pa
    import pyarrow.parquet as pq

    try:
        table = pq.read_table(where)
    except (pa.ArrowException, OSError) as error:
        raise TrackLogError(f"{where} is not a readable Parquet file ({error})") from error
    if not table.column_names:
        raise TrackLogError(f"{where} is empty: it has no columns")
    raw: dict[str, Any] = {}
    for name in table.column_names:
        column = table.column(name)
        kind = column.type
        if pa.types.is_integer(kind) or pa.types.is_floating(kind):
            values = column.to_numpy(zero_copy_only=False)
            raw[name] = values if column.null_count == 0 else column.to_pylist()
        elif pa.types.is_string(kind) or pa.types.is_large_string(kind) or pa.types.is_dictionary(kind):
            raw[name] = column.to_pylist()
        else:
            raw[name] = _Unsupported(str(kind), column.to_pylist())
    return list(table.column_names), raw


@dataclasses.dataclass(frozen=True)
class _Unsupported:
    """A Parquet column of a type that holds neither numbers nor text (a date, a list)."""

    kind: str
    values: list[Any]

    def __len__(self) -> int:
        return len(self.values)


def _match_columns(where: str, found: list[str], columns: dict[str, str], units: Units,
                   ignore: Collection[str]) -> dict[str, str]:
    """polymimic's name → the file's, for every column the file has; unknown columns refused."""
    if isinstance(ignore, str):
        ignore = (ignore,)
    not_there = [name for name in ignore if name not in found]
    if not_there:
        raise TrackLogError(f"{where}: ignore= names {', '.join(map(repr, not_there))}, which the file does not "
                            f"have; it has {', '.join(map(repr, found))}")
    names: dict[str, str] = {}
    for name in REQUIRED + OPTIONAL:
        if name in columns:
            if columns[name] not in found:
                raise TrackLogError(f"{where}: columns maps {name!r} to {columns[name]!r}, which the file does not "
                                    f"have; it has {', '.join(map(repr, found))}")
            names[name] = columns[name]
            continue
        for candidate in dict.fromkeys((default_name(name, units), name)):
            if candidate in found and candidate not in columns.values():
                names[name] = candidate
                break
    missing = [name for name in REQUIRED if name not in names]
    if missing:
        raise no_such_column(where, missing, {n: columns.get(n, default_name(n, units)) for n in missing}, found,
                             units)
    used = set(names.values()) | set(ignore)
    extra = [name for name in found if name not in used]
    if extra:
        allowed = ", ".join(default_name(n, units) for n in REQUIRED + OPTIONAL)
        raise TrackLogError(f"{where}: unknown column(s) {', '.join(map(repr, extra))}; a log has {allowed} "
                            f"(or the names given with columns=); skip others with ignore=[...]")
    return names


def _numbers(log: Log, name: str, values: Any) -> np.ndarray:
    """A column as floats (NaN where empty); an error naming the first value that is not a
    number, or an infinite one."""
    if isinstance(values, _Unsupported):
        raise TrackLogError(f"{log.path}: column {log.file_names[name]!r} holds {values.kind}; expected numbers")
    if isinstance(values, np.ndarray):
        numbers = values.astype(np.float64)
    else:
        numbers = np.full(len(values), np.nan)
        for row, value in enumerate(values):
            if value is None:
                continue
            try:
                numbers[row] = float(value)
            except (TypeError, ValueError):
                raise TrackLogError(f"{log.where(row, name)}: {value!r} is not a number") from None
    infinite = np.flatnonzero(np.isinf(numbers))
    if infinite.size:
        row = int(infinite[0])
        raise TrackLogError(f"{log.where(row, name)}: {numbers[row]} is not a finite number")
    return numbers


def _labels(values: Any) -> list[Any]:
    if isinstance(values, _Unsupported):
        return values.values
    if isinstance(values, np.ndarray):
        listed: list[Any] = values.tolist()
        return listed
    return list(values)
