"""The core's animated crowd (`footfall animate`, `plan --glb`,
`animate_gltf`): valid glTF, read back by an independent reader
(crowd_glb), with every planted foot's contact point on the plan and the
hips on the planned COM path, for the project's rig and for one under a
parent transform; bad input refused with no file left."""

import json
import math
import pathlib
import struct
import subprocess

import numpy
import pytest

from conftest import scenario_json
from crowd_glb import CrowdGlb, rewritten, with_stairs_up_clip, z_up
from ground_heights import ground_heights

ROOT = pathlib.Path(__file__).resolve().parents[2]
RIG = ROOT / "rigs" / "footfall_humanoid.glb"
PROFILE = ROOT / "rigs" / "footfall_humanoid.json"
VALIDATOR = ROOT / "tests" / "gltf" / "validate.mjs"
CONTACT_TOLERANCE = 0.002  # [m] a planted foot's contact point from the plan
HIPS_TOLERANCE = 0.02  # [m] the hips from the planned COM, on the ground


def validator_errors(path):
    run = subprocess.run(["node", str(VALIDATOR), str(path)], capture_output=True, text=True)
    return json.loads(run.stdout)["issues"]["numErrors"], run.stdout


class RigFeet:
    """Each foot of a rig at rest, Z up: ankle, ball and heel contact, read
    from the rig's file (the heel: the skinned vertex furthest behind the
    ankle among those whose strongest joint is the foot or toe)."""

    def __init__(self, rig_path, profile):
        rig = CrowdGlb(rig_path)
        document = rig.document
        names = {node.get("name"): i for i, node in enumerate(document["nodes"])}
        world = rig.world_matrices(None, numpy.zeros(1))
        bones = profile["bones"]
        self.sides = {}
        forward = numpy.zeros(3)
        for side in ("left", "right"):
            foot, toe = names[bones[side]["foot"]], names[bones[side]["toe"]]
            forward += z_up(world[toe][0, :3, 3]) - z_up(world[foot][0, :3, 3])
        forward[2] = 0.0
        self.yaw = math.atan2(forward[1], forward[0])
        forward /= numpy.linalg.norm(forward)
        skin = document["skins"][0]
        binds = [world[j][0] @ m for j, m in zip(skin["joints"], rig.accessor(skin["inverseBindMatrices"]))]
        for side in ("left", "right"):
            foot, toe = names[bones[side]["foot"]], names[bones[side]["toe"]]
            ankle = z_up(world[foot][0, :3, 3])
            points = []
            for positions, joints, weights in rig.skinned_primitives():
                for p, j, w in zip(positions, joints, weights):
                    if skin["joints"][j[numpy.argmax(w)]] not in (foot, toe):
                        continue
                    skinned = sum(wk * (binds[jk] @ numpy.append(p, 1.0))[:3] for jk, wk in zip(j, w) if wk > 0)
                    points.append(z_up(skinned))
            heel_back = max(-numpy.dot(p - ankle, forward) for p in points)
            self.sides[side] = {
                "foot": bones[side]["foot"], "toe": bones[side]["toe"], "ankle": ankle,
                "ball": z_up(world[toe][0, :3, 3]),
                "heel": numpy.array([ankle[0], ankle[1], 0.0]) - heel_back * forward,
                "rest": world[foot][0],
            }
        self.hips = bones["hips"]


def turn(angle):
    c, s = math.cos(angle), math.sin(angle)
    return numpy.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def measure(ff, plan, crowd_path, feet):
    """(worst contact error of a planted foot, worst hips-to-COM distance on
    the ground, stance frames checked) over every agent and key."""
    crowd = CrowdGlb(crowd_path)
    worst_contact = worst_hips = 0.0
    checked = 0
    prisms = [{"polygon": o.polygon, "height": o.height} for o in plan.ground]  # the demo's: prisms only

    def ground_under(point):
        return max(float(ground_heights(prisms, numpy.array([point[:2]]))[0]), 0.0) if prisms else 0.0

    y_up_to_z_up = numpy.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1.0]])
    for agent in plan.agents:
        times = crowd.animation_times(agent.name)
        root = crowd.agent_root(agent.name)
        nodes = crowd.subtree(root)
        wanted = [feet.hips] + [feet.sides[s][k] for s in feet.sides for k in ("foot", "toe")]
        world = crowd.world_matrices(agent.name, times, [nodes[n] for n in wanted])
        shown = times <= agent.end_time() + 1e-6 if agent.leaves else numpy.ones(len(times), dtype=bool)
        for i, t in enumerate(times):
            if not shown[i]:
                continue
            planned_t = min(float(t), agent.end_time())
            com = ff.com_at(agent, planned_t).position
            hips = z_up(world[nodes[feet.hips]][i, :3, 3])
            worst_hips = max(worst_hips, math.hypot(hips[0] - com[0], hips[1] - com[1]))
            for side, pose in zip(("left", "right"), ff.feet_at(agent, planned_t)):
                if not pose.planted:
                    continue
                rest = feet.sides[side]
                rotation = agent.scale * turn(pose.orientation - feet.yaw)  # the rig at the agent's size
                ankle = numpy.array([pose.position[0], pose.position[1],
                                     ground_under(pose.position) + agent.scale * rest["ankle"][2]])
                planned = [ankle, ankle + rotation @ (rest["ball"] - rest["ankle"]),
                           ankle + rotation @ (rest["heel"] - rest["ankle"])]
                foot_world = world[nodes[rest["foot"]]][i]
                # The heel rides with the foot: its rest point carried by the foot's motion.
                heel_local = numpy.linalg.inv(y_up_to_z_up @ rest["rest"]) @ numpy.append(rest["heel"], 1.0)
                posed = [z_up(foot_world[:3, 3]), z_up(world[nodes[rest["toe"]]][i, :3, 3]),
                         (y_up_to_z_up @ foot_world @ heel_local)[:3]]
                worst_contact = max(worst_contact, min(numpy.linalg.norm(a - b) for a, b in zip(posed, planned)))
                checked += 1
    return worst_contact, worst_hips, checked


@pytest.fixture(scope="module")
def demo(tmp_path_factory, cli):
    folder = tmp_path_factory.mktemp("crowd")
    plan, crowd = folder / "plan.json", folder / "crowd.glb"
    run = subprocess.run([cli, "demo", "-o", str(plan), "--glb", str(crowd), "--rig", str(RIG)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return plan, crowd, run.stdout


def test_demo_crowd_is_valid_gltf_with_an_animation_per_agent(ff, demo):
    plan_path, crowd_path, output = demo
    errors, report = validator_errors(crowd_path)
    assert errors == 0, report[:2000]
    plan = ff.load_plan(str(plan_path))
    crowd = CrowdGlb(crowd_path)
    assert sorted(crowd.animation_names()) == sorted(a.name for a in plan.agents)
    assert "walk = 'walk'" in output  # the rig's own clips play
    # One mesh, shared: its data is in the file once, however many agents.
    assert len(crowd.document["meshes"]) == 1
    assert len(crowd.document["skins"]) == len(plan.agents)
    accessors = crowd.document["accessors"]
    for animation in crowd.document["animations"]:
        for sampler in animation["samplers"]:
            for index in (sampler["input"], sampler["output"]):
                assert "min" in accessors[index] and "max" in accessors[index]


def test_demo_feet_stay_on_the_plan_and_hips_on_the_com_path(ff, demo):
    plan_path, crowd_path, _ = demo
    plan = ff.load_plan(str(plan_path))
    contact, hips, checked = measure(ff, plan, crowd_path, RigFeet(RIG, json.loads(PROFILE.read_text())))
    print(f"demo: worst contact {1000 * contact:.2f} mm over {checked} planted feet, hips {100 * hips:.2f} cm")
    assert checked > 500
    assert contact < CONTACT_TOLERANCE
    assert hips < HIPS_TOLERANCE


def test_agents_of_other_sizes_are_the_rig_scaled_with_their_feet_on_the_plan(ff, cli, tmp_path):
    """A scenario's per-agent scale sizes the agent's character and, in the
    crowd, its copy of the rig (its node's scale), the feet on the plan."""
    scenario = tmp_path / "sizes.json"
    scenario.write_text(scenario_json(agents=[
        {"name": "small", "position": [0, 0], "goals": [[6, 0]], "scale": 0.8},
        {"name": "tall", "position": [0, 3], "goals": [[6, 3]], "scale": 1.25},
        {"name": "same", "position": [0, 6], "goals": [[6, 6]]}]))
    plan_path, crowd_path = tmp_path / "plan.json", tmp_path / "crowd.glb"
    run = subprocess.run([cli, "plan", str(scenario), "-o", str(plan_path), "--glb", str(crowd_path), "--rig", str(RIG)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    plan = ff.load_plan(str(plan_path))
    agents = {a.name: a for a in plan.agents}
    assert {name: a.scale for name, a in agents.items()} == {"small": 0.8, "tall": 1.25, "same": 1.0}
    assert agents["small"].character.com_height == pytest.approx(0.8 * plan.character.com_height)
    assert agents["same"].character is None
    longest = {name: max(math.dist(s.com_start, s.com_end) for s in a.footsteps) for name, a in agents.items()}
    assert longest["small"] < longest["same"] < longest["tall"]
    crowd = CrowdGlb(crowd_path)
    for name, agent in agents.items():
        node = crowd.document["nodes"][crowd.agent_root(name)]
        assert node.get("scale", [1.0, 1.0, 1.0]) == pytest.approx([agent.scale] * 3)
    contact, hips, checked = measure(ff, plan, crowd_path, RigFeet(RIG, json.loads(PROFILE.read_text())))
    print(f"sizes: worst contact {1000 * contact:.2f} mm over {checked} planted feet, hips {100 * hips:.2f} cm")
    assert checked > 50 and contact < CONTACT_TOLERANCE and hips < HIPS_TOLERANCE


STAIRS = ROOT / "tests" / "data" / "stairs.json"
BRIDGE = ROOT / "tests" / "data" / "bridge.json"
GROUND_TOLERANCE = 0.01  # [m] a foot's vertex below the ground under it
TOUCHING = 0.002  # [m] a vertex this near the ground under it touches it
SLIDE_TOLERANCE = 0.005  # [m] the farthest one may slide while it touches


def foot_vertices(crowd, agent, times, bones):
    """(len(times), n, 3) world points, Z up, of the agent's skinned vertices
    whose strongest joint is one of `bones` (names)."""
    document = crowd.document
    skin = document["skins"][0]
    rig_names = [document["nodes"][j].get("name") for j in skin["joints"]]
    below = crowd.subtree(crowd.agent_root(agent))
    joints_here = [below[name] for name in rig_names]
    world = crowd.world_matrices(agent, times, joints_here)
    binds = crowd.accessor(skin["inverseBindMatrices"])
    skinning = numpy.stack([world[j] @ m for j, m in zip(joints_here, binds)], axis=1)  # (t, joints, 4, 4)
    wanted = {rig_names.index(name) for name in bones}
    points = []
    for positions, joints, weights in crowd.skinned_primitives():
        keep = numpy.array([j[numpy.argmax(w)] in wanted for j, w in zip(joints, weights)])
        p = numpy.append(positions[keep], numpy.ones((keep.sum(), 1)), axis=1)
        skinned = sum(weights[keep, k][None, :, None] * numpy.einsum("tvij,vj->tvi", skinning[:, joints[keep, k]], p)
                      for k in range(4))
        points.append(skinned[..., :3])
    return z_up(numpy.concatenate(points, axis=1))


def slid_while_touching(points, under):
    """How far any of `points` ((frames, n, 3)) slides across the ground
    (heights `under`, (frames, n)) while it touches it (within TOUCHING),
    from where it came to touch it [m]."""
    touched_at = numpy.full((points.shape[1], 2), numpy.nan)
    slid = 0.0
    for frame, ground in zip(points, under):
        touching = ground - frame[:, 2] >= -TOUCHING
        touched_at[~touching] = numpy.nan
        new = touching & numpy.isnan(touched_at[:, 0])
        touched_at[new] = frame[new, :2]
        if touching.any():
            slid = max(slid, float(numpy.linalg.norm(frame[touching, :2] - touched_at[touching], axis=1).max()))
    return slid


def animated_on_ground(ff, cli, tmp_path, scenario):
    """`scenario` planned and animated by `plan --glb` (a valid .glb): its
    plan, its crowd, the rig's bones, the deepest any foot's skinned vertex
    lies below the ground under it at any frame, the farthest one slides
    while it touches the ground, and the frames."""
    plan_path, crowd_path = tmp_path / "plan.json", tmp_path / "crowd.glb"
    run = subprocess.run([cli, "plan", str(scenario), "-o", str(plan_path), "--glb", str(crowd_path),
                          "--rig", str(RIG)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    errors, report = validator_errors(crowd_path)
    assert errors == 0, report[:2000]
    plan = ff.load_plan(str(plan_path))
    prisms = json.loads(plan_path.read_text())["ground"]
    crowd = CrowdGlb(crowd_path)
    bones = json.loads(PROFILE.read_text())["bones"]
    feet = [bones[side][part] for side in ("left", "right") for part in ("foot", "toe")]
    deepest, slid, frames = 0.0, 0.0, 0
    for agent in plan.agents:
        times = crowd.animation_times(agent.name)
        points = foot_vertices(crowd, agent.name, times, feet)
        under = ground_heights(prisms, points.reshape(-1, 3)).reshape(points.shape[:2])
        depth = numpy.max(under - points[..., 2], axis=1)
        deepest = max(deepest, float(depth.max()))
        slid = max(slid, slid_while_touching(points, under))
        frames += len(times)
    return plan, crowd, bones, deepest, slid, frames


def hips_height_at_end(crowd, bones, name):
    hips = crowd.world_positions(name, crowd.animation_times(name)[-1:], [bones["hips"]],
                                 crowd.agent_root(name))
    return z_up(hips[bones["hips"]])[0, 2]


def test_a_stair_crowd_keeps_every_foot_on_its_tread_and_out_of_the_risers(ff, cli, tmp_path):
    """Up and down a flight: from the skinned mesh at every frame, no vertex
    of a foot more than 1 cm below the ground under it (a toe in a riser, a
    sole through a tread), and the hips risen to the landing."""
    plan, crowd, bones, deepest, slid, frames = animated_on_ground(ff, cli, tmp_path, STAIRS)
    for agent in plan.agents:
        landing = agent.name.startswith("up")
        assert hips_height_at_end(crowd, bones, agent.name) > (1.5 if landing else 0.5), agent.name
    print(f"stairs: deepest foot vertex {1000 * deepest:.1f} mm below the ground, one touching it slides "
          f"{1000 * slid:.1f} mm, {frames} frames")
    assert frames > 2000
    assert deepest < GROUND_TOLERANCE
    assert slid < SLIDE_TOLERANCE


def test_those_on_a_bridge_walk_on_its_deck_and_those_under_it_on_the_street(ff, cli, tmp_path):
    """tests/data/bridge.json: two walk along the street under a footbridge's
    deck, two cross the deck 2.89 m above them. Every foot's skinned vertex
    on the ground under it (the deck for those above, the street below)."""
    plan, crowd, bones, deepest, slid, frames = animated_on_ground(ff, cli, tmp_path, BRIDGE)
    for agent in plan.agents:
        over = agent.name.startswith("over")
        hips = hips_height_at_end(crowd, bones, agent.name)
        assert (hips > 3.5) if over else (0.5 < hips < 1.5), (agent.name, hips)
    print(f"bridge: deepest foot vertex {1000 * deepest:.1f} mm below the ground, one touching it slides "
          f"{1000 * slid:.1f} mm, {frames} frames")
    assert deepest < GROUND_TOLERANCE
    assert slid < SLIDE_TOLERANCE


def nameless_bones(document):
    """Bones named as Blender names new ones: only the skeleton's shape shows their roles."""
    for joint in document["skins"][0]["joints"]:
        document["nodes"][joint]["name"] = f"Bone.{joint:03d}"


def collapse_bones(document):
    nameless_bones(document)
    for joint in document["skins"][0]["joints"]:
        document["nodes"][joint]["translation"] = [0.0, 0.0, 0.0]


def lying_down(document):
    """Turned a quarter about X under a new root, as a Z-up model exported without its turn to Y up."""
    scene = document["scenes"][document.get("scene", 0)]
    half = math.sqrt(0.5)
    document["nodes"].append({"name": "z_up", "children": scene["nodes"], "rotation": [-half, 0.0, 0.0, half]})
    scene["nodes"] = [len(document["nodes"]) - 1]


def with_parent_transform(document):
    """The rig under a new root that turns it a quarter about the vertical,
    moves it and scales it by 0.01, its old root scaled up by 100 to match:
    the same body, standing elsewhere, through transforms a converted FBX has."""
    scene = document["scenes"][document.get("scene", 0)]
    for root in scene["nodes"]:
        node = document["nodes"][root]
        node["scale"] = [100.0 * s for s in node.get("scale", [1.0, 1.0, 1.0])]
        node["translation"] = [100.0 * t for t in node.get("translation", [0.0, 0.0, 0.0])]
    half = math.sqrt(0.5)
    document["nodes"].append({"name": "fbx_root", "children": scene["nodes"], "rotation": [0.0, half, 0.0, half],
                              "translation": [3.0, 0.0, -2.0], "scale": [0.01, 0.01, 0.01]})
    scene["nodes"] = [len(document["nodes"]) - 1]


def test_a_rig_under_a_parent_transform_puts_its_feet_on_the_plan(ff, cli, demo, tmp_path):
    plan_path, _, _ = demo
    rig = tmp_path / "turned.glb"
    rewritten(RIG, rig, with_parent_transform)
    crowd = tmp_path / "crowd.glb"
    summary = ff.animate_gltf(ff.load_plan(str(plan_path)), str(rig), str(crowd), fps=30,
                              profile_path=str(PROFILE))
    assert summary["frames"] > 1 and crowd.stat().st_size == summary["bytes"]
    errors, report = validator_errors(crowd)
    assert errors == 0, report[:2000]
    plan = ff.load_plan(str(plan_path))
    contact, hips, checked = measure(ff, plan, crowd, RigFeet(rig, json.loads(PROFILE.read_text())))
    print(f"turned rig: worst contact {1000 * contact:.2f} mm over {checked} planted feet, hips {100 * hips:.2f} cm")
    assert contact < CONTACT_TOLERANCE
    assert hips < HIPS_TOLERANCE


def test_a_rig_without_a_profile_is_mapped_by_its_shape(ff, cli, demo, tmp_path):
    """Nameless bones and no profile: the core detects the limbs from the
    skeleton's shape, as Import Rig does, and the feet land on the plan."""
    plan_path, _, _ = demo
    rig, crowd = tmp_path / "nameless.glb", tmp_path / "crowd.glb"
    rewritten(RIG, rig, nameless_bones)
    run = run_animate(cli, plan_path, "--rig", rig, "-o", crowd)
    assert run.returncode == 0, run.stderr
    profile = json.loads(PROFILE.read_text())
    names = {node["name"]: i for i, node in enumerate(CrowdGlb(RIG).document["nodes"])}
    for side in ("left", "right"):
        for role, bone in profile["bones"][side].items():
            profile["bones"][side][role] = f"Bone.{names[bone]:03d}"
    profile["bones"]["hips"] = f"Bone.{names[profile['bones']['hips']]:03d}"
    contact, hips, checked = measure(ff, ff.load_plan(str(plan_path)), crowd, RigFeet(rig, profile))
    assert checked > 500 and contact < CONTACT_TOLERANCE and hips < HIPS_TOLERANCE


def run_animate(cli, *arguments):
    return subprocess.run([cli, "animate", *map(str, arguments)], capture_output=True, text=True)


def test_bad_input_is_refused_in_one_line_with_no_file(ff, cli, demo, tmp_path):
    plan_path, _, _ = demo
    out = tmp_path / "out.glb"
    # A rig without a skin: its profile names bones it has as nodes, not joints.
    document = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"name": "hips"}]}
    unskinned = tmp_path / "unskinned.gltf"
    unskinned.write_text(json.dumps(document))
    profile = json.loads(PROFILE.read_text())
    renamed = json.loads(PROFILE.read_text())
    renamed["bones"]["left"]["foot"] = "Foot_L"
    bad_profile = tmp_path / "renamed.json"
    bad_profile.write_text(json.dumps(renamed))
    # Nameless bones all at one point: neither names nor shape show the roles.
    shapeless = tmp_path / "shapeless.glb"
    rewritten(RIG, shapeless, collapse_bones)
    lying = tmp_path / "lying.glb"
    rewritten(RIG, lying, lying_down)
    # A plan for a character twice the rig's size.
    giant = json.loads(plan_path.read_text())
    giant["character"]["com_height"] = 2 * giant["character"]["com_height"]
    giant_plan = tmp_path / "giant.json"
    giant_plan.write_text(json.dumps(giant))
    cases = [
        ((plan_path, "--rig", unskinned, "--profile", PROFILE, "-o", out), "no skin has the bone 'hips'"),
        ((plan_path, "--rig", RIG, "--profile", bad_profile, "-o", out), "bones.left.foot = 'Foot_L'"),
        ((giant_plan, "--rig", RIG, "-o", out), "stands -51 % off"),
        ((plan_path, "--rig", tmp_path / "none.glb", "-o", out), "none.glb': no such file"),
        ((plan_path, "--rig", shapeless, "-o", out), "could not find these bones: left.upper_arm"),
        ((plan_path, "--rig", lying, "--profile", PROFILE, "-o", out), "the rig does not stand upright at rest"),
        ((plan_path, "--rig", RIG, "--fps", "0", "-o", out), "--fps: expected a number from 1 to 240"),
        ((plan_path, "--rig", RIG), "animate needs --rig RIG and -o CROWD"),
    ]
    for arguments, message in cases:
        run = run_animate(cli, *arguments)
        assert run.returncode == 2, (arguments, run.stderr)
        assert message in run.stderr and run.stderr.count("\n") == 1, run.stderr
        assert not out.exists() and not list(tmp_path.glob(".out.glb*")), arguments
    assert profile["bones"]["left"]["foot"] == "foot.L"
    with pytest.raises(ValueError, match="the rig has no such bone"):
        ff.animate_gltf(ff.load_plan(str(plan_path)), str(RIG), str(out), profile_path=str(bad_profile))
    assert not out.exists()


def test_a_rigs_own_stair_clip_plays_up_the_stairs_and_the_walk_elsewhere(ff, cli, tmp_path):
    plan_path, plain = tmp_path / "plan.json", tmp_path / "plain.glb"
    run = subprocess.run([cli, "plan", str(STAIRS), "-o", str(plan_path), "--glb", str(plain),
                          "--rig", str(RIG)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    rig, stairs = tmp_path / "stairs-rig.glb", tmp_path / "stairs.glb"
    rewritten(RIG, rig, with_stairs_up_clip)
    run = run_animate(cli, plan_path, "--rig", rig, "--profile", PROFILE, "-o", stairs)
    assert run.returncode == 0, run.stderr
    assert "stairs_up = 'stairs_up'" in run.stdout and "stairs_down" not in run.stdout, run.stdout
    plan = ff.load_plan(str(plan_path))
    agent = next(a for a in plan.agents if a.name == "up0")
    climbs = ff.stair_climbs(agent)
    up = [s for s, c in zip(agent.footsteps, climbs) if c > 0]
    assert up and all(c >= 0 for c in climbs)
    hands = [bones[side]["hand"] for bones in [json.loads(PROFILE.read_text())["bones"]] for side in ("left", "right")]

    def hands_at(path, name, times):
        crowd = CrowdGlb(path)
        found = crowd.world_positions(name, times, hands, crowd.agent_root(name))
        return numpy.concatenate([found[bone] for bone in hands], axis=1)

    # Up the flight the stair clip plays, its arms held in; those going down
    # (the rig has no stairs_down clip) walk down as before, to the bit.
    climbing = numpy.linspace(up[0].start_time + 0.6, up[-1].end_time - 0.1, 10)
    assert numpy.max(numpy.abs(hands_at(plain, "up0", climbing) - hands_at(stairs, "up0", climbing))) > 0.05
    times = CrowdGlb(plain).animation_times("down0")
    assert numpy.array_equal(hands_at(plain, "down0", times), hands_at(stairs, "down0", times))
