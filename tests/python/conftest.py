"""Shared fixtures: the add-on folder on sys.path, the native module, the CLI."""

import os
import pathlib
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
ADDON_DIR = pathlib.Path(os.environ.get("FOOTFALL_ADDON_DIR", ROOT / "blender_addon"))
sys.path.insert(0, str(ADDON_DIR))


@pytest.fixture(scope="session")
def ff():
    """The compiled planning core, footfall._native."""
    from footfall.core import native

    return native.load()


@pytest.fixture(scope="session")
def cli():
    """Path of the footfall command-line program."""
    path = pathlib.Path(os.environ.get("FOOTFALL_CLI", ROOT / "build" / "footfall"))
    if not path.exists():
        pytest.fail(f"the footfall CLI is not built at {path}")
    return str(path)


def scenario_json(**parts):
    """Scenario JSON text with the header and the given top-level parts."""
    import json

    return json.dumps({"format": "footfall-scenario", "version": 1, **parts}, allow_nan=True)


def slot_scenario_json(agents):
    """A corridor 2 m wide along x (walls at y = +-1, shut at x = -1 and 12)
    crossed at x = 5-5.3 by two boxes that leave a slot 0.25 m wide, its
    middle at (5.15, 0.3): too narrow for anyone side-stepping."""
    def box(x0, y0, x1, y1):
        return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "height": 2.0}

    return scenario_json(obstacles=[box(-1, 1, 12, 1.3), box(-1, -1.3, 12, -1), box(-1.3, -1.3, -1, 1.3),
                                    box(12, -1.3, 12.3, 1.3), box(5, -1, 5.3, 0.175), box(5, 0.425, 5.3, 1)],
                         agents=agents)
