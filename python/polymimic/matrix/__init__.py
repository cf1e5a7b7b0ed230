"""``polymimic matrix``: who learns what from whom — every imitator body against every set of
demonstrators, polymimic and ``bco`` side by side, with the transfer ratio of each cell
(docs/results/matrix.md). The run lives in a directory like every other (:mod:`polymimic.matrix.rundir`), resumes
where it stopped, and writes ``matrix.json``, ``matrix.md`` and ``matrix.html``."""

from polymimic.matrix.config import COLUMNS, MatrixConfig, MatrixSettings

__all__ = ["COLUMNS", "MatrixConfig", "MatrixSettings"]
