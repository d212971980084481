# SPDX-License-Identifier: GPL-3.0-or-later
"""Loads the compiled planning core, with an error that says how to get it."""

import sys


class CoreMissingError(ImportError):
    """The compiled module ``footfall._native`` cannot be imported."""


def load():
    """Returns the ``footfall._native`` module.

    Raises CoreMissingError naming the Python version it must be built for
    when the module is missing or was built for another interpreter.
    """
    try:
        # Relative, so that it also works as a Blender 4.2+ extension
        # (package bl_ext.<repository>.footfall).
        from .. import _native
    except ImportError as error:
        version = "%d.%d" % sys.version_info[:2]
        raise CoreMissingError(
            "Footfall's planning core (footfall/_native) is not built for this "
            f"Python {version}: run the set-up command in Footfall's README ({error})"
        ) from error
    return _native


def status():
    """A one-line description of the core for the user interface."""
    try:
        return f"Planning core {load().__version__}"
    except CoreMissingError as error:
        return str(error)
