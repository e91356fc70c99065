package org.emini.harness.run;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.scenario.ActionSpec;

/**
 * Applies the scene's actions before each tick. An action at time t acts before tick k = ⌈t/h⌉ (the
 * first tick that starts at or after t); a force or torque acts before each of the
 * max(1, round(duration/h)) ticks from there (the engine clears forces after every tick). An emit action
 * is a burst: the emitter's {@code emit(count)}, on top of its rate.
 */
public final class Schedule {
    private final List<ActionSpec> actions;
    private final BuiltWorld built;
    private final double h;

    /**
     * @param built the world the actions act on
     * @param actions the scene's actions
     * @param timestep seconds per tick
     */
    public Schedule(BuiltWorld built, List<ActionSpec> actions, double timestep) {
        this.built = built;
        this.actions = actions;
        this.h = timestep;
    }

    static long startTick(double at, double h) {
        return (long) Math.ceil(at / h - 1e-9);
    }

    static long tickCount(double duration, double h) {
        return Double.isNaN(duration) ? 1 : Math.max(1, Math.round(duration / h));
    }

    /** Applies what is due before tick {@code k} (0-based). */
    public void beforeTick(long k) {
        for (ActionSpec a : actions) {
            long start = startTick(a.at(), h);
            boolean lasting = a.kind() == ActionSpec.Kind.force || a.kind() == ActionSpec.Kind.torque;
            long end = lasting ? start + tickCount(a.duration(), h) : start + 1;
            if (k >= start && k < end) {
                apply(a);
            }
        }
    }

    private void apply(ActionSpec a) {
        World world = built.world();
        Body b = a.body() != null ? built.body(a.body()) : null;
        float vx = a.vector() != null ? (float) a.vector()[0] : 0f;
        float vy = a.vector() != null ? (float) a.vector()[1] : 0f;
        switch (a.kind()) {
            case impulse:
                if (a.point() != null) {
                    b.applyImpulseAt(vx, vy, (float) a.point()[0], (float) a.point()[1]);
                } else {
                    b.applyImpulse(vx, vy);
                }
                break;
            case angularImpulse:
                b.applyAngularImpulse((float) a.value());
                break;
            case force:
                if (a.point() != null) {
                    b.applyForceAt(vx, vy, (float) a.point()[0], (float) a.point()[1]);
                } else {
                    b.applyForce(vx, vy);
                }
                break;
            case torque:
                b.applyTorque((float) a.value());
                break;
            case emit:
                built.emitters().get(a.emitter()).emit((int) a.value());
                break;
            case velocity:
                if (a.vector() != null) {
                    b.setVelocity(vx, vy);
                }
                if (!Double.isNaN(a.value())) {
                    b.setAngularVelocity((float) a.value());
                }
                break;
            default:
                world.setGravity(vx, vy);
                break;
        }
    }
}
