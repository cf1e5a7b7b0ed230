"""The sizes every application's config holds, their meanings and checks written once: how many
learning trials, demonstrations and evaluation attempts (:class:`Sizes`), and how hard a baseline
is tuned (:class:`TuningSizes`).

``reproduce``'s ``[experiments]``, ``benchmark``'s ``[benchmark]`` and ``matrix``'s ``[matrix]``
each embed them with defaults of their own; a file writes their keys flat in that section,
beside the section's own (:func:`polymimic.runs.config.section_table`). A doc's ``{per}`` is what
one learning trial belongs to: an experiment, a crowd's profile, a matrix's cell.

>>> Sizes(trials=8).demonstrations_per_configuration
25
>>> Sizes(trials=8, attempts_per_configuration=5).evaluation_attempts(seed=1000)
Attempts(per_configuration=5, seed=1000, starts=None)
>>> Sizes(trials=0)
Traceback (most recent call last):
...
ValueError: trials = 0 must be at least 1
"""

from __future__ import annotations

import dataclasses

from polymimic._arguments import in_range, whole
from polymimic._toml import documented
from polymimic.evaluation import Attempts

__all__ = ["Sizes", "TuningSizes"]


@dataclasses.dataclass(frozen=True)
class Sizes:
    """How many learning trials a run has, how many demonstrations each demonstrator gives, and
    on how many attempts a policy is evaluated."""

    trials: int = documented("learning trials per {per} (seeds first_trial, first_trial + 1, …)", 20)
    demonstrations_per_configuration: int = documented("valid demonstrations per demonstrator and field "
                                                       "configuration", 25)
    attempts_per_configuration: int = documented("evaluation attempts per evaluated policy and field configuration",
                                                 25)

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            value = whole(field.name, getattr(self, field.name))
            in_range(field.name, value, 1)
            object.__setattr__(self, field.name, value)  # a numpy integer kept as the int it stands for

    def evaluation_attempts(self, *, seed: int) -> Attempts:
        """The attempts every evaluated policy plays: ``attempts_per_configuration`` from each of
        the thesis's two configurations, under the run's evaluation ``seed``."""
        return Attempts(per_configuration=self.attempts_per_configuration, seed=seed)


@dataclasses.dataclass(frozen=True)
class TuningSizes:
    """How hard a baseline is tuned: how many candidates, chosen on how many validation attempts
    (a seed space apart from the evaluation's), each fit on how many decision samples at most."""

    tuning_budget: int = documented("hyperparameter candidates tried per tuned method and {per}", 6)
    validation_attempts_per_configuration: int = documented("validation attempts per field configuration, on which "
                                                            "candidates are chosen (never evaluated; a policy plays "
                                                            "100 in about a second)", 50)
    validation_seed: int = documented("picks the validation attempts, from a seed space apart from the evaluation's",
                                      0)
    # polymimic.baselines.training.MAX_DECISION_SAMPLES, not imported: that would import scikit-learn.
    max_decision_samples: int = documented("the most decision samples a baseline's fit takes (its sample stride "
                                           "widens evenly to stay under it)", 20_000)

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            value = whole(field.name, getattr(self, field.name))
            if field.name == "validation_seed":
                in_range(field.name, value, 0, 2**62 - 1)
            else:
                in_range(field.name, value, 1)
            object.__setattr__(self, field.name, value)
