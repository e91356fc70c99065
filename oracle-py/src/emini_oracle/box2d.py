"""Runs a scene in Box2D v3 (3.1.1, through the PyPI package pyb2d3) and writes its trace: the second
oracle beside pymunk. Every mapping decision is in oracle-py/MAPPING.md, Box2D v3.

The metrics are the pymunk oracle's own code, read from a mirror: the scene is also built as a pymunk
space (build.build, never stepped) that gives the same masses, moments, shapes, joint anchors and
springs, and after every Box2D step each mirror body takes the Box2D body's pose and velocity. So both
oracles measure with one implementation of the harness's definitions. Penetration is measured on the
mirror's shapes too, for the pairs Box2D reports touching (its contact begin and end events).

Box2D works in metres: lengths are divided by PX_PER_METRE on the way in and multiplied on the way out
(the mapping the benchmark's metre-based peers use); y stays down, so angles keep their sign.
"""

from __future__ import annotations

import importlib.metadata
import math

from . import metrics as metric_classes
from .build import LANDSCAPE_BIT, Built, Note, UnsupportedScene, _local_anchors, build, flatten
from .run import Schedule, Trace
from .scene import Scene

PX_PER_METRE = 20.0
S = 1.0 / PX_PER_METRE
ALL_BITS = 0xFFFFFFFF
# Box2D's restitution threshold (1 m/s) would make every bounce below 20 px/s inelastic; Emini applies
# restitution at any approach speed, so the threshold is set near zero (MAPPING.md, Box2D v3).
RESTITUTION_THRESHOLD = 1e-3
# Box2D clamps speeds at 4 m/s x 100 by default; the stability maps fire bullets at 10^5 px/s = 5000 m/s.
MAXIMUM_LINEAR_SPEED = 1e6
SUPPORTED_JOINTS = ("pin", "revolute")

b2 = None


def _b2():
    global b2
    if b2 is None:
        import pyb2d3
        b2 = pyb2d3
    return b2


def versions():
    return {"box2d": "3.1.1", "pyb2d3": importlib.metadata.version("pyb2d3")}


class World2:
    """A scene built in Box2D v3 beside its pymunk mirror."""

    def __init__(self, scene: Scene):
        _b2()
        self.scene = scene
        self.mirror: Built = build(scene)
        self.unsupported = []
        self.approximations = []
        w = scene.world
        self.h = w.timestep
        self.substeps = max(1, w.iterations)
        self.sleeping = w.sleeping is not None
        self.world = b2.World(gravity=(w.gravity[0] * S, w.gravity[1] * S), maximum_linear_speed=MAXIMUM_LINEAR_SPEED,
                              restitution_threshold=RESTITUTION_THRESHOLD)
        self.world.sleeping_enabled = self.sleeping
        self.world.continuous_enabled = True
        self.bodies = {}
        self.shape_of = {}  # Box2D shape id -> mirror shape
        self.keep = (1.0 - w.damping_lateral, 1.0 - w.damping_rotational)
        if w.dynamic_iterations:
            self.approximations.append(Note("world.dynamicIterations", "$.world.dynamicIterations",
                                            "Box2D always runs all its substeps (Emini's fixed mode)"))
        if w.solver:
            self.approximations.append(Note("world.solver", "$.world.solver", "engine tunables ("
                                            + ", ".join(sorted(w.solver)) + ") have no Box2D counterpart"))
        self._bodies()
        el = scene.elements
        if "landscape" in el:
            self._landscape(el["landscape"])
        if "joints" in el:
            self._joints(el["joints"])
        for key, what in (("springs", "springs"), ("motors", "motors")):
            if key in el:
                self.unsupported.append(Note(key, "$." + key, f"the Box2D oracle does not map Emini's {what} yet "
                                             "(MAPPING.md, Box2D v3)", affects_bodies=True))
        if "particles" in el:
            self.unsupported.append(Note("particles", "$.particles", "Box2D has no particle emitters; Emini's "
                                         "particles never act on bodies", affects_bodies=False))
        if w.simulation_area is not None:
            self.unsupported.append(Note("world.simulationArea", "$.world.simulationArea",
                                         "Box2D simulates every body; Emini freezes bodies outside its area",
                                         affects_bodies=True))
        self.settings = {"units": f"metres, {PX_PER_METRE:g} px = 1 m, y down", "timestep": self.h,
                         "substeps": self.substeps, "restitutionThreshold": RESTITUTION_THRESHOLD * PX_PER_METRE,
                         "maximumLinearSpeed": MAXIMUM_LINEAR_SPEED * PX_PER_METRE, "continuous": True,
                         "sleeping": self.sleeping, "frictionMixing": "Emini's a b (each friction squared for Box2D's sqrt)",
                         "restitutionMixing": "Box2D's max, elasticities scaled by the static shapes' (_mixing)", **versions()}

    def _mixing(self):
        """Box2D mixes friction as sqrt(a b) and restitution as max(a, b); Emini multiplies both. Friction
        maps exactly (each shape's friction squared). Restitution: when every static shape (and the
        landscape) has one elasticity E, static shapes get 0 and the others e E, so a body against the
        ground bounces with e E as in Emini; pairs of moving bodies with elasticity get max instead of the
        product (an approximation, noted)."""
        statics = {b.shape.elasticity for b in self.scene.bodies if b.state.static}
        land = self.scene.elements.get("landscape")
        if land is not None:
            statics.add(float(land.get("elasticity", 0.0)))
        self.static_e = next(iter(statics)) if len(statics) == 1 else None
        bouncy = [b.name for b in self.scene.bodies if not b.state.static and b.shape.elasticity > 0]
        if self.static_e is None:
            self.approximations.append(Note("elasticity", "$.shapes", "static shapes of different elasticities: "
                                            "Box2D's max(a, b) is used against them instead of Emini's a b"))
        if len(bouncy) > 1 and self.static_e is not None:
            self.approximations.append(Note("elasticity", "$.shapes", "moving bodies with elasticity meet each other "
                                            "with Box2D's max(a E, b E) instead of Emini's a b (E: the static shapes')"))

    def _restitution(self, elasticity, static):
        if self.static_e is None:
            return elasticity
        return 0.0 if static else elasticity * self.static_e

    def _bodies(self):
        self._mixing()
        m = self.mirror
        for spec in self.scene.bodies:
            s = spec.state
            mb = m.bodies[spec.name]
            kind = b2.BodyType.STATIC if s.static else b2.BodyType.KINEMATIC if s.kinematic else b2.BodyType.DYNAMIC
            r = b2.Rot()
            r.c, r.s = math.cos(s.angle), math.sin(s.angle)
            body = self.world.create_body(type=kind, position=(spec.x * S, spec.y * S), rotation=r,
                                          linear_velocity=(s.vx * S, s.vy * S),
                                          angular_velocity=s.angular_velocity if s.rotatable else 0.0,
                                          fixed_rotation=not s.rotatable, gravity_scale=1.0 if s.gravity else 0.0,
                                          enable_sleep=self.sleeping and s.sleeping_allowed)
            if self.sleeping:
                body.sleep_threshold = float(self.scene.world.sleeping.get("linearTolerance", 1.0)) * S
            pieces = flatten(spec.shape)
            for piece, ms in zip(pieces, m.shapes[spec.name]):
                f = ms.filter
                sd = b2.shape_def(density=1.0, is_sensor=s.sensor, enable_contact_events=True,
                                  material=b2.surface_material(friction=spec.shape.friction ** 2,
                                                               restitution=self._restitution(spec.shape.elasticity,
                                                                                             s.static)),
                                  filter=b2.make_filter(category_bits=f.categories, mask_bits=f.mask))
                if piece[0] == "circle":
                    cx, cy = piece[1]
                    geo = b2.circle(center=(cx * S, cy * S), radius=piece[2] * S)
                else:
                    geo = b2.polygon(points=[(x * S, y * S) for x, y in piece[1]])
                self.shape_of[body.create_shape(sd, geo).id] = ms
            if kind == b2.BodyType.DYNAMIC:
                # The scene's mass and the mirror's moment about the body origin (the centre of mass).
                md = b2.MassData()
                md.mass = mb.mass
                md.center = (0.0, 0.0)
                md.rotational_inertia = mb.moment * S * S if s.rotatable and math.isfinite(mb.moment) else 0.0
                body.mass_data = md
            self.bodies[spec.name] = body
        self.dynamic = [(n, self.bodies[n], m.bodies[n]) for n, _ in m.dynamic()]
        self.moving = [(self.bodies[sp.name], m.bodies[sp.name]) for sp in self.scene.bodies if not sp.state.static]
        self.wrapped = [b.angle for b, _ in self.moving]

    def _landscape(self, land):
        ground = self.world.create_body(type=b2.BodyType.STATIC, position=(0.0, 0.0))
        sd = b2.shape_def(enable_contact_events=True,
                          material=b2.surface_material(friction=float(land.get("friction", 0.25)) ** 2,
                                                       restitution=self._restitution(float(land.get("elasticity", 0.0)),
                                                                                     True)),
                          filter=b2.make_filter(category_bits=LANDSCAPE_BIT, mask_bits=ALL_BITS))
        for i, (seg, ms) in enumerate(zip(land["segments"], self.mirror.shapes["$landscape"])):
            (x0, y0), (x1, y1) = seg["from"], seg["to"]
            self.shape_of[ground.create_shape(sd, b2.segment((x0 * S, y0 * S), (x1 * S, y1 * S))).id] = ms
            if i > 0 and list(land["segments"][i - 1]["to"]) == list(seg["from"]):
                self.approximations.append(Note(
                    "landscape joint", f"$.landscape.segments[{i}].from",
                    "joined segments are separate Box2D segments: a body sliding across the joint can catch on "
                    "its end (Box2D's ghost collisions; its chain shapes avoid them but are one-sided)"))
            face = seg.get("face", "none")
            if face != "none":
                self.approximations.append(Note(
                    "landscape face", f"$.landscape.segments[{i}].face",
                    f"face '{face}' makes Emini's segment one-sided; the Box2D oracle's segments are two-sided"))

    def _joints(self, joints):
        for i, j in enumerate(joints):
            kind = j.get("type", "pin")
            path = f"$.joints[{i}]"
            if kind not in SUPPORTED_JOINTS:
                self.unsupported.append(Note(f"{kind} joint", path, f"the Box2D oracle maps pin and revolute joints "
                                             f"only so far (MAPPING.md, Box2D v3)", affects_bodies=True))
                continue
            a, b = self.bodies[j["bodyA"]], self.bodies[j["bodyB"]]
            pa, pb = _local_anchors(j, self.mirror.bodies[j["bodyA"]], self.mirror.bodies[j["bodyB"]])
            la, lb = (pa[0] * S, pa[1] * S), (pb[0] * S, pb[1] * S)
            common = dict(body_a=a, body_b=b, local_anchor_a=la, local_anchor_b=lb,
                          collide_connected=bool(j.get("collide", False)))
            if j.get("fixed", False):
                ref = self._angle(j["bodyB"]) - self._angle(j["bodyA"])
                self.world.create_weld_joint(reference_angle=ref, **common)
                continue
            extra = {}
            if kind == "revolute":
                if "limits" in j:
                    lo, hi = j["limits"]
                    extra.update(enable_limit=True, lower_angle=float(lo), upper_angle=float(hi))
                if "motor" in j:
                    mo = j["motor"]
                    extra.update(enable_motor=True, motor_speed=float(mo.get("speed", 0.0)),
                                 max_motor_torque=float(mo.get("maxTorque", 0.0)) * S * S)
                if "spring" in j:
                    self.unsupported.append(Note("revolute spring", path + ".spring", "the Box2D oracle does not map "
                                                 "a revolute joint's spring yet", affects_bodies=True))
                extra["reference_angle"] = self._angle(j["bodyB"]) - self._angle(j["bodyA"])
            self.world.create_revolute_joint(**common, **extra)

    def _angle(self, name):
        return self.mirror.specs[name].state.angle

    def step(self):
        self.world.step(self.h, self.substeps)
        kl, kr = self.keep
        if kl != 1.0 or kr != 1.0:
            # Emini removes a fraction of the velocity at the end of each tick (MAPPING.md, Damping).
            for _, body, _ in self.dynamic:
                if body.awake:
                    v = body.linear_velocity
                    body.linear_velocity = (v.x * kl, v.y * kl)
                    body.angular_velocity = body.angular_velocity * kr

    def mirror_state(self):
        """Each mirror body takes its Box2D body's pose and velocity (px, rad)."""
        for i, (body, mb) in enumerate(self.moving):
            p, v = body.position, body.linear_velocity
            mb.position = (p.x * PX_PER_METRE, p.y * PX_PER_METRE)
            # Box2D keeps the angle in (-pi, pi]; Emini's turns on past it: unwrap by the step's turn.
            a = body.angle
            turn = a - self.wrapped[i]
            turn -= 2 * math.pi * round(turn / (2 * math.pi))
            self.wrapped[i] = a
            mb.angle = mb.angle + turn
            mb.velocity = (v.x * PX_PER_METRE, v.y * PX_PER_METRE)
            mb.angular_velocity = body.angular_velocity

    def apply(self, a):
        """A scheduled action, as run.Schedule applies it to pymunk."""
        if a.kind == "gravity":
            self.world.gravity = (a.vector[0] * S, a.vector[1] * S)
            return
        if a.kind == "emit":
            return
        body = self.bodies[a.body]
        st = self.scene_state(a.body)
        if st.static:
            return
        if st.kinematic:
            if a.kind == "velocity":
                self._velocity(body, a, st)
            return
        if a.kind == "impulse":
            if st.rotatable and a.point is not None:
                body.apply_linear_impulse((a.vector[0] * S, a.vector[1] * S), (a.point[0] * S, a.point[1] * S), True)
            else:
                body.apply_linear_impulse_to_center((a.vector[0] * S, a.vector[1] * S), True)
        elif a.kind == "angularImpulse":
            if st.rotatable:
                body.apply_angular_impulse(a.value * S * S, True)
        elif a.kind == "force":
            if st.rotatable and a.point is not None:
                body.apply_force((a.vector[0] * S, a.vector[1] * S), (a.point[0] * S, a.point[1] * S), True)
            else:
                body.apply_force_to_center((a.vector[0] * S, a.vector[1] * S), True)
        elif a.kind == "torque":
            if st.rotatable:
                body.apply_torque(a.value * S * S, True)
        elif a.kind == "velocity":
            self._velocity(body, a, st)

    @staticmethod
    def _velocity(body, a, st):
        if a.vector is not None:
            body.linear_velocity = (a.vector[0] * S, a.vector[1] * S)
        if not math.isnan(a.value) and st.rotatable:
            body.angular_velocity = a.value

    def scene_state(self, name):
        return self.mirror.specs[name].state


class _Touching:
    """The pairs Box2D reports touching, as mirror shapes (begin and end touch events after each step)."""

    def __init__(self, world: World2, penetration):
        self.world = world
        self.penetration = penetration

    def update(self):
        ev = self.world.world.get_contact_events()
        pairs = self.penetration.pairs
        of = self.world.shape_of
        for e in ev.begin_events():
            a, b = of.get(e.shape_a.id), of.get(e.shape_b.id)
            if a is not None and b is not None:
                if metric_classes._TYPE_ORDER[type(a)] > metric_classes._TYPE_ORDER[type(b)]:
                    a, b = b, a
                pairs[(id(a), id(b))] = (a, b)
        for e in ev.end_events():
            a, b = of.get(e.shape_a.id), of.get(e.shape_b.id)
            pairs.pop((id(a), id(b)), None)
            pairs.pop((id(b), id(a)), None)

    def refresh(self):
        # The mirror's shapes hold the poses of their last cache: bring them to the mirrored poses.
        for a, b in self.penetration.pairs.values():
            a.cache_bb()
            b.cache_bb()


class _Sleeping(metric_classes.Metric):
    def __init__(self, world: World2):
        self.bodies = [b for _, b, _ in world.dynamic]

    def sample(self, tick):
        n = sum(1 for b in self.bodies if not b.awake)
        return [float(n), n / len(self.bodies) if self.bodies else 0.0]


def run_scene(scene: Scene, ticks=None, timing=None):
    """Runs a scene in Box2D v3; returns (trace JSON, the world) as run.run_scene does for pymunk.
    `ticks` is not supported (the whole run); `timing` receives "loop" as there."""
    import time
    loop_start = time.perf_counter()
    w = World2(scene)
    built = w.mirror
    snapshot = metric_classes.Snapshot(built)
    metrics = []
    touching = None
    for spec in scene.record.metrics:
        if spec.kind == "sleeping":
            metrics.append(_Sleeping(w))
            continue
        m = metric_classes.create(spec, built, snapshot)
        if spec.kind == "penetration":
            touching = _Touching(w, m)
        metrics.append(m)
    channels = [c for m in scene.record.metrics for c in m.channels()]
    names = scene.recorded_bodies()
    recorded = [(built.bodies[n], w.bodies[n]) for n in names]
    trace = Trace(scene, names, channels)
    entries = _schedule(w)
    every = scene.sampling_ticks
    monitors = [m for m in metrics if type(m).after_tick is not metric_classes.Metric.after_tick]

    def sample(k):
        if touching is not None:
            touching.refresh()
        trace.ticks.append(k)
        trace.body_rows.append([(mb.position.x, mb.position.y, mb.angle, mb.velocity.x, mb.velocity.y,
                                 mb.angular_velocity, not bb.awake) for mb, bb in recorded])
        row = []
        for m in metrics:
            row.extend(m.sample(k))
        trace.metric_rows.append(row)

    sample(0)
    for k in range(scene.ticks):
        for start, end, a in entries:
            if start <= k < end:
                w.apply(a)
        w.step()
        w.mirror_state()
        if touching is not None:
            touching.update()
        for m in monitors:
            m.after_tick(k + 1)
        if (k + 1) % every == 0 or k + 1 == scene.ticks:
            sample(k + 1)
    if timing is not None:
        timing["loop"] = time.perf_counter() - loop_start
    built.unsupported, built.approximations = w.unsupported, w.approximations
    trace.pairs = metric_classes.penetration_pairs(metrics)
    doc = trace.to_json(built)
    doc["source"] = "box2d"
    doc["oracle"] = {**versions(), "settings": w.settings}
    return doc, w


def time_steps(scene: Scene):
    """Time of a scene's ticks alone in Box2D, (wall seconds, CPU seconds of this thread): a fresh world,
    then per tick the scheduled actions, the step and Emini's damping, no metrics (run.time_steps for
    pymunk)."""
    import gc
    import time
    w = World2(scene)
    entries = _schedule(w)
    collecting = gc.isenabled()
    gc.disable()
    try:
        c0, t0 = time.thread_time(), time.perf_counter()
        for k in range(scene.ticks):
            for start, end, a in entries:
                if start <= k < end:
                    w.apply(a)
            w.step()
        return time.perf_counter() - t0, time.thread_time() - c0
    finally:
        if collecting:
            gc.enable()


def _schedule(w: World2):
    """(first tick, end tick, action) as run.Schedule times them for pymunk (from the mirror)."""
    return Schedule(w.mirror).entries


__all__ = ["run_scene", "time_steps", "World2", "versions", "UnsupportedScene"]
