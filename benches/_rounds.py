"""Two rates measured alternately, round after round in one run, and their median ratio: the
machine's drift over a run falls on both alike."""

import statistics


def alternate(rounds, measure_ours, measure_theirs, *, names, unit):
    """Each round ``measure_ours(round_)`` then ``measure_theirs(round_)`` (rates, higher is
    faster), printed as they come; the two median rates and the median ratio."""
    ours, theirs = [], []
    for round_ in range(rounds):
        ours.append(measure_ours(round_))
        theirs.append(measure_theirs(round_))
        print(f"round {round_}: {names[0]} {ours[-1]:8.0f}  {names[1]} {theirs[-1]:8.0f} {unit}  "
              f"ratio {ours[-1] / theirs[-1]:.2f}")
    return statistics.median(ours), statistics.median(theirs), statistics.median(a / b for a, b in zip(ours, theirs))
