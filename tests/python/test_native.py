"""footfall._native from Python: planning, errors as Python exceptions, GIL, cancel."""

import json
import math
import sys
import threading
from time import perf_counter

import pytest

from conftest import scenario_json, slot_scenario_json


def test_demo_plans_to_the_goal(ff):
    plan = ff.plan_scenario(ff.demo_scenario())
    assert all(agent.status == ff.AgentStatus.REACHED for agent in plan.agents)
    walker = plan.agents[0]
    assert walker.footsteps[-1].kind == ff.StepKind.STOP
    goal = ff.demo_scenario().agents[0].goals[0]
    assert math.dist(walker.footsteps[-1].com_end, goal) < 1.0
    feet = ff.feet_at(walker, walker.footsteps[2].start_time + 0.1)
    assert len(feet) == 2 and not all(f.planted for f in feet)


def test_sample_motion_is_com_at_and_feet_at_at_every_time(ff):
    walker = ff.plan_scenario(ff.demo_scenario()).agents[0]
    times = [-1.0, 0.0, walker.footsteps[2].start_time + 0.1, walker.end_time() / 2, walker.end_time() + 3]
    com, feet, yaw, lift, planted = ff.sample_motion(walker, times)
    assert com.shape == (5, 2) and feet.shape == (5, 2, 2) and planted.dtype == bool
    for i, t in enumerate(times):
        assert tuple(com[i]) == tuple(ff.com_at(walker, t).position)
        for side, pose in enumerate(ff.feet_at(walker, t)):
            assert tuple(feet[i, side]) == tuple(pose.position)
            assert (yaw[i, side], lift[i, side], planted[i, side]) == (pose.orientation, pose.lift, pose.planted)
    assert not planted[2].all()  # a foot swings in the third step


def test_create_footstep_from_python(ff):
    character = ff.CharacterParams()
    start = ff.standing_state((0.0, 0.0), 0.0, character)
    action = ff.FootstepAction(ff.StepKind.WALK, ff.Foot.LEFT, -0.1, 1.0, 0.5)
    result = ff.create_footstep(start, action, character)
    assert result.valid()
    assert result.step.com_end[0] == pytest.approx(0.5 * math.cos(0.1) * math.cos(-0.1), rel=1e-12)
    # Starting from rest pays the whole kinetic energy.
    assert result.step.cost.speed_change == pytest.approx(0.5 * character.mass * 1.0)
    bad = ff.create_footstep(start, ff.FootstepAction(ff.StepKind.WALK, ff.Foot.LEFT, 0.1, 1.0, 0.5), character)
    assert bad.validity == ff.StepValidity.NOT_POSITIVE


@pytest.mark.parametrize(
    "parts, message",
    [
        ({"agents": [{"position": [0, "x"], "goals": [[1, 1]]}]}, "agents[0].position[1]: expected a number, got string"),
        ({"agents": [{"position": [float("nan"), 0], "goals": [[1, 1]]}]}, "agents[0].position[0]: must be a finite number, got NaN"),
        ({"obstacles": [{"polygon": [[0, 0], [1, 1]]}]}, "obstacles[0].polygon: needs at least 3 points, got 2"),
        (
            {"obstacles": [{"polygon": [[-1, -1], [1, -1], [1, 1]]}], "agents": [{"position": [0, 0], "goals": [[5, 0]]}]},
            "agents[0].position: the standing agent overlaps obstacles[0]",
        ),
        ({"character": {"height": 2}}, "character.height: unknown field"),
        (
            {"agents": [{"name": "ann", "position": [0, 0], "goals": [[5, 0]]},
                        {"name": "bo", "position": [3, 0], "goals": [[5, 2]]},
                        {"name": "cy", "position": [0.3, 0.1], "goals": [[5, 4]]}]},
            "agents[2].position: the standing agent overlaps agents[0] ('ann')",
        ),
        (
            {"agents": [{"name": f"a{i}", "position": [1, 1], "goals": [[5, i]]} for i in range(200)]},
            "agents[1].position: the standing agent overlaps agents[0] ('a0')",
        ),
        ({"planner": {"max_expansions": 1.5}}, "planner.max_expansions: expected an integer, got number"),
    ],
)
def test_bad_scenarios_raise_value_error_naming_the_field(ff, parts, message):
    with pytest.raises(ValueError) as error:
        ff.parse_scenario(scenario_json(**parts), "scene.json")
    assert str(error.value) == "scene.json: " + message


def test_a_number_too_large_for_a_double_is_a_value_error_naming_the_field(ff):
    text = scenario_json(agents=[{"position": [0, 0], "goals": [[1, 1]]}]).replace("[0, 0]", "[0, -2e308]")
    with pytest.raises(ValueError, match=r"^scene.json: agents\[0\].position\[1\]: must be a finite number, got -2e308$"):
        ff.parse_scenario(text, "scene.json")


def test_an_obstacle_of_fewer_than_three_points_is_refused(ff):
    with pytest.raises(ValueError, match="polygon: needs at least 3 points, got 2"):
        ff.Obstacle([(0, 0), (1, 0)])


def test_a_plan_path_with_a_nul_byte_is_refused(ff, tmp_path):
    plan = ff.plan_scenario(ff.demo_scenario())
    with pytest.raises(ValueError, match="a file name cannot hold a NUL byte"):
        ff.write_plan_file(plan, str(tmp_path / "plan.json") + "\0.txt")
    assert not list(tmp_path.iterdir())


def test_malformed_json_names_the_position(ff):
    with pytest.raises(ValueError, match=r"^scene.json: not valid JSON: .*line 1, column \d+"):
        ff.parse_scenario('{"format": "footfall-scenario",', "scene.json")


def test_parameter_validation_names_field_and_limit(ff):
    character = ff.CharacterParams()
    character.right.min_step_duration = 0.0
    with pytest.raises(ValueError, match=r"^character.right.min_step_duration: must be in \(0, 5\], got 0$"):
        ff.validate(character)


def test_io_failure_is_a_footfall_error(ff, tmp_path):
    plan = ff.plan_scenario(ff.demo_scenario())
    with pytest.raises(ff.FootfallError):
        ff.write_plan_file(plan, str(tmp_path / "missing-dir" / "plan.json"))
    assert not list(tmp_path.iterdir())
    with pytest.raises(ValueError, match="cannot open the file"):
        ff.load_plan(str(tmp_path / "none.json"))


def test_plan_file_fields(ff, tmp_path):
    path = tmp_path / "plan.json"
    plan = ff.plan_scenario(ff.demo_scenario())
    ff.write_plan_file(plan, str(path))
    document = json.loads(path.read_text())
    assert document["format"] == "footfall-plan" and document["version"] == 2
    agent = document["agents"][0]
    assert agent["status"] == "reached"
    # Version 2: the footsteps as columns, one item per step (docs/file-formats.md); each step
    # starts where the one before ended, and its cost is the sum of its terms.
    steps = agent["footsteps"]
    for key in ("foot", "end_time", "foot_position", "foot_orientation", "com_end", "com_velocity_end",
                "behavior", "fixed_rate", "speed_change", "curvature"):
        assert len(steps[key]) == steps["count"] == len(plan.agents[0].footsteps)
    assert steps["foot"][0] in "lr" and steps["behavior"][0] == "w"
    first, second = plan.agents[0].footsteps[:2]
    assert tuple(steps["foot_position"][0]) == first.foot_position
    assert steps["end_time"][0] == first.end_time == second.start_time
    cost = sum(steps["values"][steps[term][0]] for term in ("fixed_rate", "speed_change", "curvature"))
    assert cost == first.cost.total()


def test_plans_are_bit_identical(ff):
    scenario = ff.demo_scenario()
    assert ff.plan_to_json(ff.plan_scenario(scenario)) == ff.plan_to_json(ff.plan_scenario(scenario))


def test_threads_do_not_change_the_plan(ff):
    scenario = ff.demo_scenario()
    scenario.agents = [ff.AgentSpec(f"a{i}", (0.0, -3.0 + 2.0 * i), 0.0, [(11.0, 3.0 - 2.0 * i)])
                       for i in range(4)]
    one = ff.plan_to_json(ff.plan_scenario(scenario, threads=1))
    assert one == ff.plan_to_json(ff.plan_scenario(scenario, threads=2))
    with pytest.raises(ValueError, match="threads"):
        ff.plan_scenario(scenario, threads=0)


def test_replan_agents_keeps_the_others_plans(ff):
    scenario = ff.demo_scenario()
    scenario.agents = [ff.AgentSpec(f"a{i}", (0.0, -3.0 + 2.0 * i), 0.0, [(11.0, 3.0 - 2.0 * i)])
                       for i in range(3)]
    first = ff.plan_scenario(scenario)
    scenario.agents[1].goals = [(11.0, 0.0)]
    again = ff.replan_agents(scenario, first, ["a1"], threads=2)
    assert [a.name for a in again.agents] == ["a0", "a1", "a2"]
    assert again.agents[1].status == ff.AgentStatus.REACHED
    assert ff.measure_plan(again).overlaps == 0
    for i in (0, 2):  # kept as they were
        assert again.agents[i].footsteps[-1].end_time == first.agents[i].footsteps[-1].end_time
        assert len(again.agents[i].footsteps) == len(first.agents[i].footsteps)
    with pytest.raises(ValueError, match="agents: 'a9' is not an agent of the scenario"):
        ff.replan_agents(scenario, first, ["a9"])


def test_progress_and_cancel(ff):
    scenario = ff.demo_scenario()
    scenario.agents = [ff.AgentSpec(f"a{i}", (0.0, -4.5 + 1.5 * i), 0.0, [(11.0, 0.3)])
                       for i in range(4)]
    seen = []
    plan = ff.plan_scenario(scenario, progress=seen.append)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen)
    assert plan.status == ff.Status.SUCCESS

    flag = ff.CancelFlag()
    flag.set()
    cancelled = ff.plan_scenario(scenario, cancel=flag)
    assert cancelled.status == ff.Status.CANCELLED
    # Cancelled before the first tick: every agent is there, unplanned, saying why.
    assert [a.reason for a in cancelled.agents] == ["cancelled"] * 4
    assert all(a.status == ff.AgentStatus.PARTIAL and not a.footsteps for a in cancelled.agents)


def test_progress_callback_errors_propagate(ff):
    def explode(fraction):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        ff.plan_scenario(ff.demo_scenario(), progress=explode)


def test_planning_releases_the_gil(ff):
    # While one thread plans, another Python thread keeps running. Were the GIL held, the other
    # thread could still tick just before the call and just after it, for a switch interval or
    # so each (tens of thousands of ticks here): only ticks well inside the call count, 10 switch
    # intervals from either end (none while sum(range(10**7)) holds the GIL for 1.5 s). The
    # city of 80 takes 1-2 s to plan here, the demo of 20 it replaced some 0.1-0.5 s.
    scenario = ff.city_scenario(80, 30.0, 1)
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(perf_counter())

    counter = threading.Thread(target=count)
    counter.start()
    try:
        start = perf_counter()
        ff.plan_scenario(scenario)
        end = perf_counter()
    finally:
        done.set()
        counter.join()
    margin = 10 * sys.getswitchinterval()
    assert end - start > 3 * margin, "the plan is over too soon to tell"
    assert sum(start + margin < tick < end - margin for tick in ticks) > 1000


def test_measure_plan(ff):
    metrics = ff.measure_plan(ff.plan_scenario(ff.demo_scenario()))
    assert all(a.reached and a.overlaps == 0 and a.collision_episodes == 0 for a in metrics.agents)
    mean_acceleration = sum(a.acceleration for a in metrics.agents) / len(metrics.agents)
    assert metrics.composite02 == pytest.approx(metrics.composite01 + mean_acceleration)
    with pytest.raises(ValueError, match="rate"):
        ff.measure_plan(ff.plan_scenario(ff.demo_scenario()), 0.0)


@pytest.mark.parametrize("rate", [1e7, 1e300, float("inf")])
def test_measure_plan_refuses_a_rate_that_would_run_for_minutes(ff, rate):
    with pytest.raises(ValueError, match=r"^rate: must be in \(0, 1000\] Hz"):
        ff.measure_plan(ff.plan_scenario(ff.demo_scenario()), rate)


@pytest.mark.parametrize("time", [1e8, 2e9, -1.0])
def test_a_plan_file_time_out_of_bounds_is_refused_by_field(ff, tmp_path, time):
    path = tmp_path / "plan.json"
    ff.write_plan_file(ff.plan_scenario(ff.demo_scenario()), str(path))
    plan = json.loads(path.read_text())
    agent = plan["agents"][0]
    if time > 0:
        agent["footsteps"]["end_time"][-1] = time
        field = r"end_time\[\d+\]"
    else:  # a first step that does not start at 0
        agent["footsteps"]["starts"] = [{"step": 0, "start_time": time, "com_start": agent["start"]["position"],
                                         "com_velocity_start": [0, 0]}]
        field = r"starts\[0\]\.start_time"
    path.write_text(json.dumps(plan))
    with pytest.raises(ValueError, match=rf"footsteps\.{field}: must be in \[0, 200000\] s"):
        ff.load_plan(str(path))


def test_a_scene_at_the_edge_of_the_world_has_a_navigation_mesh(ff):
    text = scenario_json(
        obstacles=[{"polygon": [[999999990, -1], [999999991, -1], [999999991, 1], [999999990, 1]]}],
        agents=[{"position": [999999985, 0], "goals": [[999999999.5, 0]]}])
    mesh = ff.navmesh_of(ff.parse_scenario(text))
    assert mesh.find_path((999999985, 0), (999999999.5, 0), 0.3)["status"] == "found"


def test_search_keeps_clear_of_other_plans(ff):
    character = ff.CharacterParams()
    planner = ff.FootstepPlanner(character, ff.PlannerParams(), ff.ObstacleMap([]))
    first = ff.plan_agent(ff.AgentSpec("first", (0.0, 0.0), 0.0, [(8.0, 0.0)]), planner)
    start = ff.standing_state((8.0, 0.0), math.pi, character)
    alone = planner.plan(start, (0.0, 0.0))
    aware = planner.plan(start, (0.0, 0.0), [first])
    assert aware.status == ff.Status.SUCCESS
    # Alone it walks the line through the other; aware, it steps aside.
    assert max(abs(s.com_end[1]) for s in alone.footsteps) < 0.3
    assert max(abs(s.com_end[1]) for s in aware.footsteps) > 0.3


def test_search_takes_a_walking_agents_rest_for_its_grace_only(ff):
    character = ff.CharacterParams()
    planner = ff.FootstepPlanner(character, ff.PlannerParams(), ff.ObstacleMap([]))
    # It crosses the way and rests on it, at (8, 0).
    crossing = ff.plan_agent(ff.AgentSpec("crossing", (8.0, -1.5), math.pi / 2, [(8.0, 0.0)]), planner)
    start = ff.standing_state((0.0, 0.0), 0.0, character)
    around = planner.plan(start, (12.0, 0.0), [crossing])
    assert around.status == ff.Status.SUCCESS
    # Its rest taken for a second only: straight on, cut before the rest.
    straight = planner.plan(start, (12.0, 0.0), [crossing], rest_grace=1.0)
    assert straight.status == ff.Status.PARTIAL
    assert straight.footsteps and straight.end_state.com[0] < 8.0
    with pytest.raises(ValueError, match="rest_grace"):
        planner.plan(start, (12.0, 0.0), [crossing], rest_grace=-1.0)
    # The search names the agent that turned down its steps.
    assert around.refused_by == [0]


def test_an_agents_scale_sizes_it_and_is_kept_in_the_plan_file(ff, tmp_path):
    def scenario(scale, character=None):
        agent = {"name": "kid", "position": [0, 0], "goals": [[4, 0]], "scale": scale}
        if character:
            agent["character"] = character
        return ff.parse_scenario(scenario_json(agents=[agent]), "kid.json")

    with pytest.raises(ValueError, match=r"^kid.json: agents\[0\].scale: must be in \[0.5, 1.6\]"):
        scenario(5.0)
    (kid,) = scenario(0.5).agents
    assert kid.scale == 0.5
    assert kid.character.com_height == pytest.approx(0.5) and kid.character.body_height == pytest.approx(0.875)
    # Speeds and durations by the square root, so that it walks alike.
    assert kid.character.preferred_speed == pytest.approx(1.3 * 0.5 ** 0.5)
    assert kid.character.left.max_step_duration == pytest.approx(0.8 * 0.5 ** 0.5)
    # Its own overrides win over the scaled values.
    (own,) = scenario(0.5, {"preferred_speed": 1.0}).agents
    assert own.character.preferred_speed == 1.0 and own.character.com_height == pytest.approx(0.5)
    plan = ff.plan_scenario(scenario(0.5))
    path = tmp_path / "plan.json"
    ff.write_plan_file(plan, str(path))
    assert json.loads(path.read_text())["agents"][0]["scale"] == 0.5
    assert ff.load_plan(str(path)).agents[0].scale == 0.5


def test_an_agent_turns_to_its_end_facing_at_its_last_goal(ff):
    def ann(end_facing=None, leave=False):
        agent = {"name": "ann", "position": [0, 0], "goals": [[4, 0]], "leave_at_goal": leave}
        if end_facing is not None:
            agent["end_facing"] = end_facing
        others = [{"name": "bob", "position": [0, 2], "goals": [[4, 2]]}]
        return ff.plan_scenario(ff.parse_scenario(scenario_json(agents=[agent, *others]), "turn.json")).agents[0]

    plain = ann()
    for facing in (math.pi / 2, math.pi, -2.5):
        turned = ann(facing)
        assert turned.status == ff.AgentStatus.REACHED
        assert abs(math.remainder(turned.footsteps[-1].phi - facing, math.tau)) < 1e-6
        # Both feet point the new way, and the turn comes after it arrived as it would have.
        for foot in ff.feet_at(turned, turned.end_time()):
            assert abs(math.remainder(foot.orientation - facing, math.tau)) < 1e-6
        assert all(s.kind == ff.StepKind.STOP for s in turned.footsteps[len(plain.footsteps):])
        assert turned.footsteps[-1].com_end == pytest.approx(plain.footsteps[-1].com_end, abs=0.05)
    # One that leaves at its goal does not stop to turn.
    assert len(ann(math.pi, leave=True).footsteps) == len(ann(leave=True).footsteps)
    with pytest.raises(ValueError, match=r"agents\[0\].end_facing: must be a finite number"):
        ff.parse_scenario(scenario_json(agents=[{"position": [0, 0], "goals": [[1, 0]], "end_facing": float("nan")}]),
                          "nan.json")


def test_an_agent_turns_to_its_facing_at_each_goal_and_waits_facing_it(ff):
    def ann(goal_facings=None, **extra):
        agent = {"name": "ann", "position": [0, 0], "goals": [[3, 0], [3, 3]], "goal_wait": 2.0, **extra}
        if goal_facings is not None:
            agent["goal_facings"] = goal_facings
        return ff.plan_scenario(ff.parse_scenario(scenario_json(agents=[agent]), "turns.json")).agents[0]

    facing = -math.pi / 2  # away from the next goal, as at a shop window behind it
    turned = ann([facing, None])
    assert turned.status == ff.AgentStatus.REACHED
    # It arrives, turns (both feet), then stands facing that way for its whole wait.
    facing_steps = [s for s in turned.footsteps if abs(math.remainder(s.phi - facing, math.tau)) < 1e-5]
    assert all(s.kind == ff.StepKind.STOP for s in facing_steps)
    turned_at = min(s.end_time for s in facing_steps if s.foot != facing_steps[0].foot)
    for foot in ff.feet_at(turned, turned_at):
        assert abs(math.remainder(foot.orientation - facing, math.tau)) < 1e-5
    assert max(s.end_time for s in facing_steps) - turned_at >= 2.0 - 1e-9
    # And walks on to its last goal, where it stands as it arrives.
    last_walk = [s for s in turned.footsteps if s.kind == ff.StepKind.WALK][-1]
    assert turned.footsteps[-1].phi == pytest.approx(last_walk.phi)
    # The last goal's facing: from either field, not both.
    assert abs(math.remainder(ann([None, 2.0]).footsteps[-1].phi - 2.0, math.tau)) < 1e-6
    with pytest.raises(ValueError, match=r"agents\[0\].end_facing: and goal_facings\[1\] both give"):
        ann([None, 2.0], end_facing=1.0)
    with pytest.raises(ValueError, match=r"agents\[0\].goal_facings: needs one facing \(or null\) per goal: 2 goals, 1"):
        ann([1.0])


def test_an_agent_that_cannot_reach_says_where_its_way_is_too_narrow(ff, tmp_path):
    scenario = ff.parse_scenario(slot_scenario_json([{"name": "wide", "position": [1, 0], "goals": [[10, 0]]}]),
                                 "slot.json")
    plan = ff.plan_scenario(scenario)
    agent = plan.agents[0]
    assert agent.status == ff.AgentStatus.PARTIAL and agent.reason == "unreachable"
    narrowest = agent.narrowest
    assert narrowest.at == pytest.approx((5.15, 0.3), abs=0.03)
    assert narrowest.width == pytest.approx(0.25, abs=0.005)
    assert narrowest.needs > narrowest.width and narrowest.behavior == "side_step"
    assert str(narrowest).startswith("cannot reach its goal: the way at (5.1")
    path = tmp_path / "plan.json"
    ff.write_plan_file(plan, str(path))
    read = ff.load_plan(str(path)).agents[0].narrowest
    assert (read.at, read.width, read.needs) == (narrowest.at, narrowest.width, narrowest.needs)
    assert ff.plan_scenario(ff.demo_scenario()).agents[0].narrowest is None
