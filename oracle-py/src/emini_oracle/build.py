"""Builds a pymunk Space from a Scene. Every mapping decision is documented in oracle-py/MAPPING.md.

What pymunk cannot express is not dropped silently: it is listed in `Built.unsupported` (the element
is left out of the simulation; `affectsBodies` says whether that changes the bodies' motion) or in
`Built.approximations` (the element is simulated, with different semantics).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import pymunk

from .scene import Body, Scene, Shape

# Collision categories (pymunk ShapeFilter bits); see MAPPING.md, Collision layers.
LANDSCAPE_BIT = 1 << 31
NON_INTERACTING_BIT = 1 << 30
MAX_LAYER_CLASSES = 30
ALL_BITS = 0xFFFFFFFF

# Chipmunk's own default, set explicitly: the fraction of overlap left after one second.
COLLISION_BIAS = pow(1.0 - 0.1, 60.0)
# Emini's sleeping defaults (SolverSettings): rest below 1 px/s and 2 deg/s for 0.5 s.
SLEEP_LINEAR_TOLERANCE = 1.0
SLEEP_ANGULAR_TOLERANCE = 2.0 * math.pi / 180.0
SLEEP_TIME = 0.5
# collision_slop = SLOP_PER_LENGTH x the smallest dynamic body (Chipmunk's default 0.1 px would leave a
# resting body at its impact depth; verification-notes.md, pymunk pitfalls).
SLOP_PER_LENGTH = 1e-5


@dataclass
class Note:
    element: str
    path: str
    reason: str
    affects_bodies: bool = True

    def to_json(self):
        return {"element": self.element, "path": self.path, "reason": self.reason,
                "affectsBodies": self.affects_bodies}


@dataclass
class Link:
    """A pin joint or rigid link, for the constraintError metric: world anchors from local ones."""
    kind: str  # "pin" (anchor distance), "rigid" (|d - d0|), "range" (d outside [rest, upper]) or "line"
    a: pymunk.Body
    b: pymunk.Body
    anchor_a: tuple
    anchor_b: tuple
    rest: float = 0.0
    upper: float = 0.0
    axis: tuple = (0.0, 0.0)  # "line": b's anchor off the line through a's anchor along this axis (a's frame)


@dataclass
class Hinge:
    """A revolute joint's limits, for the jointLimits metric: the angle is b's minus a's minus ref."""
    a: pymunk.Body
    b: pymunk.Body
    ref: float
    lower: float
    upper: float


@dataclass
class Spring:
    """A spring with stiffness, for the spring potential term of energy.total."""
    a: pymunk.Body
    b: pymunk.Body
    anchor_a: tuple
    anchor_b: tuple
    rest: float
    stiffness: float


@dataclass
class Built:
    scene: Scene
    space: pymunk.Space
    bodies: dict  # scene name -> pymunk.Body, in creation order
    specs: dict  # scene name -> scene.Body
    shapes: dict  # scene name -> [pymunk.Shape]
    links: list = field(default_factory=list)
    springs: list = field(default_factory=list)
    hinges: list = field(default_factory=list)
    slides: list = field(default_factory=list)  # (line Link, lower, upper) of each limited prismatic joint
    unsupported: list = field(default_factory=list)
    approximations: list = field(default_factory=list)
    settings: dict = field(default_factory=dict)
    damping: tuple = (1.0, 1.0)  # velocity kept per tick (lateral, rotational), applied after the step
    sleeping: bool = False  # world.sleeping is on: pymunk's sleeping runs (MAPPING.md, Sleeping)
    never_sleep: list = field(default_factory=list)  # bodies with sleepingAllowed: false, activated every tick

    def damp_quietly(self, damped):
        """Emini's per-tick damping (MAPPING.md, Damping) without waking anything, for a space that lets
        bodies sleep: pymunk's velocity setters activate the body, which resets its idle time, so no damped
        body could ever fall asleep. cpBodyUpdateVelocity(body, g, d, dt) sets v = d·v + g·dt and
        ω = d·ω (forces and torques are already cleared after the step) without activating: with d the
        rotational factor and g·dt = (lateral − rotational)·v it gives both factors. Sleeping bodies are
        left alone (Emini does not simulate them)."""
        keep_lin, keep_rot = self.damping
        from pymunk._chipmunk import lib
        update = lib.cpBodyUpdateVelocity
        for b, rot in damped:
            if b.is_sleeping:
                continue
            d = keep_rot if rot else 1.0
            v = b.velocity
            update(b._body, ((keep_lin - d) * v.x, (keep_lin - d) * v.y), d, 1.0)

    def keep_awake(self):
        """Before each step: Emini's sleepingAllowed: false. Body.activate() resets the body's idle time
        (and that of the bodies it touches), so its component cannot rest long enough to sleep."""
        for b in self.never_sleep:
            b.activate()

    def dynamic(self):
        return [(n, b) for n, b in self.bodies.items() if b.body_type == pymunk.Body.DYNAMIC]

    def gravity_affected(self, name):
        return self.specs[name].state.gravity


# ------------------------------------------------------------------------------------------------
# Shapes: geometry in body-local coordinates, mass and moment about the body origin

def _rotate(v, angle):
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def flatten(shape: Shape, ox=0.0, oy=0.0, angle=0.0, mass_scale=1.0):
    """The convex pieces of a shape, each ("circle", centre, radius, mass) or ("poly", vertices, mass),
    in body-local coordinates. A multi-shape's parts keep their own masses, scaled so that they add up
    to the multi-shape's mass."""
    def place(v):
        r = _rotate(v, angle)
        return (r[0] + ox, r[1] + oy)

    m = shape.mass * mass_scale
    if shape.kind == "circle":
        return [("circle", place((0.0, 0.0)), shape.radius, m)]
    if shape.kind == "rectangle":
        w, h = shape.width / 2, shape.height / 2
        return [("poly", [place(v) for v in ((-w, -h), (w, -h), (w, h), (-w, h))], m)]
    if shape.kind == "regularPolygon":
        n, r = shape.sides, shape.radius
        verts = [(r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n)) for i in range(n)]
        return [("poly", [place(v) for v in verts], m)]
    if shape.kind == "polygon":
        return [("poly", [place(v) for v in shape.vertices], m)]
    # multiShape: parts placed by offset and angle, nested multi-shapes composed.
    total = sum(p[0].mass for p in shape.parts)
    scale = m / total if total > 0 else 0.0
    out = []
    for part, pox, poy, pangle in shape.parts:
        po = place((pox, poy))
        out.extend(flatten(part, po[0], po[1], angle + pangle, scale))
    return out


def moment(pieces):
    """Moment of inertia about the body origin: uniform density over each piece (as the engine)."""
    total = 0.0
    for p in pieces:
        if p[0] == "circle":
            total += pymunk.moment_for_circle(p[3], 0, p[2], p[1])
        else:
            total += pymunk.moment_for_poly(p[2], p[1])
    return total


def local_aabb(pieces):
    """(min x, min y, max x, max y) of the pieces in body-local coordinates at angle 0."""
    xs, ys = [], []
    for p in pieces:
        if p[0] == "circle":
            (cx, cy), r = p[1], p[2]
            xs += [cx - r, cx + r]
            ys += [cy - r, cy + r]
        else:
            xs += [v[0] for v in p[1]]
            ys += [v[1] for v in p[1]]
    return min(xs), min(ys), max(xs), max(ys)


# ------------------------------------------------------------------------------------------------
# The space

def build(scene: Scene) -> Built:
    w = scene.world
    space = pymunk.Space()
    space.gravity = w.gravity
    space.iterations = w.iterations
    space.collision_bias = COLLISION_BIAS
    space.damping = 1.0  # Emini's per-tick damping is applied after each step (Built.damping)
    space.idle_speed_threshold = 0.0
    space.sleep_time_threshold = float("inf")  # no sleeping unless the scene turns it on (below)
    built = Built(scene, space, {}, {}, {})
    built.damping = (1.0 - w.damping_lateral, 1.0 - w.damping_rotational)
    if w.dynamic_iterations:
        built.approximations.append(Note("world.dynamicIterations", "$.world.dynamicIterations",
                                         "pymunk always runs all its iterations (Emini's fixed mode)"))
    if w.solver:
        built.approximations.append(Note("world.solver", "$.world.solver",
                                         "engine tunables (" + ", ".join(sorted(w.solver)) + ") have no pymunk "
                                         "counterpart; pymunk uses the settings of MAPPING.md"))

    filters = _filters(scene)
    smallest = math.inf
    no_gravity = _no_gravity_velocity
    for spec in scene.bodies:
        pieces = flatten(spec.shape)
        s = spec.state
        if s.static:
            body = pymunk.Body(body_type=pymunk.Body.STATIC)
        elif s.kinematic:
            body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        else:
            inertia = moment(pieces) if s.rotatable else math.inf
            body = pymunk.Body(spec.shape.mass, inertia)
            x0, y0, x1, y1 = local_aabb(pieces)
            smallest = min(smallest, x1 - x0, y1 - y0)
        body.position = (spec.x, spec.y)
        body.angle = s.angle
        if not s.static:
            body.velocity = (s.vx, s.vy)
            body.angular_velocity = s.angular_velocity if s.rotatable else 0.0
            if not s.gravity:
                body.velocity_func = no_gravity
        shapes = []
        for p in pieces:
            sh = pymunk.Circle(body, p[2], p[1]) if p[0] == "circle" else pymunk.Poly(body, p[1])
            sh.friction = spec.shape.friction
            sh.elasticity = spec.shape.elasticity
            sh.filter = filters(spec)
            sh.sensor = s.sensor
            shapes.append(sh)
        space.add(body, *shapes)
        if not s.static and not s.sleeping_allowed:
            built.never_sleep.append(body)
        built.bodies[spec.name] = body
        built.specs[spec.name] = spec
        built.shapes[spec.name] = shapes

    slop = SLOP_PER_LENGTH * (smallest if math.isfinite(smallest) and smallest > 0 else 1.0)
    space.collision_slop = slop
    built.settings = {"timestep": w.timestep, "iterations": w.iterations, "collision_slop": slop,
                      "collision_bias": COLLISION_BIAS, "collision_persistence": space.collision_persistence,
                      "damping": 1.0, "perTickDamping": {"lateral": w.damping_lateral,
                                                         "rotational": w.damping_rotational}}
    if w.sleeping is not None:
        _sleeping(built, w.sleeping)

    el = scene.elements
    if "landscape" in el:
        _landscape(built, el["landscape"])
    if "joints" in el:
        _joints(built, el["joints"])
    if "springs" in el:
        _springs(built, el["springs"])
    if "motors" in el:
        _motors(built, el["motors"])
    if "particles" in el:
        built.unsupported.append(Note(
            "particles", "$.particles",
            "pymunk has no particle emitters; Emini's particles never act on bodies, so the bodies' motion "
            "and every metric are unchanged", affects_bodies=False))
    if w.simulation_area is not None:
        built.unsupported.append(Note(
            "world.simulationArea", "$.world.simulationArea",
            "pymunk simulates every body; Emini freezes bodies outside " + _area_text(w.simulation_area)
            + " (checked at each sample: see affectsBodies)", affects_bodies=False))
    return built


def _sleeping(built: Built, tolerances):
    """world.sleeping on: pymunk's sleeping (MAPPING.md, Sleeping). Chipmunk lets a component sleep when
    every body's m|v|² + I·ω² stayed at most m·idle_speed_threshold² for sleep_time_threshold, so the
    threshold is Emini's linear tolerance and its angular tolerance has no separate counterpart."""
    space = built.space
    linear = float(tolerances.get("linearTolerance", SLEEP_LINEAR_TOLERANCE))
    angular = float(tolerances.get("angularTolerance", SLEEP_ANGULAR_TOLERANCE))
    seconds = float(tolerances.get("timeToSleep", SLEEP_TIME))
    space.idle_speed_threshold = linear
    space.sleep_time_threshold = seconds
    built.sleeping = True
    built.settings["sleep_time_threshold"] = seconds
    built.settings["idle_speed_threshold"] = linear
    built.approximations.append(Note(
        "world.sleeping", "$.world.sleeping",
        f"pymunk's sleeping: a body rests while m|v|² + I·ω² ≤ m·{linear:g}² (Emini: |v| ≤ {linear:g} px/s and "
        f"|ω| ≤ {angular:g} rad/s, each on its own), for {seconds:g} s; sleeping bodies keep their last tiny "
        "velocities (Emini zeroes them)"))
    if built.never_sleep and seconds <= built.scene.world.timestep:
        built.approximations.append(Note(
            "sleepingAllowed", "$.bodies",
            "timeToSleep is not longer than a tick, so pymunk may put a body that may not sleep to sleep within a "
            "step before the oracle wakes it again"))


def _area_text(a):
    if "min" in a:
        return f"the rectangle {list(a['min'])}..{list(a['max'])}"
    return f"the x range [{a['start']}, {a['end']}]"


def _no_gravity_velocity(body, gravity, damping, dt):
    pymunk.Body.update_velocity(body, (0.0, 0.0), damping, dt)


def _filter_key(state):
    return frozenset(state.layers), state.categories, state.mask, state.group


def _collide(a, b):
    """Emini's rule between two filter keys: no shared layer bit, and Box2D's categories, mask, group."""
    layers_a, cat_a, mask_a, group_a = a
    layers_b, cat_b, mask_b, group_b = b
    if layers_a & layers_b:
        return False
    if group_a == group_b and group_a != 0:
        return group_a > 0
    return (cat_a & mask_b) != 0 and (cat_b & mask_a) != 0


def _filters(scene: Scene):
    """ShapeFilter per body: Emini's "bodies sharing a layer bit do not collide" and Box2D's filter
    (categories, mask, group), both at once, as categories and masks.

    Each distinct filter (layer set, categories, mask, group) of an interacting body gets one category
    bit; its mask holds the bits of every filter it collides with, itself included when it does
    (the relation is symmetric). Without Box2D's fields this is the layer sets alone: layer-less
    bodies collide with everything interacting. Non-interacting bodies only meet the landscape, which
    meets everything.
    """
    sets = []
    for b in scene.bodies:
        key = _filter_key(b.state)
        if b.state.interacting and key not in sets:
            sets.append(key)
    if len(sets) > MAX_LAYER_CLASSES:
        raise UnsupportedScene(f"{len(sets)} distinct collision filters (layer sets, categories, masks, "
                               f"groups); the filter mapping holds {MAX_LAYER_CLASSES}")
    masks = {}
    for i, a in enumerate(sets):
        m = LANDSCAPE_BIT
        for j, b in enumerate(sets):
            if _collide(a, b):
                m |= 1 << j
        masks[a] = pymunk.ShapeFilter(categories=1 << i, mask=m)
    non_interacting = pymunk.ShapeFilter(categories=NON_INTERACTING_BIT, mask=LANDSCAPE_BIT)

    def of(spec: Body):
        return masks[_filter_key(spec.state)] if spec.state.interacting else non_interacting
    return of


class UnsupportedScene(Exception):
    """The oracle cannot run this scene at all."""


def _landscape(built: Built, land):
    static = built.space.static_body
    segments = []
    for i, seg in enumerate(land["segments"]):
        s = pymunk.Segment(static, tuple(seg["from"]), tuple(seg["to"]), 0.0)
        s.friction = float(land.get("friction", 0.25))
        s.elasticity = float(land.get("elasticity", 0.0))
        s.filter = pymunk.ShapeFilter(categories=LANDSCAPE_BIT, mask=ALL_BITS)
        segments.append(s)
        face = seg.get("face", "none")
        if face != "none":
            built.approximations.append(Note(
                "landscape face", f"$.landscape.segments[{i}].face",
                f"face '{face}' makes Emini's segment one-sided; pymunk segments are two-sided, so a body "
                "reaching it from the open side is stopped instead of passing"))
    built.space.add(*segments)
    built.shapes["$landscape"] = segments


def _anchor(j, key):
    return tuple(map(float, j.get(key, (0.0, 0.0))))


def _joints(built: Built, joints):
    for i, j in enumerate(joints):
        kind = j.get("type", "pin")
        if kind in ("revolute", "distance", "rope"):
            _game_joint(built, i, j, kind)
            continue
        if kind == "wheel" or (kind == "prismatic" and "motor" not in j):
            _slide_joint(built, i, j, kind)
            continue
        if kind != "pin":
            # Not mapped yet (MAPPING.md, Joints): left out rather than built as a plain pin.
            built.unsupported.append(Note(
                f"joint type {kind}", f"$.joints[{i}]",
                ("pymunk has no linear motor, so the oracle does not map a prismatic joint with a motor; "
                 if kind == "prismatic" else f"the oracle does not map the engine's {kind} joint to pymunk yet; ")
                + "it is left out, so its bodies are not joined"))
            continue
        if "stiffness" in j:
            built.approximations.append(Note(
                "soft weld", f"$.joints[{i}].stiffness",
                "pymunk's PivotJoint and GearJoint are rigid: the weld's stiffness is left out"))
        if "breakForce" in j:
            built.approximations.append(Note(
                "breakForce", f"$.joints[{i}].breakForce", "pymunk's constraints never break"))
        a, b = built.bodies[j["bodyA"]], built.bodies[j["bodyB"]]
        if "at" in j:
            at = tuple(map(float, j["at"]))
            la, lb = a.world_to_local(at), b.world_to_local(at)
        else:
            la, lb = _anchor(j, "anchorA"), _anchor(j, "anchorB")
        pivot = pymunk.PivotJoint(a, b, la, lb)
        parts = [pivot]
        if j.get("fixed", False):
            # Lock the relative angle the bodies have now (the original's fixed joint).
            parts.append(pymunk.GearJoint(a, b, b.angle - a.angle, 1.0))
        for c in parts:
            c.collide_bodies = bool(j.get("collide", False))
        built.space.add(*parts)
        built.links.append(Link("pin", a, b, tuple(la), tuple(lb)))


def _local_anchors(j, a, b):
    if "at" in j:
        at = tuple(map(float, j["at"]))
        return tuple(a.world_to_local(at)), tuple(b.world_to_local(at))
    return _anchor(j, "anchorA"), _anchor(j, "anchorB")


def _effective(x, y):
    """1 / (1/x + 1/y), a static body's infinite mass or moment counting as none."""
    inv = (0.0 if math.isinf(x) else 1.0 / x) + (0.0 if math.isinf(y) else 1.0 / y)
    return 1.0 / inv if inv > 0 else math.inf


def _soft(built, path, spring, mass, what):
    """Emini's spring in Hz and damping ratio as a pymunk stiffness and damping, through the bodies' effective
    mass (or moment): k = m (2 pi f)^2, c = 2 m zeta (2 pi f). Emini's soft rows use the mass along the row,
    which differs when the anchors are off the centres: an approximation."""
    w = 2 * math.pi * float(spring["hertz"])
    built.approximations.append(Note(what, path, "the frequency becomes a stiffness through the bodies' "
                                     "effective mass about their centres, not along the joint's row"))
    return mass * w * w, 2 * mass * float(spring["dampingRatio"]) * w


def _game_joint(built: Built, i, j, kind):
    """revolute: PivotJoint + RotaryLimitJoint + SimpleMotor + DampedRotarySpring; distance: PinJoint,
    SlideJoint (range) or DampedSpring (spring); rope: SlideJoint(0, length). MAPPING.md, Joints."""
    a, b = built.bodies[j["bodyA"]], built.bodies[j["bodyB"]]
    la, lb = _local_anchors(j, a, b)
    path = f"$.joints[{i}]"
    parts = []
    if kind == "revolute":
        parts.append(pymunk.PivotJoint(a, b, la, lb))
        built.links.append(Link("pin", a, b, la, lb))
        ref = b.angle - a.angle
        if "limits" in j:
            lo, hi = map(float, j["limits"])
            # RotaryLimitJoint bounds b.angle - a.angle; Emini's limits count from the angle at creation.
            parts.append(pymunk.RotaryLimitJoint(a, b, ref + lo, ref + hi))
            built.hinges.append(Hinge(a, b, ref, lo, hi))
        if "motor" in j:
            # SimpleMotor(x, y, rate) drives w_x - w_y to rate: b first, so b turns at speed relative to a.
            motor = pymunk.SimpleMotor(b, a, float(j["motor"]["speed"]))
            motor.max_force = float(j["motor"]["maxTorque"])
            parts.append(motor)
        if "spring" in j:
            k, c = _soft(built, path + ".spring", j["spring"], _effective(a.moment, b.moment), "revolute spring")
            parts.append(pymunk.DampedRotarySpring(a, b, ref, k, c))
    else:
        wa, wb = a.local_to_world(la), b.local_to_world(lb)
        now = (wb - wa).length
        length = float(j.get("length", now))
        if kind == "rope":
            parts.append(pymunk.SlideJoint(a, b, la, lb, 0.0, length))
            built.links.append(Link("range", a, b, la, lb, 0.0, length))
        elif "range" not in j and "spring" not in j:
            pin = pymunk.PinJoint(a, b, la, lb)
            pin.distance = length
            parts.append(pin)
            built.links.append(Link("rigid", a, b, la, lb, length))
        else:
            lo, hi = map(float, j["range"]) if "range" in j else (0.0, math.inf)
            if "range" in j:
                parts.append(pymunk.SlideJoint(a, b, la, lb, lo, hi))
            if "spring" in j:
                k, c = _soft(built, path + ".spring", j["spring"], _effective(a.mass, b.mass), "distance spring")
                parts.append(pymunk.DampedSpring(a, b, la, lb, length, k, c))
            built.links.append(Link("range", a, b, la, lb, lo, hi))
    if "breakForce" in j:
        built.approximations.append(Note("breakForce", path + ".breakForce", "pymunk's constraints never break"))
    for c in parts:
        c.collide_bodies = bool(j.get("collide", False))
    built.space.add(*parts)


# Half-length of a groove without limits, and the arm of a spring along an axis (px): long enough that
# no scene slides off it, short enough that pymunk's doubles keep the anchors exact.
_FREE_GROOVE = 1.0e5
_SPRING_ARM = 1.0e4


def _slide_joint(built: Built, i, j, kind):
    """wheel: GrooveJoint (its ends the limits) + DampedSpring along the axis + SimpleMotor; prismatic (no
    motor: pymunk has no linear one): GrooveJoint + GearJoint (the angle lock) + DampedSpring. The axis is a
    world direction at the start, carried by body A. The spring pulls from a point _SPRING_ARM px behind
    A's anchor with that rest length: as B's anchor stays on the groove, its line is the axis itself, so
    it pulls along the axis toward translation 0, as Emini's does. MAPPING.md, Joints."""
    a, b = built.bodies[j["bodyA"]], built.bodies[j["bodyB"]]
    la, lb = _local_anchors(j, a, b)
    path = f"$.joints[{i}]"
    ax, ay = map(float, j["axis"])
    norm = math.hypot(ax, ay)
    axis = pymunk.Vec2d(ax / norm, ay / norm).rotated(-a.angle)
    lo, hi = map(float, j["limits"]) if "limits" in j else (-_FREE_GROOVE, _FREE_GROOVE)
    pa = pymunk.Vec2d(*la)
    parts = [pymunk.GrooveJoint(a, b, pa + axis * lo, pa + axis * hi, lb)]
    if kind == "prismatic":
        parts.append(pymunk.GearJoint(a, b, b.angle - a.angle, 1.0))
    if "spring" in j:
        k, c = _soft(built, path + ".spring", j["spring"], _effective(a.mass, b.mass), f"{kind} spring")
        parts.append(pymunk.DampedSpring(a, b, pa - axis * _SPRING_ARM, lb, _SPRING_ARM, k, c))
    if kind == "wheel" and "motor" in j:
        motor = pymunk.SimpleMotor(b, a, float(j["motor"]["speed"]))
        motor.max_force = float(j["motor"]["maxTorque"])
        parts.append(motor)
    if "breakForce" in j:
        built.approximations.append(Note("breakForce", path + ".breakForce", "pymunk's constraints never break"))
    for c in parts:
        c.collide_bodies = bool(j.get("collide", False))
    built.space.add(*parts)
    line = Link("line", a, b, la, lb, axis=(axis.x, axis.y))
    built.links.append(line)
    if kind == "prismatic" and "limits" in j:
        built.slides.append((line, lo, hi))


def _springs(built: Built, springs):
    for i, s in enumerate(springs):
        a, b = built.bodies[s["bodyA"]], built.bodies[s["bodyB"]]
        la, lb = _anchor(s, "anchorA"), _anchor(s, "anchorB")
        wa, wb = a.local_to_world(la), b.local_to_world(lb)
        rest = float(s["restLength"]) if "restLength" in s else (wb - wa).length
        k = float(s.get("stiffness", 0.0))
        if k > 0:
            c = pymunk.DampedSpring(a, b, la, lb, rest, k, float(s.get("damping", 0.0)))
            built.springs.append(Spring(a, b, la, lb, rest, k))
        else:
            c = pymunk.PinJoint(a, b, la, lb)
            c.distance = rest
            built.links.append(Link("rigid", a, b, la, lb, rest))
            if float(s.get("damping", 0.0)) > 0:
                built.approximations.append(Note("spring damping", f"$.springs[{i}].damping",
                                                 "a rigid link (stiffness 0) has no damping in pymunk's PinJoint"))
        c.collide_bodies = bool(s.get("collide", True))
        built.space.add(c)


def _motors(built: Built, motors):
    h = built.scene.world.timestep
    for i, m in enumerate(motors):
        body = built.bodies[m["body"]]
        if "velocity" in m:
            built.unsupported.append(Note(
                "linear motor", f"$.motors[{i}]",
                "pymunk has no motor that drives a linear velocity; the motor is left out, so its body is not "
                "driven"))
            continue
        if body.body_type != pymunk.Body.DYNAMIC:
            continue  # the original: a motor on a static body does nothing
        # SimpleMotor(a, b, rate) drives a.w - b.w to rate; maxImpulse caps the impulse per tick.
        motor = pymunk.SimpleMotor(body, built.space.static_body, float(m["angularVelocity"]))
        motor.max_force = float(m["maxImpulse"]) / h
        built.space.add(motor)
