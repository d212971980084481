"""Blender background test: the zips scripts/package.sh makes install into a
fresh Blender (the legacy add-on on 3.4, the extension from 4.2 on) and plan
and animate a walk from there, not from the source folder.

Run with BLENDER_USER_RESOURCES set to an empty folder (ctest does), so that
the install goes there and not into the user's Blender.
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-package-"))
EXTENSIONS = bpy.app.version >= (4, 2, 0)


def installed_module():
    """Installs the zip for this Blender; the name of the module it enables."""
    resources = os.environ.get("BLENDER_USER_RESOURCES", "")
    check(resources and pathlib.Path(bpy.utils.user_resource("SCRIPTS")).is_relative_to(resources),
          "BLENDER_USER_RESOURCES must name a scratch folder for this test")
    subprocess.run(["bash", str(ROOT / "scripts" / "package.sh"), str(TMP)], check=True)
    kind = "extension" if EXTENSIONS else "addon"
    (package,) = TMP.glob(f"footfall-*-{kind}.zip")
    bpy.ops.wm.read_homefile(use_empty=True)
    if EXTENSIONS:
        result = bpy.ops.extensions.package_install_files(filepath=str(package), repo="user_default",
                                                          enable_on_install=True)
        check(result == {"FINISHED"}, f"the extension did not install: {result}")
        return "bl_ext.user_default.footfall"
    check(bpy.ops.preferences.addon_install(filepath=str(package)) == {"FINISHED"}, "the add-on did not install")
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    return "footfall"


def test_the_package_installs_and_plans_a_walk():
    module = installed_module()
    loaded = sys.modules.get(module)
    check(loaded is not None, f"{module} is not enabled")
    where = pathlib.Path(loaded.__file__).resolve()
    check(where.is_relative_to(pathlib.Path(os.environ["BLENDER_USER_RESOURCES"]).resolve()),
          f"the add-on runs from {where}, not from the installed package")
    scenario = TMP / "walk.json"
    scenario.write_text(json.dumps({"format": "footfall-scenario", "version": 1,
                                    "agents": [{"name": "ann", "position": [0, 0], "goals": [[4, 1]]}]}))
    check(bpy.ops.footfall.load_scenario(filepath=str(scenario)) == {"FINISHED"}, "load failed")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    rig = ROOT / "rigs" / "footfall_humanoid.glb"
    check(bpy.ops.footfall.import_rig(filepath=str(rig)) == {"FINISHED"}, "import_rig failed")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    check(bpy.data.objects["ann"].type == "ARMATURE", "no instance named 'ann'")


run([test_the_package_installs_and_plans_a_walk])
