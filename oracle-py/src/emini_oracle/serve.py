"""Runs scene variants for the harness's sweeps and stability maps in one long-lived process.

    emini-oracle serve [--schema FILE]

The harness (`sweep`, `stability`: sweep/OracleBackend.java) starts one such process per command and
sends it every variant, so Python's and pymunk's start-up are paid once, not per point. The protocol
is JSON lines. The process first prints

    {"ready": true, "protocol": 1, "pymunk": "7.3.1", "chipmunk": "7.0.3"}

then, for each request line read from stdin,

    {"id": 7, "scene": "closed-form/projectile-60hz", "text": "<the variant: scene text, YAML or JSON>",
     "repeats": 3}

it prints one response line

    {"id": 7, "scene": "...", "status": "ok" | "unsupported" | "error", "message": "...",
     "unsupported": [...], "approximations": [...], "stepSeconds": 0.0123, "stepCpuSeconds": 0.012,
     "loopSeconds": 0.05, "runsPerRepeat": 2, "simulatedSeconds": 4.0, "repeats": 3,
     "trace": {trace format v1, source "pymunk"} or null}

and it exits when stdin ends. The same works by hand: `emini-oracle serve < requests.jsonl`.

Timing (the same definition as the engine side of a sweep, harness/README.md): the variant runs
once with its metrics, which gives the trace (runs are deterministic) and serves as the warm-up;
then `repeats` times (0: the trace only) with nothing but its ticks (`run.time_steps`: actions,
`space.step(h)` and the damping that completes Emini's tick, timed as one block, no metrics or
samples, the garbage collector paused). A repeat of a short scene runs it n times (n doubling until
the repeat lasts 20 ms, as timeit's autorange) and divides by n. `stepSeconds` is the best repeat's
wall time (the cost of the point is stepSeconds per simulated second), `stepCpuSeconds` the best
repeat's CPU time of the thread (not inflated when other processes share the machine). `loopSeconds` is the trace run's tick loop
with the oracle's metrics (they are Python, so it is several times slower: reported, not used as the
cost).

Status: `unsupported` when pymunk cannot run the scene at all, when the scene says the oracle must
skip it, or when an element pymunk leaves out would change the bodies' motion (MAPPING.md); the
message names the element and the reason. `error` for an invalid variant or a failure of pymunk.
"""

from __future__ import annotations

import json
import math
import sys
import time

import pymunk

from .build import UnsupportedScene
from .run import run_scene, time_steps
from .scene import SceneError

PROTOCOL = 1
# A timed repeat lasts at least this long (s): a short scene is run several times per repeat and its
# time divided by the count, as timeit's autorange does; the engine side uses the same figure.
MIN_REPEAT_SECONDS = 0.02
MAX_RUNS_PER_REPEAT = 1024


def best_time(scene, repeats, time_steps=time_steps):
    """Best time of the scene's ticks over `repeats` repeats, each of as many runs n as make it last
    MIN_REPEAT_SECONDS of wall time (n doubles from 1; the runs that find n are warm-up, the last of
    them is the first repeat), divided by n. Returns (wall seconds per run, CPU seconds per run, n);
    (inf, inf, 0) without repeats."""
    if repeats <= 0:
        return math.inf, math.inf, 0

    def repeat(n):
        wall = cpu = 0.0
        for _ in range(n):
            w, c = time_steps(scene)
            wall += w
            cpu += c
        return wall, cpu

    n = 1
    while True:
        wall, cpu = repeat(n)
        if wall >= MIN_REPEAT_SECONDS or n >= MAX_RUNS_PER_REPEAT:
            break
        n *= 2
    best_wall, best_cpu = wall / n, cpu / n
    for _ in range(repeats - 1):
        wall, cpu = repeat(n)
        best_wall, best_cpu = min(best_wall, wall / n), min(best_cpu, cpu / n)
    return best_wall, best_cpu, n


def run_variant(loader, request, engine="pymunk"):
    """Runs one request (a dict as above) in pymunk or Box2D; returns the response dict. Never raises for
    a scene problem."""
    from .run import engine_functions
    run_scene, time_steps = engine_functions(engine)
    scene_id = str(request.get("scene") or "variant")
    repeats = max(0, int(request.get("repeats", 1)))
    out = {"id": request.get("id"), "scene": scene_id, "status": "ok", "message": "", "unsupported": [],
           "approximations": [], "stepSeconds": None, "loopSeconds": None, "simulatedSeconds": None,
           "repeats": repeats, "trace": None}
    try:
        scene = loader.load_text(f"{scene_id} (sweep variant)", request["text"], scene_id)
    except SceneError as e:
        out.update(status="error", message=f"invalid variant: {e}")
        return out
    except KeyError:
        out.update(status="error", message="the request has no scene text")
        return out
    out["simulatedSeconds"] = scene.ticks * scene.world.timestep
    skip = (scene.oracle or {}).get("skip")
    if skip:
        out.update(status="unsupported", message=f"the scene says the oracle cannot run it: {skip}")
        return out
    try:
        timing = {}
        doc, _built = run_scene(scene, timing=timing)
        moving = [n for n in doc["unsupported"] if n["affectsBodies"]]
        best_steps, best_cpu, runs = best_time(scene, repeats, time_steps) if not moving else (math.inf, math.inf, 0)
    except UnsupportedScene as e:
        out.update(status="unsupported", message=str(e))
        return out
    except Exception as e:  # a failure of the oracle or of pymunk: reported, not hidden
        out.update(status="error", message=f"{type(e).__name__}: {e}")
        return out
    out["unsupported"] = doc["unsupported"]
    out["approximations"] = doc["approximations"]
    if moving:
        out.update(status="unsupported", message=f"{engine} cannot express " + "; ".join(
            f"{n['element']} ({n['path']}): {n['reason']}" for n in moving))
        return out
    out["stepSeconds"] = best_steps if math.isfinite(best_steps) else None
    out["stepCpuSeconds"] = best_cpu if math.isfinite(best_cpu) else None
    out["loopSeconds"] = timing["loop"]
    out["runsPerRepeat"] = runs
    out["trace"] = doc
    return out


def serve(loader, stdin=None, stdout=None, engine="pymunk"):
    """Answers requests until stdin ends. Anything else printed while running goes to stderr, so the
    protocol stream carries only responses."""
    stdin = stdin or sys.stdin
    stdout = stdout or sys.stdout
    real_stdout, sys.stdout = sys.stdout, sys.stderr
    try:
        ready = {"ready": True, "protocol": PROTOCOL, "engine": engine, "pymunk": pymunk.version,
                 "chipmunk": pymunk.chipmunk_version}
        if engine == "box2d":
            from .box2d import versions
            ready.update(versions())
        _send(stdout, ready)
        for line in stdin:
            if not line.strip():
                continue
            try:
                request = json.loads(line)
            except ValueError as e:
                _send(stdout, {"id": None, "status": "error", "message": f"not a JSON request: {e}"})
                continue
            t0 = time.perf_counter()
            response = run_variant(loader, request, engine)
            response["seconds"] = round(time.perf_counter() - t0, 4)
            _send(stdout, response)
    finally:
        sys.stdout = real_stdout
    return 0


def _send(stdout, doc):
    stdout.write(json.dumps(doc, allow_nan=False, separators=(",", ":")))
    stdout.write("\n")
    stdout.flush()
