package org.emini.bench.engine;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.scenario.Scenario;
import org.emini.particle.ParticleEmitter;

/**
 * Emini, built by the harness's own {@link WorldBuilder}: the very world {@code ./emini run} judges.
 * Scene units are Emini's units (px), so nothing is scaled.
 */
final class EminiEngine implements BenchEngine {
    private final int workers;
    private World world;
    private Body[] bodies;

    /** Emini solving on the benchmark's thread alone ({@code emini}), or sharing its contact passes ({@code emini-2t}). */
    EminiEngine(int workers) {
        this.workers = workers;
    }

    @Override
    public String id() {
        return workers == 1 ? "emini" : "emini-" + workers + "t";
    }

    @Override
    public void build(Scenario scenario) throws UnsupportedSceneException {
        BuiltWorld built;
        try {
            built = WorldBuilder.build(scenario);
        } catch (UnsupportedElementException e) {
            throw new UnsupportedSceneException(e.getMessage());
        }
        world = built.world();
        world.setWorkerCount(workers);
        bodies = built.bodies().values().toArray(new Body[0]);
    }

    @Override
    public void tick() {
        world.tick();
    }

    @Override
    public int bodyCount() {
        return bodies.length;
    }

    @Override
    public void poses(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            out[3 * i] = bodies[i].getX();
            out[3 * i + 1] = bodies[i].getY();
            out[3 * i + 2] = bodies[i].getAngle();
        }
    }

    @Override
    public void speeds(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            out[i] = Math.hypot(bodies[i].getVelocityX(), bodies[i].getVelocityY());
        }
    }

    @Override
    public void angularVelocities(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            out[i] = bodies[i].getAngularVelocity();
        }
    }

    @Override
    public int sleepingCount() {
        if (!world.isSleepingEnabled()) {
            return -1;
        }
        int n = 0;
        for (Body b : bodies) {
            n += b.isSleeping() ? 1 : 0;
        }
        return n;
    }

    @Override
    public int particleCount() {
        int n = 0;
        for (int k = 0; k < world.getParticleEmitterCount(); k++) {
            n += world.getParticleEmitter(k).getParticleCount();
        }
        return n;
    }

    @Override
    public void particlePositions(double[] out) {
        int i = 0;
        for (int k = 0; k < world.getParticleEmitterCount(); k++) {
            ParticleEmitter e = world.getParticleEmitter(k);
            for (int j = 0; j < e.getParticleCount(); j++, i++) {
                out[2 * i] = e.getX(j);
                out[2 * i + 1] = e.getY(j);
            }
        }
    }

    @Override
    public String settings() {
        return (workers == 1 ? "" : workers + " threads share the contact passes (World.setWorkerCount); ") + "px units; timestep " + world.getTimestep() + " s; " + world.getConstraintIterations()
            + " substeps (each one soft solve + one relax pass); default SolverSettings; "
            + (world.isSleepingEnabled() ? String.format(java.util.Locale.ROOT, "sleeping on (%.1f px/s = %.2f m/s, "
                + "%.1f deg/s, %.1f s)", world.getSolverSettings().getSleepLinearTolerance(),
                world.getSolverSettings().getSleepLinearTolerance() / PeerScene.PX_PER_M,
                Math.toDegrees(world.getSolverSettings().getSleepAngularTolerance()),
                world.getSolverSettings().getTimeToSleep()) : "sleeping off")
            + (world.getParticleEmitterCount() > 0 ? "; particles: Emini's particle system (points, exact parabolas, "
                + "swept against the bodies; never touch each other)" : "");
    }

    @Override
    public void close() {
        if (world != null) {
            world.setWorkerCount(1);
        }
        world = null;
        bodies = null;
    }
}
