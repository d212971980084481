"""Blender background test: the add-on registers and unregisters cleanly, and
its planning core plans a walk inside Blender's Python.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_addon.py
"""

import math
import os
import pathlib
import sys

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, run  # noqa: E402

ADDON_DIR = os.environ.get("FOOTFALL_ADDON_DIR", str(pathlib.Path(__file__).resolve().parents[2] / "blender_addon"))
sys.path.insert(0, ADDON_DIR)



def test_registers_and_unregisters_cleanly():
    for _ in range(2):
        addon_utils.enable("footfall", default_set=True, handle_error=None)
        check(hasattr(bpy.types, "FOOTFALL_PT_main"), "the panel is not registered")
        addon_utils.disable("footfall", default_set=True, handle_error=None)
        check(not hasattr(bpy.types, "FOOTFALL_PT_main"), "the panel is still registered")


def test_plans_a_walk_inside_blender():
    from footfall.core import native, scenario as sc

    ff = native.load()
    document = sc.scenario_document(
        sc.ScenarioInput(
            agents=[sc.AgentInput("walker", (0.0, 0.5), [(11.0, 0.3)])],
            obstacles=[sc.ObstacleInput(o.polygon, o.height) for o in ff.demo_scenario().obstacles],
        )
    )
    plan = sc.plan(document, "blender-test")
    (walker,) = plan.agents
    check(walker.status == ff.AgentStatus.REACHED, f"not reached: {walker.reason}")
    end = walker.footsteps[-1].com_end
    check(math.dist(end, (11.0, 0.3)) < 1.0, f"ended at {end}")



run([test_registers_and_unregisters_cleanly, test_plans_a_walk_inside_blender])
