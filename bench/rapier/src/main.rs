//! Times Rapier (rapier2d, the version Cargo.toml pins) on the benchmark scenes.
//!
//! Run by `./emini bench` (org.emini.bench.run.ExternalBench), which builds it with
//! `cargo build --release --locked` on first use. The scenes come as the Java side's flat export
//! (PeerSceneExport: metres, y up, the mapping every metre-based peer gets). The method and the
//! result file are those of bench/peers/peer_bench.py (the Python peers'): a snapshot of the built
//! world, the untimed preroll and a snapshot (the check), warm-up and measurement rounds timed by the
//! thread's CPU clock, a last snapshot. The Java side judges the snapshots with the benchmark's one
//! scene check.
//!
//! Settings (bench/ENGINES.md): Rapier's defaults (4 solver iterations, its contact softness,
//! speculative contacts and its CCD against fixed bodies), one thread (no "parallel" feature),
//! sleeping off except in a scene with world.sleeping (the game level: Rapier's own tolerances).
//!
//!     emini-rapier-bench --scenes-dir DIR --out FILE [--preroll N] [--warmups 3 --iterations 5 --seconds 1] SCENE_ID...

use rapier2d::prelude::*;
use serde::Deserialize;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The rapier2d version Cargo.toml pins, for the report.
const RAPIER: &str = "0.36.1";
/// The motors' damping gain: with Rapier's (default) acceleration-based motor model one impulse removes
/// dt·F / (1 + dt·F) of the speed error, so a large F makes the motor the hard velocity constraint the
/// other peers' joint motors are (still capped by the maximum torque).
const MOTOR_GAIN: f32 = 1.0e6;

#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct Scene {
    format: String,
    version: u32,
    timestep: f32,
    ticks: u64,
    gravity: [f32; 2],
    sleeping: bool,
    shapes: Vec<Vec<Part>>,
    bodies: Vec<Body>,
    joints: Vec<Joint>,
    motors: Vec<Motor>,
    emitters: u32,
}

#[derive(Deserialize)]
struct Part {
    radius: Option<f32>,
    center: Option<[f32; 2]>,
    vertices: Option<Vec<[f32; 2]>>,
    density: f32,
    friction: f32,
    restitution: f32,
}

#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct Body {
    shape: usize,
    dynamic: bool,
    x: f32,
    y: f32,
    angle: f32,
    vx: f32,
    vy: f32,
    omega: f32,
    rotatable: bool,
    gravity: bool,
    sleeping_allowed: bool,
}

#[derive(Deserialize)]
struct Joint {
    a: usize,
    b: usize,
    x: f32,
    y: f32,
    fixed: bool,
    collide: bool,
}

#[derive(Deserialize)]
#[serde(rename_all = "camelCase")]
struct Motor {
    joint: usize,
    speed: f32,
    max_torque: f32,
}

struct Args {
    out: PathBuf,
    scenes_dir: PathBuf,
    preroll: i64,
    warmups: u32,
    iterations: u32,
    seconds: f64,
    scenes: Vec<String>,
}

fn args() -> Result<Args, String> {
    let mut a = Args {
        out: PathBuf::new(),
        scenes_dir: PathBuf::new(),
        preroll: -1,
        warmups: 3,
        iterations: 5,
        seconds: 1.0,
        scenes: Vec::new(),
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "--out" => a.out = value("--out")?.into(),
            "--scenes-dir" => a.scenes_dir = value("--scenes-dir")?.into(),
            "--preroll" => a.preroll = value("--preroll")?.parse().map_err(|e| format!("--preroll: {e}"))?,
            "--warmups" => a.warmups = value("--warmups")?.parse().map_err(|e| format!("--warmups: {e}"))?,
            "--iterations" => a.iterations = value("--iterations")?.parse().map_err(|e| format!("--iterations: {e}"))?,
            "--seconds" => a.seconds = value("--seconds")?.parse().map_err(|e| format!("--seconds: {e}"))?,
            s if s.starts_with("--") => return Err(format!("unknown option {s}")),
            s => a.scenes.push(s.to_string()),
        }
    }
    if a.out.as_os_str().is_empty() || a.scenes_dir.as_os_str().is_empty() || a.scenes.is_empty() {
        return Err("usage: emini-rapier-bench --scenes-dir DIR --out FILE [--preroll N] [--warmups N] \
                    [--iterations N] [--seconds S] SCENE_ID..."
            .into());
    }
    Ok(a)
}

/// What the driver cannot build, or why it failed: (status, message).
type Refusal = (&'static str, String);

struct World {
    w: PhysicsWorld,
    bodies: Vec<RigidBodyHandle>,
    sleeping: bool,
    ticks: u64,
    settings: String,
}

impl World {
    fn build(s: Scene) -> Result<World, Refusal> {
        if s.format != "emini-peer-scene" || s.version != 1 {
            return Err(("error", "not a version 1 emini-peer-scene file".into()));
        }
        if s.emitters > 0 {
            return Err((
                "unsupported",
                "the Rapier driver does not make particles (the Java peers' circle bodies, PeerParticles); \
                 the scene has emitters"
                    .into(),
            ));
        }
        let mut w = PhysicsWorld::new();
        w.gravity = Vector::new(s.gravity[0], s.gravity[1]);
        w.integration_parameters.dt = s.timestep;
        let mut bodies = Vec::with_capacity(s.bodies.len());
        for b in &s.bodies {
            let mut rb = if b.dynamic { RigidBodyBuilder::dynamic() } else { RigidBodyBuilder::fixed() }
                .translation(Vector::new(b.x, b.y))
                .rotation(b.angle)
                .linvel(Vector::new(b.vx, b.vy))
                .angvel(b.omega)
                .gravity_scale(if b.gravity { 1.0 } else { 0.0 })
                .can_sleep(s.sleeping && b.sleeping_allowed);
            if !b.rotatable {
                rb = rb.lock_rotations();
            }
            let h = w.insert_body(rb);
            for p in &s.shapes[b.shape] {
                let c = match (p.radius, &p.vertices) {
                    (Some(r), _) => {
                        let [cx, cy] = p.center.unwrap_or([0.0, 0.0]);
                        ColliderBuilder::ball(r).translation(Vector::new(cx, cy))
                    }
                    (None, Some(v)) => ColliderBuilder::convex_polyline(v.iter().map(|q| Vector::new(q[0], q[1])).collect())
                        .ok_or(("error", "a polygon Rapier finds degenerate".to_string()))?,
                    _ => return Err(("error", "a shape part with neither radius nor vertices".into())),
                }
                .density(p.density)
                // The export's frictions are for √(fA·fB) mixing, as Box2D's (Rapier's default is the average).
                .friction(p.friction)
                .friction_combine_rule(CoefficientCombineRule::GeometricMean)
                .restitution(p.restitution)
                .restitution_combine_rule(CoefficientCombineRule::Max);
                w.insert_collider(c, Some(h));
            }
            bodies.push(h);
        }
        for (k, j) in s.joints.iter().enumerate() {
            let (ba, bb) = (&s.bodies[j.a], &s.bodies[j.b]);
            let local = |b: &Body| {
                let (sn, c) = b.angle.sin_cos();
                let (dx, dy) = (j.x - b.x, j.y - b.y);
                Vector::new(c * dx + sn * dy, -sn * dx + c * dy)
            };
            let joint: GenericJoint = if j.fixed {
                FixedJointBuilder::new()
                    .local_frame1(Pose::from_parts(local(ba), Rotation::identity()))
                    .local_frame2(Pose::from_parts(local(bb), Rotation::new(ba.angle - bb.angle)))
                    .contacts_enabled(j.collide)
                    .into()
            } else {
                let mut r = RevoluteJointBuilder::new().local_anchor1(local(ba)).local_anchor2(local(bb)).contacts_enabled(j.collide);
                if let Some(m) = s.motors.iter().find(|m| m.joint == k) {
                    r = r.motor_velocity(m.speed, MOTOR_GAIN).motor_max_force(m.max_torque);
                }
                r.into()
            };
            w.insert_impulse_joint(bodies[j.a], bodies[j.b], joint);
        }
        let p = &w.integration_parameters;
        let settings = format!(
            "metres (20 px = 1 m); timestep {} s; Rapier's defaults: {} solver iterations, {} stabilization iteration, \
             CCD substeps {} (fast bodies against fixed ones), speculative distance {} m; 1 thread (no parallel feature), \
             no SIMD feature; {}; rapier2d {}",
            s.timestep,
            p.num_solver_iterations,
            p.num_internal_stabilization_iterations,
            p.max_ccd_substeps,
            p.normalized_prediction_distance,
            if s.sleeping { "sleeping on at Rapier's tolerances (0.05 m/s = 1 px/s, 0.5 s)" } else { "sleeping off" },
            RAPIER
        );
        Ok(World { w, bodies, sleeping: s.sleeping, ticks: s.ticks, settings })
    }

    fn tick(&mut self) {
        self.w.step();
    }

    fn snapshot(&self, ticks: u64) -> Value {
        let (mut poses, mut speeds, mut omegas) = (Vec::new(), Vec::new(), Vec::new());
        let mut asleep = 0;
        for h in &self.bodies {
            let b = &self.w.bodies[*h];
            let t = b.translation();
            poses.extend([t.x, t.y, b.rotation().angle()].map(finite));
            speeds.push(finite(b.linvel().length()));
            omegas.push(finite(b.angvel()));
            asleep += (b.is_dynamic() && b.is_sleeping()) as i64;
        }
        json!({"ticks": ticks, "poses": poses, "speeds": speeds, "omegas": omegas, "particles": [],
               "asleep": if self.sleeping { asleep } else { -1 }})
    }
}

/// JSON has no NaN: a lost body's figure is written as null (the check counts it non-finite).
fn finite(x: f32) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

/// The thread's CPU time (s), as Python's time.thread_time.
fn thread_time() -> f64 {
    let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: clock_gettime writes the timespec it is given; CLOCK_THREAD_CPUTIME_ID exists on Linux.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// n rounds of ticks, each about `seconds` long: (wall s per tick, CPU s per tick, ticks) per round.
fn rounds(world: &mut World, n: u32, seconds: f64) -> Vec<(f64, f64, u64)> {
    (0..n)
        .map(|_| {
            let (w0, c0) = (Instant::now(), thread_time());
            let mut k = 0u64;
            while w0.elapsed().as_secs_f64() < seconds {
                world.tick();
                k += 1;
            }
            (w0.elapsed().as_secs_f64() / k as f64, (thread_time() - c0) / k as f64, k)
        })
        .collect()
}

/// Preroll, check, warm-up and measurement, as peer_bench.measure.
fn measure(mut world: World, a: &Args) -> Value {
    let initial = world.snapshot(0);
    let preroll = if a.preroll >= 0 { a.preroll as u64 } else { world.ticks };
    let t0 = Instant::now();
    for _ in 0..preroll {
        world.tick();
    }
    let preroll_s = t0.elapsed().as_secs_f64();
    let mut ticks = preroll;
    let check = world.snapshot(ticks);
    ticks += rounds(&mut world, a.warmups, a.seconds).iter().map(|r| r.2).sum::<u64>();
    let measured = rounds(&mut world, a.iterations, a.seconds);
    let n: u64 = measured.iter().map(|r| r.2).sum();
    ticks += n;
    let mut wall: Vec<f64> = measured.iter().map(|r| r.0 * 1e3).collect();
    let mean = wall.iter().sum::<f64>() / wall.len() as f64;
    let sd = (wall.iter().map(|w| (w - mean).powi(2)).sum::<f64>() / (wall.len().max(2) - 1) as f64).sqrt();
    wall.sort_by(f64::total_cmp);
    json!({"status": "ok", "message": "", "units": "m", "settings": world.settings,
           "msPerTick": mean, "msPerTickError": sd, "msPerTickMedian": wall[wall.len() / 2],
           "cpuMsPerTick": measured.iter().map(|r| r.1 * r.2 as f64).sum::<f64>() / n as f64 * 1e3,
           "prerollMsPerTick": if preroll > 0 { json!(preroll_s * 1e3 / preroll as f64) } else { Value::Null },
           "initial": initial, "check": check, "afterRun": world.snapshot(ticks)})
}

fn load(dir: &Path, id: &str) -> Result<Scene, Refusal> {
    let f = dir.join(format!("{id}.json"));
    let text = std::fs::read_to_string(&f).map_err(|e| ("error", format!("cannot read {}: {e}", f.display())))?;
    serde_json::from_str(&text).map_err(|e| ("error", format!("{}: {e}", f.display())))
}

fn main() {
    let a = match args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("emini-rapier-bench: {e}");
            std::process::exit(2);
        }
    };
    if a.iterations == 0 {
        eprintln!("emini-rapier-bench: --iterations must be at least 1");
        std::process::exit(2);
    }
    let mut out = Vec::new();
    for id in &a.scenes {
        let mut entry = match load(&a.scenes_dir, id).and_then(World::build) {
            Ok(world) => measure(world, &a),
            Err((status, message)) => json!({"status": status, "message": message}),
        };
        entry["scene"] = json!(id);
        entry["engine"] = json!("rapier");
        let figure = |k: &str| entry.get(k).and_then(Value::as_f64).unwrap_or(f64::NAN);
        let status = entry["status"].as_str().unwrap_or("").to_string();
        let what = if status == "ok" { "timed".to_string() } else { format!("{status}: {}", entry["message"].as_str().unwrap_or("")) };
        println!("{id:28} {:10} {:9.3} ms/tick cpu  {:9.3} wall  {what}", "rapier", figure("cpuMsPerTick"), figure("msPerTick"));
        out.push(entry);
    }
    let text = serde_json::to_string_pretty(&out).expect("the result is plain JSON");
    if let Err(e) = std::fs::write(&a.out, text) {
        eprintln!("emini-rapier-bench: cannot write {}: {e}", a.out.display());
        std::process::exit(1);
    }
}
