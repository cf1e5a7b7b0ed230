"""Tracker logs: your own overhead tracker's readings imported as demonstrations, and
demonstrations written as tracker logs (docs/guides/own-data.md).

A log is a CSV or Parquet table, one row per reading: time, the robot's x, y and heading, the
ball's x and y, and optionally the episode, its outcome, the command sent and the field
configuration. Units and column names are declared on import; readings are resampled to
polymimic's 30 frames a second.

Examples
--------
>>> import pathlib, tempfile, polymimic
>>> log = pathlib.Path(tempfile.mkdtemp()) / "tiny.parquet"
>>> write_tracks(polymimic.record("tiny", configuration=2, n=2, seed=4), log, rate_hz=50, include=())
>>> imported = import_tracks(log, demonstrator="citizen", body="tiny")
>>> imported.summary()
'2 episodes from tiny.parquet: 2 demonstrations, 0 invalid'
>>> [d.configuration for d in imported.demonstrations]
[2, 2]
"""

from polymimic.tracks.errors import LostTrackingWarning, TrackLogError
from polymimic.tracks.importing import ImportedTracks, import_tracks
from polymimic.tracks.writing import write_tracks

__all__ = ["ImportedTracks", "LostTrackingWarning", "TrackLogError", "import_tracks", "write_tracks"]
