# SPDX-License-Identifier: GPL-3.0-or-later
"""bpy <-> plain data: rig import, adding scenarios to the scene and reading
it back, the plan stored in the .blend, applying a plan to rig instances,
and baking and exporting the crowd as glTF."""
