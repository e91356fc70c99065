package org.emini.harness.fuzz.world;

import java.util.function.Consumer;
import org.emini.dynamics.Landscape;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.particle.ParticleEmitter;

/**
 * Idle features change nothing, bit for bit, each added alone to the built world: a listener (on a
 * world without one; if the world has events they now fire, which must not move anything), an
 * emitter at rate 0, an empty landscape (on a world without segments) or a segment 10⁶ px away (on a
 * world with some), and an event whose condition never holds.
 */
final class IdleFeaturesRelation implements Relation {
    private static final PhysicsEventListener QUIET = (event, parameter) -> { };

    @Override
    public ViolationKind kind() {
        return ViolationKind.IDLE_FEATURES;
    }

    @Override
    public Profile profile() {
        return Profile.GENERAL;
    }

    @Override
    public Violation check(Recipe r) {
        Trajectory base = Trajectory.run(r, r.ticks);
        String[] names = {"a listener", "an emitter at rate 0", r.segments.isEmpty() ? "an empty landscape" : "a segment 1e6 px away",
            "an event that never holds"};
        @SuppressWarnings("unchecked")
        Consumer<FuzzWorld>[] changes = new Consumer[] {
            (Consumer<FuzzWorld>) w -> {
                if (w.world().getPhysicsEventListener() == null) {
                    w.world().setPhysicsEventListener(QUIET);
                }
            },
            (Consumer<FuzzWorld>) w -> {
                ParticleEmitter idle = new ParticleEmitter(50);
                idle.setCreationRate(0f, 0f);
                w.world().addParticleEmitter(idle);
            },
            (Consumer<FuzzWorld>) w -> {
                if (w.world().getLandscape().getSegmentCount() == 0) {
                    w.world().setLandscape(new Landscape());
                } else {
                    w.world().getLandscape().addSegment(1e6f, 1e6f, 1e6f + 100f, 1e6f);
                }
            },
            (Consumer<FuzzWorld>) w -> w.world().addEvent(Event.createPositionEvent(null, null, 1e6f, 1e6f, 1e6f + 1f, 1e6f + 1f)),
        };
        for (int i = 0; i < changes.length; i++) {
            String d = base.firstDifference(Trajectory.run(r, r.ticks, changes[i]), r.ticks);
            if (d != null) {
                return new Violation(kind(), -1, "with " + names[i] + ": " + d);
            }
        }
        return null;
    }
}
