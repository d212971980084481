"""The viewport overlay's lines: paths coloured by behaviour, footprints,
the steps under way, and a cross where an agent that did not arrive stopped."""

import math

import numpy
import pytest

from conftest import scenario_json
from footfall.core.plan_overlay import BEHAVIOR_COLORS, CURRENT_COLOR, FAILED_COLOR, FOOT_COLORS, PlanOverlay


def colored(lines, color):
    return numpy.all(numpy.isclose(lines.colors, numpy.array(color, dtype=numpy.float32)), axis=1)


@pytest.fixture(scope="module")
def corridor_plan(ff):
    scenario, _, _ = ff.behavior_scene("corridor")
    return ff.plan_scenario(scenario)


def test_paths_take_their_sections_colours_and_join_step_to_step(ff, corridor_plan):
    overlay = PlanOverlay(corridor_plan)
    (agent,) = corridor_plan.agents
    steps = agent.footsteps
    lines = overlay.fixed
    assert lines.points.dtype == numpy.float32 and len(lines.points) == len(lines.colors)
    # One chord per step, then eight points (four sides) per footprint.
    assert len(lines.points) == 2 * len(steps) + 8 * len(steps)
    for i, step in enumerate(steps):
        assert lines.points[2 * i, :2] == pytest.approx(step.com_start, abs=1e-5)
        assert lines.points[2 * i + 1, :2] == pytest.approx(step.com_end, abs=1e-5)
        assert tuple(lines.colors[2 * i]) == pytest.approx(BEHAVIOR_COLORS[step.behavior.name.lower()])
    for behavior in ("walk", "arms_in", "side_step"):
        assert colored(lines, BEHAVIOR_COLORS[behavior]).any(), f"no {behavior} on the corridor's path"
    footprints = lines.points[2 * len(steps):].reshape(len(steps), 8, 3)
    for step, ring in zip(steps, footprints):
        assert ring[:, :2].mean(axis=0) == pytest.approx(step.foot_position, abs=1e-5)
        along, across = ring[0] - ring[1], ring[3] - ring[2]  # toe to heel, then across the heel
        assert numpy.linalg.norm(along) > 2 * numpy.linalg.norm(across)  # a foot: longer than wide
        assert abs(math.remainder(numpy.arctan2(along[1], along[0]) - step.foot_orientation, math.tau)) < 1e-4
    assert colored(lines, FOOT_COLORS[0]).sum() == 8 * sum(s.foot.name == "LEFT" for s in steps)
    assert not colored(lines, FAILED_COLOR).any()


def test_the_steps_under_way_light_up(ff, corridor_plan):
    overlay = PlanOverlay(corridor_plan)
    (agent,) = corridor_plan.agents
    middle = agent.footsteps[len(agent.footsteps) // 2]
    now = overlay.under_way(0.5 * (middle.start_time + middle.end_time))
    assert len(now.points) == 8 and colored(now, CURRENT_COLOR).all()
    assert now.points[:, :2].mean(axis=0) == pytest.approx(middle.foot_position, abs=1e-5)
    assert len(overlay.under_way(agent.end_time() + 1.0).points) == 0
    assert len(overlay.under_way(-1.0).points) == 0


def test_an_agent_that_did_not_arrive_is_crossed_where_it_stopped(ff):
    text = scenario_json(
        obstacles=[{"polygon": [[4, -5], [5, -5], [5, 5], [4, 5]], "height": 2}],
        agents=[{"name": "late", "position": [0, 0], "goals": [[10, 0]], "time_limit": 3.0},
                {"name": "fine", "position": [0, 8], "goals": [[3, 8]]}])
    plan = ff.plan_scenario(ff.parse_scenario(text, "late.json"))
    statuses = {a.name: a.status for a in plan.agents}
    assert statuses == {"late": ff.AgentStatus.PARTIAL, "fine": ff.AgentStatus.REACHED}
    lines = PlanOverlay(plan).fixed
    cross = lines.points[colored(lines, FAILED_COLOR)]
    assert len(cross) == 4
    late = next(a for a in plan.agents if a.name == "late")
    assert cross[:, :2].mean(axis=0) == pytest.approx(late.footsteps[-1].com_end, abs=1e-5)


def test_an_empty_plan_draws_nothing(ff):
    plan = ff.plan_scenario(ff.parse_scenario(scenario_json(), "empty.json"))
    overlay = PlanOverlay(plan)
    assert overlay.fixed.points.shape == (0, 3) and overlay.under_way(0.0).points.shape == (0, 3)
