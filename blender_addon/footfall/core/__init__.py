# SPDX-License-Identifier: GPL-3.0-or-later
"""Pure Python, no bpy: loading the planning core, scenario documents, rigs'
bone maps, profiles and dimensions, the parameters and clip timing derived
from them, and glTF files and bone transforms for export."""
