package org.emini.designer;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.emini.constraint.MouseJoint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.harness.metrics.DynamicBodies;
import org.emini.io.BuildResult;
import org.emini.io.PhyWorld;
import org.emini.io.UnsupportedElement;
import org.emini.io.WorldBuilder;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * A document played: the engine's world built from the world file by the engine's own
 * {@link WorldBuilder} (as an application loading the file would), with the page's timestep and
 * iteration count (a world file stores neither). The same class runs in the page (compiled by
 * TeaVM) and on the JVM (the parity check), so both build the same world the same way.
 */
final class Play {
    /** The drag joint's largest force per unit of the dragged body's mass (px/s²). */
    private static final float DRAG_ACCELERATION = 5000f;

    private final BuildResult result;
    private final World world;
    private final Map<Body, Integer> docIndex = new IdentityHashMap<>();
    private MouseJoint drag;
    private float[] frame = new float[0];
    private int eventsFired;
    private int lastEvent = -1;

    /**
     * Builds a document.
     *
     * @param doc the world file
     * @param ticksPerSecond ticks per second, &gt; 0
     * @param iterations constraint iterations, &gt; 0
     * @throws IllegalArgumentException if the engine refuses the settings
     */
    Play(PhyWorld doc, int ticksPerSecond, int iterations) {
        result = new WorldBuilder().build(doc);
        world = result.getWorld();
        world.setTicksPerSecond(ticksPerSecond);
        world.setConstraintIterations(iterations);
        // The document's events are counted as they fire (the page shows them beside the metrics).
        world.setPhysicsEventListener((event, parameter) -> {
            eventsFired++;
            for (int e = 0; e < doc.getEvents().size(); e++) {
                if (result.getEvent(e) == event) {
                    lastEvent = e;
                }
            }
        });
        for (int i = 0; i < doc.getBodies().size(); i++) {
            Body b = result.getBody(i);
            if (b != null) {
                docIndex.put(b, i);
            }
        }
    }

    World world() {
        return world;
    }

    /** Runs ticks. @param n how many */
    void tick(int n) {
        for (int i = 0; i < n; i++) {
            world.tick();
        }
    }

    /**
     * The bodies' shapes in their own frames, in the world's body order, with what the engine did not
     * build or built differently, as JSON for the page.
     */
    String geometry() {
        StringBuilder sb = new StringBuilder(1024);
        sb.append("{\"bodies\":[");
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (i > 0) {
                sb.append(',');
            }
            Integer doc = docIndex.get(b);
            sb.append("{\"doc\":").append(doc == null ? -1 : doc).append(",\"dynamic\":").append(b.isDynamic())
                    .append(",\"sensor\":").append(b.isSensor()).append(",\"parts\":[");
            shape(sb, b.getShape());
            sb.append("]}");
        }
        sb.append("],\"unsupported\":");
        list(sb, result.getUnsupported());
        sb.append(",\"approximations\":");
        list(sb, result.getApproximations());
        sb.append('}');
        return sb.toString();
    }

    private static void shape(StringBuilder sb, Shape s) {
        if (s instanceof MultiShape) {
            MultiShape m = (MultiShape) s;
            for (int i = 0; i < m.getShapeCount(); i++) {
                if (i > 0) {
                    sb.append(',');
                }
                shape(sb, m.getShape(i));
            }
        } else if (s instanceof Circle) {
            Circle c = (Circle) s;
            sb.append("{\"circle\":[").append(c.getCenterX()).append(',').append(c.getCenterY()).append(',')
                    .append(c.getRadius()).append("]}");
        } else {
            Polygon p = (Polygon) s;
            sb.append("{\"polygon\":[");
            for (int i = 0; i < p.getVertexCount(); i++) {
                if (i > 0) {
                    sb.append(',');
                }
                sb.append(p.getVertexX(i)).append(',').append(p.getVertexY(i));
            }
            sb.append("]}");
        }
    }

    private static void list(StringBuilder sb, List<UnsupportedElement> items) {
        sb.append('[');
        for (int i = 0; i < items.size(); i++) {
            if (i > 0) {
                sb.append(',');
            }
            Json.quote(sb, items.get(i).toString());
        }
        sb.append(']');
    }

    /**
     * Each body's state, 7 floats a body in the world's order: x, y, angle, vx, vy, ω and 1 when
     * sleeping (0 otherwise). The array is reused while the body count stays.
     */
    float[] frame() {
        int n = world.getBodyCount();
        if (frame.length != 7 * n) {
            frame = new float[7 * n];
        }
        for (int i = 0; i < n; i++) {
            Body b = world.getBody(i);
            int k = 7 * i;
            frame[k] = b.getX();
            frame[k + 1] = b.getY();
            frame[k + 2] = b.getAngle();
            frame[k + 3] = b.getVelocityX();
            frame[k + 4] = b.getVelocityY();
            frame[k + 5] = b.getAngularVelocity();
            frame[k + 6] = b.isSleeping() ? 1 : 0;
        }
        return frame;
    }

    /** The touching contacts' points: x, y, normal x, normal y, depth (5 floats a point). */
    float[] contacts() {
        int points = 0;
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            if (c.isTouching()) {
                points += c.getPointCount();
            }
        }
        float[] out = new float[5 * points];
        int k = 0;
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            if (!c.isTouching()) {
                continue;
            }
            for (int p = 0; p < c.getPointCount(); p++) {
                out[k++] = c.getPointX(p);
                out[k++] = c.getPointY(p);
                out[k++] = c.getNormalX();
                out[k++] = c.getNormalY();
                out[k++] = c.getDepth(p);
            }
        }
        return out;
    }

    /** The particles' positions, x and y for each live particle of every emitter. */
    float[] particles() {
        int n = 0;
        for (int e = 0; e < world.getParticleEmitterCount(); e++) {
            n += world.getParticleEmitter(e).getParticleCount();
        }
        float[] out = new float[2 * n];
        int k = 0;
        for (int e = 0; e < world.getParticleEmitterCount(); e++) {
            ParticleEmitter pe = world.getParticleEmitter(e);
            for (int i = 0; i < pe.getParticleCount(); i++) {
                out[k++] = pe.getX(i);
                out[k++] = pe.getY(i);
            }
        }
        return out;
    }

    /**
     * The harness's live metrics with its definitions (harness/metrics): kinetic, potential and total
     * energy (springs with a stiffness included), linear momentum x and y, angular momentum about the
     * origin, the deepest touching contact point (the contacts' own depth from the tick's narrow phase,
     * where the harness re-runs it on the final poses), the tick count, how many events fired so far and
     * the document index of the last one (−1 when none).
     */
    double[] metrics() {
        double gx = world.getGravityX();
        double gy = world.getGravityY();
        double kinetic = 0;
        double potential = 0;
        double px = 0;
        double py = 0;
        double l = 0;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (!b.isDynamic()) {
                continue;
            }
            double m = b.getMass();
            double vx = b.getVelocityX();
            double vy = b.getVelocityY();
            // The harness's definitions: a body that cannot rotate has an infinite inertia and no spin.
            double spin = DynamicBodies.spin(b);
            kinetic += 0.5 * m * (vx * vx + vy * vy) + DynamicBodies.rotationalEnergy(b);
            if (b.isAffectedByGravity()) {
                potential -= m * (gx * b.getX() + gy * b.getY());
            }
            px += m * vx;
            py += m * vy;
            l += m * (b.getX() * vy - b.getY() * vx) + spin;
        }
        double springs = 0;
        for (int i = 0; i < world.getConstraintCount(); i++) {
            if (world.getConstraint(i) instanceof Spring) {
                Spring s = (Spring) world.getConstraint(i);
                if (!s.isRigid()) {
                    double stretch = s.getLength() - s.getRestLength();
                    springs += 0.5 * s.getCoefficient() * stretch * stretch;
                }
            }
        }
        double depth = 0;
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            for (int p = 0; c.isTouching() && p < c.getPointCount(); p++) {
                depth = Math.max(depth, c.getDepth(p));
            }
        }
        return new double[] {kinetic, potential, kinetic + potential + springs, px, py, l, depth, world.getTickCount(),
            eventsFired, lastEvent};
    }

    /**
     * The body under a point, or −1.
     *
     * @return its index in the world's body order
     */
    int bodyAt(float x, float y) {
        Body b = world.findBodyAt(x, y);
        if (b == null) {
            return -1;
        }
        for (int i = 0; i < world.getBodyCount(); i++) {
            if (world.getBody(i) == b) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Starts dragging a dynamic body by a point of it with the engine's {@link MouseJoint}.
     *
     * @return whether a drag started (false for a static body or an index out of range)
     */
    boolean dragStart(int body, float x, float y) {
        dragEnd();
        if (body < 0 || body >= world.getBodyCount() || !world.getBody(body).isDynamic()) {
            return false;
        }
        Body b = world.getBody(body);
        drag = new MouseJoint(b, x, y, DRAG_ACCELERATION * b.getMass());
        world.addConstraint(drag);
        return true;
    }

    /** Moves the drag target. */
    void dragMove(float x, float y) {
        if (drag != null) {
            drag.setTarget(x, y);
        }
    }

    /** Ends a drag (nothing when none). */
    void dragEnd() {
        if (drag != null) {
            world.removeConstraint(drag);
            drag = null;
        }
    }
}
