"""Progress bars for long stages: tqdm on stderr, shown only on a terminal and unless quiet.

>>> from polymimic.runs.progress import progress
>>> with progress(total=3, desc="trials", quiet=True) as bar:
...     for _ in range(3):
...         _ = bar.update(1)
>>> bar.disable
True
"""

from __future__ import annotations

import sys
from typing import Any


def progress(*, total: int, desc: str, quiet: bool = False) -> Any:
    """A tqdm bar counting to ``total``; hidden when ``quiet`` or stderr is not a terminal."""
    from tqdm import tqdm

    return tqdm(total=total, desc=desc, unit="task", file=sys.stderr, leave=False, dynamic_ncols=True,
                disable=quiet or not sys.stderr.isatty())
