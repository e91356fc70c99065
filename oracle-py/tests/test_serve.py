"""The oracle's side of the harness's sweeps and stability maps (`emini-oracle serve`, serve.py).

The harness sends scene variants (timestep and iterations replaced) as JSON lines to one long-lived
process; each answer carries the trace and the best wall time of the ticks alone.
"""

import json
import subprocess
import sys

import pytest

from conftest import SCENARIOS, SCHEMA
from emini_oracle.run import time_steps
from emini_oracle.serve import run_variant

PROJECTILE = (SCENARIOS / "closed-form" / "projectile-60hz.yaml").read_text()


def variant(text, rate, iterations=10):
    """The projectile scene at another rate and iteration count (as the harness's SceneVariant does)."""
    return text.replace("world: {ticksPerSecond: 60}", f"world: {{ticksPerSecond: {rate}, iterations: {iterations}}}")


def parabola_error(trace):
    """Largest distance of the ball from x = 100 t, y = -200 t + 50 t^2 over the run (px)."""
    b = trace["bodies"]["ball"]
    return max(((x - 100 * t) ** 2 + (y - (-200 * t + 50 * t * t)) ** 2) ** 0.5
               for t, x, y in zip(trace["time"], b["x"], b["y"]))


def test_pymunks_projectile_error_halves_with_the_timestep(loader):
    # Chipmunk moves a body with its old velocity, then adds g h: the height lags the parabola by
    # g h t / 2, so the error is first order in h. Measured order: exactly 1 (200 h px at t = 4 s).
    errors = []
    for rate in (15, 30, 60, 120):
        r = run_variant(loader, {"id": rate, "scene": "closed-form/projectile-60hz",
                                 "text": variant(PROJECTILE, rate), "repeats": 1})
        assert r["status"] == "ok", r["message"]
        assert r["trace"]["timestep"] == pytest.approx(1 / rate)
        errors.append(parabola_error(r["trace"]))
        assert errors[-1] == pytest.approx(200 / rate, rel=1e-9)
    for coarse, fine in zip(errors, errors[1:]):
        assert coarse / fine == pytest.approx(2, rel=1e-9)


def test_iterations_map_to_space_iterations_and_the_timestep_to_the_step(loader):
    r = run_variant(loader, {"id": 1, "scene": "p", "text": variant(PROJECTILE, 30, 3), "repeats": 0})
    settings = r["trace"]["oracle"]["settings"]
    assert settings["iterations"] == 3
    assert settings["timestep"] == pytest.approx(1 / 30)
    assert r["trace"]["tick"][-1] == 120  # 4 s at 30 ticks/s: one space.step(h) per tick


def test_the_cost_is_the_ticks_alone_best_of_the_repeats(loader):
    r = run_variant(loader, {"id": 1, "scene": "p", "text": variant(PROJECTILE, 60), "repeats": 3})
    assert r["repeats"] == 3
    assert r["simulatedSeconds"] == pytest.approx(4.0)
    assert 0 < r["stepSeconds"] < r["loopSeconds"], "the metrics (Python) are not part of the cost"
    none = run_variant(loader, {"id": 2, "scene": "p", "text": variant(PROJECTILE, 60), "repeats": 0})
    assert none["stepSeconds"] is None and none["trace"] is not None
    wall, cpu = time_steps(loader.load_text("p.yaml", PROJECTILE, "p"))
    assert wall > 0 and cpu >= 0
    assert 0 < r["stepCpuSeconds"] < 10 * r["stepSeconds"]


def test_unsupported_and_invalid_variants_say_why(loader):
    motor = """
world: {gravity: [0, 0]}
bodies:
  - {name: cart, shape: {type: rectangle, width: 10, height: 10}}
motors: [{body: cart, velocity: [10, 0], maxImpulse: 100}]
run: {duration: 1}
"""
    r = run_variant(loader, {"id": 1, "scene": "m", "text": motor, "repeats": 1})
    assert r["status"] == "unsupported"
    assert "linear motor" in r["message"] and r["trace"] is None
    bad = run_variant(loader, {"id": 2, "scene": "b", "text": "run: {duration: -1}", "repeats": 1})
    assert bad["status"] == "error" and "invalid variant" in bad["message"] and "duration" in bad["message"]
    skip = run_variant(loader, {"id": 3, "scene": "s", "repeats": 1, "text":
                                "reference: {oracle: {skip: no such element}}\n"
                                "bodies: [{shape: {type: circle, radius: 1}}]\nrun: {duration: 1}\n"})
    assert skip["status"] == "unsupported" and "no such element" in skip["message"]


def test_particles_are_left_out_without_making_the_point_unsupported(loader):
    scene = """
bodies: [{name: ball, shape: {type: circle, radius: 5}}]
particles: [{from: [0, 0], rate: 10, lifetime: 1}]
run: {duration: 0.5}
"""
    r = run_variant(loader, {"id": 1, "scene": "p", "text": scene, "repeats": 1})
    assert r["status"] == "ok", r["message"]
    assert [n["element"] for n in r["unsupported"]] == ["particles"]


def test_serve_answers_each_request_line_with_one_response_line():
    requests = [{"id": 7, "scene": "closed-form/projectile-60hz", "text": variant(PROJECTILE, 15), "repeats": 1},
                {"id": "x", "scene": "bad", "text": "run: {duration: -1}"}]
    stdin = "\n".join(json.dumps(r) for r in requests) + "\nnot json\n"
    out = subprocess.run([sys.executable, "-m", "emini_oracle", "serve", "--schema", str(SCHEMA)],
                         input=stdin, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    lines = [json.loads(line) for line in out.stdout.splitlines()]
    assert lines[0]["ready"] is True and lines[0]["pymunk"] == "7.3.1" and lines[0]["protocol"] == 1
    assert [r["id"] for r in lines[1:]] == [7, "x", None]
    assert lines[1]["status"] == "ok" and lines[1]["trace"]["source"] == "pymunk"
    assert lines[1]["trace"]["format"] == "emini-trace" and lines[1]["trace"]["version"] == 1
    assert lines[2]["status"] == "error" and lines[3]["status"] == "error"
