"""Issue 20's scene-language additions as the oracle reads them: a group's members are recorded in the
order the scene creates them (as the harness's runner), and the derived body quantities are known."""

from conftest import load
from emini_oracle import box2d
from emini_oracle.run import run_scene
from emini_oracle.scene import BODY_QUANTITIES, group_matches


def test_group_patterns_match_any_text_for_star_and_the_rest_literally():
    assert group_matches("box[*]", "box[3]")
    assert not group_matches("box[*]", "box3")
    assert group_matches("drop*", "drop12")
    assert not group_matches("drop*", "xdrop1")
    assert {"displacement", "turn"} <= set(BODY_QUANTITIES)


def test_a_groups_members_are_recorded_in_creation_order(loader):
    scene = load(loader, """
shapes: {ball: {type: circle, radius: 5}}
bodies:
  - {name: drop1, shape: ball, position: [0, -100]}
  - {name: other, shape: ball, position: [60, -50]}
  - {name: drop2, shape: ball, position: [20, -200]}
run:
  duration: 0.5
  record: {bodies: [other]}
  expect:
    - {metric: body.drop2.y, of: max, atMost: 1000}
    - {metric: 'body.drop*.y', of: firstCrossing, crossing: 0, inOrder: true}
""")
    assert scene.recorded_bodies() == ["drop1", "other", "drop2"]
    for run in (run_scene, box2d.run_scene):
        doc, _ = run(scene)
        assert list(doc["bodies"]) == ["drop1", "other", "drop2"]


def test_minus_and_relative_to_record_their_bodies_and_metrics(loader):
    scene = load(loader, """
shapes: {ball: {type: circle, radius: 5}}
bodies:
  - {name: a, shape: ball, position: [0, -100]}
  - {name: b, shape: ball, position: [20, -200]}
  - {name: c, shape: ball, position: [40, -300]}
run:
  duration: 0.5
  record: {bodies: [a]}
  expect:
    - {metric: body.a.y, minus: body.b.y, of: maxAbs, atMost: 1000}
    - {metric: body.a.speed, at: 0.4, atLeast: 0.5, relativeTo: {metric: energy.kinetic, of: max}}
""")
    assert scene.recorded_bodies() == ["a", "b"]
    assert "energy" in [m.kind for m in scene.record.metrics]


def test_whole_shape_tunnelling_counts_a_rods_tip_once_in_both_oracles(loader):
    def count(points):
        scene = load(loader, """
world: {gravity: [0, 0], ticksPerSecond: 60}
bodies: [{name: rod, shape: {type: rectangle, width: 40, height: 4}, position: [-30, 0], velocity: [250, 0]}]
run: {duration: 0.1, record: {metrics: [{tunnelling: {walls: [{from: [0, -100], to: [0, 100]}]%s}}]}}
""" % points)
        return [run(scene)[0]["metrics"]["tunnelling.count"][-1] for run in (run_scene, box2d.run_scene)]
    assert count("") == [0, 0]
    assert count(", points: shape") == [1, 1]
