# SPDX-License-Identifier: GPL-3.0-or-later
"""What a plan's outcome says to the user: how many agents reached their
goals, and which did not, and why."""

from typing import Sequence, Tuple

NAMED = 5  # agents named at most; the rest are counted
NOT_THERE = "; not there: "  # where the outcome goes on to name those that did not arrive


def outcome(agents: Sequence[Tuple[str, bool, str]]) -> str:
    """`agents`: (name, reached, reason) per agent, in the plan's order.
    "3/5 agents reached their goals; not there: 'kid' (stuck), 'bob' (time limit)"."""
    missing = [(name, reason) for name, reached, reason in agents if not reached]
    text = f"{len(agents) - len(missing)}/{len(agents)} agents reached their goals"
    if not missing:
        return text
    named = ", ".join(f"'{name}' ({reason or 'partial'})" for name, reason in missing[:NAMED])
    more = f" and {len(missing) - NAMED} more" if len(missing) > NAMED else ""
    return f"{text}{NOT_THERE}{named}{more}"
