# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender classes: panels (and later operators and properties)."""
