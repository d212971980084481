"""docs/parameters.md is what the parameter tables say, and the Python
attributes carry the same units, ranges and meanings."""
import pathlib

import pytest

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "parameters.md"


def test_the_docs_page_is_the_tables(ff):
    assert DOCS.read_text() == ff.parameter_docs(), (
        "docs/parameters.md is out of date; write it anew with footfall._native.parameter_docs()")


def test_every_field_is_documented_with_unit_and_range(ff):
    for cls in (ff.CharacterParams, ff.FootLimits, ff.PlannerParams, ff.Gait):
        fields = [name for name in dir(cls) if not name.startswith("_")]
        assert fields
        for name in fields:
            doc = getattr(cls, name).__doc__
            assert doc and doc.strip(), f"{cls.__name__}.{name} has no doc"
            assert f"`{name}`" in DOCS.read_text(), f"{cls.__name__}.{name} missing from the docs"
    assert ff.CharacterParams.torso_radius.__doc__.startswith("[m] (0, torso_width / 2]. ")


def test_a_value_out_of_its_tabled_range_names_the_field_and_the_limit(ff):
    character = ff.CharacterParams()
    character.torso_radius = 0.4  # above torso_width / 2
    with pytest.raises(ValueError, match=r"character.torso_radius: must be in \(0, 0.3\], got 0.4"):
        ff.validate(character)
    planner = ff.PlannerParams()
    planner.turn_angles = []
    with pytest.raises(ValueError, match="planner.turn_angles: must hold 1 to 32 angles, got 0"):
        ff.validate(planner)
    planner = ff.PlannerParams()
    planner.goal_tolerance = 5.0
    planner.local_goal_distance = 4.0
    with pytest.raises(ValueError, match="planner.goal_tolerance: must be less than local_goal_distance"):
        ff.validate(planner)
