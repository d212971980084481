# SPDX-License-Identifier: GPL-3.0-or-later
"""Pure Python, no bpy: loading the planning core, building scenarios."""
