# SPDX-License-Identifier: GPL-3.0-or-later
"""The Blender classes: operators (failing through
operator_errors.report_and_cancel), sidebar panels and scene properties, and
registration.py, which registers them in order."""
