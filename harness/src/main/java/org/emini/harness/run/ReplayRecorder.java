package org.emini.harness.run;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.emini.constraint.MouseJoint;
import org.emini.constraint.Spring;
import org.emini.constraint.TwoBodyConstraint;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Landscape;
import org.emini.harness.build.BuiltWorld;
import org.emini.particle.ParticleEmitter;
import org.emini.world.World;

/**
 * What the dashboard's replay draws, recorded whatever the scene's {@code record} says: every body's pose
 * (and whether it sleeps), each joint's and spring's two anchors, the live particles and the landscape,
 * at most {@link #MAX_FRAMES} frames spread evenly over the run. Scenes of more than {@link #MAX_BODIES}
 * bodies get none (their replay would be megabytes). Written beside the trace as
 * {@code SCENE.replay.json} (harness/README.md, dashboard).
 */
public final class ReplayRecorder {
    /** Frames kept. */
    public static final int MAX_FRAMES = 300;
    /** Scenes with more bodies than this get no replay. */
    public static final int MAX_BODIES = 400;
    /** Particles kept per frame (the first ones of each emitter). */
    static final int MAX_PARTICLES = 2000;

    private final World world;
    private final String[] names;
    private final Body[] bodies;
    private final long every;
    private final long ticks;
    private final JsonArray time = new JsonArray();
    private final List<JsonArray[]> poses = new ArrayList<>();
    private final List<JsonArray> anchors = new ArrayList<>();
    private final JsonArray particles = new JsonArray();

    private ReplayRecorder(BuiltWorld built, long ticks) {
        this.world = built.world();
        Map<String, Body> all = built.bodies();
        this.names = all.keySet().toArray(new String[0]);
        this.bodies = all.values().toArray(new Body[0]);
        this.ticks = ticks;
        this.every = Math.max(1, (ticks + MAX_FRAMES - 2) / (MAX_FRAMES - 1));
        for (int i = 0; i < bodies.length; i++) {
            poses.add(new JsonArray[] {new JsonArray(), new JsonArray(), new JsonArray(), new JsonArray()});
        }
    }

    /** A recorder for a built world that runs {@code ticks} ticks, or null when it has too many bodies. */
    public static ReplayRecorder of(BuiltWorld built, long ticks) {
        return built.bodies().size() > MAX_BODIES ? null : new ReplayRecorder(built, ticks);
    }

    /** Records the world after {@code tick} ticks when that tick is a frame (the first and the last always are). */
    public void after(long tick) {
        if (tick % every != 0 && tick != ticks) {
            return;
        }
        time.add(round(tick * (double) world.getTimestep(), 1e6));
        for (int i = 0; i < bodies.length; i++) {
            Body b = bodies[i];
            JsonArray[] p = poses.get(i);
            p[0].add(round(b.getX(), 100));
            p[1].add(round(b.getY(), 100));
            p[2].add(round(b.getAngle(), 1e4));
            p[3].add(b.isSleeping() ? 1 : 0);
        }
        JsonArray frame = new JsonArray();
        for (int i = 0; i < world.getConstraintCount(); i++) {
            float[] a = anchors(world.getConstraint(i));
            if (a != null) {
                for (float v : a) {
                    frame.add(round(v, 100));
                }
            }
        }
        anchors.add(frame);
        JsonArray dots = new JsonArray();
        int left = MAX_PARTICLES;
        for (int e = 0; e < world.getParticleEmitterCount() && left > 0; e++) {
            ParticleEmitter em = world.getParticleEmitter(e);
            int n = Math.min(left, em.getParticleCount());
            for (int k = 0; k < n; k++) {
                dots.add(round(em.getX(k), 10));
                dots.add(round(em.getY(k), 10));
            }
            left -= n;
        }
        particles.add(dots);
    }

    /** The recorded frames as the dashboard reads them. */
    public JsonObject json() {
        JsonObject out = new JsonObject();
        out.addProperty("format", "emini-replay");
        out.addProperty("version", 1);
        out.addProperty("source", "emini");
        out.add("time", time);
        JsonObject bs = new JsonObject();
        for (int i = 0; i < bodies.length; i++) {
            JsonObject c = new JsonObject();
            JsonArray[] p = poses.get(i);
            c.add("x", p[0]);
            c.add("y", p[1]);
            c.add("a", p[2]);
            if (world.isSleepingEnabled()) {
                c.add("s", p[3]);
            }
            bs.add(names[i], c);
        }
        out.add("bodies", bs);
        if (world.isSleepingEnabled()) {
            out.addProperty("sleeping", true);
        }
        JsonArray kinds = new JsonArray();
        for (int i = 0; i < world.getConstraintCount(); i++) {
            Constraint c = world.getConstraint(i);
            if (anchors(c) != null) {
                kinds.add(c instanceof Spring ? "spring" : c instanceof MouseJoint ? "mouse" : "joint");
            }
        }
        out.add("constraints", kinds);
        out.add("anchors", anchorsArray());
        out.add("particles", particles);
        JsonArray segs = new JsonArray();
        Landscape l = world.getLandscape();
        for (int i = 0; i < l.getSegmentCount(); i++) {
            JsonArray s = new JsonArray();
            s.add(l.getStartX(i));
            s.add(l.getStartY(i));
            s.add(l.getEndX(i));
            s.add(l.getEndY(i));
            segs.add(s);
        }
        out.add("landscape", segs);
        return out;
    }

    private JsonArray anchorsArray() {
        JsonArray out = new JsonArray();
        anchors.forEach(out::add);
        return out;
    }

    /** A constraint's two world points (A's anchor, B's anchor or the target), or null for one without (a motor). */
    private static float[] anchors(Constraint c) {
        if (c instanceof TwoBodyConstraint t) {
            return new float[] {t.getAnchorAX(), t.getAnchorAY(), t.getAnchorBX(), t.getAnchorBY()};
        }
        if (c instanceof MouseJoint m) {
            return new float[] {m.getAnchorX(), m.getAnchorY(), m.getTargetX(), m.getTargetY()};
        }
        return null;
    }

    /** Rounded to 1/scale; null (JSON's null) for a non-finite value, which the replay skips. */
    private static Double round(double v, double scale) {
        return Double.isFinite(v) ? Math.round(v * scale) / scale : null;
    }
}
