"""Benchmark: apply a plan of many agents walking for a minute, then bake and
export it, timing each stage; beside it, the core's headless writer on the
same plan (footfall._native.animate_gltf).

Run: blender -b --factory-startup --python bench/blender_crowd.py -- [AGENTS] [SECONDS] [apply-only]
(defaults 200 agents, 60 s at 24 fps, then bake and export), or
... -- --plan PLAN.json [apply-only] for a plan written before (a SteerSuite case's, say).
"""

import pathlib
import sys
import tempfile
import time

import addon_utils
import bpy

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "blender_addon"))
arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
PLAN = None
if arguments[:1] == ["--plan"]:
    PLAN, arguments = pathlib.Path(arguments[1]).resolve(), arguments[2:]
EXPORT = "apply-only" not in arguments
numbers = [a for a in arguments if a != "apply-only"]
AGENTS = int(numbers[0]) if numbers else 200
SECONDS = float(numbers[1]) if len(numbers) > 1 else 60.0
RIG = ROOT / "rigs" / "footfall_humanoid.glb"


def planned_walk(sc):
    """AGENTS agents in rows, each walking straight for about SECONDS (they ignore each other)."""
    distance = 1.3 * SECONDS
    agents = [sc.AgentInput(f"a{i:03d}", (0.0, 2.0 * i), [(distance, 2.0 * i)]) for i in range(AGENTS)]
    document = sc.scenario_document(sc.ScenarioInput(agents, planner={"max_time": SECONDS + 30}))
    begin = time.perf_counter()
    plan = sc.plan(document)
    print(f"planned in {time.perf_counter() - begin:.2f} s", flush=True)
    return plan


def main():
    from footfall.core import native, scenario as sc

    ff = native.load()
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    bpy.ops.footfall.import_rig(filepath=str(RIG))
    folder = pathlib.Path(tempfile.mkdtemp(prefix="footfall-bench-"))
    plan = ff.load_plan(str(PLAN)) if PLAN else planned_walk(sc)
    plan_path = PLAN or folder / "plan.json"
    if not PLAN:
        ff.write_plan_file(plan, str(plan_path))
    longest = max(agent.end_time() for agent in plan.agents)
    print(f"agents {len(plan.agents)}, longest plan {longest:.1f} s", flush=True)
    begin = time.perf_counter()
    ff.animate_gltf(plan, str(RIG), str(folder / "core.glb"), fps=bpy.context.scene.render.fps)
    print(f"core animate_gltf {time.perf_counter() - begin:.2f} s; glb "
          f"{(folder / 'core.glb').stat().st_size / 1e6:.1f} MB", flush=True)
    begin = time.perf_counter()
    bpy.ops.footfall.apply(plan_filepath=str(plan_path))
    applied = time.perf_counter() - begin
    print(f"apply {applied:.2f} s", flush=True)
    if not EXPORT:
        return
    begin = time.perf_counter()
    bpy.ops.footfall.export_gltf(filepath=str(folder / "crowd.glb"))
    exported = time.perf_counter() - begin
    size = (folder / "crowd.glb").stat().st_size / 1e6
    frames = bpy.context.scene.frame_end - bpy.context.scene.frame_start + 1
    print(f"{frames} frames; bake + export {exported:.2f} s; glb {size:.1f} MB", flush=True)


main()
