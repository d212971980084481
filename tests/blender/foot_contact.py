"""Shared by the Blender tests: how far a planted foot's contact point is
from the plan. A foot rolls (footfall.core.foot_roll): on its heel after
heel strike, flat on the planned spot, then on its ball; whichever it rests
on must stay where the plan puts it."""

import math

from mathutils import Matrix, Vector


class FootRest:
    """One side's foot of an imported rig at rest, in the world: the ankle,
    the ball and the heel's contact, and the rig's facing."""

    def __init__(self, rig, profile, side):
        from footfall.bridge.rig_import import foot_points
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
                                     foot_points(rig, profile.bones)[side])
        self.heel = Vector((self.ankle.x, self.ankle.y, 0.0)) - shape.heel_back * forward

    def error(self, armature, pose) -> float:
        """The distance of the nearest of the posed ankle, ball and heel to
        where the plan's foot `pose` puts it (an evaluated instance
        `armature`, whose armature space is the world, times its scale for
        an agent of another size)."""
        scale = armature.matrix_world.to_scale().x
        turn = scale * Matrix.Rotation(pose.orientation - self.yaw, 3, "Z")
        ankle = Vector((pose.position[0], pose.position[1], scale * self.ankle.z))
        planned = {"ankle": ankle, "ball": ankle + turn @ (self.ball - self.ankle),
                   "heel": ankle + turn @ (self.heel - self.ankle)}
        foot = armature.pose.bones[self.foot]
        rest = armature.data.bones[self.foot].matrix_local
        posed = {"ankle": foot.head, "ball": armature.pose.bones[self.toe].head,
                 "heel": foot.matrix @ rest.inverted() @ self.heel}
        world = armature.matrix_world
        return min((world @ posed[k] - planned[k]).length for k in planned)
