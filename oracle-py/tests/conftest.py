"""Shared helpers: the repository's schema and library, scenes from text, the harness's command line."""

import json
import os
import subprocess
from pathlib import Path

import pytest

from emini_oracle import scene as scene_mod
from emini_oracle.run import run_scene

REPO = Path(__file__).resolve().parents[2]
SCENARIOS = REPO / "scenarios"
SCHEMA = SCENARIOS / "scenario.schema.json"
HARNESS_CLASSES = REPO / "harness" / "target" / "classes"


@pytest.fixture(scope="session")
def loader():
    return scene_mod.Loader(SCHEMA)


def load(loader, text, name="test"):
    return loader.load_text(f"{name}.yaml", text, name)


def run(loader, text):
    """Runs a scene written as YAML text; returns its trace document."""
    doc, _ = run_scene(load(loader, text))
    return doc


def harness(*args):
    """Runs the harness's command line (built by `./emini test` before the Python tests run).

    Without a built harness the test is skipped, unless EMINI_REQUIRE_HARNESS is set (as ./emini test
    sets it), where it fails: the checks against the harness must not skip quietly in CI."""
    if not HARNESS_CLASSES.is_dir():
        if os.environ.get("EMINI_REQUIRE_HARNESS"):
            pytest.fail("the harness is not built (harness/target/classes); run ./emini test")
        pytest.skip("the harness is not built; ./emini test builds it first")
    cp = f"{HARNESS_CLASSES}{os.pathsep}{REPO / 'harness' / 'target' / 'lib' / '*'}"
    out = subprocess.run(["java", "-cp", cp, "org.emini.harness.cli.Main", *args], cwd=REPO,
                         capture_output=True, text=True, timeout=600)
    if out.returncode != 0:
        raise AssertionError(f"harness {' '.join(args)} exited {out.returncode}:\n{out.stdout}\n{out.stderr}")
    return out.stdout


def harness_json(*args):
    return json.loads(harness(*args))
