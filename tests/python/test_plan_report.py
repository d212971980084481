"""The plan's outcome as the Plan operator and the panel report it."""

from footfall.core.plan_report import NAMED, outcome, overlapping, unreachable


def test_all_reached_is_one_count():
    assert outcome([("a", True, ""), ("b", True, "")]) == "2/2 agents reached their goals"


def test_those_not_there_are_named_with_their_reason():
    text = outcome([("ann", True, ""), ("kid", False, "stuck"), ("bob", False, "time limit")])
    assert text == "1/3 agents reached their goals; not there: 'kid' (stuck), 'bob' (time limit)"


def test_a_long_list_is_cut_short_and_counted():
    agents = [(f"agent{i}", False, "stuck") for i in range(NAMED + 3)]
    text = outcome(agents)
    assert text.count("(stuck)") == NAMED and text.endswith("and 3 more")
    assert text.startswith(f"0/{NAMED + 3} agents")


def test_only_agents_planned_again_that_overlap_are_named():
    agents = [("ann", 14), ("bo", 12), ("cy", 0)]
    assert overlapping(agents, {"cy"}, 20.0) == ""
    text = overlapping(agents, {"bo", "cy"}, 20.0)
    assert text.startswith("; overlapping others: 'bo' (12 samples at 20 Hz): ") and "ann" not in text
    assert text.endswith("plan every agent")
    many = overlapping([(f"a{i}", 1) for i in range(NAMED + 2)], {f"a{i}" for i in range(NAMED + 2)}, 20.0)
    assert many.count("(1 samples") == NAMED and "and 2 more" in many


def test_those_that_cannot_reach_get_a_line_each_saying_where():
    said = "cannot reach its goal: the way at (5.10, 0.00) is 0.52 m wide, its body needs 0.60 m side-stepping"
    assert unreachable([]) == ""
    assert unreachable([("big", said)]) == "; 'big' " + said
    many = unreachable([(f"a{i}", said) for i in range(NAMED + 2)])
    assert many.count("; ") == NAMED + 1 and many.endswith("; 2 more cannot reach their goals")
