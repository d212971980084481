"""The footfall command line: plan, demo, bench, and bad input."""

import json
import math
import pathlib
import subprocess
import time

import pytest

import re

from conftest import scenario_json, slot_scenario_json


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
    # Too large for a double: named like NaN, not the JSON library's own words.
    "overflow.json": (
        scenario_json(agents=[{"position": [0, 0], "goals": [[1, 1]]}]).replace("[0, 0]", "[1e400, 0]"),
        "agents[0].position[0]: must be a finite number, got 1e400",
    ),
    "digits.json": (
        scenario_json(agents=[{"position": [0, 0], "goals": [[1, 1]]}]).replace("[0, 0]", "[" + "9" * 400 + ", 0]"),
        "agents[0].position[0]: must be a finite number, got 99999999999999999999...",
    ),
    # What the file holds is quoted and escaped: it cannot add a line.
    "key.json": (scenario_json(planner={"de\npth\u001b[31m": 3}), "planner.'de\\npth\\x1b[31m': unknown field"),
    "names.json": (
        scenario_json(agents=[{"name": "a\nfootfall: ok", "position": [0, 0], "goals": [[1, 1]]},
                              {"name": "a\nfootfall: ok", "position": [3, 0], "goals": [[4, 1]]}]),
        "agents[1].name: 'a\\nfootfall: ok' is used twice",
    ),
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


@pytest.mark.parametrize("args, message", [
    (["plan", "scene.json"], "plan needs -o PLAN"),
    (["bench", "--repeat", "1abc"], "--repeat: expected a whole number from 1 to 1000000, got '1abc'"),
    (["bench", "--box-seeds", "200"], "--box-seeds: give FIRST-LAST, as 1-200, not '200'"),
    (["bench", "--box-seeds", "9-3"], "--box-seeds: the first seed is after the last: '9-3'"),
    (["bench", "--box-seeds", "1-2", "--crowds"], "bench: one of --crowds, --behaviors, --box-seeds and --city"),
    (["bench", "--city", "1000"], "--city: give AGENTS,SIZE, as 1000,60, not '1000'"),
    (["bench", "--city", "100,65"], "--city: size: a city's side is a multiple of 10 m (a block and a street) from 10 to 10000 m"),
    (["bench", "--seeds", "1-2"], "bench: --seeds goes with --city"),
    (["bench", "--crowds", "-o", "plan.json"], "bench: -o goes with --city or --box-seeds"),
    (["plan", "s.json", "-o", "p.json", "--threads", "99"], "--threads: expected a whole number from 1 to 64, got '99'"),
    (["path", "s.json", "--from", "0,0", "--to", "1e10,0", "--radius", "0.3"],
     "--to: must be within 1e9 m of the origin, got '1e10,0'"),
    (["path", "s.json", "--from", "0,0", "--to", "1,0", "--radius", "-1"], "--radius: must be >= 0, got '-1'"),
    (["pl\x1b[31man\nfootfall: ok"], "unknown command 'pl\\x1b[31man\\nfootfall: ok'"),
    (["plan", "s.json", "-o", "p.json", "--fixed", "f.json"], "plan: --fixed PLAN and --agents NAME,NAME go together"),
    (["plan", "s.json", "-o", "p.json", "--fixed", "f.json", "--agents", "ann,,bo"], "--agents: an empty name in 'ann,,bo'"),
    (["metrics", "p.json", "--agents", "ann"], "metrics takes one plan file"),
])
def test_a_usage_error_is_one_line_that_names_the_flag_and_value(cli, tmp_path, args, message):
    result = run(cli, *args, cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.splitlines() == [f"footfall: {message} (footfall --help shows the usage)"]


def test_a_radius_too_small_for_a_normal_double_is_still_a_number(cli, tmp_path):
    scenario = tmp_path / "empty.json"
    scenario.write_text(scenario_json())
    result = run(cli, "path", str(scenario), "--from", "0,0", "--to", "1,0", "--radius", "1e-320")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["status"] == "found"


def test_two_runs_writing_one_plan_at_once_both_succeed(cli, tmp_path):
    scenario = tmp_path / "walk.json"
    scenario.write_text(scenario_json(agents=[{"name": "ann", "position": [0, 0], "goals": [[30, 0]]}]))
    out = tmp_path / "plan.json"
    for _ in range(5):
        runs = [subprocess.Popen([cli, "plan", str(scenario), "-o", str(out)], stdout=subprocess.DEVNULL,
                                 stderr=subprocess.PIPE, text=True) for _ in range(2)]
        for process in runs:
            assert process.wait(timeout=120) == 0, process.stderr.read()
        assert json.loads(out.read_text())["agents"][0]["status"] == "reached"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["plan.json", "walk.json"]


def test_a_temporary_left_by_a_stopped_run_is_removed(cli, tmp_path):
    scenario = tmp_path / "walk.json"
    scenario.write_text(scenario_json(agents=[{"name": "ann", "position": [0, 0], "goals": [[3, 0]]}]))
    stale = tmp_path / ".plan.json.999999999-0.partial"  # no process has that number
    stale.write_text("{half a pla")
    mine = tmp_path / ".other.json.999999999-0.partial"  # another plan's: not ours to remove
    mine.write_text("{")
    assert run(cli, "plan", str(scenario), "-o", str(tmp_path / "plan.json")).returncode == 0
    assert not stale.exists() and mine.exists()


def test_a_stopped_run_leaves_no_half_written_plan(cli, tmp_path):
    """SIGTERM at any moment of a run that plans and writes a large plan: no
    temporary stays behind, and the plan is there whole or not at all."""
    out = tmp_path / "plan.json"
    case = pathlib.Path(__file__).resolve().parents[1] / "data" / "steersuite" / "hallway-two-way.xml"
    for delay in (0.3, 1.0, 2.0, 3.0):
        process = subprocess.Popen([cli, "plan", str(case), "-o", str(out)], stdout=subprocess.DEVNULL)
        time.sleep(delay)
        process.terminate()
        process.wait(timeout=120)
        assert [path.name for path in tmp_path.iterdir() if path.name != "plan.json"] == []
        if out.exists():
            assert json.loads(out.read_text())["format"] == "footfall-plan"


def test_bench_prints_every_workload(cli):
    result = run(cli, "bench", "--repeat", "1")
    assert result.returncode == 0, result.stderr
    for workload in ("open 10 m", "around a box", "0.7 m door", "field of 700 boxes"):
        assert workload in result.stdout


def test_bench_box_seeds_lists_who_falls_short(cli):
    result = run(cli, "bench", "--box-seeds", "7-7", "--threads", "2")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].startswith("seed 7: 500 of 500 reached, 0 overlap samples, travel ")
    assert result.stdout.splitlines()[-1] == (
        "0 agent(s) short of their goals and 0 overlap samples over seeds 7-7")


def test_bench_city_plans_each_seed_and_writes_the_last(cli, tmp_path):
    plan = tmp_path / "city.json"
    result = run(cli, "bench", "--city", "60,30", "--seeds", "3-4", "-o", str(plan))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert [line.split(":")[0] for line in lines[:2]] == ["seed 3", "seed 4"]
    assert all(" of 60 reached, " in line and " x alone (" in line for line in lines[:2])
    written = json.loads(plan.read_text())
    assert len(written["agents"]) == 60 and len(written["obstacles"]) == 9


def test_metrics_of_the_demo(cli, tmp_path):
    plan = tmp_path / "demo.json"
    assert run(cli, "demo", "-o", str(plan)).returncode == 0
    result = run(cli, "metrics", str(plan))
    assert result.returncode == 0, result.stderr
    assert "five-circle overlaps: 0" in result.stdout
    assert "composite01" in result.stdout and "walker" in result.stdout
    missing = run(cli, "metrics", str(tmp_path / "none.json"))
    assert missing.returncode == 2 and "cannot open the file" in missing.stderr


def test_plan_again_the_named_agents_among_the_fixed_plans_of_the_others(cli, tmp_path):
    """`plan --fixed PLAN --agents NAMES`: the others' plans are copied as they
    are, the named agents are planned again, and errors name the file or flag."""
    walkers = [{"name": "ann", "position": [0, 0], "goals": [[8, 0]]},
               {"name": "bo", "position": [4, -4], "goals": [[4, 4]]},
               {"name": "cy", "position": [0, 3], "goals": [[8, 3]]}]
    scenario = tmp_path / "three.json"
    scenario.write_text(scenario_json(agents=walkers))
    first = tmp_path / "first.json"
    assert run(cli, "plan", str(scenario), "-o", str(first)).returncode == 0
    walkers[0]["goals"] = [[8, 1]]  # ann's goal moved: only she is planned again
    scenario.write_text(scenario_json(agents=walkers))
    again = tmp_path / "again.json"
    result = run(cli, "plan", str(scenario), "--fixed", str(first), "--agents", "ann", "-o", str(again))
    assert result.returncode == 0, result.stderr
    before, after = json.loads(first.read_text())["agents"], json.loads(again.read_text())["agents"]
    assert [a["name"] for a in after] == ["ann", "bo", "cy"]
    assert after[1:] == before[1:]
    assert after[0]["status"] == "reached"
    assert after[0]["footsteps"]["com_end"][-1][1] == pytest.approx(1, abs=0.25)  # it was at 0
    assert "five-circle overlaps: 0" in run(cli, "metrics", str(again)).stdout
    assert "warning" not in result.stderr

    missing = run(cli, "plan", str(scenario), "--fixed", str(again), "--agents", "dee", "-o", str(tmp_path / "x.json"))
    assert missing.returncode == 2
    assert missing.stderr.splitlines() == ["footfall: --agents: 'dee' is not an agent of the scenario"]
    only_ann = tmp_path / "ann.json"
    plan = json.loads(again.read_text())
    plan["agents"] = plan["agents"][:1]
    only_ann.write_text(json.dumps(plan))
    unplanned = run(cli, "plan", str(scenario), "--fixed", str(only_ann), "--agents", "ann", "-o", str(tmp_path / "x.json"))
    assert unplanned.returncode == 2
    assert unplanned.stderr.splitlines() == [
        f"footfall: {only_ann}: has no plan for agent 'bo', which is not among the agents to plan"]
    assert not (tmp_path / "x.json").exists()


def test_an_agent_planned_again_where_fixed_agents_walk_is_named(cli, tmp_path):
    """Fixed agents make way for no one: bo, kept at his start for 10 s, stands
    where ann's fixed plan walks once he had gone; the plan is written, and bo
    is named."""
    walkers = [{"name": "ann", "position": [0, 0], "goals": [[10, 0]], "start_delay": 3.0},
               {"name": "bo", "position": [6, 0], "facing": 1.5708, "goals": [[6, 5]]}]
    scenario = tmp_path / "crossing.json"
    scenario.write_text(scenario_json(agents=walkers))
    first = tmp_path / "first.json"
    assert run(cli, "plan", str(scenario), "-o", str(first)).returncode == 0
    assert "five-circle overlaps: 0" in run(cli, "metrics", str(first)).stdout
    walkers[1]["start_delay"] = 10.0
    scenario.write_text(scenario_json(agents=walkers))
    again = tmp_path / "again.json"
    result = run(cli, "plan", str(scenario), "--fixed", str(first), "--agents", "bo", "-o", str(again))
    assert result.returncode == 0, result.stderr
    assert again.exists()
    warnings = [line for line in result.stderr.splitlines() if "warning" in line]
    assert len(warnings) == 1 and warnings[0].startswith("footfall: warning: agent 'bo' planned again overlaps "
                                                         "others or obstacles at "), result.stderr
    assert "five-circle overlaps: 0" not in run(cli, "metrics", str(again)).stdout


def test_an_agent_walled_in_by_another_until_its_time_limit_is_named_where_it_stands(cli, tmp_path):
    """A corridor 0.9 m wide, shut behind the walker; another stands in it
    for good: the walker comes up behind and stands there until its time
    limit, and one line on standard error says where and why."""
    def box(x0, y0, x1, y1):
        return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "height": 2.0}

    scenario = tmp_path / "walled.json"
    scenario.write_text(scenario_json(
        obstacles=[box(-1, 0.45, 12, 0.8), box(-1, -0.8, 12, -0.45), box(-1.3, -0.8, -1, 0.8)],
        agents=[{"name": "walled", "position": [0, 0], "goals": [[10, 0]], "time_limit": 20},
                {"name": "blocker", "position": [4, 0], "goals": [[4.5, 0]]}]))
    out = tmp_path / "walled-plan.json"
    result = run(cli, "plan", str(scenario), "-o", str(out))
    assert result.returncode == 0, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    match = re.fullmatch(r"footfall: 'walled' stands at \((-?[\d.]+), (-?[\d.]+)\) short of its goal: "
                         r"its time limit ran out", lines[0])
    assert match, lines[0]
    walled = json.loads(out.read_text())["agents"][0]
    assert walled["reason"] == "time limit"
    assert [float(match[1]), float(match[2])] == pytest.approx(walled["stopped_at"], abs=0.005)
    assert 3.3 < float(match[1]) < 4.2, "it stands behind the other, not back where it started"


def test_an_agent_that_cannot_reach_its_goal_is_named_with_the_narrowest_place(cli, tmp_path):
    """The slot is 0.25 m wide; the side-stepping body needs about 0.37 m:
    one line on standard error says so, the plan file says where, and the
    one that can reach its goal is not named."""
    scenario = tmp_path / "slot.json"
    scenario.write_text(slot_scenario_json([{"name": "wide", "position": [1, 0], "goals": [[10, 0]]},
                                            {"name": "near", "position": [1, -0.6], "goals": [[3, -0.6]]}]))
    out = tmp_path / "slot-plan.json"
    result = run(cli, "plan", str(scenario), "-o", str(out))
    assert result.returncode == 0, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert re.fullmatch(r"footfall: 'wide' cannot reach its goal: the way at \(5\.1\d, 0\.3\d\) is 0\.25 m wide, "
                        r"its body needs 0\.3\d m side-stepping", lines[0]), lines[0]
    assert "partial (unreachable)" in result.stdout
    wide, near = json.loads(out.read_text())["agents"]
    assert wide["reason"] == "unreachable" and near["status"] == "reached" and "narrowest" not in near
    assert wide["narrowest"]["at"] == pytest.approx([5.15, 0.3], abs=0.03)
    assert wide["narrowest"]["width"] == pytest.approx(0.25, abs=0.005)
    assert wide["narrowest"]["behavior"] == "side_step"


STAIRS = pathlib.Path(__file__).resolve().parents[1] / "data" / "stairs.json"


def test_a_scenario_on_ground_plans_every_foot_at_the_height_of_its_tread(cli, tmp_path):
    """tests/data/stairs.json: six treads 0.3 m deep rising 0.17 m each from
    a floor at 0 (x < 0) to a landing at 1.02 m (x > 1.8); six agents go up
    and six down."""
    out = tmp_path / "plan.json"
    result = run(cli, "plan", str(STAIRS), "-o", str(out))
    assert result.returncode == 0, result.stderr
    plan = json.loads(out.read_text())
    assert len(plan["ground"]) == 8 and "max_step_up" in plan["character"]
    for agent in plan["agents"]:
        assert agent["status"] == "reached", agent["name"]
        steps = agent["footsteps"]
        heights = steps["foot_height"]
        for (x, _), z in zip(steps["foot_position"], heights):
            tread = 0 if x < 0 else 6 if x >= 1.8 else math.floor(x / 0.3) + 1
            assert z == pytest.approx(0.17 * tread, abs=1e-9), (agent["name"], x, z)
        # A tread a step: no rise or drop over one riser.
        assert max(abs(b - a) for a, b in zip(heights, heights[1:])) == pytest.approx(0.17)


BRIDGE = STAIRS.parent / "bridge.json"


def test_path_answers_on_the_level_of_the_points_given(cli):
    """tests/data/bridge.json: a street at 0 between banks 2.89 m up, a
    footbridge's deck (x -1 to 1) spanning it from bank to bank, a flight
    from the street up into the north bank at x 6-8."""
    def path(start, end):
        result = run(cli, "path", str(BRIDGE), "--from", start, "--to", end, "--radius", "0.25")
        assert result.returncode == 0, result.stderr
        return json.loads(result.stdout)

    under = path("-10,0,0", "10,0,0")
    assert under["length"] == pytest.approx(20.0) and {p[2] for p in under["points"]} == {0.0}
    over = path("0,-8", "0,8")
    assert over["length"] == pytest.approx(16.0) and {p[2] for p in over["points"]} == {2.89}
    # From the deck to the street under it: round by the flight, 23 m.
    down = path("0,0,2.9", "0,0.5,0")
    assert down["points"][0] == [0.0, 0.0, 2.89] and down["points"][-1] == [0.0, 0.5, 0.0]
    assert any(6 < x < 8 and y > 4 for x, y, _ in down["points"])
    assert 22 < down["length"] < 25


def test_a_crowd_plans_on_and_under_a_bridge(cli, tmp_path):
    out = tmp_path / "plan.json"
    result = run(cli, "plan", str(BRIDGE), "-o", str(out))
    assert result.returncode == 0, result.stderr
    plan = json.loads(out.read_text())
    for agent in plan["agents"]:
        assert agent["status"] == "reached", agent["name"]
        heights = set(agent["footsteps"]["foot_height"]) | set(agent["start"]["foot_heights"])
        assert heights == ({2.89} if agent["name"].startswith("over") else {0.0}), agent["name"]
    metrics = run(cli, "metrics", str(out))
    assert "five-circle overlaps: 0" in metrics.stdout
    assert "off the ground 0, soles unsupported 0, rises over the limit 0, swing feet through the ground 0" in metrics.stdout


def test_path_between_two_levels_asks_for_the_height(cli):
    result = run(cli, "path", str(BRIDGE), "--from", "0,0", "--to", "5,0", "--radius", "0.25")
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr == (
        "footfall: --from: 2 levels at (0.00, 0.00), at 0.00 and 2.89 m: give its height (X,Y,Z)\n")


@pytest.mark.parametrize("scenario", [STAIRS, BRIDGE], ids=["stairs", "bridge"])
def test_a_plan_on_ground_is_animated_by_plan_and_by_animate(cli, tmp_path, scenario):
    plan, glb, again = tmp_path / "plan.json", tmp_path / "crowd.glb", tmp_path / "again.glb"
    rig = pathlib.Path(__file__).resolve().parents[2] / "rigs" / "footfall_humanoid.glb"
    result = run(cli, "plan", str(scenario), "-o", str(plan), "--glb", str(glb), "--rig", str(rig))
    assert result.returncode == 0, result.stderr
    assert run(cli, "animate", str(plan), "-o", str(again), "--rig", str(rig)).returncode == 0
    assert glb.read_bytes() == again.read_bytes()