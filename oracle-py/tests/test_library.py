"""Every scene of the library runs in the oracle or states why not."""

import json

import pytest

from conftest import SCENARIOS, SCHEMA
from emini_oracle import cli
from emini_oracle import scene as scene_mod
from emini_oracle.run import run_scene

FILES = scene_mod.scene_files([SCENARIOS])


@pytest.mark.parametrize("file", FILES, ids=[str(f.relative_to(SCENARIOS)) for f in FILES])
def test_library_scene_runs_or_states_why_not(loader, file):
    s = loader.load(file)
    skip = (s.oracle or {}).get("skip")
    if skip:
        assert skip.strip(), "a skipped scene says why"
        return
    # The first ticks exercise the whole mapping (every element is built); the full runs are in
    # ./emini run's comparison.
    doc, built = run_scene(s, ticks=3)
    assert doc["tick"][0] == 0 and doc["tick"][-1] == min(3, s.ticks)
    for note in doc["unsupported"] + doc["approximations"]:
        assert note["element"] and note["path"].startswith("$") and note["reason"]
    # Nothing dropped silently: an element section is either built or named as unsupported.
    named = {n["element"] for n in doc["unsupported"]}
    if "particles" in s.elements:
        assert "particles" in named
    if any("velocity" in m for m in s.elements.get("motors", [])):
        assert "linear motor" in named
    for j in s.elements.get("joints", []):
        mapped = j.get("type", "pin") in ("pin", "revolute", "distance", "rope", "wheel") or (
            j["type"] == "prismatic" and "motor" not in j)
        if not mapped:
            assert "joint type " + j["type"] in named


def test_skipped_and_invalid_scenes_are_reported_not_run(tmp_path):
    (tmp_path / "skip.yaml").write_text(
        "reference: {oracle: {skip: needs an element pymunk lacks}}\n"
        "bodies: [{shape: {type: circle, radius: 1}}]\nrun: {duration: 1}\n")
    (tmp_path / "bad.yaml").write_text("run: {duration: -1}\n")
    out = tmp_path / "out"
    status = cli.main(["run", "--quiet", "--jobs", "1", "--schema", str(SCHEMA), "--out", str(out), str(tmp_path)])
    assert status == 1  # an invalid scene fails the run
    entries = {e["file"].rsplit("/", 1)[-1]: e for e in json.loads((out / "oracle-results.json").read_text())["scenes"]}
    assert entries["skip.yaml"]["status"] == "skipped"
    assert entries["skip.yaml"]["message"] == "needs an element pymunk lacks"
    assert entries["bad.yaml"]["status"] == "invalid" and "duration" in entries["bad.yaml"]["message"]
