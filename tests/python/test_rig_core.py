"""Rig handling without Blender: bone-map detection, profiles, dimensions,
and the planner parameters derived from a rig."""

import json
import math
import random

import pytest

from footfall.core import body_capsules, bone_map, character, rig_measure, rig_profile
from footfall.core.bone_map import Bone


def chain(*pairs):
    """Bones from (name, parent) pairs."""
    return [Bone(name, parent) for name, parent in pairs]


def limbs(prefix, names, trunk_hips, trunk_chest, side_of):
    """Arm and leg chains of both sides, named by `names` and `side_of`."""
    bones = []
    for side in ("left", "right"):
        n = {role: side_of(side, base) for role, base in names.items()}
        shoulder = n.get("shoulder")
        arm_parent = trunk_chest
        if shoulder:
            bones.append(Bone(prefix + shoulder, prefix + trunk_chest))
            arm_parent = shoulder
        bones += chain(
            (prefix + n["upper_arm"], prefix + arm_parent),
            (prefix + n["forearm"], prefix + n["upper_arm"]),
            (prefix + n["hand"], prefix + n["forearm"]),
            (prefix + n["thigh"], prefix + trunk_hips),
            (prefix + n["shin"], prefix + n["thigh"]),
            (prefix + n["foot"], prefix + n["shin"]),
            (prefix + n["toe"], prefix + n["foot"]),
        )
    return bones


OURS = chain(("hips", None), ("spine", "hips"), ("chest", "spine"), ("neck", "chest"), ("head", "neck")) + limbs(
    "",
    dict(upper_arm="upper_arm", forearm="forearm", hand="hand", thigh="thigh", shin="shin", foot="foot", toe="toe"),
    "hips",
    "chest",
    lambda side, base: f"{base}.{side[0].upper()}",
)

MIXAMO = chain(
    ("mixamorig:Hips", None),
    ("mixamorig:Spine", "mixamorig:Hips"),
    ("mixamorig:Spine1", "mixamorig:Spine"),
    ("mixamorig:Spine2", "mixamorig:Spine1"),
    ("mixamorig:Neck", "mixamorig:Spine2"),
    ("mixamorig:Head", "mixamorig:Neck"),
    ("mixamorig:HeadTop_End", "mixamorig:Head"),
) + limbs(
    "mixamorig:",
    dict(shoulder="Shoulder", upper_arm="Arm", forearm="ForeArm", hand="Hand", thigh="UpLeg", shin="Leg", foot="Foot", toe="ToeBase"),
    "Hips",
    "Spine2",
    lambda side, base: ("Left" if side == "left" else "Right") + base,
)

UNREAL = chain(
    ("root", None), ("pelvis", "root"), ("spine_01", "pelvis"), ("spine_02", "spine_01"), ("spine_03", "spine_02"),
    ("neck_01", "spine_03"), ("head", "neck_01"),
) + limbs(
    "",
    dict(shoulder="clavicle", upper_arm="upperarm", forearm="lowerarm", hand="hand", thigh="thigh", shin="calf", foot="foot", toe="ball"),
    "pelvis",
    "spine_03",
    lambda side, base: f"{base}_{side[0]}",
)

UNITY = chain(
    ("Hips", None), ("Spine", "Hips"), ("Chest", "Spine"), ("UpperChest", "Chest"), ("Neck", "UpperChest"), ("Head", "Neck"),
) + limbs(
    "",
    dict(shoulder="Shoulder", upper_arm="UpperArm", forearm="LowerArm", hand="Hand", thigh="UpperLeg", shin="LowerLeg", foot="Foot", toe="Toes"),
    "Hips",
    "UpperChest",
    lambda side, base: ("Left" if side == "left" else "Right") + base,
)


@pytest.mark.parametrize(
    "name, expected",
    [
        ("upper_arm.L", ("left", "upperarm")),
        ("thigh.R", ("right", "thigh")),
        ("mixamorig:LeftForeArm", ("left", "forearm")),
        ("mixamorig:RightUpLeg", ("right", "upleg")),
        ("calf_l", ("left", "calf")),
        ("foot-R", ("right", "foot")),
        ("L_Hand", ("left", "hand")),
        ("Left Arm", ("left", "arm")),
        ("Leg", (None, "leg")),
        ("Lowerback", (None, "lowerback")),
        ("Head", (None, "head")),
    ],
)
def test_split_side(name, expected):
    assert bone_map.split_side(name) == expected


@pytest.mark.parametrize(
    "bones, expected",
    [
        (OURS, {"hips": "hips", "spine": "spine", "chest": "chest", "neck": "neck", "head": "head",
                "left": {"upper_arm": "upper_arm.L", "toe": "toe.L", "shin": "shin.L"}}),
        (MIXAMO, {"hips": "mixamorig:Hips", "spine": "mixamorig:Spine", "chest": "mixamorig:Spine2",
                  "neck": "mixamorig:Neck", "head": "mixamorig:Head",
                  "left": {"upper_arm": "mixamorig:LeftArm", "shin": "mixamorig:LeftLeg", "toe": "mixamorig:LeftToeBase"},
                  "right": {"thigh": "mixamorig:RightUpLeg", "forearm": "mixamorig:RightForeArm"}}),
        (UNREAL, {"hips": "pelvis", "spine": "spine_01", "chest": "spine_03", "neck": "neck_01", "head": "head",
                  "left": {"upper_arm": "upperarm_l", "shin": "calf_l", "toe": "ball_l"}}),
        (UNITY, {"hips": "Hips", "spine": "Spine", "chest": "UpperChest", "neck": "Neck", "head": "Head",
                 "right": {"upper_arm": "RightUpperArm", "forearm": "RightLowerArm", "shin": "RightLowerLeg"}}),
    ],
    ids=["footfall", "mixamo", "unreal", "unity"],
)
def test_detects_common_naming_schemes(bones, expected):
    mapping = bone_map.detect(bones)
    for role, bone in expected.items():
        if isinstance(bone, dict):
            for limb, name in bone.items():
                assert mapping[role][limb] == name, (role, limb)
        else:
            assert mapping[role] == bone, role
    bone_map.validate_map(mapping, [b.name for b in bones])


def test_undetectable_rig_lists_every_missing_bone():
    bones = [b for b in OURS if not b.name.startswith("toe")]
    bones = [Bone("Bip01 Head" if b.name == "head" else b.name, b.parent) for b in bones]
    with pytest.raises(bone_map.BoneMapError) as error:
        bone_map.detect(bones, "robot.glb")
    assert error.value.missing == ["left.toe", "right.toe"]
    assert "robot.glb" in str(error.value) and "left.toe, right.toe" in str(error.value)
    assert "profile JSON beside the file" in str(error.value)


def test_validate_map_names_unknown_bones():
    mapping = bone_map.detect(OURS)
    mapping["left"]["hand"] = "paw.L"
    with pytest.raises(bone_map.BoneMapError, match=r"left\.hand"):
        bone_map.validate_map(mapping, [b.name for b in OURS])


def profile_document(**changes):
    document = {
        "format": "footfall-rig-profile", "version": 1,
        "bones": bone_map.detect(OURS),
        "clips": {"walk": "walk", "arms_in": "arms_in", "side_step": None, "idle": "idle"},
        "dimensions": {"hip_height": 0.95, "leg_length": 0.9, "shoulder_width": 0.4, "foot_length": 0.25},
    }
    document.update(changes)
    return document


def test_profile_round_trips(tmp_path):
    path = tmp_path / "rig.json"
    path.write_text(json.dumps(profile_document()))
    profile = rig_profile.load(str(path))
    assert profile.bones["left"]["foot"] == "foot.L"
    assert profile.clips["side_step"] is None
    assert rig_profile.parse(profile.to_document()).dimensions == profile.dimensions


@pytest.mark.parametrize(
    "changes, message",
    [
        ({"format": "other"}, 'format: expected "footfall-rig-profile"'),
        ({"bones": {"hips": "hips"}}, "bones.spine: missing"),
        ({"clips": {"run": "run"}}, "clips.run: unknown behaviour"),
        ({"dimensions": {"hip_height": -1, "leg_length": 0.9, "shoulder_width": 0.4, "foot_length": 0.2}},
         "dimensions.hip_height: expected a positive number of metres, got -1"),
        ({"extra": 1}, "extra: unknown field"),
    ],
)
def test_bad_profiles_name_the_field(changes, message):
    with pytest.raises(rig_profile.ProfileError) as error:
        rig_profile.parse(profile_document(**changes), "rig.json")
    assert str(error.value).startswith("rig.json: ") and message in str(error.value)


def test_partial_profile_is_accepted_for_completion():
    profile = rig_profile.parse({"format": "footfall-rig-profile", "version": 1, "bones": {"left": {"toe": "Toe_L"}}}, partial=True)
    assert profile.bones["left"] == {"toe": "Toe_L"}


def test_measure_dimensions():
    mapping = bone_map.detect(OURS)
    heads, tails = {}, {}
    for side, x in (("L", 0.1), ("R", -0.1)):
        heads[f"thigh.{side}"] = (x, 0.0, 0.95)
        heads[f"shin.{side}"] = (x, 0.0, 0.5)
        heads[f"foot.{side}"] = (x, 0.0, 0.08)
        heads[f"toe.{side}"] = (x, -0.13, 0.02)
        tails[f"toe.{side}"] = (x, -0.18, 0.0)
        heads[f"upper_arm.{side}"] = (2 * x + 0.0, 0.0, 1.45)
    d = rig_measure.measure(mapping, heads, tails)
    assert d["hip_height"] == pytest.approx(0.95)
    assert d["leg_length"] == pytest.approx(0.45 + 0.42)
    assert d["shoulder_width"] == pytest.approx(0.4)
    assert d["foot_length"] == pytest.approx(0.18)
    # With the foot's mesh: heel (5 cm behind the ankle) to the tip (22 cm ahead).
    mesh = {side: [(x, 0.05, 0.0), (x, -0.22, 0.01), (x + 0.03, -0.1, 0.0)] for side, x in (("left", 0.1), ("right", -0.1))}
    assert rig_measure.measure(mapping, heads, tails, mesh)["foot_length"] == pytest.approx(0.27)


def test_reference_size_gives_the_papers_character():
    c, p = character.derive_parameters({"hip_height": 0.95, "leg_length": 0.9, "shoulder_width": 0.4, "foot_length": 0.27})
    assert c["com_height"] == pytest.approx(1.0, abs=0.01)
    assert c["max_step_length"] == pytest.approx(1.0)
    assert c["torso_width"] == pytest.approx(0.6)
    assert c["sole_length"] == pytest.approx(0.27)  # the rig's foot, for footholds on treads
    assert p["gaits"][1] == {"speed": pytest.approx(1.3), "duration": pytest.approx(0.5)}


def test_a_tall_rig_takes_longer_strides(ff):
    from footfall.core import scenario as sc

    def mean_stride(dimensions):
        c, p = character.derive_parameters(dimensions)
        document = sc.scenario_document(
            sc.ScenarioInput(agents=[sc.AgentInput("a", (0, 0), [(12, 0)])], character=c, planner=p)
        )
        (agent,) = sc.plan(document).agents
        walks = [s for s in agent.footsteps if s.kind == ff.StepKind.WALK]
        return sum(math.dist(s.com_start, s.com_end) for s in walks) / len(walks)

    short = mean_stride({"hip_height": 0.7, "leg_length": 0.65, "shoulder_width": 0.3, "foot_length": 0.2})
    tall = mean_stride({"hip_height": 1.1, "leg_length": 1.05, "shoulder_width": 0.46, "foot_length": 0.3})
    assert tall > 1.3 * short


def test_a_rig_the_core_would_refuse_is_named_in_the_users_terms(ff):
    """character.problem asks the core's own checks, and names the rig and
    the measurement a refused field comes from."""
    person = {"hip_height": 0.93, "leg_length": 0.85, "shoulder_width": 0.38, "foot_length": 0.26}
    assert character.problem(person, None, "ann") is None
    small = {key: 0.2 * value for key, value in person.items()}
    assert character.problem(small, None, "tiny.glb") == (
        "rig 'tiny.glb'; its hip height of 0.19 m gives a centre of mass Footfall cannot plan "
        "(character.com_height: must be in [0.2, 3], got 0.1953): scale the rig")
    broad = character.problem({**person, "shoulder_width": 1.4}, None, "ox")
    assert broad.startswith("rig 'ox'; its shoulder width of 1.40 m gives a torso Footfall cannot plan "
                            "(character.torso_width: must be in (0, 1.5], got 1.5")
    stilts = character.problem({**person, "leg_length": 3.0}, None, "stilts")
    assert stilts.startswith("rig 'stilts'; its leg length of 3.00 m gives strides and paces Footfall cannot plan "
                             "(character.left.max_step_length: must be in")
    pose = {limb: [0.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.1] for limb in body_capsules.LIMBS}
    fat = {"height": 1.8, "poses": {b: [{**pose, "torso": [0.0, 0.0, 0.9, 0.0, 0.0, 1.4, 1.2]}]
                                    for b in ("walk", "arms_in", "side_step")}}
    assert character.problem(person, fat, "fat") == (
        "rig 'fat' is 1.80 m tall; its walk clip gives its torso a capsule Footfall cannot plan "
        "(character.behaviors.walk.poses[0].torso: radius must be in (0, 1] m): scale the rig")


def test_an_agent_scaled_past_the_cores_limits_is_named_in_the_users_terms(ff):
    """character.scaled_problem words the core's own refusal of a scaled
    agent (issue 49): the agent, its rig and height, the scale and the height
    it makes, the limits, and which way the scale must go."""
    from footfall.core import scenario

    def pose(radius):  # the clearances rise with the radius: side_step < arms_in < walk
        return [{limb: [0.0, 0.0, 0.5, 0.0, 0.0, 1.0, radius] for limb in body_capsules.LIMBS}]

    def refusal(dimensions, height, scale):
        body = {"height": height, "poses": {"walk": pose(0.12), "arms_in": pose(0.1), "side_step": pose(0.08)}}
        own, planner = character.derive_parameters(dimensions, body)
        document = scenario.scenario_document(scenario.ScenarioInput(
            agents=[scenario.AgentInput("w", (0.0, 0.0), [(5.0, 0.0)], scale=scale)], character=own, planner=planner))
        scenario.parse({**document, "agents": [{**document["agents"][0], "scale": 1.0}]}, "scene")  # plans unscaled
        with pytest.raises(ValueError) as refused:
            scenario.parse(document, "scene")
        return str(refused.value).removeprefix("scene: ")

    giant = {"hip_height": 1.49, "leg_length": 1.36, "shoulder_width": 0.61, "foot_length": 0.42}
    said = refusal(giant, 2.88, 1.1)
    assert said.startswith("agents[0].character.body_height: must be in [0.5, 3], got 3.168"), said
    assert character.scaled_problem(said, "Walker.003", "giant.glb", 2.88, 1.1) == (
        "agent 'Walker.003': its rig 'giant.glb' (2.88 m) at scale 1.10 is 3.17 m tall; Footfall plans bodies "
        "from 0.5 to 3 m: lower its scale to 1.04 or less")
    assert character.scaled_problem(said.replace("got 3.168", "got 0.4"), "tot", None, 0.8, 0.5) == (
        "agent 'tot': the scene's character (0.80 m) at scale 0.50 is 0.40 m tall; Footfall plans bodies "
        "from 0.5 to 3 m: raise its scale to 0.63 or more")
    small = {"hip_height": 0.3, "leg_length": 0.27, "shoulder_width": 0.12, "foot_length": 0.08}
    said = refusal(small, 0.56, 0.6)
    assert character.scaled_problem(said, "kid", "tiny.glb", 0.56, 0.6).startswith(
        "agent 'kid': its rig 'tiny.glb' (0.56 m) at scale 0.60 gives a centre of mass Footfall cannot plan "
        "(character.com_height: must be in [0.2, 3], got 0.18"), said


def test_given_limbs_guide_the_trunk():
    # Thighs detection cannot read: given, they still locate the hips.
    bones = [Bone({"thigh.L": "Femur_A", "thigh.R": "Femur_B"}.get(b.name, b.name),
                  {"thigh.L": "Femur_A", "thigh.R": "Femur_B"}.get(b.parent, b.parent)) for b in OURS]
    mapping, missing = bone_map.detect_partial(bones)
    assert "hips" in missing and "left.thigh" in missing
    mapping, missing = bone_map.detect_partial(bones, {"left": {"thigh": "Femur_A"}, "right": {"thigh": "Femur_B"}})
    assert missing == [] and mapping["hips"] == "hips" and mapping["left"]["thigh"] == "Femur_A"


def test_with_rig_keeps_the_documents_own_overrides():
    document = {"format": "footfall-scenario", "version": 1, "agents": [],
                "character": {"mass": 60.0, "max_step_length": 0.8}}
    result = character.with_rig(document, {"hip_height": 1.1, "leg_length": 1.05, "shoulder_width": 0.46,
                                           "foot_length": 0.3})
    assert result["character"]["mass"] == 60.0 and result["character"]["max_step_length"] == 0.8
    assert result["character"]["com_height"] == pytest.approx(1.155)
    assert len(result["planner"]["gaits"]) == 3
    assert document["character"] == {"mass": 60.0, "max_step_length": 0.8}  # not changed in place


def nameless_humanoid(facing_y=-1.0):
    """A humanoid whose bones are named Bone.000, Bone.001, ... in no order
    of role, facing +-Y, with its rest geometry; and the map by construction."""
    roles = {}  # role -> (parent role, head, tail)

    def add(role, parent, head, tail):
        roles[role] = (parent, head, tail)

    f = facing_y
    add("hips", None, (0, 0, 1.0), (0, 0, 1.1))
    add("spine", "hips", (0, 0, 1.1), (0, 0, 1.25))
    add("chest", "spine", (0, 0, 1.25), (0, 0, 1.45))
    add("neck", "chest", (0, 0, 1.45), (0, 0, 1.55))
    add("head", "neck", (0, 0, 1.55), (0, 0, 1.75))
    for side, x in (("left", -f * 0.1), ("right", f * 0.1)):
        s = 1 if x > 0 else -1
        add(f"{side}.thigh", "hips", (x, 0, 1.0), (x, 0, 0.55))
        add(f"{side}.shin", f"{side}.thigh", (x, 0, 0.55), (x, 0, 0.1))
        add(f"{side}.foot", f"{side}.shin", (x, 0, 0.1), (x, 0.15 * f, 0.03))
        add(f"{side}.toe", f"{side}.foot", (x, 0.15 * f, 0.03), (x, 0.22 * f, 0.03))
        add(f"{side}.clavicle", "chest", (0, 0, 1.42), (s * 0.16, 0, 1.42))
        add(f"{side}.upper_arm", f"{side}.clavicle", (s * 0.16, 0, 1.42), (s * 0.45, 0, 1.4))
        add(f"{side}.forearm", f"{side}.upper_arm", (s * 0.45, 0, 1.4), (s * 0.7, 0, 1.38))
        add(f"{side}.hand", f"{side}.forearm", (s * 0.7, 0, 1.38), (s * 0.78, 0, 1.38))
        for k in range(3):
            add(f"{side}.finger{k}", f"{side}.hand", (s * 0.78, 0.02 * k, 1.38), (s * 0.86, 0.02 * k, 1.38))
    order = sorted(roles)
    random.Random(3).shuffle(order)  # names unrelated to roles
    name = {role: f"Bone.{i:03d}" for i, role in enumerate(order)}
    bones = [Bone(name[r], name[p] if p else None, h, t) for r, (p, h, t) in roles.items()]
    expected = {r: name[r] for r in ("hips", "spine", "chest", "neck", "head")}
    for side in ("left", "right"):
        expected[side] = {role: name[f"{side}.{role}"] for role in bone_map.LIMB_ROLES}
    return bones, expected


@pytest.mark.parametrize("facing_y", [-1.0, 1.0])
def test_bones_with_names_of_no_scheme_are_found_from_the_skeletons_shape(facing_y):
    bones, expected = nameless_humanoid(facing_y)
    assert bone_map.detect(bones) == expected
    # Without their rest geometry they cannot be found, and the error lists the rig's bones.
    with pytest.raises(bone_map.BoneMapError) as error:
        bone_map.detect([Bone(b.name, b.parent) for b in bones], "nameless.glb")
    assert "left.thigh" in str(error.value) and "Its bones: Bone.0" in str(error.value)


def test_a_neck_chain_branching_into_a_face_ends_at_the_head():
    """Rigify's metarig: the chest (spine.003) carries the neck (spine.004,
    spine.005), the head (spine.006, whose one child, the face, starts back at
    its root and carries the face's bones) and breasts pointing forward."""
    bones = [b for b in OURS if b.name not in ("neck", "head")]
    chest = next(b for b in OURS if b.name == "chest")
    geometry = {"spine.004": ((0, 0, 1.45), (0, 0, 1.5)), "spine.005": ((0, 0, 1.5), (0, 0, 1.55)),
                "spine.006": ((0, 0, 1.55), (0, 0, 1.75)), "breast.L": ((0.1, 0, 1.35), (0.1, -0.1, 1.35)),
                "breast.R": ((-0.1, 0, 1.35), (-0.1, -0.1, 1.35)), "face": ((0, 0, 1.55), (0, 0, 1.65)),
                "jaw": ((0, 0, 1.6), (0, -0.1, 1.58)), "nose": ((0, -0.05, 1.65), (0, -0.1, 1.64))}
    parents = {"spine.004": chest.name, "spine.005": "spine.004", "spine.006": "spine.005",
               "breast.L": chest.name, "breast.R": chest.name, "face": "spine.006", "jaw": "face", "nose": "face"}
    bones += [Bone(name, parents[name], *geometry[name]) for name in geometry]
    mapping = bone_map.detect(bones)
    assert (mapping["neck"], mapping["head"]) == ("spine.004", "spine.006")


def test_a_mapping_naming_a_bone_the_rig_lacks_says_which():
    mapping = bone_map.detect(OURS)
    mapping["left"]["foot"] = "Foot_L"
    with pytest.raises(bone_map.BoneMapError) as error:
        bone_map.validate_map(mapping, [b.name for b in OURS], "robot.glb")
    message = str(error.value)
    assert "names bones 'robot.glb' does not have: left.foot = 'Foot_L'" in message
    assert "could not find" not in message and "Its bones: hips" in message
