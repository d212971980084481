"""Shared by the Blender tests: how far a planted foot's contact point is
from the plan. A foot rolls (footfall.core.foot_roll): on its heel after
heel strike, flat on the planned spot, then on its ball; whichever it rests
on must stay where the plan puts it."""

import math

import bpy
from mathutils import Matrix, Vector


class FootRest:
    """One side's foot of an imported rig at rest, in the world: the ankle,
    the ball and the heel's contact, and the rig's facing."""

    def __init__(self, rig, profile, side):
        from footfall.bridge.rig_import import foot_skin
        from footfall.core import foot_roll

        world = rig.matrix_world
        bones = rig.data.bones
        forward = Vector((0.0, 0.0, 0.0))
        for s in ("left", "right"):
            foot = bones[profile.bones[s]["foot"]]
            forward += world @ foot.tail_local - world @ foot.head_local
        self.yaw = math.atan2(forward.y, forward.x)
        forward = Vector((math.cos(self.yaw), math.sin(self.yaw), 0.0))
        self.foot, self.toe = profile.bones[side]["foot"], profile.bones[side]["toe"]
        self.ankle = world @ bones[self.foot].head_local
        self.ball = world @ bones[self.toe].head_local
        shape = foot_roll.foot_shape(self.ankle, self.ball, forward, profile.dimensions["foot_length"],
                                     foot_skin(rig, profile.bones)[side])
        self.heel = Vector((self.ankle.x, self.ankle.y, 0.0)) - shape.heel_back * forward

    def error(self, armature, pose, ground: float = 0.0) -> float:
        """The distance of the nearest of the posed ankle, ball and heel to
        where the plan's foot `pose` puts it on a floor at height `ground`
        (an evaluated instance `armature`, whose armature space is the world,
        times its scale for an agent of another size)."""
        scale = armature.matrix_world.to_scale().x
        turn = scale * Matrix.Rotation(pose.orientation - self.yaw, 3, "Z")
        ankle = Vector((pose.position[0], pose.position[1], ground + scale * self.ankle.z))
        planned = {"ankle": ankle, "ball": ankle + turn @ (self.ball - self.ankle),
                   "heel": ankle + turn @ (self.heel - self.ankle)}
        foot = armature.pose.bones[self.foot]
        rest = armature.data.bones[self.foot].matrix_local
        posed = {"ankle": foot.head, "ball": armature.pose.bones[self.toe].head,
                 "heel": foot.matrix @ rest.inverted() @ self.heel}
        world = armature.matrix_world
        return min((world @ posed[k] - planned[k]).length for k in planned)


def plan_errors(ff, plan, rig, profile):
    """The farthest any planted foot's contact point (heel, ankle or ball, as
    it rolls) is from the plan (on its ground: flat treads and floors), and
    the hips from the COM, in the world at every frame, for agents animated
    on `rig` (profile `profile`): (foot, pelvis, stance samples)."""
    feet = {side: FootRest(rig, profile, side) for side in ("left", "right")}
    ground = ff.Ground(plan.ground)  # flat treads: a planted foot lies flat on the ground under it

    def under(position) -> float:
        if ground.empty():
            return 0.0
        return ground.standing_height(position[0], position[1], plan.character.body_height)
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    worst_foot, worst_pelvis, stance_frames = 0.0, 0.0, 0
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        t = (frame - scene.frame_start) / fps
        for agent in plan.agents:
            armature = bpy.data.objects[agent.name].evaluated_get(bpy.context.evaluated_depsgraph_get())
            world = armature.matrix_world
            for side, pose in zip(("left", "right"), ff.feet_at(agent, t)):
                if not pose.planted:
                    continue
                stance_frames += 1
                worst_foot = max(worst_foot, feet[side].error(armature, pose, under(pose.position)))
            hips = world @ armature.pose.bones[profile.bones["hips"]].head
            worst_pelvis = max(worst_pelvis, math.dist(hips.xy, ff.com_at(agent, t).position))
    print(f"stance samples {stance_frames}, worst foot error {worst_foot * 1000:.2f} mm, "
          f"worst pelvis error {worst_pelvis * 100:.2f} cm")
    return worst_foot, worst_pelvis, stance_frames
