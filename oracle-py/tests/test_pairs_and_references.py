"""Penetration per named pair (between), a bare generator name as a group, and a reference trace
(minus: {trace}) as the oracles read them: the same channels, pairs and recorded bodies as the harness."""

import json

import pytest

from conftest import SCHEMA, harness, load
from emini_oracle import box2d
from emini_oracle.run import run_scene
from emini_oracle.scene import SceneError

# A ball put down on a ground, another on a landscape segment, a row of three on a shelf; sampled every tick.
PAIRS = """
world: {ticksPerSecond: 20, iterations: 4}
shapes: {ball: {type: circle, radius: 10}, ground: {type: rectangle, width: 200, height: 20}}
bodies:
  - {name: ground, shape: ground, position: [0, 10], static: true}
  - {name: sunk, shape: ball, position: [0, -9]}
  - {name: slow, shape: ball, position: [1000, -10.5]}
  - {name: shelf, shape: ground, position: [-1000, 10], static: true}
generators: [{type: row, name: pebble, shape: ball, start: [-1040, -10.5], count: 3, spacing: [40, 0]}]
landscape: {segments: [{from: [900, 0], to: [1100, 0]}]}
run:
  duration: 1
  record: {bodies: none, metrics: [penetration]}
  expect:
    - {metric: penetration.max, between: [sunk, ground], of: max, atMost: 5}
    - {metric: penetration.mean, between: [pebble, shelf], of: max, atMost: 5}
    - {metric: penetration.max, between: [sunk, slow], of: max, atMost: 0}
    - {metric: penetration.points, between: ['*', landscape], of: max, atLeast: 0}
"""

PAIR_CHANNELS = [f"penetration.{q}({a}, {b})" for a, b in
                 (("sunk", "ground"), ("pebble[*]", "shelf"), ("sunk", "slow"), ("*", "landscape"))
                 for q in ("max", "mean", "points")]


@pytest.mark.parametrize("run", [run_scene, box2d.run_scene], ids=["pymunk", "box2d"])
def test_pairs_are_named_and_between_narrows_the_worlds_penetration(loader, run):
    doc, _ = run(load(loader, PAIRS))
    m = doc["metrics"]
    assert list(m) == ["penetration.max", "penetration.mean", "penetration.points"] + PAIR_CHANNELS
    pairs = doc["penetrationPairs"]
    named = {(p["a"], p["b"]) for p in pairs}
    assert named == {("ground", "sunk"), ("slow", "landscape"), ("shelf", "pebble[0]"), ("shelf", "pebble[1]"),
                     ("shelf", "pebble[2]")}
    assert [p["max"] for p in pairs] == sorted((p["max"] for p in pairs), reverse=True)
    # Sampled every tick: the deepest pair's max is the world's over the run, and each filter reads its pairs only.
    assert pairs[0]["max"] == max(m["penetration.max"])
    by = {(p["a"], p["b"]): p for p in pairs}
    assert max(m["penetration.max(sunk, ground)"]) == by[("ground", "sunk")]["max"]
    assert max(m["penetration.max(pebble[*], shelf)"]) == max(by[("shelf", f"pebble[{i}]")]["max"] for i in range(3))
    assert m["penetration.max(sunk, slow)"] == [0.0] * len(doc["tick"])
    assert max(m["penetration.points(*, landscape)"]) >= 1
    for p in pairs:
        assert 0 < p["mean"] <= p["max"] and p["samples"] > 0


def test_pair_channels_and_names_line_up_with_the_engines_trace(loader, tmp_path):
    f = tmp_path / "pairs.yaml"
    f.write_text(PAIRS)
    reports = tmp_path / "engine"
    harness("run", "--schema", str(SCHEMA), "--reports", str(reports), "--no-progress", str(f))
    theirs = json.loads((reports / "traces" / "pairs.trace.json").read_text())
    ours, _ = run_scene(load(loader, PAIRS, "pairs"))
    assert list(ours["metrics"]) == list(theirs["metrics"])
    assert {(p["a"], p["b"]) for p in ours["penetrationPairs"]} == {(p["a"], p["b"]) for p in theirs["penetrationPairs"]}


def test_a_bare_generator_name_is_its_bodies_unless_a_body_has_that_name(loader):
    text = """
shapes: {box: {type: rectangle, width: 20, height: 20}}
bodies: [{name: ground, shape: {type: rectangle, width: 400, height: 20}, position: [0, 10], static: true}]
generators: [{type: tower, name: box, shape: box, base: [0, -10], count: 3}]
run:
  duration: 0.2
  record: {bodies: [ground]}
  expect:
    - {metric: body.box.displacement, of: max, atMost: 1}
"""
    scene = load(loader, text)
    assert scene.recorded_bodies() == ["ground", "box[0]", "box[1]", "box[2]"]
    assert scene.expect[0]["metric"] == "body.box[*].displacement"
    clash = text.replace("bodies: [{name: ground,", "bodies: [{name: box, shape: box, position: [300, 0]}, {name: ground,")
    with pytest.raises(SceneError, match=r"'box' names both a body and the generator box"):
        load(loader, clash)


def test_a_reference_trace_is_the_harnesss_to_read_and_the_oracle_records_the_channel(loader):
    scene = load(loader, """
bodies: [{name: ball, shape: {type: circle, radius: 5}}]
run:
  duration: 0.5
  record: {bodies: none}
  expect:
    - {metric: body.ball.y, minus: {trace: nowhere.trace.json}, of: maxAbs, atMost: 1}
""")
    # The oracle does not read the reference (the harness judges it): it records the channel compared.
    assert scene.recorded_bodies() == ["ball"]
    doc, _ = run_scene(scene)
    assert list(doc["bodies"]) == ["ball"]
