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
