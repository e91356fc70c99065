"""Times pymunk on the benchmark scenes, through the oracle's scene reader and space builder (oracle-py/).

Run by `./emini bench` (org.emini.bench.run.ExternalBench) with the oracle's environment
(oracle-py/.venv); the timing method and the result file are bench/peers/peer_bench.py's, the scene
check is the Java side's. pymunk runs at Chipmunk's default 10 iterations, sleeping off (the oracle's
build), as the other peers run at their own defaults (bench/ENGINES.md); a scene with world.sleeping (the
game level) sleeps at Chipmunk's own idle speed threshold (0: derived from gravity, |g|·h) after 0.5 s, as
the other peers sleep at their own tolerances. Units: px, as Emini.

    python pymunk_bench.py --root REPO --out FILE [--preroll N] [--warmups 3 --iterations 5 --seconds 1] SCENE_ID...
"""

from __future__ import annotations

import heapq
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "peers"))
import peer_bench  # noqa: E402

PYMUNK_ITERATIONS = 10  # Chipmunk's default
pymunk = None  # imported in main, from the oracle's environment


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


class World:
    """A scene built by the oracle's builder, in px (peer_bench's world)."""

    units = "px"

    def __init__(self, loader, build, root, scene_id):
        path = next((root / "scenarios" / (scene_id + ext) for ext in (".yaml", ".yml", ".json")
                     if (root / "scenarios" / (scene_id + ext)).is_file()), None)
        if path is None:
            raise ValueError("no scene file for " + scene_id)
        scene = loader.load(path)
        # The oracle builds joints as pymunk PivotJoints and rotational motors as SimpleMotors against the
        # static body (oracle-py/MAPPING.md). Particles: pymunk has none; the benchmark makes them bodies.
        missing = [e for e in scene.elements if e not in ("joints", "motors", "particles")]
        if missing:
            raise peer_bench.Unsupported("the benchmark does not build " + ", ".join(missing))
        if scene.world.sleeping:  # the scene sets Emini's tolerances: the peers sleep at their own (PeerScene)
            raise peer_bench.Unsupported("the benchmark sleeps at each engine's own tolerances; "
                                         "the scene sets Emini's (world.sleeping)")
        built = self.built = build(scene)
        self.space = space = built.space
        space.iterations = PYMUNK_ITERATIONS
        if built.sleeping:
            space.idle_speed_threshold = 0.0  # Chipmunk's default: derived from gravity, |g| * h
        self.h = h = scene.world.timestep
        self.ticks = int(math.ceil(scene.duration / h - 1e-9))
        self.bodies = [built.bodies[b.name] for b in scene.bodies]
        self.dynamic = [b for _, b in built.dynamic()]
        self.parts = Particles(space, scene.elements["particles"]) if "particles" in scene.elements else None
        self.settings = (f"px units via the oracle's builder (oracle-py/); timestep {h:g} s; "
                         f"{PYMUNK_ITERATIONS} iterations (Chipmunk's default); "
                         + (f"sleeping on at Chipmunk's idle speed threshold (|g| h = {math.hypot(*space.gravity) * h:.2f} px/s) "
                            f"for {space.sleep_time_threshold:g} s" if built.sleeping else "sleeping off")
                         + f"; pymunk {pymunk.version}, Chipmunk {pymunk.chipmunk_version}"
                         + ("; particles as circle bodies of 2 px, infinite moment, no friction, meeting the scene's shapes but "
                            "not each other (ShapeFilter), created as emitted and removed when their lifetime ends"
                            if self.parts else ""))

    def tick(self):
        if self.parts is not None:
            self.parts.before_step(self.h)
        self.built.keep_awake()
        self.space.step(self.h)

    def state(self):
        poses = [c for b in self.bodies for c in (b.position.x, b.position.y, b.angle)]
        speeds = [math.hypot(b.velocity.x, b.velocity.y) for b in self.bodies]
        omegas = [b.angular_velocity for b in self.bodies]
        particles = [c for p in self.parts.positions() for c in p] if self.parts is not None else []
        asleep = sum(1 for b in self.dynamic if b.is_sleeping) if self.built.sleeping else -1
        return poses, speeds, omegas, particles, asleep


def main(argv=None):
    ap = peer_bench.arguments(__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, type=Path)
    args = ap.parse_args(argv)
    sys.path.insert(0, str(args.root / "oracle-py" / "src"))
    from emini_oracle import scene as scene_mod
    from emini_oracle.build import build
    global pymunk
    import pymunk
    loader = scene_mod.Loader(args.root / "scenarios" / "scenario.schema.json")
    peer_bench.run("pymunk", args, lambda s, a: World(loader, build, a.root, s))


if __name__ == "__main__":
    main()
