"""Runs a scene in pymunk and writes its trace in the harness's trace format, version 1.

The tick loop is the harness's (run/ScenarioRunner.java): actions before the tick that starts at or
after their time, one space.step(h) per tick, after-tick monitors, samples at tick 0, every
round(every / h) ticks and after the last tick.
"""

from __future__ import annotations

import gc
import json
import math
import time
from pathlib import Path

import pymunk

from . import metrics as metric_classes
from .build import Built, Note, UnsupportedScene, build
from .scene import Scene, java_round

BODY_FIELDS = ("x", "y", "angle", "vx", "vy", "omega")


class Trace:
    def __init__(self, scene: Scene, bodies, channels):
        self.scene = scene
        self.bodies = bodies
        self.channels = channels
        self.ticks = []
        self.body_rows = []
        self.metric_rows = []
        self.pairs = None  # penetration per pair of bodies over the run (the penetration metric's)

    def to_json(self, built: Built):
        h = self.scene.world.timestep
        out = {
            "format": "emini-trace",
            "version": 1,
            "scene": self.scene.name,
            "source": "pymunk",
            "timestep": h,
            "tick": list(self.ticks),
            "time": [t * h for t in self.ticks],
            "bodies": {},
            "metrics": {},
        }
        for i, name in enumerate(self.bodies):
            out["bodies"][name] = {f: [_finite(row[i][k]) for row in self.body_rows]
                                   for k, f in enumerate(BODY_FIELDS)}
            if built.sleeping:
                # As the harness writes it: 1 while the body sleeps, only when the world lets bodies sleep.
                out["bodies"][name]["sleeping"] = [1 if row[i][len(BODY_FIELDS)] else 0 for row in self.body_rows]
        for c, channel in enumerate(self.channels):
            out["metrics"][channel] = [_finite(row[c]) for row in self.metric_rows]
        if self.pairs:
            out["penetrationPairs"] = [dict(p, max=_finite(p["max"]), mean=_finite(p["mean"])) for p in self.pairs]
        # Fields a trace reader ignores unless it knows them (harness/README.md, Trace format).
        out["unsupported"] = [n.to_json() for n in built.unsupported]
        out["approximations"] = [n.to_json() for n in built.approximations]
        out["oracle"] = {"pymunk": pymunk.version, "chipmunk": pymunk.chipmunk_version,
                         "settings": built.settings}
        return out


def _finite(v):
    return v if math.isfinite(v) else None


class Schedule:
    """Actions applied before tick k = ceil(at / h); forces and torques for max(1, round(duration / h)) ticks."""

    def __init__(self, built: Built):
        self.built = built
        self.h = built.scene.world.timestep
        self.entries = []
        for a in built.scene.actions:
            start = int(math.ceil(a.at / self.h - 1e-9))
            lasting = a.kind in ("force", "torque")
            n = (1 if math.isnan(a.duration) else max(1, java_round(a.duration / self.h))) if lasting else 1
            self.entries.append((start, start + n, a))

    def before_tick(self, k):
        for start, end, a in self.entries:
            if start <= k < end:
                self.apply(a)

    def apply(self, a):
        built = self.built
        if a.kind == "gravity":
            built.space.gravity = a.vector
            if built.sleeping:
                # Emini wakes every body when gravity changes. Chipmunk's cpSpaceSetGravity means to, but in
                # pymunk 7.3.1 it wakes only every other sleeping component (MAPPING.md, Sleeping).
                for b in built.space.bodies:
                    if b.is_sleeping:
                        b.activate()
            return
        if a.kind == "emit":
            return  # a particle burst; pymunk has no particles, and they never act on bodies
        body = built.bodies[a.body]
        rotatable = built.specs[a.body].state.rotatable
        if body.body_type == pymunk.Body.KINEMATIC and a.kind == "velocity":
            # A kinematic body moves by the velocity set; impulses and forces do not act on it.
            if a.vector is not None:
                body.velocity = a.vector
            if not math.isnan(a.value) and rotatable:
                body.angular_velocity = a.value
            return
        if body.body_type != pymunk.Body.DYNAMIC:
            return  # no impulse or force acts on a static or kinematic body
        if a.kind == "impulse":
            point = a.point if a.point is not None else tuple(body.position)
            if rotatable:
                body.apply_impulse_at_world_point(a.vector, point)
            else:
                body.velocity += (a.vector[0] / body.mass, a.vector[1] / body.mass)
        elif a.kind == "angularImpulse":
            if rotatable:
                body.angular_velocity += a.value / body.moment
        elif a.kind == "force":
            point = a.point if a.point is not None else tuple(body.position)
            if rotatable:
                body.apply_force_at_world_point(a.vector, point)
            else:
                body.force += a.vector
        elif a.kind == "torque":
            if rotatable:
                body.torque += a.value
        elif a.kind == "velocity":
            if a.vector is not None:
                body.velocity = a.vector
            if not math.isnan(a.value) and rotatable:
                body.angular_velocity = a.value


def run_scene(scene: Scene, ticks=None, timing=None):
    """Runs a scene (or only its first `ticks` ticks); returns (trace JSON, built world).

    If `timing` is a dict it receives "loop": the wall seconds of the tick loop with its metrics and
    samples (the cost of a sweep point is `time_steps`, without them)."""
    built = build(scene)
    space = built.space
    snapshot = metric_classes.Snapshot(built)
    metrics = [metric_classes.create(m, built, snapshot) for m in scene.record.metrics]
    channels = [c for m in scene.record.metrics for c in m.channels()]
    names = scene.recorded_bodies()
    recorded = [built.bodies[n] for n in names]
    trace = Trace(scene, names, channels)
    schedule = Schedule(built)
    h = scene.world.timestep
    ticks = scene.ticks if ticks is None else min(ticks, scene.ticks)
    every = scene.sampling_ticks
    keep_lin, keep_rot = built.damping
    damped = [(b, built.specs[n].state.rotatable) for n, b in built.dynamic()] \
        if keep_lin != 1.0 or keep_rot != 1.0 else []
    area = _AreaWatch(built) if scene.world.simulation_area is not None else None
    monitors = [m for m in metrics if type(m).after_tick is not metric_classes.Metric.after_tick]

    def sample(k):
        trace.ticks.append(k)
        trace.body_rows.append([(b.position.x, b.position.y, b.angle, b.velocity.x, b.velocity.y,
                                 b.angular_velocity, b.is_sleeping) for b in recorded])
        row = []
        for m in metrics:
            row.extend(m.sample(k))
        trace.metric_rows.append(row)
        if area is not None:
            area.check(k * h)

    loop_start = time.perf_counter()
    sample(0)
    for k in range(ticks):
        schedule.before_tick(k)
        built.keep_awake()
        space.step(h)
        if built.sleeping:
            built.damp_quietly(damped)
        for b, rot in () if built.sleeping else damped:
            # Emini removes a fraction of the velocity at the end of each tick (MAPPING.md, Damping).
            b.velocity = b.velocity * keep_lin
            if rot:
                b.angular_velocity *= keep_rot
        for m in monitors:
            m.after_tick(k + 1)
        if (k + 1) % every == 0 or k + 1 == ticks:
            sample(k + 1)
    if timing is not None:
        timing["loop"] = time.perf_counter() - loop_start
    if area is not None:
        area.report()
    trace.pairs = metric_classes.penetration_pairs(metrics)
    return trace.to_json(built), built


def time_steps(scene: Scene):
    """Time of a scene's ticks alone, (wall seconds, CPU seconds of this thread): a fresh space, then
    per tick the scheduled actions, `space.step(h)` and the damping that completes Emini's tick, timed
    as one block with no metrics, no samples and the garbage collector paused. The harness's engine
    side times the same loop (ScenarioRunner.timeTicks: actions and World.tick), so the two costs of a
    sweep point are alike."""
    built = build(scene)
    space = built.space
    step = space.step
    schedule = Schedule(built)
    before = schedule.before_tick if schedule.entries else None
    h = scene.world.timestep
    ticks = scene.ticks
    keep_lin, keep_rot = built.damping
    damped = [(b, built.specs[n].state.rotatable) for n, b in built.dynamic()] \
        if keep_lin != 1.0 or keep_rot != 1.0 else []
    collecting = gc.isenabled()
    gc.disable()
    try:
        c0 = time.thread_time()
        t0 = time.perf_counter()
        if before is None and not damped and not built.never_sleep:
            for _ in range(ticks):
                step(h)
        else:
            for k in range(ticks):
                if before is not None:
                    before(k)
                built.keep_awake()
                step(h)
                if built.sleeping:
                    built.damp_quietly(damped)
                    continue
                for b, rot in damped:
                    b.velocity = b.velocity * keep_lin
                    if rot:
                        b.angular_velocity *= keep_rot
        t1 = time.perf_counter()
        return t1 - t0, time.thread_time() - c0
    finally:
        if collecting:
            gc.enable()


class _AreaWatch:
    """Emini freezes bodies outside its simulation area; pymunk cannot. Note whether any body left it."""

    def __init__(self, built: Built):
        self.built = built
        a = built.scene.world.simulation_area
        if "min" in a:
            (self.min_x, self.min_y), (self.max_x, self.max_y) = a["min"], a["max"]
        else:
            self.min_x, self.min_y, self.max_x, self.max_y = float(a["start"]), -math.inf, float(a["end"]), math.inf
        self.left_at = None

    def check(self, t):
        if self.left_at is not None:
            return
        for name, body in self.built.dynamic():
            # Emini simulates a body while its bounding box overlaps the area (touching counts).
            boxes = [s.cache_bb() for s in self.built.shapes[name]]
            left = min(bb.left for bb in boxes)
            right = max(bb.right for bb in boxes)
            bottom = min(bb.bottom for bb in boxes)
            top = max(bb.top for bb in boxes)
            if right < self.min_x or left > self.max_x or top < self.min_y or bottom > self.max_y:
                self.left_at = (name, t)
                return

    def report(self):
        note = next(n for n in self.built.unsupported if n.element == "world.simulationArea")
        if self.left_at is None:
            note.reason += "; every body stayed inside at every sample, so the run is unaffected"
        else:
            note.affects_bodies = True
            note.reason += f"; body {self.left_at[0]} was outside at t = {self.left_at[1]:g} s"


def engine_functions(engine: str):
    """(run_scene, time_steps) of an oracle engine: pymunk (this module) or box2d (box2d.py)."""
    if engine == "box2d":
        from . import box2d
        return box2d.run_scene, box2d.time_steps
    if engine != "pymunk":
        raise ValueError(f"unknown oracle engine {engine!r}: pymunk or box2d")
    return run_scene, time_steps


def run_file(loader, file, out_dir: Path, engine: str = "pymunk"):
    """Runs one scene file; returns its entry for oracle-results.json (never raises for a scene problem)."""
    from .scene import SceneError
    t0 = time.perf_counter()
    entry = {"file": str(file), "scene": None, "status": "ok", "message": "", "unsupported": [],
             "approximations": [], "trace": None, "seconds": 0.0}
    try:
        scene = loader.load(file)
    except SceneError as e:
        entry.update(status="invalid", message=str(e))
        return entry
    entry["scene"] = scene.name
    skip = (scene.oracle or {}).get("skip")
    if skip:
        entry.update(status="skipped", message=skip)
        return entry
    try:
        doc, built = engine_functions(engine)[0](scene)
    except UnsupportedScene as e:
        entry.update(status="unsupported", message=str(e))
        return entry
    except Exception as e:  # a bug of the oracle or its engine: reported, not hidden
        entry.update(status="error", message=f"{type(e).__name__}: {e}")
        return entry
    entry["unsupported"] = doc["unsupported"]
    entry["approximations"] = doc["approximations"]
    # Written even when record.trace is false: the trace is what the comparison reads.
    path = Path(out_dir) / f"{scene.name}.trace.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f, allow_nan=False, separators=(",", ":"))
    entry["trace"] = str(path)
    entry["seconds"] = round(time.perf_counter() - t0, 3)
    return entry


__all__ = ["run_scene", "run_file", "time_steps", "engine_functions", "Note"]
