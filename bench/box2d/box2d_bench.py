"""Times Box2D v3 (3.1.1, through the PyPI package pyb2d3) on the benchmark scenes.

Run by `./emini bench` (org.emini.bench.run.ExternalBench) with bench/box2d/.venv, made from
requirements.txt beside this file. The scenes come as the Java side's flat export (PeerSceneExport:
metres, y up, the mapping every metre-based peer gets); the timing method and the result file are
bench/peers/peer_bench.py's, the scene check is the Java side's.

Settings (bench/ENGINES.md): Box2D's default 4 substeps, one worker and no thread pool, continuous
collision on (its default), sleeping off, except in a scene with world.sleeping (the game level),
which sleeps at Box2D's own tolerances (body sleep threshold 0.05 m/s, 0.5 s).

    python box2d_bench.py --scenes-dir DIR --out FILE [--preroll N] [--warmups 3 --iterations 5 --seconds 1] SCENE_ID...
"""

from __future__ import annotations

import importlib.metadata
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "peers"))
import peer_bench  # noqa: E402

SUBSTEPS = 4  # Box2D v3's default (b2World_Step's subStepCount in its samples and benchmarks)
MAX_POLYGON_VERTICES = 8  # B2_MAX_POLYGON_VERTICES; the Java side refuses larger polygons
b2 = None  # imported in main, from bench/box2d/.venv


def rot(angle):
    # b2MakeRot approximates cos and sin (3.1); the exact rotation keeps the start pose the scene's.
    r = b2.Rot()
    r.c, r.s = math.cos(angle), math.sin(angle)
    return r


class World:
    """A scene built in Box2D v3 from the flat export (peer_bench's world), in metres."""

    units = "m"

    def __init__(self, scene):
        if scene.get("format") != "emini-peer-scene" or scene.get("version") != 1:
            raise ValueError("not a version 1 emini-peer-scene file")
        if scene["emitters"]:
            raise peer_bench.Unsupported("the Box2D v3 driver does not make particles (the Java peers' circle bodies, "
                                         "PeerParticles); the scene has emitters")
        self.h = scene["timestep"]
        self.ticks = scene["ticks"]
        self.sleeping = scene["sleeping"]
        w = self.world = b2.World(gravity=tuple(scene["gravity"]))  # no thread_pool: one worker
        w.sleeping_enabled = self.sleeping
        w.continuous_enabled = True
        self.bodies = []
        for b in scene["bodies"]:
            body = w.create_body(type=b2.BodyType.DYNAMIC if b["dynamic"] else b2.BodyType.STATIC,
                                 position=(b["x"], b["y"]), rotation=rot(b["angle"]),
                                 linear_velocity=(b["vx"], b["vy"]), angular_velocity=b["omega"],
                                 fixed_rotation=not b["rotatable"], gravity_scale=1.0 if b["gravity"] else 0.0,
                                 enable_sleep=self.sleeping and b["sleepingAllowed"])
            for part in scene["shapes"][b["shape"]]:
                sd = b2.shape_def(density=part["density"],
                                  material=b2.surface_material(friction=part["friction"], restitution=part["restitution"]))
                if "radius" in part:
                    body.create_shape(sd, b2.circle(center=tuple(part["center"]), radius=part["radius"]))
                else:
                    body.create_shape(sd, b2.polygon(points=[tuple(v) for v in part["vertices"]]))
            self.bodies.append(body)
        self.dynamic = [b for b, spec in zip(self.bodies, scene["bodies"]) if spec["dynamic"]]
        motors = {m["joint"]: m for m in scene["motors"]}
        for k, j in enumerate(scene["joints"]):
            a, bb = self.bodies[j["a"]], self.bodies[j["b"]]
            at = (j["x"], j["y"])
            common = dict(body_a=a, body_b=bb, local_anchor_a=a.local_point(at), local_anchor_b=bb.local_point(at),
                          collide_connected=j["collide"])
            if j["fixed"]:
                w.create_weld_joint(reference_angle=scene["bodies"][j["b"]]["angle"] - scene["bodies"][j["a"]]["angle"],
                                    **common)
            elif k in motors:
                w.create_revolute_joint(enable_motor=True, motor_speed=motors[k]["speed"],
                                        max_motor_torque=motors[k]["maxTorque"], **common)
            else:
                w.create_revolute_joint(**common)
        self.settings = (f"metres (20 px = 1 m); timestep {self.h:g} s; {SUBSTEPS} substeps (Box2D's default); "
                         "1 worker, no thread pool; continuous on; "
                         + ("sleeping on at Box2D's tolerances (0.05 m/s = 1 px/s, 0.5 s)" if self.sleeping else "sleeping off")
                         + f"; Box2D v3.1.1 through pyb2d3 {importlib.metadata.version('pyb2d3')}")

    def tick(self):
        self.world.step(self.h, SUBSTEPS)

    def state(self):
        poses, speeds, omegas = [], [], []
        for b in self.bodies:
            p, v = b.position, b.linear_velocity
            poses += (p.x, p.y, b.angle)
            speeds.append(math.hypot(v.x, v.y))
            omegas.append(b.angular_velocity)
        asleep = sum(1 for b in self.dynamic if not b.awake) if self.sleeping else -1
        return poses, speeds, omegas, [], asleep


def main(argv=None):
    ap = peer_bench.arguments(__doc__.splitlines()[0])
    ap.add_argument("--scenes-dir", required=True, type=Path, help="the Java side's exports: DIR/SCENE_ID.json")
    args = ap.parse_args(argv)
    global b2
    import pyb2d3
    b2 = pyb2d3
    peer_bench.run("box2d-v3", args,
                   lambda s, a: World(json.loads((a.scenes_dir / (s + ".json")).read_text(encoding="utf-8"))))


if __name__ == "__main__":
    main()
