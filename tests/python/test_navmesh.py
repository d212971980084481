"""The navigation mesh from Python and from `footfall path`."""

import json
import subprocess

import pytest

from conftest import scenario_json

WALL_WITH_GAP = [
    {"polygon": [[4.9, 0], [5.1, 0], [5.1, 4.5], [4.9, 4.5]], "height": 2},
    {"polygon": [[4.9, 5.5], [5.1, 5.5], [5.1, 10], [4.9, 10]], "height": 2},
]


def path_cli(cli, scenario, *args):
    return subprocess.run([cli, "path", str(scenario), *args], capture_output=True, text=True,
                          timeout=60)


def test_navmesh_updates_and_queries(ff):
    mesh = ff.NavMesh((0, 0), (10, 10))
    box = mesh.add_polygon([(4, 4), (6, 4), (6, 6), (4, 6)], "box")
    result = mesh.find_path((1, 5), (9, 5), 0.5)
    assert result["status"] == "found"
    assert result["points"][0] == (1, 5) and result["points"][-1] == (9, 5)
    assert result["min_clearance"] >= 0.5 - 1e-9
    assert mesh.find_path((5, 5), (9, 5), 0.5)["status"] == "start_blocked"
    assert not mesh.line_of_sight((1, 5), (9, 5)) and mesh.line_of_sight((1, 7), (9, 7))
    assert mesh.clearance_between((1, 7), (9, 7)) == pytest.approx(1.0)
    assert box in mesh
    mesh.remove(box)
    assert box not in mesh
    assert mesh.find_path((1, 5), (9, 5), 0.5)["length"] == pytest.approx(8.0)
    with pytest.raises(IndexError):
        mesh.remove(box)
    with pytest.raises(ValueError, match="box vertex 1"):
        mesh.add_polygon([(1, 1), (float("nan"), 1), (2, 2)], "box")


def test_a_region_with_a_hole(ff):
    mesh = ff.NavMesh((0, 0), (10, 10))
    ring = mesh.add_region([[(2, 2), (8, 2), (8, 8), (2, 8)]], [[(3, 3), (7, 3), (7, 7), (3, 7)]], "ring")
    assert mesh.clearance((5, 5)) == pytest.approx(2.0)  # in the hole, 2 m from the ring
    assert mesh.clearance((2.5, 5)) == 0.0
    assert mesh.find_path((5, 5), (9, 9), 0.3)["status"] == "no_path"
    mesh.remove(ring)
    assert mesh.find_path((5, 5), (9, 9), 0.3)["status"] == "found"
    with pytest.raises(ValueError, match="ring vertex 1"):
        mesh.add_region([[(1, 1), (float("nan"), 1), (2, 2)]], [], "ring")


def test_triangles_for_drawing(ff):
    mesh = ff.NavMesh((0, 0), (10, 10))
    mesh.add_point((5, 5))
    triangles = mesh.triangles()
    assert len(triangles) == mesh.triangle_count == 4
    assert all(t["walkable"] for t in triangles)
    assert all(0 < c <= 5 for t in triangles for c in t["corner_clearance"])


def test_path_command_prints_json(cli, tmp_path):
    scenario = tmp_path / "gap.json"
    scenario.write_text(scenario_json(obstacles=WALL_WITH_GAP, agents=[]))
    result = path_cli(cli, scenario, "--from", "1,5", "--to", "9,5", "--radius", "0.4")
    assert result.returncode == 0, result.stderr
    answer = json.loads(result.stdout)
    assert list(answer) == ["status", "points", "length", "min_clearance"]
    assert answer["status"] == "found" and answer["min_clearance"] >= 0.4 - 1e-9
    # Too wide for the gap: around the end of the wall, inside the domain (the
    # scenario's bounding box grown by 5 m).
    around = json.loads(path_cli(cli, scenario, "--from", "1,5", "--to", "9,5",
                                 "--radius", "0.6").stdout)
    assert around["status"] == "found" and around["length"] > 14
    assert min(y for _, y in around["points"]) < 0 or max(y for _, y in around["points"]) > 10
    outside = json.loads(path_cli(cli, scenario, "--from", "1,5", "--to", "99,5",
                                  "--radius", "0.6").stdout)
    assert outside == {"status": "outside", "points": [], "length": 0.0, "min_clearance": 0.0}


@pytest.mark.parametrize("args, message", [
    (["--from", "1,x", "--to", "9,5", "--radius", "0.4"], "--from: expected a finite number"),
    (["--from", "1,5", "--to", "9,5"], "path needs SCENARIO"),
    (["--from", "1,5", "--to", "9,5", "--radius", "-1"], "--radius: must be >= 0"),
])
def test_path_command_bad_input(cli, tmp_path, args, message):
    scenario = tmp_path / "gap.json"
    scenario.write_text(scenario_json(obstacles=WALL_WITH_GAP, agents=[]))
    result = path_cli(cli, scenario, *args)
    assert result.returncode == 2
    assert message in result.stderr
    assert result.stdout == ""
