"""Fixtures of the Python module's tests: the repository's scenes, the CLI, a tiny scene.

ctest runs them (python/CMakeLists.txt) with PYTHONPATH at build/python, CANDELA_CLI naming the
candela program and CANDELA_SOURCE_DIR the repository; by hand, from the repository:
    PYTHONPATH=build/python python3 -m pytest python/tests
"""
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CANDELA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("CANDELA_CLI", SOURCE_DIR / "build" / "candela"))
CORNELL = SOURCE_DIR / "scenes" / "cornell-box" / "scene.json"
CORNELL_PBRT = SOURCE_DIR / "scenes" / "pbrt-v4" / "cornell-box" / "scene-v4.pbrt"
BAD_INPUTS = SOURCE_DIR / "tests" / "data" / "bad_inputs"


def tiny_document(albedo=0.5):
    """A diffuse sphere under a uniform sky, 8x6 pixels, 2 spp: milliseconds to render."""
    return {
        "sampler": {"spp": 2, "seed": 0},
        "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40,
                   "resolution": [8, 6]},
        "materials": {"m": {"type": "diffuse", "albedo": albedo}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
        "lights": [{"type": "environment", "color": [1, 1, 1]}],
    }


def run_cli(*args, check=True):
    """Runs the candela program; its CompletedProcess (text output)."""
    done = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"candela {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}")
    return done


@pytest.fixture(scope="session")
def cornell():
    import candela
    return candela.load(CORNELL)
