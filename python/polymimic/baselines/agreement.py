"""How well a labelling from tracker frames alone matches the commands sent: the share of its
labelled frames whose label is the primitive of the command sent there (the privileged labels
of :func:`polymimic.baselines.labels.command_labels`), and the share of frames it labels.

Measured with every frame named, on ten demonstrations of each demonstrator (five per field
configuration, seed 3) and on two crowds (five per member and configuration, crowd seed 0), by
the full benchmark's recogniser (1000 self-observed sequences a primitive, 512 codewords; its
steps leave about 1 % of frames unlabelled, gaps) and the Lego's inverse dynamics model
(:mod:`polymimic.baselines.inverse_dynamics`, which labels every frame; ``python
studies/which_labels_bco_should_learn_from.py``):

========================== ================== ==================
demonstrations             recogniser steps   inverse dynamics
========================== ================== ==================
expert                     84.2 %             92.2 %
poor                       94.7 %             97.0 %
tiny                       77.1 %             81.6 %
humanoid                   64.8 %             65.9 %
``linear`` crowd           75.6 %             92.7 %
``mixed_bodies`` crowd     70.0 %             84.0 %
========================== ================== ==================

>>> import polymimic
>>> from polymimic.baselines.labels import command_labels
>>> demos = polymimic.record("poor", configuration=1, n=2, seed=0)
>>> command_agreement(command_labels(demos), demos)
Agreement(frames=..., agreement=1.0, coverage=1.0)
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np

from polymimic.baselines.labels import NO_LABEL, Labelled, check_demonstrations, command_labels
from polymimic.field import Demonstration

__all__ = ["Agreement", "command_agreement"]


@dataclasses.dataclass(frozen=True)
class Agreement:
    """A labelling against the commands sent.

    Attributes
    ----------
    frames : int
        Frames compared: those both the labelling and the commands label.
    agreement : float
        The share of them whose label is the command's primitive (NaN when there are none).
    coverage : float
        The share of the frames with a command's label that the labelling labels too.
    """

    frames: int
    agreement: float
    coverage: float


def command_agreement(labelled: Sequence[Labelled], demonstrations: Sequence[Demonstration]) -> Agreement:
    """How ``labelled`` (the ``demonstrations`` labelled, in order) agrees with the commands sent
    in them; a ValueError if the two do not pair up frame for frame or the commands were not
    recorded."""
    demos = check_demonstrations(demonstrations)
    if len(labelled) != len(demos):
        raise ValueError(f"labelled holds {len(labelled)} demonstrations; demonstrations holds {len(demos)}")
    sent = command_labels(demos)
    for i, (item, commands) in enumerate(zip(labelled, sent)):
        if len(item.labels) != len(commands.labels):
            raise ValueError(f"labelled[{i}] has {len(item.labels)} frames; demonstrations[{i}] has "
                             f"{len(commands.labels)}")
    named = np.concatenate([item.labels for item in labelled])
    truth = np.concatenate([item.labels for item in sent])
    known = truth != NO_LABEL
    both = known & (named != NO_LABEL)
    agreement = float((named[both] == truth[both]).mean()) if both.any() else float("nan")
    return Agreement(frames=int(both.sum()), agreement=agreement, coverage=float(both.sum() / max(known.sum(), 1)))
