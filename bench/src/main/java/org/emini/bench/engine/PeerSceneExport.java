package org.emini.bench.engine;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.Scenario;

/**
 * A scene as {@link PeerScene} maps it for the metre-based engines (metres, y up, counter-clockwise
 * polygons, densities, squared frictions, motors as joint motors), written as flat JSON for the peers
 * that run in another process and do not read the scene format: Box2D v3 ({@code bench/box2d}) and
 * Rapier ({@code bench/rapier}). So every metre-based peer gets the very same mapping. They report
 * poses in the same frame; {@link #toScene} brings them back to the scene's units for the check.
 *
 * <p>Format {@value #FORMAT}, version 1: {@code timestep} (s), {@code ticks} (the scene's run
 * duration in ticks: the default preroll), {@code gravity} [x, y] (m/s²), {@code sleeping} (the
 * scene lets bodies sleep: at each engine's own tolerances), {@code shapes} (lists of convex parts,
 * shared by index: {@code {"radius", "center": [x, y]}} or {@code {"vertices": [[x, y], ...]}},
 * each with {@code density} (kg/m²), {@code friction} (for √(fA·fB) mixing) and
 * {@code restitution}), {@code bodies} ({@code name}, {@code shape} index, {@code dynamic},
 * {@code x}, {@code y}, {@code angle}, {@code vx}, {@code vy}, {@code omega}, {@code rotatable},
 * {@code gravity}, {@code sleepingAllowed}), {@code joints} (body indices {@code a}, {@code b}, the
 * world point {@code x}, {@code y} of the start pose, {@code fixed} for a weld, {@code collide}),
 * {@code motors} ({@code joint} index, {@code speed} in rad/s of b relative to a,
 * {@code maxTorque} in N·m) and {@code emitters} (how many particle emitters the scene has).
 */
public final class PeerSceneExport {
    /** The format's name, in every file. */
    public static final String FORMAT = "emini-peer-scene";

    private PeerSceneExport() {
    }

    /**
     * The scene in the peers' frame.
     *
     * @param id the scene id, written into the file
     * @param engine the engine's id, for messages
     * @param maxVertices the engine's polygon vertex limit
     * @throws UnsupportedSceneException if {@link PeerScene} cannot map the scene
     */
    public static JsonObject toJson(String id, Scenario s, String engine, int maxVertices) throws UnsupportedSceneException {
        PeerScene p = PeerScene.of(s, engine, maxVertices);
        JsonObject o = new JsonObject();
        o.addProperty("format", FORMAT);
        o.addProperty("version", 1);
        o.addProperty("scene", id);
        o.addProperty("pxPerMetre", PeerScene.PX_PER_M);
        o.addProperty("timestep", p.timestep);
        o.addProperty("ticks", s.ticks());
        o.add("gravity", pair(p.gravityX, p.gravityY));
        o.addProperty("sleeping", p.sleeping);
        // Bodies of one shape share its parts list (PeerScene maps each shape once): written once.
        Map<List<PeerScene.PeerShape>, Integer> shapeIndex = new IdentityHashMap<>();
        JsonArray shapes = new JsonArray();
        JsonArray bodies = new JsonArray();
        for (PeerScene.PeerBody b : p.bodies) {
            Integer k = shapeIndex.get(b.parts);
            if (k == null) {
                k = shapes.size();
                shapeIndex.put(b.parts, k);
                JsonArray parts = new JsonArray();
                b.parts.forEach(part -> parts.add(part(part)));
                shapes.add(parts);
            }
            JsonObject j = new JsonObject();
            j.addProperty("name", b.name);
            j.addProperty("shape", k);
            j.addProperty("dynamic", b.dynamic);
            j.addProperty("x", b.x);
            j.addProperty("y", b.y);
            j.addProperty("angle", b.angle);
            j.addProperty("vx", b.vx);
            j.addProperty("vy", b.vy);
            j.addProperty("omega", b.omega);
            j.addProperty("rotatable", b.rotatable);
            j.addProperty("gravity", b.gravity);
            j.addProperty("sleepingAllowed", b.sleepingAllowed);
            bodies.add(j);
        }
        o.add("shapes", shapes);
        o.add("bodies", bodies);
        JsonArray joints = new JsonArray();
        for (PeerScene.PeerJoint pj : p.joints) {
            JsonObject j = new JsonObject();
            j.addProperty("a", pj.a);
            j.addProperty("b", pj.b);
            j.addProperty("x", pj.x);
            j.addProperty("y", pj.y);
            j.addProperty("fixed", pj.fixed);
            j.addProperty("collide", pj.collide);
            joints.add(j);
        }
        o.add("joints", joints);
        JsonArray motors = new JsonArray();
        for (PeerScene.PeerMotor pm : p.motors) {
            JsonObject m = new JsonObject();
            m.addProperty("joint", pm.joint);
            m.addProperty("speed", pm.speed);
            m.addProperty("maxTorque", pm.maxTorque);
            motors.add(m);
        }
        o.add("motors", motors);
        o.addProperty("emitters", p.emitters.size());
        return o;
    }

    private static JsonObject part(PeerScene.PeerShape sh) {
        JsonObject j = new JsonObject();
        if (sh.circle) {
            j.addProperty("radius", sh.radius);
            j.add("center", pair(sh.cx, sh.cy));
        } else {
            JsonArray v = new JsonArray();
            for (int i = 0; i < sh.vertexCount(); i++) {
                v.add(pair(sh.xy[2 * i], sh.xy[2 * i + 1]));
            }
            j.add("vertices", v);
        }
        j.addProperty("density", sh.density);
        j.addProperty("friction", sh.friction);
        j.addProperty("restitution", sh.restitution);
        return j;
    }

    private static JsonArray pair(double x, double y) {
        JsonArray a = new JsonArray();
        a.add(x);
        a.add(y);
        return a;
    }

    /**
     * Brings a snapshot the peer reported in its frame to the scene's, in place: poses (x, y, angle
     * per body) and particle positions (x, y) to px, y down, clockwise angles; speeds to px/s;
     * angular velocities to the scene's sense.
     */
    public static void toScene(double[] poses, double[] speeds, double[] omegas, double[] particleXy) {
        for (int i = 0; i < poses.length / 3; i++) {
            PeerScene.putPose(poses, i, poses[3 * i], poses[3 * i + 1], poses[3 * i + 2]);
        }
        for (int i = 0; i < speeds.length; i++) {
            speeds[i] *= PeerScene.PX_PER_M;
        }
        for (int i = 0; i < omegas.length; i++) {
            omegas[i] = -omegas[i];
        }
        for (int i = 0; i < particleXy.length; i++) {
            particleXy[i] *= i % 2 == 0 ? PeerScene.PX_PER_M : -PeerScene.PX_PER_M;
        }
    }
}
