"""Blender background test: footfall.apply animates rig instances that walk
exactly on the plan.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_apply.py
"""

import json
import math
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from foot_contact import plan_errors  # noqa: E402
from harness import check, expect_valid_gltf, run  # noqa: E402
import mathutils
import numpy

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-apply-"))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"



def fresh_scene_with_rig():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")


def doorway_plan(ff):
    """Three agents through a 1.2 m doorway, planned with the rig's parameters, as a plan file."""
    from footfall.core import character, scenario as sc

    c, p = character.derive_parameters(imported_rig()[1].dimensions)
    walls = [sc.ObstacleInput(o.polygon, o.height) for o in ff.wall_with_door(4.0, 1.2)]
    # Goals far enough apart for all three to stand at them.
    agents = [sc.AgentInput("ann", (0, 0.2), [(8, 0.7)]), sc.AgentInput("bob", (-1.5, -0.4), [(8, -0.5)]),
              sc.AgentInput("cy", (-3, 0.5), [(7, 0.1)])]
    plan = sc.plan(sc.scenario_document(sc.ScenarioInput(agents, walls, c, p)))
    check(all(a.status == ff.AgentStatus.REACHED for a in plan.agents), "not every agent reached")
    path = TMP / "doorway-plan.json"
    ff.write_plan_file(plan, str(path))
    return plan, path


def applied(make_plan):
    """A fresh scene with the rig, the plan `make_plan(ff)` made and applied: (ff, plan, plan file)."""
    from footfall.core import native

    ff = native.load()
    fresh_scene_with_rig()
    plan, path = make_plan(ff)
    check(bpy.ops.footfall.apply(plan_filepath=str(path)) == {"FINISHED"}, "apply failed")
    return ff, plan, path


def demo_applied():
    """The README's demo, planned and applied in Blender as scripts/demo.py
    does: (ff, plan)."""
    from footfall.bridge import plan_store, scene_build
    from footfall.core import native
    from footfall.core.scenario import document_of

    ff = native.load()
    fresh_scene_with_rig()
    scene_build.build(bpy.context.scene, document_of(ff.demo_scenario()), "demo")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    return ff, plan_store.load_plan()


def imported_rig():
    """The rig imported with Footfall, and its profile."""
    from footfall.bridge import rig_import

    (rig,) = rig_import.imported_rigs()
    return rig, rig_import.profile_of(rig)


def evaluated(name):
    return bpy.data.objects[name].evaluated_get(bpy.context.evaluated_depsgraph_get())


def test_feet_and_pelvis_follow_the_plan():
    ff, plan, path = applied(doorway_plan)
    worst_foot, worst_pelvis, stance_frames = plan_errors(ff, plan, *imported_rig())
    check(stance_frames > 300, f"only {stance_frames} stance samples")
    check(worst_foot <= 0.002, f"a planted foot is {worst_foot * 1000:.2f} mm off the plan")
    check(worst_pelvis <= 0.02, f"the pelvis is {worst_pelvis * 100:.2f} cm off the COM")


def test_on_the_demo_no_stance_foot_moves():
    # On the demo every foot the plan has planted stays within 2 mm of its place at every
    # frame, from the first instant of its stance to the last (the start of a
    # walk from standing no longer slides it in), and the COM moves without
    # a jump in its velocity.
    ff, plan = demo_applied()
    for agent in plan.agents:
        motion = ff.check_motion(agent)
        check(motion.velocity_jump < 1e-3, f"{agent.name}: the velocity jumps by {motion.velocity_jump:.3f} m/s")
        check(motion.stance_slide < 1e-6, f"{agent.name}: a stance foot moves {motion.stance_slide * 1000:.3f} mm")
    starts = sum(s.kind == ff.StepKind.START for a in plan.agents for s in a.footsteps)
    check(starts > 0, "no walk from standing needed a start")
    worst_foot, _, stance_frames = plan_errors(ff, plan, *imported_rig())
    check(stance_frames > 1000, f"only {stance_frames} stance samples")
    check(worst_foot <= 0.002, f"a planted foot is {worst_foot * 1000:.2f} mm off the plan")


def test_feet_roll_from_heel_to_toe():
    """At full speed a foot strikes with its toes up, is flat in mid-stance,
    and leaves with its heel up and its toes bent (footfall.core.foot_roll)."""
    from footfall.core import foot_roll

    ff, plan, path = applied(doorway_plan)
    rig, profile = imported_rig()
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    agent = plan.agents[0]

    def angles(step, u):
        """The foot's pitch and the toe's bend from rest [deg], a share u into `step`."""
        t = step.start_time + u * (step.end_time - step.start_time)
        frame = scene.frame_start + t * fps
        scene.frame_set(int(frame), subframe=frame % 1)
        armature = evaluated(agent.name)
        side = step.foot.name.lower()
        found = []
        for data in (rig.data, None):
            bones = {r: (data.bones[profile.bones[side][r]] if data else armature.pose.bones[profile.bones[side][r]])
                     for r in ("foot", "toe")}
            world = rig.matrix_world if data else armature.matrix_world
            ends = {r: (world @ (b.head_local if data else b.head), world @ (b.tail_local if data else b.tail))
                    for r, b in bones.items()}
            foot, toe = (ends[r][1] - ends[r][0] for r in ("foot", "toe"))
            found.append((math.atan2(foot.z, foot.xy.length), foot.angle(toe)))
        (pitch, bend), (rest_pitch, rest_bend) = found[1], found[0]
        return math.degrees(pitch - rest_pitch), math.degrees(bend - rest_bend)

    walks = [s for s in agent.footsteps if s.kind == ff.StepKind.WALK]
    checked = 0
    for before, step, after in zip(walks, walks[1:], walks[2:]):
        full = math.dist(step.com_start, step.com_end) / (step.end_time - step.start_time) >= 1.2
        if not full or before.end_time != step.start_time or after.start_time != step.end_time:
            continue
        strike, _ = angles(step, 0.02)
        flat, flat_bend = angles(step, 0.4)
        off, off_bend = angles(step, 0.98)
        print(f"step at {step.start_time:.2f} s: pitch {strike:.1f} / {flat:.1f} / {off:.1f} deg, toe bend {off_bend:.1f}")
        check(strike > 0.6 * math.degrees(foot_roll.HEEL_STRIKE), f"toes not up at heel strike: {strike:.1f} deg")
        check(abs(flat) < 0.5 and abs(flat_bend) < 0.5, f"not flat in mid-stance: {flat:.1f}, {flat_bend:.1f} deg")
        check(off < -0.6 * math.degrees(foot_roll.TOE_OFF), f"heel not up at toe-off: {off:.1f} deg")
        check(abs(off_bend + off) < 1.0, f"the toe does not stay flat: bent {off_bend:.1f} deg at {off:.1f} deg")
        checked += 1
    check(checked >= 3, f"only {checked} full-speed steps checked")


def hands_ahead(armature, profile, hips_rest):
    """How far each hand (its tail) is ahead of the hips, in the body's frame. [m]"""
    hips = armature.pose.bones[profile.bones["hips"]]
    body = (armature.matrix_world @ hips.matrix @ hips_rest.inverted()).inverted()
    ahead = {}
    for side in ("left", "right"):
        hand = armature.pose.bones[profile.bones[side]["hand"]]
        ahead[side] = -(body @ (armature.matrix_world @ hand.tail)).y  # the rig faces -Y at rest
    return ahead


def yaw_of(armature, bone: str) -> float:
    """The world yaw [rad] of the bone's rest facing (-Y, the rig's) as posed."""
    posed = armature.matrix_world @ armature.pose.bones[bone].matrix @ armature.data.bones[bone].matrix_local.inverted()
    forward = posed.to_3x3() @ mathutils.Vector((0.0, -1.0, 0.0))
    return math.atan2(forward.y, forward.x)


def straight_walk_plan(gaits: slice):
    """A plan maker: one agent walking 10 m straight with the rig's gaits[gaits]."""
    def make(ff):
        from footfall.core import character, scenario as sc

        c, p = character.derive_parameters(imported_rig()[1].dimensions)
        p["gaits"] = p["gaits"][gaits]
        plan = sc.plan(sc.scenario_document(sc.ScenarioInput([sc.AgentInput("amble", (0, 0), [(10, 0)])], [], c, p)))
        path = TMP / "straight-plan.json"
        ff.write_plan_file(plan, str(path))
        return plan, path
    return make


def swing_amplitudes(ff, plan):
    """Per pair of walking steps in the middle of the one agent's walk: (the
    mean share of the walking clip's amplitude ff.upper_body gives it, half
    the range of the left hand's lead over the right). [m]"""
    rig, profile = imported_rig()
    hips_rest = rig.data.bones[profile.bones["hips"]].matrix_local
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    (agent,) = plan.agents
    frames = numpy.arange(scene.frame_start, scene.frame_end + 1)
    times = numpy.minimum((frames - scene.frame_start) / fps, agent.end_time())
    _, swing, _, _ = ff.upper_body(agent, times, (agent.character or plan.character).preferred_speed)
    lead = []
    for frame in frames:
        scene.frame_set(int(frame))
        ahead = hands_ahead(evaluated(agent.name), profile, hips_rest)
        lead.append(ahead["left"] - ahead["right"])
    lead = numpy.array(lead)
    walks = [s for s in agent.footsteps if s.kind == ff.StepKind.WALK]
    result = []
    for first, second in zip(walks[2:-3], walks[3:-2]):  # past the set-off, before the stop
        inside = (times >= first.start_time) & (times <= second.end_time)
        result.append((swing[inside].mean(), 0.5 * (lead[inside].max() - lead[inside].min())))
    return result


def test_arms_swing_as_far_as_the_steps_are_fast():
    """The walking clip plays at the share of its amplitude the step's speed
    gives: a walk in the slowest gait swings the arms less, in proportion."""
    measured = {}
    for name, gaits in (("full", slice(None)), ("slow", slice(0, 1))):
        ff, plan, path = applied(straight_walk_plan(gaits))
        pairs = swing_amplitudes(ff, plan)
        check(len(pairs) >= 4, f"{name}: only {len(pairs)} pairs of steps measured")
        measured[name] = numpy.array(pairs).mean(axis=0)
        print(f"{name} gaits: swing share {measured[name][0]:.2f}, hands' amplitude {measured[name][1] * 100:.1f} cm")
    share = measured["slow"][0] / measured["full"][0]
    amplitude = measured["slow"][1] / measured["full"][1]
    check(share < 0.6, f"the slow walk's share of the swing is {share:.2f} of the full one's")
    check(abs(amplitude - share) < 0.1, f"the hands swing {amplitude:.2f} as far at {share:.2f} of the share")


def test_the_head_and_chest_look_into_a_turn():
    """On the demo the head turns from the hips by the look angle's share
    (the chest's and its own) and the chest's twist at every frame, and
    ahead of every turn of the body that walks (at half its preferred speed
    or more) the head is already turned that way; standing, the body turns
    whole, in its pivots."""
    ff, plan = demo_applied()
    rig, profile = imported_rig()
    shares = ff.LOOK_SHARES["chest"] + ff.LOOK_SHARES["head"]
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    frames = numpy.arange(scene.frame_start, scene.frame_end + 1)
    worst, most, leads, turns = 0.0, 0.0, 0, 0
    looks = {}
    for agent in plan.agents:
        times = numpy.minimum((frames - scene.frame_start) / fps, agent.end_time())
        looks[agent.name] = ff.upper_body(agent, times, (agent.character or plan.character).preferred_speed)
    for i, frame in enumerate(frames):
        scene.frame_set(int(frame))
        for agent in plan.agents:
            facing, _, look, twist = looks[agent.name]
            armature = evaluated(agent.name)
            turned = math.remainder(yaw_of(armature, profile.bones["head"]) - yaw_of(armature, profile.bones["hips"])
                                    - twist[i], math.tau)
            worst = max(worst, abs(turned - shares * look[i]))
            most = max(most, abs(look[i]))
            ahead = facing[min(i + round(0.4 * fps), len(frames) - 1)]  # the body's facing 0.4 s later
            coming = math.remainder(ahead - facing[i], math.tau)
            speed = math.hypot(*ff.com_at(agent, min((frame - scene.frame_start) / fps, agent.end_time())).velocity)
            walking = speed >= 0.5 * (agent.character or plan.character).preferred_speed
            if walking and abs(coming) > math.radians(10):
                turns += 1
                leads += turned * coming > 0 and abs(turned) > math.radians(2)
    print(f"head from the hips: at most {math.degrees(worst):.2f} degrees off its share of the look; "
          f"look up to {math.degrees(most):.1f} degrees; the head leads {leads} of {turns} frames before a turn")
    check(most > math.radians(10), f"the demo's looks reach only {math.degrees(most):.1f} degrees")
    check(worst < math.radians(3), f"the head is {math.degrees(worst):.1f} degrees off its share of the look")
    check(turns > 10 and leads == turns, f"the head leads the body into {leads} of {turns} frames of turns")


def test_arms_swing_opposite_to_the_legs():
    """At each right heel strike of a walk the left hand is ahead of the right, and the other way round."""

    ff, plan, path = applied(doorway_plan)
    rig, profile = imported_rig()
    hips_rest = rig.data.bones[profile.bones["hips"]].matrix_local
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    agent = plan.agents[0]
    walks = [s for s in agent.footsteps if s.kind == ff.StepKind.WALK][2:-2]  # past the start, before the stop
    checked = 0
    for step in walks:
        frame = scene.frame_start + step.start_time * fps
        scene.frame_set(int(frame), subframe=frame % 1)
        ahead = hands_ahead(evaluated(agent.name), profile, hips_rest)
        leading = "left" if step.foot == ff.Foot.RIGHT else "right"
        other = "right" if leading == "left" else "left"
        check(ahead[leading] > ahead[other] + 0.05,
              f"at the {step.foot.name.lower()} heel strike at {step.start_time:.2f} s the {leading} hand is not ahead: {ahead}")
        checked += 1
    check(checked >= 8, f"only {checked} heel strikes checked")


def test_applying_again_replaces_the_crowd():
    from footfall.bridge import animate
    from footfall.core import native

    ff = native.load()
    fresh_scene_with_rig()
    plan, path = doorway_plan(ff)
    for _ in range(2):
        check(bpy.ops.footfall.apply(plan_filepath=str(path)) == {"FINISHED"}, "apply failed")
    crowd = bpy.data.collections[animate.CROWD_COLLECTION]
    names = sorted(o.name for o in crowd.objects if o.type == "ARMATURE")
    check(names == sorted(a.name for a in plan.agents), f"agents after a second apply: {names}")
    check(len(crowd.objects) == 2 * len(plan.agents), f"{len(crowd.objects)} objects in the crowd")
    locomotion = [a for a in bpy.data.actions if a.name.endswith("locomotion")]
    check(len(locomotion) == len(plan.agents), f"{len(locomotion)} locomotion actions")
    check(not [o for o in bpy.data.objects if "(replaced)" in o.name], "replaced agents were left")


def select_only(*objects):
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in objects)


def test_replanning_the_selected_agents_updates_only_their_rigs():
    """plan(selected_only=True) plans the selected agents again among the
    others' stored plans, which stay as they were; the next apply() makes
    their rigs again and keeps the others'. With none selected, or an agent
    the stored plan lacks left out, it refuses and changes nothing."""
    from footfall.bridge import animate, plan_store, scene_build

    fresh_scene_with_rig()
    scene = bpy.context.scene
    scene_build.build(scene, {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[8, 0]]},
        {"name": "bob", "position": [4, -4], "goals": [[4, 4]]},
        {"name": "cy", "position": [0, 3], "goals": [[8, 3]]}]}, "three")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    before = {a["name"]: a for a in json.loads(plan_store.load())["agents"]}
    crowd = bpy.data.collections[animate.CROWD_COLLECTION]
    rigs = {o.name: o.as_pointer() for o in crowd.objects if o.type == "ARMATURE"}

    bpy.data.objects["ann goal 1"].matrix_world = mathutils.Matrix.Translation((8, 1, 0))
    select_only(bpy.data.objects["ann goal 1"])  # her goal stands for her
    check(bpy.ops.footfall.plan(selected_only=True) == {"FINISHED"}, "plan of the selected failed")
    after = {a["name"]: a for a in json.loads(plan_store.load())["agents"]}
    check(after["bob"] == before["bob"] and after["cy"] == before["cy"], "the others' plans changed")
    ann_end = after["ann"]["footsteps"]["com_end"][-1]
    check(abs(ann_end[1] - 1) < 0.25 and abs(before["ann"]["footsteps"]["com_end"][-1][1]) < 0.25,
          f"ann was not planned to her new goal: she ends at {ann_end}")
    check(plan_store.pending(scene) == ["ann"], f"pending: {plan_store.pending(scene)}")

    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    now = {o.name: o.as_pointer() for o in crowd.objects if o.type == "ARMATURE"}
    check(sorted(now) == ["ann", "bob", "cy"], f"armatures: {sorted(now)}")
    check(now["bob"] == rigs["bob"] and now["cy"] == rigs["cy"], "the others' rigs were made again")
    check(now["ann"] != rigs["ann"], "ann's rig was not made again")
    check(not [o for o in bpy.data.objects if "(replaced)" in o.name], "replaced objects were left")
    check(len([a for a in bpy.data.actions if a.name.endswith("locomotion")]) == 3, "locomotion actions")
    scene.frame_set(scene.frame_end)
    hips = evaluated("ann").matrix_world @ evaluated("ann").pose.bones[imported_rig()[1].bones["hips"]].head
    check(math.dist(hips.xy, ann_end) < 0.15, f"ann's hips end at {tuple(hips.xy)}, her plan at {ann_end}")
    check(plan_store.pending(scene) == [], f"pending after apply: {plan_store.pending(scene)}")

    stored = plan_store.load()
    select_only()
    expect_error(bpy.ops.footfall.plan, "No agents selected", selected_only=True)
    new = bpy.data.objects.new("dee", None)
    new.location = (0, -3, 0)
    bpy.data.collections["Footfall Agents"].objects.link(new)
    goal = bpy.data.objects.new("dee goal", None)
    goal.parent, goal.location = new, (0, -2, 0)
    bpy.data.collections["Footfall Agents"].objects.link(goal)
    select_only(bpy.data.objects["ann (agent)"])
    expect_error(bpy.ops.footfall.plan, "the stored plan has no plan for agent 'dee'", selected_only=True)
    check(plan_store.load() == stored and plan_store.pending(scene) == [], "a refused plan changed the stored one")


def glb_json(path):
    """The JSON chunk of a .glb file."""
    import struct

    data = pathlib.Path(path).read_bytes()
    length, kind = struct.unpack_from("<I4s", data, 12)
    check(kind == b"JSON", "not a GLB file")
    return json.loads(data[20:20 + length])


def bones_now(names, bones):
    """World positions of the heads and tails of every agent's `bones` at the current frame."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    result = {}
    for name in names:
        armature = bpy.data.objects[name].evaluated_get(depsgraph)
        for bone in bones:
            pose = armature.pose.bones[bone]
            result[(name, bone, "head")] = armature.matrix_world @ pose.head
            result[(name, bone, "tail")] = armature.matrix_world @ pose.tail
    return result


def exported_and_reimported(plan, out, before_export=None):
    """Exports the applied crowd to `out` (after `before_export()`, if given),
    validates it, re-imports it into an empty scene and returns how far every
    bone's head (a glTF joint; tails are the importer's guess) then is from
    where it was, at every fifth frame [m]."""
    rig, _profile = imported_rig()
    body_bones = [bone.name for bone in rig.data.bones]
    names = [agent.name for agent in plan.agents]
    scene = bpy.context.scene
    expected = {}
    for frame in range(scene.frame_start, scene.frame_end + 1, 5):
        scene.frame_set(frame)
        expected[frame] = bones_now(names, body_bones)
    if before_export:
        before_export()
    objects_before = sorted(o.name for o in bpy.data.objects)
    check(bpy.ops.footfall.export_gltf(filepath=str(out)) == {"FINISHED"}, "export failed")
    check(sorted(o.name for o in bpy.data.objects) == objects_before, "the export changed the scene")
    check(not pathlib.Path(str(out) + ".partial.glb").exists(), "a partial file was left")
    expect_valid_gltf(out)
    gltf = glb_json(out)
    check(sorted(a["name"] for a in gltf["animations"]) == sorted(names), [a["name"] for a in gltf["animations"]])

    bpy.ops.wm.read_homefile(use_empty=True)
    import numpy

    if "bool" not in numpy.__dict__:
        numpy.bool = bool  # Debian's Blender 3.4 importer
    bpy.ops.import_scene.gltf(filepath=str(out))
    for name in names:
        data = bpy.data.objects[name].animation_data
        if data.action is None:  # the importer may leave the animation on an NLA track
            data.action = data.nla_tracks[0].strips[0].action
        for track in data.nla_tracks:
            track.mute = True
    worst = 0.0
    for frame, feet in expected.items():
        bpy.context.scene.frame_set(frame)
        for key, position in bones_now(names, body_bones).items():
            if key[2] == "head":
                worst = max(worst, (position - feet[key]).length)
    print(f"re-imported joints (every bone's head): worst {worst * 1000:.2f} mm off")
    return worst


def test_export_validates_and_reimports():
    ff, plan, path = applied(doorway_plan)

    def a_failed_export_first():
        """Into a folder that does not exist: a clear error, and the scene as it was."""
        objects_before = sorted(o.name for o in bpy.data.objects)
        hidden = sorted(o.name for o in bpy.data.objects if o.hide_viewport)
        expect_error(bpy.ops.footfall.export_gltf, "/no/such/folder/crowd.glb: the folder /no/such/folder does not exist", filepath="/no/such/folder/crowd.glb")
        check(sorted(o.name for o in bpy.data.objects) == objects_before, "the failed export changed the scene")
        check(sorted(o.name for o in bpy.data.objects if o.hide_viewport) == hidden, "the failed export hid objects")

    worst = exported_and_reimported(plan, TMP / "crowd.glb", a_failed_export_first)
    check(worst <= 0.005, f"re-imported bones are {worst * 1000:.2f} mm off")


def test_a_live_crowd_exports_as_it_plays():
    ff, plan, path = applied(doorway_plan)
    check(bpy.ops.footfall.apply(plan_filepath=str(path), live=True) == {"FINISHED"}, "live apply failed")
    worst = exported_and_reimported(plan, TMP / "live-crowd.glb")
    check(worst <= 0.005, f"re-imported bones of the live crowd are {worst * 1000:.2f} mm off")


def transform_rig(data_matrix, object_matrix, parent_matrix=None):
    """Gives the imported rig other coordinates, upright in the world as
    before: its bones and meshes turned by `data_matrix`, its object by
    `object_matrix`, under a parent empty at `parent_matrix` if given
    (parent @ object = data^-1)."""
    rig, _profile = imported_rig()
    for mesh in rig.children:
        check(mesh.matrix_parent_inverse == mathutils.Matrix() and mesh.matrix_basis == mathutils.Matrix(),
              f"{mesh.name} is not at its armature's origin")
        mesh.data.transform(data_matrix)
    rig.data.transform(data_matrix)
    if parent_matrix is not None:
        parent = bpy.data.objects.new("Y-up root", None)
        bpy.context.scene.collection.objects.link(parent)
        parent.matrix_world = parent_matrix
        rig.parent = parent
    rig.matrix_basis = object_matrix
    bpy.context.view_layer.update()


def expect_rig_walks_the_plan(case, make_rig):
    """With the rig `make_rig()` leaves imported: after plan and apply the
    feet are on the plan in the world, the head as high above the hips as at
    rest, and the export valid and the same when re-imported."""
    from footfall.core import native

    ff = native.load()
    make_rig()
    rig, profile = imported_rig()
    rest_rise = ((rig.matrix_world @ rig.data.bones[profile.bones["head"]].head_local)
                 - (rig.matrix_world @ rig.data.bones[profile.bones["hips"]].head_local)).z
    plan, path = doorway_plan(ff)
    check(bpy.ops.footfall.apply(plan_filepath=str(path)) == {"FINISHED"}, f"{case}: apply failed")
    worst_foot, worst_pelvis, _ = plan_errors(ff, plan, *imported_rig())
    check(worst_foot <= 0.002, f"{case}: a planted foot is {worst_foot * 1000:.2f} mm off the plan")
    check(worst_pelvis <= 0.02, f"{case}: the pelvis is {worst_pelvis * 100:.2f} cm off the COM")
    scene = bpy.context.scene
    worst_rise = 0.0
    for frame in range(scene.frame_start, scene.frame_end + 1, 3):
        scene.frame_set(frame)
        for agent in plan.agents:
            armature = evaluated(agent.name)
            bones = armature.pose.bones
            rise = (armature.matrix_world @ bones[profile.bones["head"]].head
                    - armature.matrix_world @ bones[profile.bones["hips"]].head).z
            worst_rise = max(worst_rise, abs(rise / rest_rise - 1.0))
    print(f"{case}: head above hips within {worst_rise * 100:.1f} % of the rest pose's rise")
    check(worst_rise <= 0.05, f"{case}: the head's rise above the hips is {worst_rise * 100:.1f} % off the rest pose's")
    worst = exported_and_reimported(plan, TMP / f"{case}.glb")
    check(worst <= 0.005, f"{case}: re-imported bones are {worst * 1000:.2f} mm off")


def test_instances_and_animations_carry_the_agents_names():
    """A scene's agents are empties named after them: Apply names each
    instance exactly after its agent (the empty becomes 'NAME (agent)' and
    keeps the name), planning again reads the same names, and the exported
    animations carry them."""
    fresh_scene_with_rig()
    scenario = TMP / "named.json"
    scenario.write_text(json.dumps({"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[4, 0]]},
        {"name": "bob", "position": [0, 2], "goals": [[4, 2]]}]}))
    check(bpy.ops.footfall.load_scenario(filepath=str(scenario)) == {"FINISHED"}, "load failed")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    for name in ("ann", "bob"):
        check(bpy.data.objects[name].type == "ARMATURE", f"'{name}' is not the instance")
        check(bpy.data.objects[f"{name} (agent)"].type == "EMPTY", f"no empty '{name} (agent)'")
    check(bpy.ops.footfall.plan() == {"FINISHED"} and bpy.ops.footfall.apply() == {"FINISHED"}, "re-plan failed")
    check(sorted(o.name for o in bpy.data.objects if o.type == "ARMATURE" and o.name in ("ann", "bob")) ==
          ["ann", "bob"], "the instances lost their names on a second apply")
    out = TMP / "named.glb"
    check(bpy.ops.footfall.export_gltf(filepath=str(out)) == {"FINISHED"}, "export failed")
    check(sorted(a["name"] for a in glb_json(out)["animations"]) == ["ann", "bob"], "animations misnamed")


def test_rigs_of_other_origins_walk_on_the_plan():
    """Blender's Rigify human metarig made in the scene, and the project's rig
    with its bones renamed Bone.000, ... (found from the skeleton's shape),
    both used as they are in the scene."""

    def metarig():
        bpy.ops.wm.read_homefile(use_empty=True)
        addon_utils.enable("footfall", default_set=True, handle_error=None)
        addon_utils.enable("rigify", default_set=True, handle_error=None)
        bpy.ops.object.armature_human_metarig_add()
        check(bpy.ops.footfall.import_rig(armature=bpy.context.active_object.name) == {"FINISHED"}, "metarig refused")

    def nameless():
        bpy.ops.wm.read_homefile(use_empty=True)
        addon_utils.enable("footfall", default_set=True, handle_error=None)
        if "bool" not in numpy.__dict__:
            numpy.bool = bool  # Debian's Blender 3.4 importer
        bpy.ops.import_scene.gltf(filepath=str(RIG))
        (armature,) = [o for o in bpy.data.objects if o.type == "ARMATURE"]
        for i, bone in enumerate(sorted(armature.data.bones, key=lambda b: b.name[::-1])):
            bone.name = f"Bone.{i:03d}"  # renames the vertex groups of its meshes too
        check(bpy.ops.footfall.import_rig(armature=armature.name) == {"FINISHED"}, "nameless rig refused")

    expect_rig_walks_the_plan("Rigify metarig", metarig)
    expect_rig_walks_the_plan("rig of no naming scheme", nameless)


def test_rigs_with_object_and_parent_transforms_walk_upright_on_the_plan():
    """The project's rig as a glTF Y-up file has it (under a root turned -90
    degrees about X) and as an FBX from Mixamo (its armature object turned 90
    degrees about X and scaled 0.01)."""
    from footfall.core import native

    turn = mathutils.Matrix.Rotation(math.radians(90), 4, "X")
    cases = {"Y-up parent": (turn, mathutils.Matrix(), turn.inverted()),
             "scaled and turned object": (mathutils.Matrix.Scale(100, 4) @ turn.inverted(),
                                          turn @ mathutils.Matrix.Scale(0.01, 4), None)}
    for case, (data_matrix, object_matrix, parent_matrix) in cases.items():
        def make_rig():
            fresh_scene_with_rig()
            transform_rig(data_matrix, object_matrix, parent_matrix)

        expect_rig_walks_the_plan(case, make_rig)

    # A rig turned under a parent stretched along one axis is sheared: refused, naming it.
    ff = native.load()
    fresh_scene_with_rig()
    rig, _profile = imported_rig()
    stretched = mathutils.Matrix.Diagonal((1.0, 1.5, 1.0, 1.0))
    transform_rig(mathutils.Matrix(), mathutils.Matrix.Rotation(math.radians(30), 4, "Z"), stretched)
    plan, path = doorway_plan(ff)
    objects_before = sorted(o.name for o in bpy.data.objects)
    expect_error(bpy.ops.footfall.apply, f"rig '{rig.name}': its world transform shears it", plan_filepath=str(path))
    check(sorted(o.name for o in bpy.data.objects) == objects_before, "the refused apply changed the scene")


def behaviour_plan(ff):
    """A planned straight walk, edited by hand: steps 4-9 'arms_in', 10-15
    'side_step' with the feet turned across the way, as a plan file."""
    from footfall.core import scenario as sc

    plan = sc.plan(sc.scenario_document(sc.ScenarioInput([sc.AgentInput("dee", (0, 0), [(14, 0)])])))
    document = json.loads(ff.plan_to_json(plan))
    # Version 2's columns (docs/file-formats.md): the behaviours a string of
    # letters, the angles indexes into the agent's values.
    steps = document["agents"][0]["footsteps"]
    values, behavior = steps["values"], list(steps["behavior"])
    for i in range(steps["count"]):
        if 4 <= i <= 9:
            behavior[i] = "a"  # arms_in
        elif 10 <= i <= 15:
            behavior[i] = "s"  # side_step
            values.append(values[steps["phi"][i]] + math.pi / 2)
            steps["foot_orientation"][i] = len(values) - 1
    steps["behavior"] = "".join(behavior)
    path = TMP / "behaviours-plan.json"
    path.write_text(json.dumps(document))
    return ff.load_plan(str(path)), path


def torso_half_width(rig, profile):
    """Half the torso's width below the armpits, from the vertices skinned to the trunk."""
    (body,) = [c for c in rig.children if c.type == "MESH"]
    armpit = rig.data.bones[profile.bones["left"]["upper_arm"]].head_local.z
    groups = {body.vertex_groups[profile.bones[r]].index for r in ("hips", "spine", "chest")}
    xs = [abs(v.co.x) for v in body.data.vertices if v.co.z < armpit and any(
        g.group in groups and g.weight >= 0.5 for g in v.groups)]
    return max(xs)


def test_behaviours_play_their_clips():
    from footfall.core import clip_timing

    ff, plan, path = applied(behaviour_plan)
    rig, profile = imported_rig()
    agent = plan.agents[0]
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    sections = clip_timing.sections([clip_timing.Step(s.start_time, s.end_time, s.foot.name.lower(),
                                                      s.kind.name.lower(), s.behavior.name.lower())
                                     for s in agent.footsteps])
    check([s.behavior for s in sections] == ["walk", "arms_in", "side_step", "walk", "idle"],
          [s.behavior for s in sections])
    strips = sorted(section_strips("dee"), key=lambda strip: strip.frame_start)
    check(len(strips) == len(sections), f"{len(strips)} strips for {len(sections)} sections")
    for strip, section in zip(strips, sections):
        start, end = scene.frame_start + section.start * fps, scene.frame_start + section.end * fps
        check(strip.action.get("footfall_clip_of") == profile.clips[section.behavior],
              f"{strip.name} plays {strip.action.name}")
        # Blender holds frames in single precision.
        check(strip.frame_start <= start + 1e-4 and strip.frame_end >= end - 1e-4,
              f"{strip.name} spans {strip.frame_start}-{strip.frame_end}, its section {start}-{end}")

    half_width = torso_half_width(rig, profile)
    hips_rest = rig.data.bones[profile.bones["hips"]].matrix_local
    worst_hand, worst_facing = 0.0, 0.0
    for section in sections[1:3]:
        settle = 0.3  # past the cross-fade
        for frame in range(math.ceil(scene.frame_start + (section.start + settle) * fps),
                           math.floor(scene.frame_start + (section.end - settle) * fps) + 1):
            scene.frame_set(frame)
            armature = evaluated("dee")
            hips = armature.pose.bones[profile.bones["hips"]]
            body_frame = (armature.matrix_world @ hips.matrix @ hips_rest.inverted()).inverted()
            if section.behavior == "arms_in":
                for side, sign in (("left", 1), ("right", -1)):
                    hand = armature.pose.bones[profile.bones[side]["hand"]]
                    local = body_frame @ (armature.matrix_world @ ((hand.head + hand.tail) / 2))
                    worst_hand = max(worst_hand, abs(local.x - sign * half_width))
            else:
                t = (frame - scene.frame_start) / fps
                velocity = ff.com_at(agent, t).velocity
                forward = (armature.matrix_world @ hips.matrix).to_3x3() @ hips_rest.to_3x3().inverted() @ \
                    mathutils.Vector((0.0, -1.0, 0.0))  # the rig faces -Y at rest
                angle = math.degrees(math.atan2(velocity[1], velocity[0]) - math.atan2(forward.y, forward.x))
                worst_facing = max(worst_facing, abs(abs(math.remainder(angle, 360.0)) - 90.0))
    print(f"arms_in: hands at most {worst_hand * 100:.1f} cm from the torso's side; "
          f"side_step: facing at most {worst_facing:.1f} degrees from across the way")
    check(worst_hand <= 0.15, f"a hand is {worst_hand * 100:.1f} cm from the torso's side")
    check(worst_facing <= 20.0, f"the pelvis faces {worst_facing:.1f} degrees off across the way")


def inventory():
    kinds = ("objects", "meshes", "armatures", "actions", "collections")
    return {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in kinds}


def expect_error(operator, fragment, **arguments):
    try:
        operator(**arguments)
    except RuntimeError as error:
        check(fragment in str(error), f"unexpected message: {error}")
        return
    raise AssertionError("no error")


def test_a_sheared_pose_is_refused_by_name():
    applied(doorway_plan)
    rig, profile = imported_rig()
    spine = bpy.data.objects["ann"].pose.bones[profile.bones["spine"]]
    spine.scale = (1.0, 3.0, 1.0)  # stretches the chest above it, which the clips turn
    objects_before = sorted(o.name for o in bpy.data.objects)
    expect_error(bpy.ops.footfall.export_gltf, "agent 'ann', bone ", filepath=str(TMP / "sheared.glb"))
    check(sorted(o.name for o in bpy.data.objects) == objects_before, "the failed export changed the scene")
    check(not (TMP / "sheared.glb").exists(), "a failed export left a file")


def demo_plan(ff):
    """The built-in demo planned for the rig, as scripts/demo.py does: a crowd
    through a doorway, whose waits make sections shorter than the clips'
    cross-fades."""
    from footfall.core import character, scenario as sc

    document = sc.document_of(ff.demo_scenario())
    document["character"], document["planner"] = character.derive_parameters(imported_rig()[1].dimensions)
    plan = sc.plan(document)
    path = TMP / "demo-plan.json"
    ff.write_plan_file(plan, str(path))
    return plan, path


def test_a_crowd_with_short_waits_applies():
    ff, plan, path = applied(demo_plan)
    for agent in plan.agents:
        strips = section_strips(agent.name)
        check(len(strips) >= 1, f"{agent.name}: no clip strips")
        # Strips on one track never overlap (Blender refuses that), and every section has its strip.
        check(len(strips) == len(sections_of(agent)), f"{agent.name}: {len(strips)} strips")


def test_a_strip_ending_a_hair_past_a_whole_frame_leaves_room():
    """An agent of hallway-two-way whose first strip ends at frame 187 by the
    clip timing but at 187.0000153 as Blender holds it (single precision):
    the next strip, from frame 187, went on the same track and Blender
    refused it, failing the whole Apply."""
    from footfall.core import native

    ff = native.load()
    path = ROOT / "tests" / "data" / "plans" / "strip-ends-past-a-whole-frame.json"
    _ff, plan, _path = applied(lambda _ff: (ff.load_plan(str(path)), path))
    (agent,) = plan.agents
    check(len(section_strips(agent.name)) == len(sections_of(agent)), "a section has no strip")


def section_strips(name):
    """The NLA strips of an instance's sections (not its idle base or look-ahead)."""
    from footfall.bridge import animate

    return [strip for track in bpy.data.objects[name].animation_data.nla_tracks
            if track.name.startswith(animate.UPPER_BODY_TRACK) and track.name != f"{animate.UPPER_BODY_TRACK} idle"
            for strip in track.strips]


def sections_of(agent):
    from footfall.core import clip_timing

    return clip_timing.sections([clip_timing.Step(s.start_time, s.end_time, s.foot.name.lower(), s.kind.name.lower(),
                                                  s.behavior.name.lower()) for s in agent.footsteps])


def test_failures_leave_the_scene_as_it_was():
    from footfall.core import native

    ff = native.load()
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    _plan, path = doorway_plan_without_rig(ff)
    before = inventory()
    expect_error(bpy.ops.footfall.apply, "Import a rig first", plan_filepath=str(path))
    expect_error(bpy.ops.footfall.apply, "No plan: run Plan first")
    expect_error(bpy.ops.footfall.export_gltf, "Nothing to export", filepath=str(TMP / "none.glb"))
    check(inventory() == before, "a failed operator changed the scene")
    check(not (TMP / "none.glb").exists(), "a failed export left a file")
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")
    bad = TMP / "bad-plan.json"
    document = json.loads(path.read_text())
    steps = document["agents"][0]["footsteps"]
    # The step of the first left foot (the first step may be a start by the right).
    first_left = steps["foot"].index("l")
    steps["foot"] = steps["foot"][:first_left] + "m" + steps["foot"][first_left + 1:]
    bad.write_text(json.dumps(document))
    before = inventory()
    expect_error(bpy.ops.footfall.apply, f"footsteps.foot[{first_left}]: 'm' is not one of",
                 plan_filepath=str(bad))
    check(inventory() == before, "a failed apply changed the scene")


def doorway_plan_without_rig(ff):
    from footfall.core import scenario as sc

    plan = sc.plan(sc.scenario_document(sc.ScenarioInput([sc.AgentInput("ann", (0, 0), [(4, 0)])])))
    path = TMP / "plain-plan.json"
    ff.write_plan_file(plan, str(path))
    return plan, path



def leaving_plan(ff):
    """leo walks through its goal and leaves there; sam walks on for longer
    (planned with the rig's parameters, as Plan does)."""
    from footfall.core import character, scenario as sc

    c, p = character.derive_parameters(imported_rig()[1].dimensions)
    agents = [sc.AgentInput("leo", (0, 0), [(5, 0)], leave_at_goal=True),
              sc.AgentInput("sam", (0, 2.5), [(12, 2.5)])]
    plan = sc.plan(sc.scenario_document(sc.ScenarioInput(agents, [], c, p)))
    check(plan.agents[0].leaves and plan.agents[0].end_time() + 2 < plan.agents[1].end_time(), "leo does not leave first")
    path = TMP / "leaving-plan.json"
    ff.write_plan_file(plan, str(path))
    return plan, path


def test_a_leaving_agent_walks_off_and_disappears():
    """Walking on off its last step, its hips no lower than a walker's up to
    its leave time, hidden in viewports and renders after it, and in the
    exported glTF scaled to nothing from then on."""
    import numpy
    from footfall.core import glb

    ff, plan, path = applied(leaving_plan)
    rig, profile = imported_rig()
    leo = plan.agents[0]
    standing = rig.data.bones[profile.bones["hips"]].head_local.z
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    leave_frame = scene.frame_start + leo.end_time() * fps
    worst, walking, hidden_frames = 0.0, 0.0, 0
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        armature = bpy.data.objects["leo"]
        parts = [armature, *armature.children]
        if frame <= leave_frame:
            hips = evaluated("leo").matrix_world @ evaluated("leo").pose.bones[profile.bones["hips"]].head
            worst = max(worst, abs(hips.z - standing))
            sam = evaluated("sam").matrix_world @ evaluated("sam").pose.bones[profile.bones["hips"]].head
            walking = max(walking, abs(sam.z - standing))
            check(not any(o.hide_render or o.hide_viewport for o in parts), f"leo hidden at frame {frame}")
        else:
            hidden_frames += 1
            check(all(o.hide_render and o.hide_viewport for o in parts), f"leo shown at frame {frame}")
        check(not bpy.data.objects["sam"].hide_render, f"sam hidden at frame {frame}")
    # The gait itself lowers the hips at each double support (some 6.5 cm with
    # this rig's strides): leo's may go no lower than sam's, who walks on.
    print(f"leo's hips at most {worst * 100:.2f} cm from standing height (sam's {walking * 100:.2f} cm); "
          f"hidden for {hidden_frames} frames")
    check(worst <= walking + 0.005, f"leo's hips {worst * 100:.1f} cm below their standing height")
    check(worst <= 0.05, f"leo's hips {worst * 100:.1f} cm below their standing height")
    check(hidden_frames >= 2 * fps, f"leo hidden for only {hidden_frames} frames")

    out = TMP / "leaving.glb"
    check(bpy.ops.footfall.export_gltf(filepath=str(out)) == {"FINISHED"}, "export failed")
    expect_valid_gltf(out)
    file = glb.read(str(out))
    document = file.document

    def floats(accessor_index):
        accessor = document["accessors"][accessor_index]
        view = document["bufferViews"][accessor["bufferView"]]
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[accessor["type"]]
        start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
        return numpy.frombuffer(file.binary, "<f4", accessor["count"] * width, start).reshape(accessor["count"], width)

    (animation,) = [a for a in document["animations"] if a["name"] == "leo"]
    scales = [c for c in animation["channels"] if c["target"]["path"] == "scale"]
    check(scales, "leo's animation has no scale channel")
    sampler = animation["samplers"][scales[0]["sampler"]]
    times, values = floats(sampler["input"])[:, 0], floats(sampler["output"])
    gone = times > leo.end_time() + 1.0 / fps
    check(gone.any() and numpy.all(values[gone] == 0.0), "leo is not scaled to nothing after leaving")
    check(numpy.all(values[times <= leo.end_time()] > 0.5), "leo is scaled down before leaving")


def test_an_apply_stopped_part_way_leaves_the_scene_as_it_was():
    """The steps the modal Apply takes between events: stopped after two of
    the demo's agents, the earlier crowd and every name are as they were;
    run to the end, it replaces the crowd as Apply does."""
    from footfall.bridge import action_curves, apply_plan

    demo_applied()
    scene = bpy.context.scene
    before, frame_end = inventory(), scene.frame_end

    def keys_of_the_crowd():
        return {obj.name: len(action_curves.curves(obj.animation_data.action)[0].keyframe_points)
                for obj in bpy.data.collections["Footfall Crowd"].objects if obj.type == "ARMATURE"}

    keys = keys_of_the_crowd()
    job = apply_plan.ApplyJob(bpy.context)
    check(job.advance() and job.advance(), "the demo has more than two agents")
    check(0.0 < job.progress < 1.0, f"progress {job.progress} after two agents")
    job.cancel()
    after = inventory()
    check(after == before, "a stopped Apply changed the scene: "
          f"{ {k: sorted(set(after[k]) ^ set(before[k])) for k in before if after[k] != before[k]} }")
    check(scene.frame_end == frame_end, "a stopped Apply changed the frame range")
    check(keys_of_the_crowd() == keys, "a stopped Apply changed the crowd's animation")
    job = apply_plan.ApplyJob(bpy.context)
    steps = 0
    while job.advance():
        steps += 1
    armatures = job.finish()
    check(steps == len(keys) and job.progress == 1.0, f"{steps} steps for {len(keys)} agents")
    check(sorted(a.name for a in armatures) == sorted(keys), "the new crowd's agents")
    after = inventory()
    check(after == before, "applying the same plan again changed what the scene holds: "
          f"{ {k: sorted(set(after[k]) ^ set(before[k])) for k in before if after[k] != before[k]} }")


run([test_feet_and_pelvis_follow_the_plan, test_on_the_demo_no_stance_foot_moves, test_feet_roll_from_heel_to_toe, test_arms_swing_opposite_to_the_legs,
     test_arms_swing_as_far_as_the_steps_are_fast, test_the_head_and_chest_look_into_a_turn, test_behaviours_play_their_clips,
     test_export_validates_and_reimports, test_a_live_crowd_exports_as_it_plays, test_failures_leave_the_scene_as_it_was,
     test_applying_again_replaces_the_crowd, test_replanning_the_selected_agents_updates_only_their_rigs,
     test_a_crowd_with_short_waits_applies, test_a_strip_ending_a_hair_past_a_whole_frame_leaves_room,
     test_a_sheared_pose_is_refused_by_name, test_a_leaving_agent_walks_off_and_disappears,
     test_rigs_with_object_and_parent_transforms_walk_upright_on_the_plan, test_rigs_of_other_origins_walk_on_the_plan,
     test_instances_and_animations_carry_the_agents_names, test_an_apply_stopped_part_way_leaves_the_scene_as_it_was])
