"""Build Footfall's own humanoid rig asset from nothing and export it.

Run:
    blender -b --factory-startup --python rigs/make_humanoid.py -- [OUT_DIR]

OUT_DIR defaults to this script's folder. Writes footfall_humanoid.glb (skinned
low-poly body, armature, four upper-body animation clips) and
footfall_humanoid.json (the rig profile: bone map, clip names, dimensions).

Conventions (Blender world space, Z up, metres):
- the character faces -Y (Blender's front view looks along +Y at its face),
  its left side is +X, the soles are on z = 0, the top of the head at 1.80 m;
- bones follow Rigify names (hips, spine, chest, neck, head, upper_arm.L, ...);
- the rest pose is an A-pose (arms 45 degrees down), legs straight with the
  knees 12 mm forward of the hip-ankle line so an IK solver knows the bend side;
- the clips key only spine, chest, neck, head and the arm bones (quaternions);
  hips and legs are left unkeyed: they are driven later by IK from a footstep plan.
- foot_length in the profile INCLUDES THE HEEL: ground distance from the foot
  bone's head (ankle) to the toe bone's tail (0.195 m) plus how far the
  foot's mesh reaches behind the ankle (0.065 m) = 0.26 m. The toe bone's tail
  sits exactly at the front of the toe mesh (glTF keeps no bone tails, so a
  reader can find the tip from the mesh);
- clips are keyed on frames 1..25 (1 s) or 1..49 (idle, 2 s), the last key equal
  to the first; Blender's exporter writes glTF times as frame / fps, so the
  clips run from t = 1/24 s to 25/24 s (49/24 s), not from 0;
- walk phase: the left arm is forward (in front of the body, -Y) during the
  first half of the cycle, most forward at 1/4 cycle, which is when the right
  leg is forward; most back at 3/4 cycle.

Everything is computed from constants below; no randomness, no downloaded
assets, so every run gives the same mesh, bones and keys (the glTF exporter
writes its own generator string, the only metadata).
"""

import json
import math
import os
import sys

import bpy
from mathutils import Quaternion, Vector

FPS = 24
ARMATURE_NAME = "footfall_humanoid"
MESH_NAME = "footfall_humanoid_body"
GLB_NAME = "footfall_humanoid.glb"
JSON_NAME = "footfall_humanoid.json"

# ---------------------------------------------------------------------------
# Skeleton (rest pose, armature space = world space, Z up, facing -Y)
# ---------------------------------------------------------------------------
S45 = math.sqrt(0.5)
SHOULDER = Vector((0.19, 0.0, 1.44))
ARM_DIR = Vector((S45, 0.0, -S45))  # A-pose: 45 degrees down, left side
UPPER_ARM_LEN, FOREARM_LEN, HAND_LEN = 0.29, 0.26, 0.18
HIP = Vector((0.09, 0.0, 0.93))
KNEE = Vector((0.09, -0.012, 0.505))
ANKLE = Vector((0.09, 0.0, 0.085))
BALL = Vector((0.09, -0.135, 0.025))
TOE_TIP = Vector((0.09, -0.195, 0.025))
HEEL_Y = 0.065  # back of the heel, behind the ankle (ankle at y = 0)


def mirror(v):
    return Vector((-v.x, v.y, v.z))


def bone_table():
    """(name, head, tail, parent, connected, roll_up_vector) in rest pose."""
    elbow = SHOULDER + ARM_DIR * UPPER_ARM_LEN
    wrist = elbow + ARM_DIR * FOREARM_LEN
    hand_tip = wrist + ARM_DIR * HAND_LEN
    fwd, up = Vector((0, -1, 0)), Vector((0, 0, 1))
    table = [
        ("hips", (0, 0, 0.95), (0, 0, 1.05), None, False, fwd),
        ("spine", (0, 0, 1.05), (0, 0, 1.25), "hips", True, fwd),
        ("chest", (0, 0, 1.25), (0, 0, 1.47), "spine", True, fwd),
        ("neck", (0, 0, 1.47), (0, 0, 1.60), "chest", True, fwd),
        ("head", (0, 0, 1.60), (0, 0, 1.80), "neck", True, fwd),
    ]
    for side, m in (("L", lambda v: Vector(v)), ("R", mirror)):
        table += [
            (f"upper_arm.{side}", m(SHOULDER), m(elbow), "chest", False, fwd),
            (f"forearm.{side}", m(elbow), m(wrist), f"upper_arm.{side}", True, fwd),
            (f"hand.{side}", m(wrist), m(hand_tip), f"forearm.{side}", True, fwd),
            (f"thigh.{side}", m(HIP), m(KNEE), "hips", False, fwd),
            (f"shin.{side}", m(KNEE), m(ANKLE), f"thigh.{side}", True, fwd),
            (f"foot.{side}", m(ANKLE), m(BALL), f"shin.{side}", True, up),
            (f"toe.{side}", m(BALL), m(TOE_TIP), f"foot.{side}", True, up),
        ]
    return table


# ---------------------------------------------------------------------------
# Mesh: lofted rings (tubes, boxes, spheres) joined into one mesh, each vertex
# weighted by a small function of its rest position.
# ---------------------------------------------------------------------------
class MeshBuilder:
    def __init__(self):
        self.verts, self.faces, self.smooth, self.weights = [], [], [], []

    def loft(self, sections, segments, weight_fn, smooth=True, angle0=0.0, caps=(True, True)):
        """sections: [(centre, u_axis, v_axis, ru, rv)], rings joined in order."""
        rings = []
        for centre, u, v, ru, rv in sections:
            ring = []
            for k in range(segments):
                a = angle0 + 2.0 * math.pi * k / segments
                p = Vector(centre) + Vector(u) * (ru * math.cos(a)) + Vector(v) * (rv * math.sin(a))
                ring.append(self._vert(p, weight_fn))
            rings.append(ring)
        for r0, r1 in zip(rings, rings[1:]):
            for k in range(segments):
                k1 = (k + 1) % segments
                self._face([r0[k], r0[k1], r1[k1], r1[k]], smooth)
        if caps[0]:
            self._face(list(reversed(rings[0])), smooth)
        if caps[1]:
            self._face(list(rings[-1]), smooth)

    def tube(self, points, radii, segments, weight_fn, side=None, flatten=1.0, smooth=True, angle0=0.0):
        """A tube through points (a polyline) with one radius per point."""
        sections = []
        for i, p in enumerate(points):
            p = Vector(p)
            d = (Vector(points[min(i + 1, len(points) - 1)]) - Vector(points[max(i - 1, 0)])).normalized()
            s = Vector(side) if side is not None else (Vector((1, 0, 0)) if abs(d.x) < 0.9 else Vector((0, 1, 0)))
            u = (s - d * s.dot(d)).normalized()
            v = d.cross(u)
            sections.append((p, u, v, radii[i], radii[i] * flatten))
        self.loft(sections, segments, weight_fn, smooth, angle0)

    def box(self, start, end, side, half_u0, half_v0, half_u1, half_v1, weight_fn, v_axis=None):
        """A tapered box between two face centres (4-segment loft turned 45 degrees)."""
        d = (Vector(end) - Vector(start)).normalized()
        u = (Vector(side) - d * Vector(side).dot(d)).normalized()
        v = Vector(v_axis) if v_axis is not None else d.cross(u)
        if u.cross(v).dot(d) < 0:  # keep (u, v, d) right-handed so faces point outwards
            v = -v
        k = math.sqrt(2.0)
        self.loft(
            [(start, u, v, half_u0 * k, half_v0 * k), (end, u, v, half_u1 * k, half_v1 * k)],
            4, weight_fn, smooth=False, angle0=math.pi / 4,
        )

    def ellipsoid(self, centre, radii, segments, rings, weight_fn):
        c, (rx, ry, rz) = Vector(centre), radii
        top = self._vert(c + Vector((0, 0, rz)), weight_fn)
        bottom = self._vert(c - Vector((0, 0, rz)), weight_fn)
        grid = []
        for i in range(1, rings):
            t = math.pi * i / rings
            ring = []
            for k in range(segments):
                a = 2.0 * math.pi * k / segments
                p = c + Vector((rx * math.sin(t) * math.cos(a), ry * math.sin(t) * math.sin(a), rz * math.cos(t)))
                ring.append(self._vert(p, weight_fn))
            grid.append(ring)
        for k in range(segments):
            k1 = (k + 1) % segments
            self._face([top, grid[0][k], grid[0][k1]], True)
            self._face([bottom, grid[-1][k1], grid[-1][k]], True)
        for r0, r1 in zip(grid, grid[1:]):
            for k in range(segments):
                k1 = (k + 1) % segments
                self._face([r0[k], r1[k], r1[k1], r0[k1]], True)

    def _vert(self, p, weight_fn):
        self.verts.append(tuple(p))
        w = {b: x for b, x in weight_fn(Vector(p)).items() if x > 1e-6}
        total = sum(w.values())
        self.weights.append({b: x / total for b, x in w.items()})
        return len(self.verts) - 1

    def _face(self, idx, smooth):
        self.faces.append(tuple(idx))
        self.smooth.append(smooth)


def blend(value, controls):
    """Piecewise-linear weights: controls = [(value, bone), ...] sorted by value;
    at each control value the named bone has weight 1, in between they blend."""
    if value <= controls[0][0]:
        return {controls[0][1]: 1.0}
    for (v0, b0), (v1, b1) in zip(controls, controls[1:]):
        if value <= v1:
            t = (value - v0) / (v1 - v0) if v1 > v0 else 1.0
            t = t * t * (3 - 2 * t)  # smoothstep
            out = {b0: 1.0 - t}
            out[b1] = out.get(b1, 0.0) + t
            return out
    return {controls[-1][1]: 1.0}


def build_body():
    mb = MeshBuilder()
    X, Y, Z = Vector((1, 0, 0)), Vector((0, 1, 0)), Vector((0, 0, 1))

    # Torso: pelvis, belly, chest and shoulders as one elliptic loft.
    torso_w = lambda p: blend(p.z, [(1.00, "hips"), (1.10, "spine"), (1.20, "spine"), (1.30, "chest"), (1.45, "chest"), (1.50, "neck")])
    profile = [  # z, half width (x), half depth (y), y offset
        (0.835, 0.140, 0.090, 0.000), (0.90, 0.175, 0.112, 0.005), (1.00, 0.165, 0.110, 0.000),
        (1.11, 0.145, 0.100, -0.005), (1.24, 0.160, 0.110, -0.010), (1.35, 0.180, 0.118, -0.010),
        (1.43, 0.175, 0.105, 0.000), (1.475, 0.120, 0.085, 0.005), (1.50, 0.065, 0.060, 0.005),
    ]
    mb.loft([((0, yo, z), X, Y, rx, ry) for z, rx, ry, yo in profile], 16, torso_w)

    # Neck and head (with a nose so the front reads in a render).
    mb.tube([(0, 0.005, 1.46), (0, 0.0, 1.56), (0, -0.005, 1.63)], [0.052, 0.048, 0.050], 12,
            lambda p: blend(p.z, [(1.47, "chest"), (1.52, "neck"), (1.58, "neck"), (1.63, "head")]))
    head_w = lambda p: {"head": 1.0}
    mb.ellipsoid((0, -0.01, 1.69), (0.082, 0.100, 0.112), 16, 10, head_w)
    mb.box((0, -0.100, 1.685), (0, -0.128, 1.672), X, 0.012, 0.020, 0.008, 0.010, head_w, v_axis=Z)

    for side in ("L", "R"):
        m = (lambda v: Vector(v)) if side == "L" else mirror
        sx = 1.0 if side == "L" else -1.0
        ua, fa, hd = f"upper_arm.{side}", f"forearm.{side}", f"hand.{side}"
        th, sh, ft, to = f"thigh.{side}", f"shin.{side}", f"foot.{side}", f"toe.{side}"
        shoulder, adir = m(SHOULDER), m(ARM_DIR)
        elbow = shoulder + adir * UPPER_ARM_LEN
        wrist = elbow + adir * FOREARM_LEN

        def arm_w(p, shoulder=shoulder, adir=adir, ua=ua, fa=fa, hd=hd, side=side):
            s = (p - shoulder).dot(adir)
            return blend(s, [(-0.02, "chest"), (0.05, ua), (UPPER_ARM_LEN - 0.035, ua), (UPPER_ARM_LEN + 0.035, fa),
                             (UPPER_ARM_LEN + FOREARM_LEN - 0.02, fa), (UPPER_ARM_LEN + FOREARM_LEN + 0.02, hd)])

        # Shoulder cap, upper arm, forearm (a little flattened front to back).
        mb.ellipsoid(shoulder + Vector((0, 0, 0.005)), (0.062, 0.060, 0.058), 12, 6, arm_w)
        mb.tube([shoulder, shoulder + adir * 0.15, elbow], [0.050, 0.046, 0.038], 10, arm_w, side=(0, 1, 0), flatten=0.9)
        mb.tube([elbow, elbow + adir * 0.09, wrist + adir * 0.01], [0.038, 0.040, 0.028], 10, arm_w, side=(0, 1, 0), flatten=0.8)
        # Hand: a flat paddle (palm facing down-in, width along Y) plus a thumb.
        palm_n = Vector((0, 1, 0)).cross(adir).normalized()
        mb.box(wrist - adir * 0.01, wrist + adir * 0.10, Y, 0.042, 0.016, 0.045, 0.014, arm_w, v_axis=palm_n)
        mb.box(wrist + adir * 0.10, wrist + adir * HAND_LEN, Y, 0.043, 0.011, 0.036, 0.008, arm_w, v_axis=palm_n)
        thumb0 = wrist + adir * 0.03 + Vector((0, -0.038, 0)) + palm_n * 0.006
        mb.box(thumb0, thumb0 + (adir * 0.7 + Vector((0, -0.3, 0))).normalized() * 0.07, palm_n, 0.011, 0.011, 0.009, 0.009, arm_w)

        # Legs: thigh and shin tubes, weighted along z.
        hip, knee, ankle = m(HIP), m(KNEE), m(ANKLE)

        def leg_w(p, th=th, sh=sh, ft=ft):
            return blend(p.z, [(0.105, ft), (0.15, sh), (0.47, sh), (0.54, th), (0.87, th), (0.95, "hips")])

        mb.tube([hip + Vector((sx * 0.005, 0.005, 0.04)), hip + Vector((sx * 0.003, 0.0, -0.12)), knee],
                [0.080, 0.075, 0.052], 12, leg_w)
        mb.tube([knee, knee + Vector((0, 0.008, -0.12)), ankle + Vector((0, 0.005, 0.06)), ankle + Vector((0, 0.0, 0.0))],
                [0.052, 0.055, 0.036, 0.034], 12, leg_w)

        # Foot: heel-to-ball block (foot bone) and toe block (toe bone); soles at z = 0.
        def foot_w(p, ft=ft, to=to):
            return blend(-p.y, [(-BALL.y - 0.02, ft), (-BALL.y + 0.015, to)])

        fx = m(Vector((BALL.x, 0, 0))).x
        mb.box((fx, HEEL_Y, 0.045), (fx, BALL.y, 0.0275), X, 0.040, 0.045, 0.050, 0.0275, foot_w, v_axis=Z)
        mb.box((fx, BALL.y, 0.0275), (fx, TOE_TIP.y, 0.02), X, 0.050, 0.0275, 0.046, 0.020, foot_w, v_axis=Z)
    return mb


# ---------------------------------------------------------------------------
# Animation: each clip is a function phase -> {bone: G}, G a rotation in
# armature axes applied about the bone's head relative to its parent; it is
# turned into the bone's local quaternion q = R_rest^-1 G R_rest.
# ---------------------------------------------------------------------------
def rot(axis, degrees):
    return Quaternion(Vector(axis).normalized(), math.radians(degrees))


def arm_pose(side, hang, swing, elbow_flex, elbow_in=0.0, wrist_flex=0.0):
    """hang: degrees of the upper arm from vertical (45 = rest A-pose);
    swing: degrees forward (+) / back (-); elbow_flex: forearm bend forward;
    elbow_in: forearm turned towards the body; wrist_flex: hand bend forward."""
    sx = 1.0 if side == "L" else -1.0
    adir = Vector((sx * S45, 0, -S45))
    fwd = Vector((0, -1, 0))
    lower = rot((0, sx, 0), 45.0 - hang)  # about +Y lowers the left arm
    flex_axis = adir.cross(fwd)  # rotating about it moves the rest arm forward
    return {
        f"upper_arm.{side}": rot((1, 0, 0), -swing) @ lower,
        f"forearm.{side}": rot(flex_axis, elbow_flex) @ rot((0, sx, 0), elbow_in),
        f"hand.{side}": rot(flex_axis, wrist_flex),
    }


def torso_pose(spine=(0, 0, 0), chest=(0, 0, 0), neck=(0, 0, 0), head=(0, 0, 0)):
    """Each tuple: (pitch forward, roll to the character's left, yaw) in degrees."""
    def g(p):
        return rot((0, 0, 1), p[2]) @ rot((0, 1, 0), p[1]) @ rot((1, 0, 0), p[0])
    return {"spine": g(spine), "chest": g(chest), "neck": g(neck), "head": g(head)}


def walk(phase):
    s, s2 = math.sin(2 * math.pi * phase), math.sin(4 * math.pi * phase)
    pose = torso_pose(spine=(2.0, 0, -1.5 * s), chest=(0.6 * s2, 0, -3.0 * s),
                      neck=(0, 0, 2.0 * s), head=(-2.0 - 0.6 * s2, 0, 2.5 * s))
    pose.update(arm_pose("L", hang=12, swing=20 * s, elbow_flex=14 + 9 * s, wrist_flex=5))
    pose.update(arm_pose("R", hang=12, swing=-20 * s, elbow_flex=14 - 9 * s, wrist_flex=5))
    return pose


def arms_in(phase):
    s, s2 = math.sin(2 * math.pi * phase), math.sin(4 * math.pi * phase)
    pose = torso_pose(spine=(2.0, 0, -1.0 * s), chest=(0.4 * s2, 0, -2.0 * s),
                      neck=(0, 0, 1.2 * s), head=(-2.0 - 0.4 * s2, 0, 1.8 * s))
    pose.update(arm_pose("L", hang=6, swing=2.5 * s, elbow_flex=3 + 1 * s, elbow_in=6, wrist_flex=2))
    pose.update(arm_pose("R", hang=6, swing=-2.5 * s, elbow_flex=3 - 1 * s, elbow_in=6, wrist_flex=2))
    return pose


def side_step(phase):
    # One lateral step per cycle: the body sways towards the stepping side and
    # back; the head stays level; arms hang and only drift with the sway.
    s = math.sin(2 * math.pi * phase)
    pose = torso_pose(spine=(1.0, 2.0 * s, 0), chest=(0, 1.5 * s, 0), neck=(0, -1.5 * s, 0), head=(-1.0, -2.0 * s, 0))
    pose.update(arm_pose("L", hang=11 - 2.0 * s, swing=1.5 * s, elbow_flex=10))
    pose.update(arm_pose("R", hang=11 + 2.0 * s, swing=1.5 * s, elbow_flex=10))
    return pose


def idle(phase):
    # Breathing: in on the first half (chest lifts a little, shoulders rise), out on the second.
    b = 0.5 - 0.5 * math.cos(2 * math.pi * phase)
    s = math.sin(2 * math.pi * phase)
    pose = torso_pose(spine=(0.5 - 0.6 * b, 0, 0), chest=(-1.2 * b, 0.3 * s, 0),
                      neck=(0.6 * b, 0, 0.8 * s), head=(1.1 * b - 0.5, -0.3 * s, 0.6 * s))
    pose.update(arm_pose("L", hang=9 + 1.5 * b, swing=0.5 * s, elbow_flex=9 + 1.5 * b, wrist_flex=4))
    pose.update(arm_pose("R", hang=9 + 1.5 * b, swing=0.5 * s, elbow_flex=9 + 1.5 * b, wrist_flex=4))
    return pose


CLIPS = [  # name, pose function, cycle length in frames (at 24 fps)
    ("walk", walk, 24),
    ("arms_in", arms_in, 24),
    ("side_step", side_step, 24),
    ("idle", idle, 48),
]


def make_action(arm_obj, name, pose_fn, frames):
    action = bpy.data.actions.new(name)
    rest = {b.name: b.matrix_local.to_quaternion() for b in arm_obj.data.bones}
    samples = [pose_fn(i / frames) for i in range(frames + 1)]  # frames 1..frames+1, last == first
    for bone in sorted(samples[0]):
        path = f'pose.bones["{bone}"].rotation_quaternion'
        quats = []
        for pose in samples:
            q = rest[bone].conjugated() @ pose[bone] @ rest[bone]
            q.normalize()
            if quats and quats[-1].dot(q) < 0:
                q.negate()
            quats.append(q)
        for index in range(4):
            fc = action.fcurves.new(path, index=index, action_group=bone)
            fc.keyframe_points.add(len(quats))
            co = []
            for i, q in enumerate(quats):
                co += [1.0 + i, q[index]]
            fc.keyframe_points.foreach_set("co", co)
            for kp in fc.keyframe_points:
                kp.interpolation = "LINEAR"
            fc.update()
    action.use_frame_range = True
    action.frame_start, action.frame_end = 1, 1 + frames
    action.use_cyclic = True
    return action


# ---------------------------------------------------------------------------
def measure(arm_obj, mesh_obj):
    """Rig-profile dimensions from the armature's rest pose in world space."""
    mw = arm_obj.matrix_world
    bones = arm_obj.data.bones
    head = lambda n: mw @ bones[n].head_local
    tail = lambda n: mw @ bones[n].tail_local
    flat = lambda v: Vector((v.x, v.y))
    hip_h, leg, foot = [], [], []
    verts = [mesh_obj.matrix_world @ v.co for v in mesh_obj.data.vertices]
    gidx = {g.name: g.index for g in mesh_obj.vertex_groups}
    for side in ("L", "R"):
        hip_h.append(head(f"thigh.{side}").z)
        leg.append((head(f"thigh.{side}") - head(f"shin.{side}")).length
                   + (head(f"shin.{side}") - head(f"foot.{side}")).length)
        ankle, tip = flat(head(f"foot.{side}")), flat(tail(f"toe.{side}"))
        ahead = (tip - ankle).normalized()
        # Foot length = ground distance ankle -> toe tail, plus the heel: how far
        # the foot.<side> vertices reach behind the ankle along the foot's ground axis.
        foot_verts = [verts[v.index] for v in mesh_obj.data.vertices
                      if any(g.group == gidx[f"foot.{side}"] and g.weight > 0.5 for g in v.groups)]
        heel = max(0.0, max(-(flat(p) - ankle).dot(ahead) for p in foot_verts))
        foot.append((tip - ankle).length + heel)
    return {
        "hip_height": round(sum(hip_h) / 2, 4),
        "leg_length": round(sum(leg) / 2, 4),
        "shoulder_width": round((head("upper_arm.L") - head("upper_arm.R")).length, 4),
        "foot_length": round(sum(foot) / 2, 4),
    }


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out_dir = os.path.abspath(argv[0]) if argv else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(out_dir, exist_ok=True)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = FPS, 1.0
    scene.frame_start, scene.frame_end = 1, 1 + max(f for _, _, f in CLIPS)

    # Armature.
    arm_data = bpy.data.armatures.new(ARMATURE_NAME)
    arm_obj = bpy.data.objects.new(ARMATURE_NAME, arm_data)
    scene.collection.objects.link(arm_obj)
    bpy.context.view_layer.objects.active = arm_obj
    bpy.ops.object.mode_set(mode="EDIT")
    for name, head, tail, parent, connected, roll_up in bone_table():
        eb = arm_data.edit_bones.new(name)
        eb.head, eb.tail = Vector(head), Vector(tail)
        eb.align_roll(roll_up)
        if parent:
            eb.parent = arm_data.edit_bones[parent]
            eb.use_connect = connected
    bpy.ops.object.mode_set(mode="OBJECT")
    for pb in arm_obj.pose.bones:
        pb.rotation_mode = "QUATERNION"

    # Body mesh, weights, material.
    mb = build_body()
    me = bpy.data.meshes.new(MESH_NAME)
    me.from_pydata(mb.verts, [], mb.faces)
    me.polygons.foreach_set("use_smooth", mb.smooth)
    me.validate()
    me.update()
    mesh_obj = bpy.data.objects.new(MESH_NAME, me)
    scene.collection.objects.link(mesh_obj)
    groups = {b.name: mesh_obj.vertex_groups.new(name=b.name) for b in arm_data.bones}
    for vi, w in enumerate(mb.weights):
        for bone in sorted(w):
            groups[bone].add([vi], w[bone], "REPLACE")
    mat = bpy.data.materials.new("footfall_skin")
    mat.diffuse_color = (0.62, 0.60, 0.56, 1.0)
    mat.roughness = 0.6
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.62, 0.60, 0.56, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.6
    me.materials.append(mat)
    mesh_obj.parent = arm_obj
    mod = mesh_obj.modifiers.new("Armature", "ARMATURE")
    mod.object = arm_obj

    # Actions, each alone on an NLA track of the same name (one glTF animation each).
    arm_obj.animation_data_create()
    for name, fn, frames in CLIPS:
        action = make_action(arm_obj, name, fn, frames)
        track = arm_obj.animation_data.nla_tracks.new()
        track.name = name
        track.strips.new(name, 1, action)
        track.mute = True  # keep the rest pose in the scene; the exporter reads strips anyway
    arm_obj.animation_data.action = None
    scene.frame_set(1)

    dims = measure(arm_obj, mesh_obj)
    tris = sum(len(p.vertices) - 2 for p in me.polygons)

    glb_path = os.path.join(out_dir, GLB_NAME)
    bpy.ops.export_scene.gltf(
        filepath=glb_path,
        export_format="GLB",
        use_selection=False,  # the scene holds only the armature and the body
        export_yup=True,
        export_apply=False,
        export_skins=True,
        export_all_influences=False,
        export_def_bones=False,
        export_animations=True,
        export_nla_strips=True,
        export_force_sampling=True,
        export_frame_step=1,
        export_optimize_animation_size=True,  # drops the unkeyed (constant) hips/leg channels
        export_anim_single_armature=False,
        export_reset_pose_bones=True,
        export_current_frame=False,
        export_cameras=False,
        export_lights=False,
        export_extras=False,
        export_morph=False,
        export_materials="EXPORT",
    )

    profile = {
        "format": "footfall-rig-profile", "version": 1,
        "rig": GLB_NAME,
        "facing": "-Y",
        "bones": {
            "hips": "hips", "spine": "spine", "chest": "chest", "neck": "neck", "head": "head",
            "left": {k: f"{k}.L" for k in ("upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe")},
            "right": {k: f"{k}.R" for k in ("upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe")},
        },
        "clips": {name: name for name, _, _ in CLIPS},
        "dimensions": dims,
    }
    json_path = os.path.join(out_dir, JSON_NAME)
    with open(json_path, "w") as f:
        f.write(format_profile(profile))

    print(f"footfall_humanoid: {len(me.vertices)} verts, {tris} tris, {len(arm_data.bones)} bones, "
          f"clips {','.join(n for n, _, _ in CLIPS)}, hip_height={dims['hip_height']:.4f} "
          f"leg_length={dims['leg_length']:.4f} shoulder_width={dims['shoulder_width']:.4f} "
          f"foot_length={dims['foot_length']:.4f} -> {glb_path}, {json_path}")


def format_profile(p):
    """The profile laid out like the documented format, numbers with 4 decimals."""
    q = json.dumps
    side = lambda d: "{" + ", ".join(f"{q(k)}: {q(v)}" for k, v in d.items()) + "}"
    b = p["bones"]
    dims = ", ".join(f"{q(k)}: {v:.4f}" for k, v in p["dimensions"].items())
    return (
        "{\n"
        f'  "format": {q(p["format"])}, "version": {p["version"]},\n'
        f'  "rig": {q(p["rig"])},\n'
        f'  "facing": {q(p["facing"])},\n'
        '  "bones": {\n'
        "    " + ", ".join(f"{q(k)}: {q(b[k])}" for k in ("hips", "spine", "chest", "neck", "head")) + ",\n"
        f'    "left":  {side(b["left"])},\n'
        f'    "right": {side(b["right"])}\n'
        "  },\n"
        f'  "clips": {side(p["clips"])},\n'
        f'  "dimensions": {{{dims}}}\n'
        "}\n"
    )


main()
