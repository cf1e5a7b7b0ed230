"""What goes wrong with a tracker log: one exception for bad input, one warning for episodes lost."""

from __future__ import annotations

__all__ = ["LostTrackingWarning", "TrackLogError"]


class TrackLogError(ValueError):
    """A tracker log that cannot be read as it is declared; the message names the file, the row
    (counted from 1 among the data rows; a CSV's line beside it) or episode, and the column."""


class LostTrackingWarning(UserWarning):
    """Some episodes of a log were not imported: tracking was lost in them (thesis §3.2.1)."""
