# SPDX-License-Identifier: GPL-3.0-or-later
"""bpy <-> plain data: rig import (later: scene extraction, applying plans, export)."""
