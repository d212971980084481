"""Shared by the Blender background tests: checks, an evaluated mesh's
points, and a runner that reports every test and makes Blender exit non-zero
when any fails."""

import json
import os
import pathlib
import subprocess
import sys
import traceback

VALIDATOR = pathlib.Path(__file__).resolve().parents[1] / "gltf" / "validate.mjs"


def check(condition, message):
    """Fails the current test with `message` unless `condition` holds."""
    if not condition:
        raise AssertionError(message)


def evaluated_points(obj, depsgraph):
    """The vertices of the object's evaluated mesh (modifiers and armature
    applied) in world space, (n, 3) [m]."""
    import numpy

    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    co = numpy.empty(3 * len(mesh.vertices), dtype=numpy.float64)
    mesh.vertices.foreach_get("co", co)
    evaluated.to_mesh_clear()
    world = numpy.array(evaluated.matrix_world)
    return co.reshape(-1, 3) @ world[:3, :3].T + world[:3, 3]


def expect_valid_gltf(path):
    """The Khronos glTF validator finds no error in the file."""
    result = subprocess.run(["node", str(VALIDATOR), str(path)], capture_output=True, text=True)
    report = json.loads(result.stdout)["issues"]
    print(f"validator: {report['numErrors']} errors, {report['numWarnings']} warnings")
    check(result.returncode == 0 and report["numErrors"] == 0, f"the validator found errors: {result.stdout[:2000]}")


def run(tests):
    """Runs the test functions in order; prints PASS/FAIL each and 'N passed, M failed'."""
    failed = 0
    for test in tests:
        try:
            test()
            print(f"PASS {test.__name__}")
        except Exception as error:  # report every test, then fail the run
            failed += 1
            traceback.print_exc()
            print(f"FAIL {test.__name__}: {error!r}")
    print(f"{len(tests) - failed} passed, {failed} failed")
    # Blender as a Python module (PyPI's bpy) may hang at interpreter exit
    # (4.5 does, after the tests have run): leave at once, with the result.
    import bpy

    if getattr(bpy.app, "module", False):
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(1 if failed else 0)
    if failed:
        sys.exit(1)
