"""blender_addon/footfall/core: pure Python, usable without Blender."""

import math

import pytest

from footfall.core import scenario as sc


def test_document_round_trips_through_the_core(ff):
    document = sc.scenario_document(
        sc.ScenarioInput(
            agents=[sc.AgentInput("ann", (0, 0), [(6, 0)], facing=0.0)],
            obstacles=[sc.ObstacleInput([(3, 1), (4, 1), (4, 2), (3, 2)], 0.9)],
            character={"mass": 65.0},
            planner={"max_expansions": 500},
        )
    )
    assert document["format"] == "footfall-scenario"
    scenario = sc.parse(document, "doc")
    assert scenario.character.mass == 65.0
    assert scenario.planner.max_expansions == 500
    assert scenario.obstacles[0].height == 0.9
    plan = sc.plan(document)
    assert plan.agents[0].status == ff.AgentStatus.REACHED


def test_bad_values_are_named_by_field():
    document = sc.scenario_document(sc.ScenarioInput(agents=[sc.AgentInput("ann", (0, math.inf), [(6, 0)])]))
    with pytest.raises(ValueError, match=r"^scene: agents\[0\].position\[1\]: must be a finite number, got Infinity$"):
        sc.parse(document, "scene")


def test_facing_defaults_toward_the_first_goal():
    document = sc.scenario_document(sc.ScenarioInput(agents=[sc.AgentInput("ann", (0, 0), [(0, 3)])]))
    assert "facing" not in document["agents"][0]
    assert sc.parse(document).agents[0].facing == pytest.approx(math.pi / 2)


def test_core_status_names_the_version(ff):
    from footfall.core import native

    assert native.status() == f"Planning core {ff.__version__}"
