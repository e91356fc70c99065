"""The Box2D v3 oracle's mapping (oracle-py/MAPPING.md, Box2D v3), checked on cases with a closed form.

Box2D integrates each substep with the new velocity (symplectic Euler, as Emini's substeps), so with N
substeps of h/N a projectile leads the parabola by g·(h/N)·t/2.
"""

import math

import pytest

from conftest import load
from emini_oracle import box2d


def run(loader, text):
    doc, world = box2d.run_scene(load(loader, text))
    return doc, world


def col(doc, body, q):
    return doc["bodies"][body][q]


def test_a_projectile_leads_the_parabola_by_one_substeps_half_step(loader):
    doc, _ = run(loader, """
world: {ticksPerSecond: 20, iterations: 10}
bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [100, -200]}]
run: {duration: 4}
""")
    assert doc["source"] == "box2d"
    g, h = 100.0, 0.05 / 10
    for t, x, y in zip(doc["time"], col(doc, "ball", "x"), col(doc, "ball", "y")):
        assert x == pytest.approx(100 * t, abs=1e-3)
        # Metres in float32: 1e-3 px of rounding per metre of travel.
        assert y == pytest.approx(-200 * t + 0.5 * g * t * t + 0.5 * g * h * t, abs=2e-3 * (1 + t))


def test_angles_turn_on_past_pi_as_emini_counts_them(loader):
    doc, _ = run(loader, """
world: {ticksPerSecond: 60, gravity: [0, 0]}
bodies: [{name: box, shape: {type: rectangle, width: 20, height: 10}, angularVelocity: 3}]
run: {duration: 5}
""")
    # Box2D keeps its rotation in (-pi, pi]; the trace unwraps it: 3 rad/s for 5 s is 15 rad.
    assert col(doc, "box", "angle")[-1] == pytest.approx(15, abs=1e-2)


def test_mass_and_moment_are_the_scenes_not_box2ds_density(loader):
    doc, world = run(loader, """
world: {gravity: [0, 0]}
bodies: [{name: box, shape: {type: rectangle, width: 40, height: 20, mass: 3}, velocity: [10, 0], angularVelocity: 2}]
run: {duration: 0.5, record: {metrics: [energy]}}
""")
    b = world.bodies["box"]
    assert b.mass == pytest.approx(3)
    # I = m (w^2 + h^2) / 12 in px^2, in Box2D's metres (20 px = 1 m).
    assert b.rotational_inertia() == pytest.approx(3 * (40 ** 2 + 20 ** 2) / 12 / 400, rel=1e-6)
    kinetic = 0.5 * 3 * 100 + 0.5 * 3 * (40 ** 2 + 20 ** 2) / 12 * 4
    assert doc["metrics"]["energy.kinetic"][-1] == pytest.approx(kinetic, rel=1e-5)


def test_a_bounce_off_the_ground_keeps_emini_s_product_of_elasticities(loader):
    # Ball e = 0.5 on a ground of elasticity 0.8: Emini bounces with 0.4; Box2D's max would give 0.8.
    doc, world = run(loader, """
world: {ticksPerSecond: 240, gravity: [0, 0]}
shapes:
  ground: {type: rectangle, width: 400, height: 40, elasticity: 0.8}
  ball: {type: circle, radius: 10, elasticity: 0.5}
bodies:
  - {name: ground, shape: ground, position: [0, 20], static: true}
  - {name: ball, shape: ball, position: [0, -50], velocity: [0, 200]}
run: {duration: 1}
""")
    assert col(doc, "ball", "vy")[-1] == pytest.approx(-0.4 * 200, rel=0.02)
    assert [n["element"] for n in doc["approximations"]] == []


def test_friction_multiplies_as_in_emini(loader):
    # A box at 30 degrees on a ground of friction 1 with its own 0.1: mu = 0.1 < tan 30, so it slides with
    # a = g (sin 30 - 0.1 cos 30) along the slope (Box2D's sqrt(a b) would give mu = 0.32, still sliding
    # but slower). Gravity turned to the slope instead of the ground: the same physics.
    g = 100.0
    doc, _ = run(loader, f"""
world: {{ticksPerSecond: 120, gravity: [{g * math.sin(math.radians(30)):.6f}, {g * math.cos(math.radians(30)):.6f}]}}
shapes:
  ground: {{type: rectangle, width: 4000, height: 40, friction: 1}}
  box: {{type: rectangle, width: 20, height: 20, friction: 0.1}}
bodies:
  - {{name: ground, shape: ground, position: [0, 20], static: true}}
  - {{name: box, shape: box, position: [0, -10]}}
run: {{duration: 2}}
""")
    a = g * (math.sin(math.radians(30)) - 0.1 * math.cos(math.radians(30)))
    assert col(doc, "box", "vx")[-1] == pytest.approx(a * 2, rel=0.02)


def test_what_box2d_cannot_express_is_named(loader):
    doc, _ = run(loader, """
shapes: {b: {type: circle, radius: 5}}
bodies:
  - {name: a, shape: b, position: [0, 0], static: true}
  - {name: c, shape: b, position: [50, 0]}
springs: [{bodyA: a, bodyB: c, stiffness: 10}]
run: {duration: 0.1}
""")
    notes = {n["element"]: n for n in doc["unsupported"]}
    assert notes["springs"]["affectsBodies"] is True
