"""The oracle's mapping of the scene format to pymunk, checked on cases with a closed form.

Each test states the physics it checks; bounds come from the closed form and pymunk's integrator
(Chipmunk integrates positions with the previous velocity, then velocities: x lags by g·h·t/2).
"""

import math

import pymunk
import pytest

from conftest import SCENARIOS, load, run
from emini_oracle.build import build
from emini_oracle.run import run_scene


def column(doc, body, q):
    return doc["bodies"][body][q]


def ellipk(m):
    """Complete elliptic integral of the first kind K(m), by the arithmetic-geometric mean."""
    a, b = 1.0, math.sqrt(1.0 - m)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


# ---------------------------------------------------------------------------------------------------
# Free fall

def test_free_fall_is_the_parabola_less_pymunks_half_step_lag(loader):
    doc = run(loader, """
world: {ticksPerSecond: 20}
bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [100, -200]}]
run: {duration: 4}
""")
    h, g = 0.05, 100.0
    for t, x, y, vx, vy in zip(doc["time"], column(doc, "ball", "x"), column(doc, "ball", "y"),
                               column(doc, "ball", "vx"), column(doc, "ball", "vy")):
        assert x == pytest.approx(100 * t, abs=1e-9)
        # y = v0 t + g t^2 / 2 exactly, less g h t / 2 (positions first, with the old velocity).
        assert y == pytest.approx(-200 * t + 0.5 * g * t * t - 0.5 * g * h * t, abs=1e-9)
        assert vx == pytest.approx(100, abs=1e-12)
        assert vy == pytest.approx(-200 + g * t, abs=1e-9)
    # So against the closed form it errs by g h t / 2 = 10 px at t = 4 s: the scene's own bound.
    assert abs(column(doc, "ball", "y")[-1] - (-800 + 800)) == pytest.approx(10, abs=1e-9)


def test_gravity_false_and_gravity_actions(loader):
    doc = run(loader, """
world: {gravity: [0, 100]}
bodies:
  - {name: floating, shape: {type: circle, radius: 5}, gravity: false, velocity: [3, 0]}
  - {name: falling, shape: {type: circle, radius: 5}, position: [100, 0]}
actions: [{at: 0.5, type: gravity, gravity: [0, -50]}]
run: {duration: 1}
""")
    assert column(doc, "floating", "vy")[-1] == 0
    assert column(doc, "floating", "x")[-1] == pytest.approx(3.0, abs=1e-9)
    # 10 ticks at +100, then 10 at -50: vy = 5.
    assert column(doc, "falling", "vy")[-1] == pytest.approx(100 * 0.5 - 50 * 0.5, abs=1e-9)


# ---------------------------------------------------------------------------------------------------
# Pendulum

def test_pendulum_period_matches_the_elliptic_integral(loader):
    # The library's pendulum (a 10 x 10 bob pinned 100 px from the pivot, released at 90 degrees),
    # run at 240 Hz so the integrator's own error is small: T = 4 sqrt(L/g) K(sin^2(45 deg)), with
    # L = I_pivot / (m d) = (100 * 2 / 12 + 100^2) / 100 (checks the box's moment and the pin joint).
    text = (SCENARIOS / "closed-form" / "pendulum-90deg.yaml").read_text()
    text = text.replace("run:\n  duration: 10", "world: {ticksPerSecond: 240}\nrun:\n  duration: 16")
    doc = run(loader, text)
    L = (100 * 2 / 12 + 100.0 ** 2) / 100
    period = 4 * math.sqrt(L / 100) * ellipk(math.sin(math.pi / 4) ** 2)
    assert period == pytest.approx(7.4225, abs=1e-3)
    # Times the bob passes under the pivot moving toward -x (x crosses 0 downward).
    times, xs = doc["time"], column(doc, "bob", "x")
    crossings = [times[i] + (times[i + 1] - times[i]) * xs[i] / (xs[i] - xs[i + 1])
                 for i in range(len(xs) - 1) if xs[i] > 0 >= xs[i + 1]]
    assert len(crossings) >= 2
    measured = crossings[1] - crossings[0]
    assert measured == pytest.approx(period, rel=0.005)
    # The first pass comes a quarter period after the release.
    assert crossings[0] == pytest.approx(period / 4, rel=0.01)


def test_pendulum_keeps_its_arm_length(loader):
    doc, built = run_scene(loader.load(SCENARIOS / "closed-form" / "pendulum-90deg.yaml"))
    assert max(doc["metrics"]["constraintError.max"]) < 1.0  # the scene's own bound


# ---------------------------------------------------------------------------------------------------
# Bounces, friction and elasticity as products

@pytest.mark.parametrize("e", [0.5, 0.8])
def test_bounce_height_is_e_squared_times_the_drop(loader, e):
    # Ball elasticity e, ground 1: the contact uses the product e. Dropped 200 px onto the floor it
    # rises e^2 * 200 px. At 240 Hz one step of travel at impact speed (200 px/s) is 0.83 px; pymunk
    # detects the impact up to one step late and bounces from there: 2 px covers it.
    doc = run(loader, f"""
world: {{ticksPerSecond: 240}}
shapes:
  ground: {{type: rectangle, width: 400, height: 40, elasticity: 1}}
  ball: {{type: circle, radius: 10, elasticity: {e}}}
bodies:
  - {{name: ground, shape: ground, position: [0, 20], static: true}}
  - {{name: ball, shape: ball, position: [0, -210]}}
run: {{duration: 4}}
""")
    times, ys = doc["time"], column(doc, "ball", "y")
    t_impact = math.sqrt(2 * 200 / 100)
    after = [y for t, y in zip(times, ys) if t_impact + 0.1 < t < t_impact + 2 * e * 2 + 0.1]
    apex = -10 - min(after)
    assert apex == pytest.approx(e * e * 200, abs=2.0)


def test_friction_and_elasticity_combine_as_products(loader):
    s = load(loader, """
world: {gravity: [0, 100]}
shapes:
  ground: {type: rectangle, width: 400, height: 40, friction: 0.5, elasticity: 0.8}
  ball: {type: circle, radius: 10, friction: 0.4, elasticity: 0.5}
bodies:
  - {name: ground, shape: ground, position: [0, 20], static: true}
  - {name: ball, shape: ball, position: [0, -9]}
run: {duration: 1}
""")
    built = build(s)
    seen = []
    built.space.on_collision(None, None, pre_solve=lambda arb, space, data: seen.append((arb.friction, arb.restitution)))
    built.space.step(0.05)
    assert seen and seen[0] == (pytest.approx(0.2), pytest.approx(0.4))


def test_sliding_box_accelerates_as_coulomb_friction_says(loader):
    # The library's incline-slip: friction 0.1 x 1, 30 degrees: a = g (sin 30 - 0.1 cos 30).
    doc, _ = run_scene(loader.load(SCENARIOS / "closed-form" / "incline-slip.yaml"))
    a = 100 * (math.sin(math.radians(30)) - 0.1 * math.cos(math.radians(30)))
    t, speed = doc["time"][-1], math.hypot(column(doc, "box", "vx")[-1], column(doc, "box", "vy")[-1])
    assert speed / t == pytest.approx(a, rel=0.01)


def test_rolling_disc_accelerates_at_two_thirds_g_sin_theta(loader):
    # Checks the disc's moment (m r^2 / 2 about its centre): a = 2/3 g sin 30, omega = v / r.
    doc, _ = run_scene(loader.load(SCENARIOS / "closed-form" / "rolling-disc.yaml"))
    t = doc["time"][-1]
    speed = math.hypot(column(doc, "disc", "vx")[-1], column(doc, "disc", "vy")[-1])
    assert speed / t == pytest.approx(2 / 3 * 100 * 0.5, rel=0.01)
    assert column(doc, "disc", "omega")[-1] == pytest.approx(speed / 10, rel=0.01)
    assert column(doc, "disc", "omega")[-1] > 0  # rolling toward +x turns clockwise: a growing angle


def test_damped_spring_follows_the_damped_oscillation(loader):
    # The library's damped-spring (k = 2, c = 0.2, m = 1, rest 80, g = 100): a DampedSpring.
    doc, _ = run_scene(loader.load(SCENARIOS / "closed-form" / "damped-spring.yaml"))
    k, c, m, rest = 2.0, 0.2, 1.0, 80.0
    w = math.sqrt(k / m)
    z = c / (2 * math.sqrt(k * m))
    wd = w * math.sqrt(1 - z * z)
    eq = rest + m * 100 / k  # 130 px below the anchor
    x0 = 100 - eq  # the spring starts 100 px long: 30 px short of equilibrium, at rest
    worst = 0.0
    for t, y in zip(doc["time"], column(doc, "weight", "y")):
        x = math.exp(-z * w * t) * (x0 * math.cos(wd * t) + (z * w * x0) / wd * math.sin(wd * t))
        worst = max(worst, abs((y + 200) - (eq + x)))
    assert worst < 3.0  # the scene's bound: 10% of the amplitude


# ---------------------------------------------------------------------------------------------------
# Mass, moment, energy, angle sign

def test_moments_are_about_the_body_origin(loader):
    s = load(loader, """
world: {gravity: [0, 0]}
bodies:
  - {name: box, shape: {type: rectangle, width: 20, height: 20, mass: 1}}
  - {name: disc, shape: {type: circle, radius: 10, mass: 2}, position: [50, 0]}
  - {name: offset, shape: {type: polygon, vertices: [[0, 0], [20, 0], [20, 20], [0, 20]]}, position: [100, 0]}
  - {name: hex, shape: {type: regularPolygon, radius: 12, sides: 6, mass: 3}, position: [150, 0]}
  - {name: hammer, position: [200, 0], shape: {type: multiShape, parts: [
        {shape: {type: rectangle, width: 40, height: 6}},
        {shape: {type: rectangle, width: 10, height: 20}, offset: [20, 0]}]}}
  - {name: fixed, shape: {type: circle, radius: 5}, position: [300, 0], rotatable: false, angularVelocity: 3}
run: {duration: 0.1}
""")
    b = build(s).bodies
    assert b["box"].moment == pytest.approx((400 + 400) / 12)
    assert b["disc"].moment == pytest.approx(2 * 100 / 2)
    # Centroid (10, 10): I = m (w^2 + h^2) / 12 + m |c|^2 about the origin.
    assert b["offset"].moment == pytest.approx(800 / 12 + 200)
    # Regular n-gon of circumradius R: I = m R^2 (1 + 2 cos^2(pi/n)) / 6.
    assert b["hex"].moment == pytest.approx(3 * 144 * (1 + 2 * math.cos(math.pi / 6) ** 2) / 6)
    # Parts of mass 1 each: the bar about the origin, the head about its centre plus m d^2.
    assert b["hammer"].mass == pytest.approx(2)
    assert b["hammer"].moment == pytest.approx((1600 + 36) / 12 + (100 + 400) / 12 + 400)
    assert b["hammer"].center_of_gravity == (0, 0)  # the origin is the centre of mass, as in Emini
    assert b["fixed"].moment == math.inf and b["fixed"].angular_velocity == 0


def test_energy_counts_one_half_and_momentum_and_angle_sign(loader):
    doc = run(loader, """
world: {gravity: [0, 0]}
bodies: [{name: box, shape: {type: rectangle, width: 20, height: 20, mass: 2}, velocity: [10, 0], angularVelocity: 1}]
run: {duration: 1, record: {metrics: [energy, linearMomentum, {angularMomentum: {about: [0, 100]}}]}}
""")
    inertia = 2 * 800 / 12
    m = doc["metrics"]
    assert m["energy.kinetic"][0] == pytest.approx(0.5 * 2 * 100 + 0.5 * inertia * 1)  # pymunk's own omits 1/2
    assert m["momentum.x"][0] == pytest.approx(20)
    # L = I w + m ((x - px) vy - (y - py) vx) = I - 2 (0 - 100) 10.
    assert m["angularMomentum"][0] == pytest.approx(inertia + 2000)
    # A positive angular velocity grows the angle (clockwise on the y-down screen).
    assert column(doc, "box", "angle")[-1] == pytest.approx(1.0)
    body = pymunk.Body(1, 1)
    body.angle = 0.3
    p = body.local_to_world((10, 0))
    assert (p.x, p.y) == (pytest.approx(10 * math.cos(0.3)), pytest.approx(10 * math.sin(0.3)))


# ---------------------------------------------------------------------------------------------------
# Collision layers, interacting, landscape

def lands(loader, ground, ball):
    doc = run(loader, f"""
shapes: {{ground: {{type: rectangle, width: 200, height: 20}}, ball: {{type: circle, radius: 5}}}}
bodies:
  - {{name: ground, shape: ground, position: [0, 10], static: true, {ground}}}
  - {{name: ball, shape: ball, position: [0, -50], {ball}}}
run: {{duration: 2}}
""")
    return column(doc, "ball", "y")[-1] < 0


@pytest.mark.parametrize("ground, ball, collide", [
    ("layers: []", "layers: []", True),
    ("layers: [1]", "layers: [1]", False),
    ("layers: [1, 2]", "layers: [1, 3]", False),  # sharing one bit is enough
    ("layers: [1]", "layers: [2]", True),
    ("layers: []", "layers: [4]", True),
    ("layers: [31]", "layers: [0, 31]", False),
    ("interacting: true", "interacting: false", False),
    ("interacting: false", "interacting: true", False),
])
def test_bodies_sharing_a_layer_bit_do_not_collide(loader, ground, ball, collide):
    assert lands(loader, ground, ball) == collide


# Box2D's rule table (b2ShouldShapesCollide) beside the layers: the same non-zero group decides alone
# (positive: collide, negative: never), else each mask must hold a category of the other; a shared
# layer bit keeps the pair apart whatever the filter.
@pytest.mark.parametrize("ground, ball, collide", [
    ("categories: [0]", "mask: [0]", True),
    ("categories: [1]", "mask: [0]", False),
    ("mask: [2]", "categories: [1]", False),
    ("categories: [1], mask: [2]", "categories: [2], mask: [1]", True),
    ("categories: [], group: 4", "mask: [], group: 4", True),
    ("group: -2", "group: -2", False),
    ("group: -2", "group: -3", True),
    ("mask: [5], group: 1", "group: -1", False),
    ("group: 3, layers: [6]", "group: 3, layers: [6]", False),
])
def test_box2ds_filter_and_the_layers_both_decide(loader, ground, ball, collide):
    assert lands(loader, ground, ball) == collide


def test_a_kinematic_platform_carries_a_box_by_friction(loader):
    """At rest on a platform moving at V: accelerated at mu g until it moves with it, at T = V/(mu g),
    having moved V^2/(2 mu g); the platform is pushed by nothing and feels no gravity."""
    doc = run(loader, """
world: {ticksPerSecond: 60}
shapes:
  deck: {type: rectangle, width: 2000, height: 20, friction: 1}
  box: {type: rectangle, width: 20, height: 20, friction: 0.5}
bodies:
  - {name: platform, shape: deck, position: [0, 10], kinematic: true, velocity: [50, 0]}
  - {name: box, shape: box, position: [0, -10]}
run: {duration: 3, record: {bodies: all}}
""")
    t = doc["time"]
    vx = column(doc, "box", "vx")
    x = column(doc, "box", "x")
    half = min(range(len(t)), key=lambda i: abs(t[i] - 0.5))
    assert vx[half] == pytest.approx(25, abs=2)
    one = min(range(len(t)), key=lambda i: abs(t[i] - 1.0))
    assert x[one] == pytest.approx(25, abs=2)
    assert x[-1] == pytest.approx(125, abs=2)
    assert vx[-1] == pytest.approx(50, abs=0.5)
    assert column(doc, "platform", "y")[-1] == 10
    assert column(doc, "platform", "x")[-1] == pytest.approx(150, abs=1e-6)


def test_a_velocity_action_moves_a_kinematic_body(loader):
    doc = run(loader, """
world: {gravity: [0, 0]}
bodies: [{name: lift, shape: {type: rectangle, width: 40, height: 10}, kinematic: true}]
actions: [{at: 1, type: velocity, body: lift, velocity: [0, -20]}]
run: {duration: 2, record: {bodies: all}}
""")
    assert column(doc, "lift", "y")[-1] == pytest.approx(-20, abs=1.5)


def test_a_static_body_with_a_velocity_is_refused(loader):
    with pytest.raises(Exception, match="kinematic: true"):
        load(loader, """
bodies: [{name: wall, shape: {type: circle, radius: 5}, static: true, velocity: [1, 0]}]
run: {duration: 1}
""")


def test_landscape_stops_bodies_whatever_their_layers_or_interacting_flag(loader):
    doc = run(loader, """
bodies:
  - {name: a, shape: {type: circle, radius: 5}, position: [0, -50], layers: [3]}
  - {name: b, shape: {type: circle, radius: 5}, position: [50, -50], interacting: false}
landscape: {segments: [{from: [-100, 0], to: [100, 0]}]}
run: {duration: 2}
""")
    assert column(doc, "a", "y")[-1] == pytest.approx(-5, abs=0.5)
    assert column(doc, "b", "y")[-1] == pytest.approx(-5, abs=0.5)


# ---------------------------------------------------------------------------------------------------
# Damping, motors, joints

def test_damping_removes_its_fraction_each_tick(loader):
    doc = run(loader, """
world: {gravity: [0, 0], damping: {lateral: 0.1, rotational: 0.5}}
bodies: [{name: b, shape: {type: circle, radius: 5}, velocity: [100, 0], angularVelocity: 8}]
run: {duration: 0.5}
""")
    for k, (vx, w) in enumerate(zip(column(doc, "b", "vx"), column(doc, "b", "omega"))):
        assert vx == pytest.approx(100 * 0.9 ** k, rel=1e-12)
        assert w == pytest.approx(8 * 0.5 ** k, rel=1e-12)


def test_rotational_motor_drives_the_angular_velocity_within_its_cap(loader):
    doc = run(loader, """
world: {gravity: [0, 0]}
bodies:
  - {name: fast, shape: {type: circle, radius: 10}}
  - {name: capped, shape: {type: circle, radius: 10}, position: [100, 0]}
motors:
  - {body: fast, angularVelocity: 2, maxImpulse: 1000}
  - {body: capped, angularVelocity: 2, maxImpulse: 1}
run: {duration: 0.5}
""")
    assert column(doc, "fast", "omega")[1] == pytest.approx(2, rel=1e-6)
    # I = m r^2 / 2 = 50: an impulse of 1 per tick adds 0.02 rad/s per tick.
    assert column(doc, "capped", "omega")[1] == pytest.approx(0.02, rel=1e-6)
    assert column(doc, "capped", "omega")[-1] == pytest.approx(0.2, rel=1e-6)


def test_fixed_joint_keeps_the_relative_angle(loader):
    # A torque on b turns the pair; the gear joint keeps b - a at its starting 0.5 rad.
    doc = run(loader, """
world: {gravity: [0, 0]}
bodies:
  - {name: a, shape: {type: rectangle, width: 20, height: 10}, angle: 0.2}
  - {name: b, shape: {type: rectangle, width: 20, height: 10}, position: [20, 0], angle: 0.7}
joints: [{bodyA: a, bodyB: b, at: [10, 0], fixed: true}]
actions: [{at: 0, type: torque, body: b, torque: 2000, duration: 0.5}]
run: {duration: 2, record: {metrics: [constraintError]}}
""")
    assert column(doc, "b", "omega")[-1] > 1
    for a, b in zip(column(doc, "a", "angle"), column(doc, "b", "angle")):
        assert b - a == pytest.approx(0.5, abs=0.01)
    assert max(doc["metrics"]["constraintError.max"]) < 1  # the pivot holds within the visible limit


def test_rigid_link_keeps_its_length(loader):
    # The library's rigid rod (a spring of stiffness 0: a PinJoint at the anchors' distance, 100 px),
    # at 240 Hz: each step's free drift (v h)^2 / 2d = 0.09 px is pulled back by the joint's bias.
    text = (SCENARIOS / "stiff" / "rigid-rod.yaml").read_text()
    doc = run(loader, text.replace("world: {gravity: [0, 0]}", "world: {gravity: [0, 0], ticksPerSecond: 240}"))
    assert max(doc["metrics"]["constraintError.max"]) < 0.5
    assert doc["metrics"]["angularMomentum"][-1] == pytest.approx(doc["metrics"]["angularMomentum"][0], rel=1e-3)


def test_revolute_limits_stop_a_pendulum_and_its_motor_turns_it(loader):
    # A bob on a hinge released horizontally, limited to [-0.5, 0.5] rad about its start: gravity swings it
    # down (growing angle on the y-down screen) until the upper limit holds it. A free wheel on a second
    # hinge turns at its motor's 3 rad/s.
    doc = run(loader, """
world: {ticksPerSecond: 60}
bodies:
  - {name: post, shape: {type: circle, radius: 2}, static: true}
  - {name: bob, shape: {type: circle, radius: 5}, position: [50, 0]}
  - {name: wheel, shape: {type: circle, radius: 10}, position: [0, 200]}
joints:
  - {type: revolute, bodyA: post, bodyB: bob, at: [0, 0], limits: [-0.5, 0.5]}
  - {type: revolute, bodyA: post, bodyB: wheel, at: [0, 200], motor: {speed: 3, maxTorque: 1.0e6}}
run: {duration: 2, record: {metrics: [constraintError, jointLimits]}}
""")
    assert max(column(doc, "bob", "angle")) == pytest.approx(0.5, abs=0.05)
    assert max(doc["metrics"]["jointLimits.angle"]) < 0.05
    # Chipmunk's RotaryLimitJoint is a pure torque: the small bob (I = 12.5) stopped at its limit turns
    # about its own centre against the pivot, which gives by some px. Emini's limit rows act about the pin
    # (RevoluteJoint's Javadoc); MAPPING.md, Joints.
    assert 1 < max(doc["metrics"]["constraintError.max"]) < 6
    assert column(doc, "wheel", "omega")[-1] == pytest.approx(3, rel=1e-3)


def test_a_rope_is_slack_below_its_length_and_taut_at_it(loader):
    # 60 px apart on a 100 px rope: the ball falls freely 40 px, then hangs at the rope's length.
    doc = run(loader, """
bodies:
  - {name: hook, shape: {type: circle, radius: 2}, static: true}
  - {name: ball, shape: {type: circle, radius: 5}, position: [0, -40]}
joints: [{type: rope, bodyA: hook, bodyB: ball, length: 100, anchorA: [0, -100]}]
run: {duration: 3, record: {metrics: [constraintError]}}
""")
    ys = column(doc, "ball", "y")
    assert ys[2] == pytest.approx(-40 + 0.5 * 100 * 0.1 ** 2, abs=0.6)  # free fall over the first 0.1 s
    assert ys[-1] == pytest.approx(0, abs=1)  # hanging 100 px below the anchor at y -100
    # Arriving at sqrt(2 g 40) = 89 px/s, the SlideJoint's bias lets the rope stretch by about half a
    # tick's travel (4.5 px) before it pulls the ball back.
    assert max(doc["metrics"]["constraintError.max"]) < 4


# ---------------------------------------------------------------------------------------------------
# Penetration and tunnelling monitors

@pytest.mark.parametrize("upper", ["{type: circle, radius: 10}", "{type: rectangle, width: 20, height: 20}"])
def test_penetration_measures_overlap_depth_on_current_poses(loader, upper):
    # Created 3 px deep in a static box, no gravity: after one tick most of the overlap is still there
    # (Chipmunk's bias removes a fraction per step), and it reads as a positive depth.
    doc = run(loader, f"""
world: {{gravity: [0, 0]}}
bodies:
  - {{name: floor, shape: {{type: rectangle, width: 200, height: 20}}, position: [0, 10], static: true}}
  - {{name: upper, shape: {upper}, position: [0, -7]}}
run: {{duration: 0.2, record: {{metrics: [penetration]}}}}
""")
    pen = doc["metrics"]["penetration.max"]
    assert pen[0] == 0  # before the first tick there is no contact, as in the engine
    assert 1.5 < pen[1] <= 3.0
    assert doc["metrics"]["penetration.mean"][1] <= pen[1]
    assert pen[-1] < pen[1]


def test_a_bullet_tunnels_through_a_thin_wall_and_is_counted(loader):
    # pymunk has no continuous collision: 50 px per tick passes a 4 px wall.
    doc, _ = run_scene(loader.load(SCENARIOS / "fast-bodies" / "bullet-1000.yaml"))
    assert doc["metrics"]["tunnelling.count"][-1] == 1
    # A slow ball is stopped and not counted.
    doc = run(loader, """
world: {gravity: [0, 0]}
bodies:
  - {name: wall, shape: {type: rectangle, width: 4, height: 200}, static: true}
  - {name: ball, shape: {type: circle, radius: 2}, position: [-50, 0], velocity: [20, 0]}
run: {duration: 4, record: {metrics: [{tunnelling: {walls: [wall]}}]}}
""")
    assert doc["metrics"]["tunnelling.count"][-1] == 0
    assert column(doc, "ball", "x")[-1] < -2


# ---------------------------------------------------------------------------------------------------
# What pymunk cannot express is reported

def test_elements_pymunk_cannot_express_are_reported(loader):
    doc = run(loader, """
world: {gravity: [0, 0], simulationArea: {start: -100, end: 100}, dynamicIterations: true}
bodies:
  - {name: pusher, shape: {type: circle, radius: 5}}
  - {name: runaway, shape: {type: circle, radius: 5}, velocity: [500, 0]}
motors: [{body: pusher, velocity: [10, 0], maxImpulse: 5}]
landscape: {segments: [{from: [-50, 50], to: [50, 50], face: left}]}
particles: [{from: [0, 0]}]
run: {duration: 1}
""")
    unsupported = {n["element"]: n for n in doc["unsupported"]}
    assert unsupported["linear motor"]["affectsBodies"] is True
    assert unsupported["particles"]["affectsBodies"] is False
    # The runaway leaves the area, which Emini would freeze it at: the run is affected.
    assert unsupported["world.simulationArea"]["affectsBodies"] is True
    approximations = {n["element"] for n in doc["approximations"]}
    assert approximations == {"landscape face", "world.dynamicIterations"}
    # The pusher is not driven (the motor is left out), and that is stated, not hidden.
    assert column(doc, "pusher", "vx")[-1] == 0


def test_a_wheel_joint_hangs_on_its_suspension_and_turns_with_its_motor(loader):
    # A 1-mass wheel on a 4 Hz vertical suspension under a static post: it sags g / w^2 (w = 2 pi 4)
    # along the axis, stays on it, and turns at its motor's 3 rad/s. The spring's stiffness is the
    # effective mass (the wheel's, the post being static) times w^2, so the sag is exact here.
    doc = run(loader, """
world: {ticksPerSecond: 60}
bodies:
  - {name: post, shape: {type: rectangle, width: 20, height: 20}, static: true}
  - {name: wheel, shape: {type: circle, radius: 10}, position: [0, 50]}
joints:
  - {type: wheel, bodyA: post, bodyB: wheel, at: [0, 50], axis: [0, 1], spring: {hertz: 4, dampingRatio: 1},
     motor: {speed: 3, maxTorque: 1.0e6}}
run: {duration: 3, record: {metrics: [constraintError]}}
""")
    sag = 100 / (2 * math.pi * 4) ** 2
    assert column(doc, "wheel", "y")[-1] == pytest.approx(50 + sag, abs=0.02)
    assert abs(column(doc, "wheel", "x")[-1]) < 1e-6
    assert max(doc["metrics"]["constraintError.max"]) < 1e-6
    assert column(doc, "wheel", "omega")[-1] == pytest.approx(3, rel=1e-3)


def test_a_prismatic_slide_keeps_its_angle_and_stops_at_its_limit(loader):
    # A box on a frictionless 30-degree slide from a static post, limited to 40 px: it slides down the
    # axis with g sin 30 and stops at the limit, never turning.
    doc = run(loader, """
world: {ticksPerSecond: 60}
bodies:
  - {name: post, shape: {type: circle, radius: 2}, static: true}
  - {name: box, shape: {type: rectangle, width: 10, height: 10}, position: [0, 0]}
joints:
  - {type: prismatic, bodyA: post, bodyB: box, at: [0, 0], axis: [0.8660254, 0.5], limits: [0, 40]}
run: {duration: 3, record: {metrics: [constraintError, jointLimits]}}
""")
    x, y = column(doc, "box", "x"), column(doc, "box", "y")
    t = 0.5
    k = round(t * 60)
    assert math.hypot(x[k], y[k]) == pytest.approx(0.5 * 100 * 0.5 * t * t, rel=0.05)
    assert math.hypot(x[-1], y[-1]) == pytest.approx(40, abs=0.5)
    assert max(abs(a) for a in column(doc, "box", "angle")) < 1e-6
    assert max(doc["metrics"]["constraintError.max"]) < 0.5
    assert max(doc["metrics"]["jointLimits.translation"]) < 1
