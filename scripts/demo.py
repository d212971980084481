"""The built-in demo in Blender: the demo scene (a doorway, and narrow gaps
walked with the arms in and side-stepped), the
project's rig walking it, a rendered picture, the animated crowd as glTF and
the .blend.

Run: blender -b --factory-startup --python scripts/demo.py -- OUT_DIR
Writes OUT_DIR/demo.png, OUT_DIR/demo.glb and OUT_DIR/demo.blend.
"""

import pathlib
import sys

import addon_utils
import bpy
from mathutils import Vector

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "blender_addon"))
OUT = pathlib.Path(sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else ROOT / "out").resolve()


def stage(scene, target: Vector) -> None:
    """Colours, and a camera looking down at `target`."""
    for obj in bpy.data.collections["Footfall Ground"].all_objects:
        obj.color = (0.85, 0.85, 0.82, 1)
    for obj in bpy.data.collections["Footfall Obstacles"].all_objects:
        obj.color = (0.45, 0.55, 0.7, 1)
    for obj in bpy.data.collections["Footfall Crowd"].all_objects:
        obj.color = (0.9, 0.55, 0.3, 1)
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.data.lens = 30
    camera.location = target + Vector((-7.0, -5.0, 14.0))
    camera.rotation_euler = (target - camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(camera)
    scene.camera = camera
    scene.render.engine = "BLENDER_WORKBENCH"
    shading = scene.display.shading
    shading.light, shading.color_type = "STUDIO", "OBJECT"
    shading.show_shadows = shading.show_cavity = True
    scene.render.resolution_x, scene.render.resolution_y = 1280, 720


def _behaviours_time(plan, ff) -> float:
    """A time [s] when one walker holds its arms in while another side-steps
    (the middle of the longest such stretch of arms held in; else half way
    through the side steps), for the picture."""
    def sections(behavior):
        """Each agent's runs of consecutive steps of the behaviour, (start, end)."""
        found = []
        for agent in plan.agents:
            run = None
            for step in agent.footsteps:
                if step.behavior != behavior:
                    run = None
                elif run is None:
                    run = [step.start_time, step.end_time]
                    found.append(run)
                else:
                    run[1] = step.end_time
        return found

    side_steps, arms_in = sections(ff.Behavior.SIDE_STEP), sections(ff.Behavior.ARMS_IN)
    if not side_steps:
        raise SystemExit("demo: nobody side-steps")
    for start, end in sorted(arms_in, key=lambda run: run[0] - run[1]):
        middle = 0.5 * (start + end)
        if any(s <= middle <= e for s, e in side_steps):
            return middle
    return 0.5 * sum(max(side_steps, key=lambda run: run[1] - run[0]))


def check(result, what):
    if "FINISHED" not in result:
        raise SystemExit(f"demo: {what} failed")


def main():
    from footfall.bridge import plan_store, rig_import, scene_build
    from footfall.core import native
    from footfall.core.scenario import document_of

    ff = native.load()
    OUT.mkdir(parents=True, exist_ok=True)
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    scene = bpy.context.scene
    scene_build.build(scene, document_of(ff.demo_scenario()), "demo")
    check(bpy.ops.footfall.import_rig(filepath=str(ROOT / "rigs" / "footfall_humanoid.glb")), "import_rig")
    for rig in rig_import.imported_rigs():  # the template stays out of the picture
        for obj in (rig, *rig.children):
            obj.hide_render = obj.hide_viewport = True
    check(bpy.ops.footfall.plan(), "plan")
    check(bpy.ops.footfall.apply(), "apply")
    stage(scene, Vector((5.5, -5.0, 0.0)))
    scene.frame_set(scene.frame_start + round(_behaviours_time(plan_store.load_plan(), ff) * scene.render.fps))
    scene.render.filepath = str(OUT / "demo.png")
    bpy.ops.render.render(write_still=True)
    check(bpy.ops.footfall.export_gltf(filepath=str(OUT / "demo.glb")), "export_gltf")
    bpy.ops.wm.save_as_mainfile(filepath=str(OUT / "demo.blend"))
    print(f"demo: wrote {OUT / 'demo.png'}, {OUT / 'demo.glb'} and {OUT / 'demo.blend'}")


main()
