# SPDX-License-Identifier: GPL-3.0-or-later
"""What a plan's outcome says to the user: how many agents reached their
goals, and which did not, and why; which cannot reach a goal, and where
their way is too narrow; on ground, how many climb; after a Plan of the
selected agents, which of them overlap others."""

from typing import Collection, Sequence, Tuple

NAMED = 5  # agents named at most; the rest are counted
NOT_THERE = "; not there: "  # where the outcome goes on to name those that did not arrive
CLIMB = 0.02  # [m] footholds further apart in height than this: the agent climbs or goes down


def outcome(agents: Sequence[Tuple[str, bool, str]]) -> str:
    """`agents`: (name, reached, reason) per agent, in the plan's order.
    "3/5 agents reached their goals; not there: 'kid' (stuck), 'bob' (time limit)"."""
    missing = [(name, reason) for name, reached, reason in agents if not reached]
    text = f"{len(agents) - len(missing)}/{len(agents)} agents reached their goals"
    if not missing:
        return text
    return text + NOT_THERE + _listed([f"'{name}' ({reason or 'partial'})" for name, reason in missing])


def unreachable(agents: Sequence[Tuple[str, str]]) -> str:
    """`agents`: (name, what the core says of its narrowest place, str(Narrowest))
    per agent that cannot reach a goal. "; 'big' cannot reach its goal: the
    way at (5.10, 0.00) is 0.52 m wide, its body needs 0.60 m side-stepping"
    for each of the first NAMED (a line of the panel each), then how many
    more; "" for none."""
    lines = [f"'{name}' {said}" for name, said in agents[:NAMED]]
    if len(agents) > NAMED:
        lines.append(f"{len(agents) - NAMED} more cannot reach their goals")
    return "".join("; " + line for line in lines)


def _listed(items: Sequence[str]) -> str:
    """The first NAMED of `items`, then how many more."""
    more = f" and {len(items) - NAMED} more" if len(items) > NAMED else ""
    return ", ".join(items[:NAMED]) + more


def overlapping(agents: Sequence[Tuple[str, int]], planned: Collection[str], rate: float) -> str:
    """`agents`: (name, overlap samples) per agent (measure_plan at `rate`
    Hz); `planned`: the agents planned again among the others' fixed plans.
    "; overlapping others: 'bo' (12 samples at 20 Hz), ...: ..." naming
    those of `planned` that overlap, or "" if none do."""
    found = [(name, count) for name, count in agents if count > 0 and name in planned]
    if not found:
        return ""
    named = _listed([f"'{name}' ({count} samples at {rate:g} Hz)" for name, count in found])
    return (f"; overlapping others: {named}: the agents not selected keep their plans and make way for no "
            "one; plan every agent")


def climbing(spans: Sequence[float]) -> str:
    """`spans`: per agent, how far its highest foothold lies above its
    lowest [m]. "; on ground: 4 of 12 agents climb or go down stairs or
    slopes"."""
    count = sum(span > CLIMB for span in spans)
    return f"; on ground: {count} of {len(spans)} agents climb or go down stairs or slopes"
