"""The full-body planner from outside: footfall path --behaviors, the Python
planner, mesh obstacles, sampled motions, and the full-body check in metrics."""

import json
import math
import subprocess

import pytest

from conftest import scenario_json

LIMBS = ["head", "shoulders", "torso", "pelvis", "upper_arm_left", "upper_arm_right",
         "forearm_left", "forearm_right", "thigh_left", "thigh_right", "shin_left",
         "shin_right", "foot_left", "foot_right"]


def run(cli, *args):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=300)


def scene_file(ff, tmp_path, name):
    """A built-in scene written as a scenario file; its start and goals."""
    scenario, start, goals = ff.behavior_scene(name)
    obstacles = [{"polygon": [list(p) for p in o.polygon], "height": o.height, "base": o.base}
                 for o in scenario.obstacles]
    agents = [{"name": "walker", "position": list(start), "goals": [list(goals[0])]}]
    path = tmp_path / f"{name}.json"
    path.write_text(scenario_json(obstacles=obstacles, agents=agents))
    return path, start, goals


def test_path_behaviors_prints_the_sections(ff, cli, tmp_path):
    path, start, goals = scene_file(ff, tmp_path, "door")
    result = run(cli, "path", str(path), "--from", "%r,%r" % start, "--to", "%r,%r" % goals[0],
                 "--behaviors")
    assert result.returncode == 0, result.stderr
    answer = json.loads(result.stdout)
    assert answer["status"] == "found"
    assert [s["behavior"] for s in answer["sections"]] == ["walk", "arms_in", "walk"]
    assert answer["point_obstacles"] > 0
    assert math.isclose(answer["length"], sum(s["length"] for s in answer["sections"]))
    # The sections join end to end into the points.
    joined = answer["sections"][0]["points"]
    for section in answer["sections"][1:]:
        assert section["points"][0] == joined[-1]
        joined += section["points"][1:]
    assert joined == answer["points"]
    assert answer["min_clearance"] > 0.2
    # The same from Python.
    scenario, _, _ = ff.behavior_scene("door")
    planned = ff.BehavioralPlanner(scenario).plan(start, goals[0])
    assert [s.behavior for s in planned.sections] == ["walk", "arms_in", "walk"]
    assert planned.point_obstacles == answer["point_obstacles"]


def test_path_takes_a_radius_or_behaviors(ff, cli, tmp_path):
    path, _, _ = scene_file(ff, tmp_path, "open_field")
    both = run(cli, "path", str(path), "--from", "0,0", "--to", "5,0", "--radius", "0.2",
               "--behaviors")
    assert both.returncode == 2
    assert len(both.stderr.strip().splitlines()) == 1
    assert "--behaviors" in both.stderr


def test_a_gap_too_narrow_says_so(ff, cli, tmp_path):
    path, start, goals = scene_file(ff, tmp_path, "gap")
    result = run(cli, "path", str(path), "--from", "%r,%r" % start, "--to", "%r,%r" % goals[0],
                 "--behaviors")
    assert result.returncode == 0, result.stderr
    answer = json.loads(result.stdout)
    assert answer["status"] == "no_path" and answer["sections"] == [] and answer["reason"]


def test_metrics_checks_the_full_body(ff, cli, tmp_path):
    path, _, _ = scene_file(ff, tmp_path, "corridor")
    plan = tmp_path / "plan.json"
    assert run(cli, "plan", str(path), "-o", str(plan)).returncode == 0
    written = json.loads(plan.read_text())
    sections = written["agents"][0]["sections"]
    assert [s["behavior"] for s in sections] == ["walk", "arms_in", "walk", "side_step", "walk"]
    result = run(cli, "metrics", str(plan))
    assert result.returncode == 0, result.stderr
    assert "full body (30 poses/s): 0 poses with a limb in an obstacle" in result.stdout
    check = ff.check_body(ff.load_plan(str(plan)))
    assert check.penetrations == 0 and check.poses > 100


def test_mesh_obstacles_are_checked_in_python(ff):
    box = ff.Obstacle.from_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 1]], [[0, 1, 2]])
    assert box.is_mesh
    with pytest.raises(ValueError, match=r"Obstacle.mesh.triangles\[0\]\[2\]: vertex index 5"):
        ff.Obstacle.from_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 1]], [[0, 1, 5]])
    with pytest.raises(ValueError, match=r"Obstacle.mesh.vertices\[1\]"):
        ff.Obstacle.from_mesh([[0, 0, 0], [1, float("nan"), 0], [0, 1, 1]], [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"Obstacle.base: must be in \[0, height\)"):
        ff.Obstacle([(0, 0), (1, 0), (1, 1)], height=1.0, base=1.5)


def test_sampled_motions_set_the_clearances(ff):
    wide = {limb: [0, 0, 0.2, 0, 0, 1.6, 0.2] for limb in LIMBS}
    wide["forearm_left"] = [0, 0.2, 0.8, 0, 0.45, 0.8, 0.05]  # a hand 0.5 m out
    text = scenario_json(
        agents=[{"position": [0, 0], "goals": [[5, 0]]}],
        character={"behaviors": {"walk": {"cycle_duration": 1.0, "speed": 1.2, "poses": [wide]}}})
    planner = ff.BehavioralPlanner(ff.parse_scenario(text, "wide.json"))
    assert planner.clearance("walk") == pytest.approx(0.52)  # the hand's reach and the margin
    narrow = dict(wide, forearm_left=[0, 0, 0.8, 0, 0, 1.0, 0.05])
    text = scenario_json(
        agents=[{"position": [0, 0], "goals": [[5, 0]]}],
        character={"behaviors": {"walk": {"cycle_duration": 1.0, "speed": 1.2, "poses": [narrow]}}})
    with pytest.raises(ValueError, match="side_step < arms_in < walk"):
        ff.parse_scenario(text, "narrow.json")
    bad = dict(wide)
    del bad["head"]
    text = scenario_json(character={"behaviors": {"walk": {"cycle_duration": 1, "speed": 1, "poses": [bad]}}})
    with pytest.raises(ValueError, match=r"character.behaviors.walk.poses\[0\].head: missing"):
        ff.parse_scenario(text, "bad.json")
    text = scenario_json(character={"behaviors": {"crawl": {}}})
    with pytest.raises(ValueError, match="character.behaviors.crawl: unknown behaviour"):
        ff.parse_scenario(text, "bad.json")


def test_bench_behaviors_reports_every_environment(cli):
    result = run(cli, "bench", "--behaviors", "--repeat", "1")
    assert result.returncode == 0, result.stderr
    rows = [line.split()[0] for line in result.stdout.splitlines()[1:5]]
    assert rows == ["random_normal_6", "random_normal_10", "random_dense_6", "random_dense_10"]
