"""What the benchmark's Python peers share: the command line, the timing method and the result file.

Used by bench/pymunk/pymunk_bench.py and bench/box2d/box2d_bench.py; bench/rapier/src/main.rs follows
the same method and writes the same file. Run by ./emini bench (org.emini.bench.run.ExternalBench),
which judges the snapshots with the benchmark's one scene check (bench/src/main/java/org/emini/bench/check/
Stability.java), so no peer carries a copy of it.

The method copies the JMH benchmark's (TickBenchmark): build the world, snapshot it, run the untimed
preroll (the scene's run duration unless --preroll is given), snapshot it (the check), then time ticks
in warm-up and measurement rounds of --seconds each; the figure is the thread's CPU time per measured
tick (time.thread_time), wall time beside it; a last snapshot after the timed ticks.

A driver gives run() a function that builds one scene as a world: an object with
  tick()                one timestep
  state()               (poses [x, y, angle per body], speeds [per body], angular velocities [per body],
                        particle positions [x, y per live particle], bodies asleep or -1), in the
                        driver's units and scene order
  ticks                 the scene's run duration in ticks (the default preroll)
  units                 "px" (the scene's: y down, clockwise) or "m" (the metre-based peers' frame,
                        converted back by the Java side)
  settings              the engine's settings as used, for the report
and raises Unsupported for what it cannot build.
"""

from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path


class Unsupported(Exception):
    """The scene uses something the driver (or its engine) cannot build; the message says what."""


def arguments(description: str) -> argparse.ArgumentParser:
    """The options every driver takes; a driver adds its own (where its scenes come from)."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", required=True, type=Path, help="result file (JSON)")
    ap.add_argument("--preroll", type=int, default=-1, help="untimed ticks before timing; -1: the scene's run duration")
    ap.add_argument("--warmups", type=int, default=3)
    ap.add_argument("--iterations", type=int, default=5)
    ap.add_argument("--seconds", type=float, default=1.0, help="length of one warm-up or measurement round")
    ap.add_argument("scenes", nargs="+", help="scene ids (bench/pyramid-20)")
    return ap


def snapshot(world, ticks: int) -> dict:
    poses, speeds, omegas, particles, asleep = world.state()
    return {"ticks": ticks, "poses": _finite(poses), "speeds": _finite(speeds), "omegas": _finite(omegas),
            "particles": _finite(particles), "asleep": asleep}


def _finite(xs):
    # JSON has no NaN or infinity: a lost body's pose is written as null (the check counts it non-finite).
    return [x if math.isfinite(x) else None for x in xs]


def rounds(tick, n: int, seconds: float) -> list[tuple[float, float, int]]:
    """n rounds of ticks, each about `seconds` long: (wall s per tick, CPU s per tick, ticks) per round."""
    out = []
    for _ in range(n):
        w0, c0, k = time.perf_counter(), time.thread_time(), 0
        while time.perf_counter() - w0 < seconds:
            tick()
            k += 1
        out.append(((time.perf_counter() - w0) / k, (time.thread_time() - c0) / k, k))
    return out


def measure(world, args) -> dict:
    """Preroll, check, warm-up and measurement of one built world: the figures and the three snapshots."""
    initial = snapshot(world, 0)
    preroll = args.preroll if args.preroll >= 0 else world.ticks
    t0 = time.perf_counter()
    for _ in range(preroll):
        world.tick()
    t1 = time.perf_counter()
    ticks = preroll
    check = snapshot(world, ticks)
    ticks += sum(r[2] for r in rounds(world.tick, args.warmups, args.seconds))
    measured = rounds(world.tick, args.iterations, args.seconds)
    ticks += sum(r[2] for r in measured)
    wall = [r[0] * 1e3 for r in measured]
    mean = sum(wall) / len(wall)
    return {"status": "ok", "message": "", "units": world.units, "settings": world.settings,
            "msPerTick": mean,
            "msPerTickError": math.sqrt(sum((w - mean) ** 2 for w in wall) / max(1, len(wall) - 1)),
            "msPerTickMedian": sorted(wall)[len(wall) // 2],
            "cpuMsPerTick": sum(r[1] * r[2] for r in measured) / sum(r[2] for r in measured) * 1e3,
            "prerollMsPerTick": (t1 - t0) * 1e3 / preroll if preroll else None,
            "initial": initial, "check": check, "afterRun": snapshot(world, ticks)}


def run(engine: str, args, build) -> list[dict]:
    """Times every scene of args.scenes built by build(scene_id, args) and writes the result file."""
    out = []
    for s in args.scenes:
        entry = {"scene": s, "engine": engine}
        try:
            entry.update(measure(build(s, args), args))
        except Unsupported as e:
            entry.update(status="unsupported", message=str(e))
        except Exception as e:  # reported in the report, never hidden
            entry.update(status="error", message=f"{type(e).__name__}: {e}")
        verdict = "timed" if entry["status"] == "ok" else entry["status"] + ": " + entry["message"]
        print(f"{s:28s} {engine:10s} {entry.get('cpuMsPerTick', math.nan):9.3f} ms/tick cpu  "
              f"{entry.get('msPerTick', math.nan):9.3f} wall  {verdict}", flush=True)
        out.append(entry)
    args.out.write_text(json.dumps(out, indent=1))
    return out
