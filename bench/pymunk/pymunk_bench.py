"""Times pymunk on the benchmark scenes, through the oracle's scene reader and space builder (oracle-py/).

Run by `./emini bench` (org.emini.bench.run.PymunkBench) with the oracle's environment
(oracle-py/.venv). The method copies the JMH benchmark's: build the space from the scene file, run the
untimed preroll (the scene's run duration unless --preroll is given) and check the scene, then time
ticks in warm-up and measurement rounds; the figure is the process's CPU time per measured tick
(time.thread_time), wall time beside it. pymunk runs at Chipmunk's default 10 iterations, sleeping off
(the oracle's build), as the other peers run at their own defaults (bench/ENGINES.md); a scene with
world.sleeping (the game level) sleeps at Chipmunk's own idle speed threshold (0: derived from gravity,
|g|·h) after 0.5 s, as the other peers sleep at their own tolerances.

The check is the same as bench/src/main/java/org/emini/bench/check/Stability.java.

    python pymunk_bench.py --root REPO --out FILE [--preroll N] [--warmups 3 --iterations 5 --seconds 1] SCENE_ID...
"""

from __future__ import annotations

import argparse
import heapq
import json
import math
import sys
import time
from pathlib import Path

PYMUNK_ITERATIONS = 10  # Chipmunk's default
pymunk = None  # imported in main, from the oracle's environment


MOTOR_TOLERANCE = 0.05  # Stability.MOTOR_TOLERANCE
PARTICLE_RADIUS = 2.0  # px, as the Java peers' 0.1 m (PeerScene.PARTICLE_RADIUS)
PARTICLE_CATEGORY, WORLD_CATEGORY = 0b10, 0b01


class Particles:
    """Emini's particles as pymunk bodies, the way the Java peers make them (PeerParticles.java): a
    circle of 2 px per particle, infinite moment (fixed rotation), no friction, the emitter's
    elasticity (the static shapes get elasticity 1: pymunk multiplies the two, Emini's particles
    bounce with the emitter's alone), meeting the scene's shapes but not each other (ShapeFilter);
    created as emitted, removed when their lifetime ends. Same distributions as Emini's emitters,
    not the same particles."""

    def __init__(self, space, emitters):
        import random
        self.space = space
        self.emitters = []
        for i, e in enumerate(emitters):
            if "body" in e or e.get("damping", 0) or e.get("gravityFactor", 1) != 1:
                raise ValueError("the benchmark's pymunk particles are fixed emitters without damping or gravity factor")
            frm = e["from"]
            to = e.get("to", frm)
            self.emitters.append(dict(
                x1=frm[0], y1=frm[1], x2=to[0], y2=to[1], max=e.get("maxCount", 100), rate=e.get("rate", 20),
                rateSpread=e.get("rateSpread", 0), life=e.get("lifetime", 2), lifeSpread=e.get("lifetimeSpread", 0),
                speed=e.get("speed", 10), speedSpread=e.get("speedSpread", 0), angle=math.radians(e.get("angleDeg", 0)),
                angleSpread=math.radians(e.get("angleSpreadDeg", 0)), e=e.get("elasticity", 1),
                collide=e.get("collide", True), random=random.Random(e.get("seed", 0x5DEECE66D + i)), owed=0.0, live=[]))
        for sh in space.shapes:
            sh.filter = pymunk.ShapeFilter(categories=WORLD_CATEGORY, mask=pymunk.ShapeFilter.ALL_MASKS())
            sh.elasticity = 1.0
        self.time = 0.0
        self.born = 0

    def before_step(self, dt):
        for em in self.emitters:
            live = em["live"]  # a heap by time of death
            while live and live[0][0] <= self.time:
                _, _, body, shape = heapq.heappop(live)
                self.space.remove(body, shape)
            r = em["random"]
            em["owed"] += max(0.0, em["rate"] + (r.random() - 0.5) * em["rateSpread"]) * dt
            n = int(em["owed"])
            em["owed"] -= n
            for _ in range(n):
                if len(live) >= em["max"]:
                    break
                u = r.random()
                a = em["angle"] + (r.random() - 0.5) * em["angleSpread"]
                v = em["speed"] + (r.random() - 0.5) * em["speedSpread"]
                life = em["life"] + (r.random() - 0.5) * em["lifeSpread"]
                body = pymunk.Body(1.0, math.inf)
                body.position = (em["x1"] + u * (em["x2"] - em["x1"]), em["y1"] + u * (em["y2"] - em["y1"]))
                body.velocity = (v * math.cos(a), v * math.sin(a))
                shape = pymunk.Circle(body, PARTICLE_RADIUS)
                shape.friction = 0.0
                shape.elasticity = em["e"]
                shape.filter = pymunk.ShapeFilter(categories=PARTICLE_CATEGORY, mask=WORLD_CATEGORY if em["collide"] else 0)
                self.space.add(body, shape)
                self.born += 1
                heapq.heappush(live, (self.time + life, self.born, body, shape))
        self.time += dt

    def positions(self):
        return [(b.position.x, b.position.y) for em in self.emitters for _, _, b, _ in em["live"]]


def moving(scene):
    """Stability.moving: dynamic bodies plus the particles each emitter keeps alive."""
    n = sum(1 for b in scene.bodies if not b.state.static)
    for e in scene.elements.get("particles") or []:
        n += min(e.get("maxCount", 100), round(e.get("rate", 20) * e.get("lifetime", 2)))
    return n


def poses(built, names):
    out = []
    for n in names:
        b = built.bodies[n]
        out.append((b.position.x, b.position.y, b.angle, math.hypot(b.velocity.x, b.velocity.y), b.angular_velocity))
    return out


def judge(scene, ticks, initial, now, flatten=None, local_aabb=None, particles=(), asleep=-1):
    """The scene check of Stability.java: same rules, same verdicts."""
    min_x, max_x, floor_top = math.inf, -math.inf, -math.inf
    size = 0.0
    container, target = -1, 0.0
    index = {b.name: i for i, b in enumerate(scene.bodies)}
    for m in scene.elements.get("motors") or []:
        if container < 0 and "angularVelocity" in m:
            container, target = index[m["body"]], float(m["angularVelocity"])
    for i, b in enumerate(scene.bodies):
        w, h = b.shape.size() if b.shape.kind != "multiShape" else (0.0, 0.0)
        if b.state.static:
            min_x = min(min_x, b.x - w / 2)
            max_x = max(max_x, b.x + w / 2)
            floor_top = max(floor_top, b.y - h / 2)
        elif size == 0 and i != container:
            size = max(w, h)
    joints = scene.elements.get("joints") or []
    half = (0.0, 0.0)
    if container >= 0:
        x0, y0, x1, y1 = local_aabb(flatten(scene.bodies[container].shape))
        half = (max(-x0, x1), max(-y0, y1))
        cx, cy, ca = now[container][0], now[container][1], now[container][2]
        cc, cs = math.cos(ca), math.sin(ca)
    stacking = scene.category == "stacking"
    # A stacking scene with joints (the game level): jointed bodies swing by design; stacks are judged without them.
    swinging = {n for j in joints for n in (j["bodyA"], j["bodyB"])} if stacking else set()
    max_d = max_dx = max_dy = max_a = max_v = 0.0
    escaped = non_finite = 0
    for i, (b, p0, p) in enumerate(zip(scene.bodies, initial, now)):
        if b.state.static:
            continue
        x, y, a, v = p[:4]
        if not all(map(math.isfinite, (x, y, a))):
            non_finite += 1
            continue
        max_v = max(max_v, v)
        if b.name in swinging:
            continue
        max_d = max(max_d, math.hypot(x - p0[0], y - p0[1]))
        max_dx = max(max_dx, abs(x - p0[0]))
        max_dy = max(max_dy, abs(y - p0[1]))
        max_a = max(max_a, abs(a - p0[2]))
        if container >= 0:
            if i != container:
                dx, dy = x - cx, y - cy
                lx, ly = cc * dx + cs * dy, -cs * dx + cc * dy
                if not (abs(lx) <= half[0] and abs(ly) <= half[1]):
                    escaped += 1
        elif not joints and min_x <= max_x and (x < min_x or x > max_x or y > floor_top):
            escaped += 1
    joint_error = 0.0
    if joints:
        index = {b.name: i for i, b in enumerate(scene.bodies)}

        def local(p, wx, wy):
            c, s = math.cos(p[2]), math.sin(p[2])
            dx, dy = wx - p[0], wy - p[1]
            return (c * dx + s * dy, -s * dx + c * dy)

        def world(p, l):
            c, s = math.cos(p[2]), math.sin(p[2])
            return (p[0] + c * l[0] - s * l[1], p[1] + s * l[0] + c * l[1])

        for j in joints:
            a, b = index[j["bodyA"]], index[j["bodyB"]]
            if "at" in j:
                la, lb = local(initial[a], *j["at"]), local(initial[b], *j["at"])
            else:
                la, lb = tuple(j.get("anchorA", (0, 0))), tuple(j.get("anchorB", (0, 0)))
            pa, pb = world(now[a], la), world(now[b], lb)
            joint_error = max(joint_error, math.hypot(pa[0] - pb[0], pa[1] - pb[1]))
    motor_error = abs(now[container][4] - target) / abs(target) if container >= 0 else 0.0
    if non_finite or math.isnan(joint_error):
        verdict = "non-finite"
    elif container >= 0:
        if escaped:
            verdict = "escaped"
        elif joint_error > size / 4:
            verdict = "stretched"
        elif not motor_error <= MOTOR_TOLERANCE:
            verdict = "slowed"
        else:
            verdict = "stable"
    elif joints and (not stacking or joint_error > size / 4):
        verdict = "stable" if joint_error <= size / 4 else "stretched"
    elif stacking:
        if max_dx <= size / 4 and max_a < 0.1 and max_dy <= size:
            verdict = "stable"
        elif max_dx > size or max_dy > 2 * size or max_a > 0.5:
            verdict = "collapsed"
        else:
            verdict = "drifted"
    else:
        verdict = "stable" if escaped == 0 else "escaped"
    return {"ticks": ticks, "verdict": verdict, "maxDisplacementPx": max_d, "maxDxPx": max_dx, "maxDyPx": max_dy,
            "bodySize": size, "maxAngle": max_a, "maxSpeed": max_v, "escaped": escaped, "nonFinite": non_finite,
            "maxJointErrorPx": joint_error, "motorSpeedError": motor_error,
            "particles": len(particles), "asleep": asleep}


def measure(loader, build, flatten, local_aabb, root, scene_id, args):
    entry = {"scene": scene_id, "engine": "pymunk", "status": "ok", "message": ""}
    path = None
    for ext in (".yaml", ".yml", ".json"):
        if (root / "scenarios" / (scene_id + ext)).is_file():
            path = root / "scenarios" / (scene_id + ext)
    if path is None:
        return dict(entry, status="error", message="no scene file")
    scene = loader.load(path)
    # The oracle builds joints as pymunk PivotJoints and rotational motors as SimpleMotors against the
    # static body (oracle-py/MAPPING.md).
    # Particles: pymunk has none; the benchmark makes them bodies (Particles above).
    missing = [e for e in scene.elements if e not in ("joints", "motors", "particles")]
    if missing:
        return dict(entry, status="unsupported", message="the benchmark does not build " + ", ".join(missing))
    sleep = scene.world.sleeping
    if sleep:  # the scene sets Emini's tolerances: the peers sleep at their own (PeerScene)
        return dict(entry, status="unsupported", message="the benchmark sleeps at each engine's own tolerances; "
                    "the scene sets Emini's (world.sleeping)")
    built = build(scene)
    space = built.space
    space.iterations = PYMUNK_ITERATIONS
    if built.sleeping:
        space.idle_speed_threshold = 0.0  # Chipmunk's default: derived from gravity, |g| * h
    h = scene.world.timestep
    names = [b.name for b in scene.bodies]
    initial = poses(built, names)
    parts = Particles(space, scene.elements["particles"]) if "particles" in scene.elements else None

    dynamic_bodies = [b for _, b in built.dynamic()]

    def tick():
        if parts is not None:
            parts.before_step(h)
        built.keep_awake()
        space.step(h)

    def check_now(ticks):
        return judge(scene, ticks, initial, poses(built, names), flatten, local_aabb,
                     parts.positions() if parts is not None else (),
                     sum(1 for b in dynamic_bodies if b.is_sleeping) if built.sleeping else -1)

    preroll = args.preroll if args.preroll >= 0 else int(math.ceil(scene.duration / h - 1e-9))
    t0 = time.perf_counter()
    for _ in range(preroll):
        tick()
    t1 = time.perf_counter()
    ticks = preroll
    check = check_now(ticks)

    def rounds(n):
        results = []
        for _ in range(n):
            w0, c0, k = time.perf_counter(), time.thread_time(), 0
            while time.perf_counter() - w0 < args.seconds:
                tick()
                k += 1
            results.append(((time.perf_counter() - w0) / k, (time.thread_time() - c0) / k, k))
        return results

    ticks += sum(m[2] for m in rounds(args.warmups))
    measured = rounds(args.iterations)
    ticks += sum(m[2] for m in measured)
    wall = [m[0] * 1e3 for m in measured]
    cpu = sum(m[1] * m[2] for m in measured) / sum(m[2] for m in measured) * 1e3
    dynamic = moving(scene)
    mean = sum(wall) / len(wall)
    sd = math.sqrt(sum((w - mean) ** 2 for w in wall) / max(1, len(wall) - 1))
    return dict(entry, bodies=len(scene.bodies), dynamicBodies=dynamic, msPerTick=mean,
                msPerTickError=sd, msPerTickMedian=sorted(wall)[len(wall) // 2], cpuMsPerTick=cpu,
                usPerBody=cpu * 1e3 / max(1, dynamic), allocBytesPerTick=None, threadBytesPerTick=None,
                prerollMsPerTick=(t1 - t0) * 1e3 / preroll if preroll else None,
                settings=f"px units via the oracle's builder (oracle-py/); timestep {h:g} s; "
                         f"{PYMUNK_ITERATIONS} iterations (Chipmunk's default); "
                         + (f"sleeping on at Chipmunk's idle speed threshold (|g| h = {math.hypot(*space.gravity) * h:.2f} px/s) "
                            f"for {space.sleep_time_threshold:g} s" if built.sleeping else "sleeping off")
                         + f"; pymunk {pymunk.version}, Chipmunk {pymunk.chipmunk_version}"
                         + ("; particles as circle bodies of 2 px, infinite moment, no friction, meeting the scene's shapes but not "
                            "each other (ShapeFilter), created as emitted and removed when their lifetime ends" if parts else ""),
                check=check, afterRun=check_now(ticks))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, type=Path)
    ap.add_argument("--out", required=True, type=Path)
    ap.add_argument("--preroll", type=int, default=-1)
    ap.add_argument("--warmups", type=int, default=3)
    ap.add_argument("--iterations", type=int, default=5)
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("scenes", nargs="+")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(args.root / "oracle-py" / "src"))
    from emini_oracle import scene as scene_mod
    from emini_oracle.build import build, flatten, local_aabb
    global pymunk
    import pymunk
    loader = scene_mod.Loader(args.root / "scenarios" / "scenario.schema.json")
    out = []
    for s in args.scenes:
        try:
            m = measure(loader, build, flatten, local_aabb, args.root, s, args)
        except Exception as e:  # reported in the report, never hidden
            m = {"scene": s, "engine": "pymunk", "status": "error", "message": f"{type(e).__name__}: {e}"}
        print(f"{s:28s} pymunk     {m.get('cpuMsPerTick', float('nan')):9.3f} ms/tick cpu  "
              f"{m.get('msPerTick', float('nan')):9.3f} wall  {m.get('check', {}).get('verdict', m['status'])}", flush=True)
        out.append(m)
    args.out.write_text(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
