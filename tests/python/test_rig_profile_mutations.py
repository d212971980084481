"""Hostile rig profiles: thousands of seeded mutations of a valid profile
(values swapped for other types, keys dropped, added and renamed, nesting
changed) are each read or refused with a ProfileError naming a field, and
never fail any other way."""

import copy
import json
import math
import pathlib
import random

import pytest

from footfall.core import rig_profile

ROOT = pathlib.Path(__file__).resolve().parents[2]
VALID = json.loads((ROOT / "rigs" / "footfall_humanoid.json").read_text())
ODD_VALUES = [None, True, 0, -1, 1e308, -0.0, math.inf, math.nan, "", "x" * 300, "\n\x1b[31m", [], [1, 2], {}, {"a": 1},
              "hips", 3.5]


def _containers(document, path=()):
    """Every (path, container) pair in the document."""
    yield path, document
    items = document.items() if isinstance(document, dict) else enumerate(document)
    for key, value in items:
        if isinstance(value, (dict, list)):
            yield from _containers(value, path + (key,))


def mutate(document, rng: random.Random):
    """One to three random edits of a copy of `document`."""
    result = copy.deepcopy(document)
    for _ in range(rng.randint(1, 3)):
        path, container = rng.choice(list(_containers(result)))
        keys = list(container.keys()) if isinstance(container, dict) else list(range(len(container)))
        action = rng.randrange(4)
        if action == 0 and keys:  # a value of another type
            container[rng.choice(keys)] = copy.deepcopy(rng.choice(ODD_VALUES))
        elif action == 1 and keys:  # a key dropped
            del container[rng.choice(keys)]
        elif action == 2 and isinstance(container, dict):  # a key added
            key = rng.choice(["bones", "clips", "extra", "left", "hips", "walk", "leg_length"])
            container[key] = copy.deepcopy(rng.choice(ODD_VALUES))
        elif keys:  # a value nested once more
            key = rng.choice(keys)
            container[key] = [container[key]] if rng.random() < 0.5 else {"value": container[key]}
    return result


@pytest.mark.parametrize("partial", [False, True])
def test_every_mutation_is_read_or_refused_by_field(partial):
    rng = random.Random(20261204 + partial)
    refused = 0
    for _ in range(3000):
        document = mutate(VALID, rng)
        try:
            rig_profile.parse(document, "robot.json", partial=partial)
        except rig_profile.ProfileError as error:
            refused += 1
            message = str(error)
            assert message.startswith("robot.json: ") and "\n" not in message, message
    assert refused > 1000  # most mutations break something


def test_a_document_of_another_shape_is_refused():
    for document in (None, [], "profile", 3, [VALID]):
        with pytest.raises(rig_profile.ProfileError):
            rig_profile.parse(document, "robot.json")
