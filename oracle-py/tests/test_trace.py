"""The oracle writes the harness's trace format (version 1): same fields, same sample ticks, same
bodies and channels in the same order as the engine's trace of the same scene."""

import json

from conftest import SCHEMA, harness
from emini_oracle import cli

SCENE = """
world: {ticksPerSecond: 30, gravity: [0, 100]}
shapes: {box: {type: rectangle, width: 20, height: 20}, ball: {type: circle, radius: 5}}
bodies:
  - {name: ground, shape: {type: rectangle, width: 400, height: 20}, position: [0, 10], static: true}
  - {name: ball, shape: ball, position: [0, -100], velocity: [10, 0]}
generators:
  - {type: tower, name: t, shape: box, base: [100, -10], count: 3}
run:
  duration: 1.01
  record:
    every: 0.1
    bodies: [ball]
    metrics: [energy, {angularMomentum: {about: [0, -50]}}, penetration,
              {tunnelling: {walls: [ground]}}, stability]
  expect:
    - {body: "t[2]", endsNear: [100, -50], tolerance: 5}
    - {metric: momentum.x, of: maxAbs, atMost: 100}
    - {metric: "body.t[0].y", of: final, atMost: 0}
"""


def oracle_trace(tmp_path):
    f = tmp_path / "fmt.yaml"
    f.write_text(SCENE)
    out = tmp_path / "oracle"
    assert cli.main(["run", "--quiet", "--jobs", "1", "--schema", str(SCHEMA), "--out", str(out), str(f)]) == 0
    results = json.loads((out / "oracle-results.json").read_text())
    (entry,) = results["scenes"]
    assert entry["status"] == "ok" and entry["scene"] == "fmt"
    return f, json.loads((out / "fmt.trace.json").read_text())


def test_trace_fields_and_sampling(tmp_path):
    _, doc = oracle_trace(tmp_path)
    assert (doc["format"], doc["version"], doc["source"], doc["scene"]) == ("emini-trace", 1, "pymunk", "fmt")
    assert doc["timestep"] == 1 / 30
    # 31 ticks (ceil(1.01 * 30) = 31), every round(0.1 * 30) = 3 ticks, and the last one.
    assert doc["tick"] == list(range(0, 31, 3)) + [31]
    assert doc["time"] == [t * (1 / 30) for t in doc["tick"]]
    # Recorded: the listed body, then bodies expectations read, in that order.
    assert list(doc["bodies"]) == ["ball", "t[2]", "t[0]"]
    for columns in doc["bodies"].values():
        assert list(columns) == ["x", "y", "angle", "vx", "vy", "omega"]
        assert all(len(c) == len(doc["tick"]) for c in columns.values())
    # Listed metrics in order, then those expectations need.
    assert list(doc["metrics"]) == [
        "energy.kinetic", "energy.potential", "energy.total", "angularMomentum",
        "penetration.max", "penetration.mean", "penetration.points", "tunnelling.count",
        "stability.maxSpeed", "stability.maxAngularSpeed", "stability.nonFinite", "momentum.x", "momentum.y"]
    assert doc["unsupported"] == [] and doc["approximations"] == []
    assert doc["oracle"]["pymunk"] == "7.3.1"


def test_trace_lines_up_with_the_engines_trace_of_the_same_scene(tmp_path):
    f, ours = oracle_trace(tmp_path)
    reports = tmp_path / "engine"
    harness("run", "--schema", str(SCHEMA), "--reports", str(reports), "--no-progress", str(f))
    theirs = json.loads((reports / "traces" / "fmt.trace.json").read_text())
    assert theirs["source"] == "emini"
    for key in ("format", "version", "scene", "timestep", "tick", "time"):
        assert ours[key] == theirs[key], key
    assert list(ours["bodies"]) == list(theirs["bodies"])
    for body in ours["bodies"]:
        assert list(ours["bodies"][body]) == list(theirs["bodies"][body])
    assert list(ours["metrics"]) == list(theirs["metrics"])
    # Same physics to the first sample: the initial state is the scene's.
    assert ours["bodies"]["ball"]["x"][0] == theirs["bodies"]["ball"]["x"][0] == 0
    assert ours["metrics"]["energy.total"][0] == theirs["metrics"]["energy.total"][0]


def test_non_finite_values_are_written_as_null(tmp_path):
    from emini_oracle.run import _finite
    assert _finite(float("nan")) is None and _finite(float("inf")) is None and _finite(1.5) == 1.5
