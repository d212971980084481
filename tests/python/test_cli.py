"""The footfall command line: plan, demo, bench, and bad input."""

import json
import subprocess

import pytest

from conftest import scenario_json


def run(cli, *args, cwd=None):
    return subprocess.run([cli, *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def test_plan_writes_a_plan_and_a_table(cli, tmp_path):
    scenario = tmp_path / "walk.json"
    scenario.write_text(scenario_json(agents=[{"name": "ann", "position": [0, 0], "goals": [[8, 0]]}]))
    out = tmp_path / "plans" / "walk-plan.json"
    result = run(cli, "plan", str(scenario), "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert "ann" in result.stdout and "reached" in result.stdout
    plan = json.loads(out.read_text())
    assert plan["agents"][0]["status"] == "reached"


def test_demo_runs_from_any_folder(cli, tmp_path):
    result = run(cli, "demo", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "out" / "demo-plan.json").exists()
    header = result.stdout.splitlines()[0].split()
    assert header[:3] == ["agent", "status", "steps"]


BAD = {
    "malformed.json": ('{"format": "footfall-scenario", ', "not valid JSON"),
    "type.json": (scenario_json(agents=[{"position": "here", "goals": [[1, 1]]}]), "agents[0].position: expected a point [x, y]"),
    "nan.json": (scenario_json(agents=[{"position": [0, float("nan")], "goals": [[1, 1]]}]), "agents[0].position[1]: must be a finite number, got NaN"),
    "polygon.json": (scenario_json(obstacles=[{"polygon": [[0, 0], [1, 0]]}]), "obstacles[0].polygon: needs at least 3 points"),
    "inside.json": (
        scenario_json(obstacles=[{"polygon": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}], agents=[{"position": [0, 0], "goals": [[3, 0]]}]),
        "agents[0].position: the standing agent overlaps obstacles[0]",
    ),
    "unknown.json": (scenario_json(planner={"depth": 3}), "planner.depth: unknown field"),
}


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_input_is_one_line_exit_2_and_no_output(cli, tmp_path, name):
    text, message = BAD[name]
    scenario = tmp_path / name
    scenario.write_text(text)
    out = tmp_path / "plan.json"
    result = run(cli, "plan", str(scenario), "-o", str(out))
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(f"footfall: {scenario}: ")
    assert message in lines[0]
    assert not out.exists()
    assert list(tmp_path.iterdir()) == [scenario]


def test_usage_errors_exit_2(cli):
    assert run(cli, "plan").returncode == 2
    assert run(cli, "fly").returncode == 2
    assert run(cli, "bench", "--crowds", "--repeat", "0").returncode == 2
    assert run(cli, "--help").returncode == 0


def test_bench_prints_every_workload(cli):
    result = run(cli, "bench", "--repeat", "1")
    assert result.returncode == 0, result.stderr
    for workload in ("open 10 m", "around a box", "0.7 m door", "field of 700 boxes"):
        assert workload in result.stdout


def test_metrics_of_the_demo(cli, tmp_path):
    plan = tmp_path / "demo.json"
    assert run(cli, "demo", "-o", str(plan)).returncode == 0
    result = run(cli, "metrics", str(plan))
    assert result.returncode == 0, result.stderr
    assert "five-circle overlaps: 0" in result.stdout
    assert "composite01" in result.stdout and "walker" in result.stdout
    missing = run(cli, "metrics", str(tmp_path / "none.json"))
    assert missing.returncode == 2 and "cannot open the file" in missing.stderr
