"""world.sleeping and sleepingAllowed in pymunk (MAPPING.md, Sleeping): the thresholds, who sleeps,
who is kept awake, what wakes a sleeping body, and the trace's sleeping column."""

import pytest

from conftest import load, run
from emini_oracle.build import SLEEP_LINEAR_TOLERANCE, SLEEP_TIME, build
from emini_oracle.run import run_scene, time_steps

# Four boxes resting apart on a static ground (each its own component), a fifth that may not sleep with
# a sixth resting on it: that pair is one component, kept awake. Everything starts at rest.
BOXES = """
world: {ticksPerSecond: 20%s}
shapes: {box: {type: rectangle, width: 20, height: 20, friction: 0.5}}
bodies:
  - {name: ground, shape: {type: rectangle, width: 600, height: 20}, position: [0, 10], static: true}
  - {name: player, shape: box, position: [200, -10], sleepingAllowed: false}
  - {name: rider, shape: box, position: [200, -30]}
generators: [{type: row, name: box, shape: box, start: [-200, -10], count: 4, spacing: [60, 0]}]
%s
run: {duration: 2, record: {metrics: [sleeping]}}
"""


def count(doc):
    return doc["metrics"]["sleeping.count"]


def test_sleeping_is_off_unless_the_scene_turns_it_on(loader):
    built = build(load(loader, BOXES % ("", "")))
    assert built.space.sleep_time_threshold == float("inf") and not built.sleeping
    doc = run(loader, BOXES % ("", ""))
    assert max(count(doc)) == 0
    assert "sleeping" not in doc["bodies"]["box[0]"]


def test_the_engines_defaults_and_a_scenes_tolerances_become_pymunks_thresholds(loader):
    built = build(load(loader, BOXES % (", sleeping: true", "")))
    assert built.space.sleep_time_threshold == SLEEP_TIME == 0.5
    assert built.space.idle_speed_threshold == SLEEP_LINEAR_TOLERANCE == 1.0
    assert [n.element for n in built.approximations] == ["world.sleeping"]
    built = build(load(loader, BOXES % (", sleeping: {linearTolerance: 3, angularTolerance: 0.2, timeToSleep: 1.25}", "")))
    assert built.space.sleep_time_threshold == 1.25
    assert built.space.idle_speed_threshold == 3.0
    assert built.settings["sleep_time_threshold"] == 1.25


def test_resting_bodies_sleep_and_one_that_may_not_keeps_its_component_awake(loader):
    doc = run(loader, BOXES % (", sleeping: true", ""))
    # The four lone boxes rest from the start: asleep once they have been idle for 0.5 s (pymunk's first
    # steps set them down on the ground faster than 1 px/s, so a little later), and they stay asleep.
    times = doc["time"]
    first = next(t for t, c in zip(times, count(doc)) if c == 4)
    assert 0.5 <= first <= 1.0
    assert count(doc)[-1] == 4 and doc["metrics"]["sleeping.fraction"][-1] == pytest.approx(4 / 6)
    # The player is activated before every step, and so is the rider it touches.
    assert max(doc["bodies"]["player"]["sleeping"]) == 0
    assert max(doc["bodies"]["rider"]["sleeping"]) == 0
    assert doc["bodies"]["box[2]"]["sleeping"][-1] == 1


def test_an_impulse_wakes_a_sleeping_body_and_damping_does_not(loader):
    doc = run(loader, BOXES % (", sleeping: true, damping: {lateral: 0.01, rotational: 0.01}",
                               "actions: [{at: 1.5, type: impulse, body: 'box[1]', impulse: [0, -100]}]"))
    s = doc["bodies"]["box[1]"]["sleeping"]
    k = doc["time"].index(1.5)
    # Asleep before the impulse although damping is applied after every step (to awake bodies only).
    assert s[k] == 1
    assert s[k + 1] == 0 and doc["bodies"]["box[1]"]["vy"][k + 1] < -50
    assert doc["bodies"]["box[0]"]["sleeping"][-1] == 1


def test_a_gravity_change_wakes_everything(loader):
    doc = run(loader, BOXES % (", sleeping: true", "actions: [{at: 1.5, type: gravity, gravity: [0, 50]}]"))
    k = doc["time"].index(1.5)
    assert count(doc)[k] == 4 and count(doc)[k + 1] == 0


def test_timing_keeps_the_player_awake_too(loader):
    wall, cpu = time_steps(load(loader, BOXES % (", sleeping: true", "")))
    assert wall > 0 and cpu >= 0
    _, built = run_scene(load(loader, BOXES % (", sleeping: true", "")))
    assert not built.bodies["player"].is_sleeping and built.bodies["box[3]"].is_sleeping


def test_damping_without_waking_removes_the_same_fractions(loader):
    # A spinning ball in flight never rests; its damped motion must not depend on whether sleeping is on,
    # though the damping then goes through cpBodyUpdateVelocity instead of the velocity setters.
    text = """
world: {ticksPerSecond: 20, damping: {lateral: 0.1, rotational: 0.3}%s}
bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [40, -30], angularVelocity: 3}]
run: {duration: 2}
"""
    off, on = run(loader, text % ""), run(loader, text % ", sleeping: true")
    for q in ("x", "y", "angle", "vx", "vy", "omega"):
        assert on["bodies"]["ball"][q] == pytest.approx(off["bodies"]["ball"][q], rel=1e-12, abs=1e-12), q
    assert max(on["bodies"]["ball"]["sleeping"]) == 0
