# SPDX-License-Identifier: GPL-3.0-or-later
"""How a Footfall operator fails: it reports the error and cancels.

The bridge functions the operators call have already removed whatever the
failed attempt created; returning {"CANCELLED"} also keeps Blender from
pushing an undo step for it.
"""


def report_and_cancel(operator, error):
    """Reports `error` on `operator` as an ERROR and returns {"CANCELLED"},
    for the operator's ``execute`` to return."""
    operator.report({"ERROR"}, str(error))
    return {"CANCELLED"}
