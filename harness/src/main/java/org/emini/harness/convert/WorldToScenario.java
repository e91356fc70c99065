package org.emini.harness.convert;

import static org.emini.harness.convert.YamlText.name;
import static org.emini.harness.convert.YamlText.num;
import static org.emini.harness.convert.YamlText.quote;
import static org.emini.harness.convert.YamlText.vec;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.emini.io.PhyBody;
import org.emini.io.PhyConstraint;
import org.emini.io.PhyEvent;
import org.emini.io.PhyFixed;
import org.emini.io.PhyJoint;
import org.emini.io.PhyLandscape;
import org.emini.io.PhyMotor;
import org.emini.io.PhyMultiShape;
import org.emini.io.PhyPairConstraint;
import org.emini.io.PhyParticleEmitter;
import org.emini.io.PhyScript;
import org.emini.io.PhyScriptBinding;
import org.emini.io.PhySegment;
import org.emini.io.PhyShape;
import org.emini.io.PhyShapeBase;
import org.emini.io.PhySpring;
import org.emini.io.PhyVector;
import org.emini.io.PhyVersion;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWorldSettings;
import org.emini.io.WorldBuilder;
import org.emini.shape.Shape;

/**
 * An original world file (as a {@link PhyWorld}) as a scene file, with the engine builder's mapping
 * (org/emini/io/phy-mapping.md): values converted exactly from fixed point, angular velocities
 * negated, circles with the original's whole-pixel radius, lines as thin slabs. What the scene format
 * cannot say (events, scripts, user data, motor flags) is listed in comments at the top, and returned.
 */
public final class WorldToScenario {
    /**
     * The scene text and what did not carry over.
     *
     * @param yaml the scene file
     * @param notConverted records left out, one line each
     * @param approximated records written in another form, one line each
     */
    public record Result(String yaml, List<String> notConverted, List<String> approximated) {
    }

    private final PhyWorld doc;
    private final List<String> notConverted = new ArrayList<>();
    private final List<String> approximated = new ArrayList<>();
    private final List<String> userData = new ArrayList<>();
    private final String[] shapeNames;
    private final String[] bodyNames;
    private final StringBuilder out = new StringBuilder();

    private WorldToScenario(PhyWorld doc) {
        this.doc = doc;
        shapeNames = new String[doc.getShapes().size()];
        bodyNames = new String[doc.getBodies().size()];
    }

    /**
     * Converts a document.
     *
     * @param doc the world file's document
     * @param source the file name, for the header
     * @param duration the run's duration (s)
     */
    public static Result convert(PhyWorld doc, String source, double duration) {
        WorldToScenario c = new WorldToScenario(doc);
        String body = c.body(duration);
        StringBuilder head = new StringBuilder();
        head.append("# Converted by `harness convert` from ").append(source).append(" (original world file, version ")
                .append(doc.getVersion()).append(", word ").append(PhyVersion.toString(doc.getVersionWord()))
                .append(").\n");
        head.append("# Values are the file's fixed point converted exactly (FX / 4096, 2FX / 2^24); angular velocities\n")
                .append("# are negated (the original turns by angle - w*dt); see engine/src/main/java/org/emini/io/phy-mapping.md.\n");
        comments(head, "Not converted (the scene format has no such element)", c.notConverted);
        comments(head, "Approximated", c.approximated);
        comments(head, "User data", c.userData);
        return new Result(head + body, List.copyOf(c.notConverted), List.copyOf(c.approximated));
    }

    private static void comments(StringBuilder b, String title, List<String> lines) {
        if (!lines.isEmpty()) {
            b.append("# ").append(title).append(" (").append(lines.size()).append("):\n");
            for (String l : lines) {
                b.append("#   ").append(l.replace("\n", "\\n")).append('\n');
            }
        }
    }

    private String body(double duration) {
        out.append("description: ").append(quote("An original World Designer file, converted.")).append('\n');
        out.append("tags: [converted]\n");
        world();
        shapes();
        bodies();
        constraints();
        landscape();
        particles();
        for (int i = 0; i < doc.getEvents().size(); i++) {
            notConverted.add("event " + i + ": " + describe(i, doc.getEvents().get(i)));
        }
        for (int i = 0; i < doc.getScripts().size(); i++) {
            PhyScript s = doc.getScripts().get(i);
            notConverted.add("script " + i + ": " + s.getElements().size() + " elements"
                    + (s.isRestarting() ? ", restarting" : ""));
        }
        for (int i = 0; i < doc.getScriptBindings().size(); i++) {
            PhyScriptBinding b = doc.getScriptBindings().get(i);
            notConverted.add("script-body row " + i + ": script " + b.getScript() + " on "
                    + (b.getBody() == PhyWorld.NONE ? "no body" : bodyLabel(b.getBody())));
        }
        out.append("run:\n  duration: ").append(num(duration)).append('\n');
        out.append("  expect:\n    - {stable: {}, why: ").append(quote("a designer world stays finite")).append("}\n");
        int dynamic = 0;
        for (PhyBody b : doc.getBodies()) {
            dynamic += b.isDynamic() ? 1 : 0;
        }
        if (dynamic >= 3) {
            // Collisions among several bodies diverge: the oracle compares aggregates only.
            out.append("reference:\n  oracle: {chaotic: true}\n");
        }
        return out.toString();
    }

    private void world() {
        PhyWorldSettings s = doc.getSettings();
        if (s == null) {
            return;
        }
        out.append("world:\n");
        out.append("  gravity: ").append(vecFx(s.getGravity())).append('\n');
        out.append("  damping: {lateral: ").append(num(unit(fx(s.getDampingLinearRaw()), "world linear damping")))
                .append(", rotational: ").append(num(unit(fx(s.getDampingRotationalRaw()), "world rotational damping")))
                .append("}\n");
        note(s.getUserData(), "world");
    }

    private void shapes() {
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < shapeNames.length; i++) {
            PhyShapeBase s = doc.getShapes().get(i);
            String line = s.isMultiShape() ? multiShape(i, (PhyMultiShape) s) : shape(i, (PhyShape) s);
            if (line != null) {
                shapeNames[i] = "shape" + i;
                lines.add("  " + shapeNames[i] + ": " + line);
                note(s.getUserData(), "shape " + i);
            }
        }
        if (!lines.isEmpty()) {
            out.append("shapes:\n");
            lines.forEach(l -> out.append(l).append('\n'));
        }
    }

    private String shape(int i, PhyShape s) {
        int n = s.getVertexCount();
        String geometry;
        if (n == 1) {
            int radius = s.getCircleRadius();
            if (radius <= 0) {
                notConverted.add("shape " + i + ": a circle whose radius truncates to 0 px");
                return null;
            }
            geometry = "type: circle, radius: " + radius;
        } else if (n == 2) {
            float[] slab = WorldBuilder.lineSlab(s.getVertex(0), s.getVertex(1), WorldBuilder.DEFAULT_LINE_THICKNESS);
            if (slab == null) {
                notConverted.add("shape " + i + ": a line of length 0");
                return null;
            }
            approximated.add("shape " + i + ": a line, written as a polygon " + num(WorldBuilder.DEFAULT_LINE_THICKNESS)
                    + " px thick centred on it");
            double[] corners = new double[slab.length];
            for (int k = 0; k < slab.length; k++) {
                corners[k] = slab[k];
            }
            geometry = "type: polygon, vertices: " + vertices(corners);
        } else if (n >= 3 && n <= Shape.MAX_VERTICES) {
            float[] xy = new float[2 * n];
            for (int k = 0; k < n; k++) {
                xy[2 * k] = s.getVertex(k).getX();
                xy[2 * k + 1] = s.getVertex(k).getY();
            }
            try {
                Shape.createPolygon(xy);
            } catch (IllegalArgumentException e) {
                notConverted.add("shape " + i + ": " + e.getMessage());
                return null;
            }
            double[] exact = new double[2 * n];
            for (int k = 0; k < n; k++) {
                exact[2 * k] = fx(s.getVertex(k).getXRaw());
                exact[2 * k + 1] = fx(s.getVertex(k).getYRaw());
            }
            geometry = "type: polygon, vertices: " + vertices(exact);
        } else {
            notConverted.add("shape " + i + ": " + n + " vertices (the original leaves such a shape "
                    + (n == 0 ? "empty)" : "unusable)"));
            return null;
        }
        String mass = "";
        if (s.getMassRaw() > 0) {
            mass = ", mass: " + num(fx(s.getMassRaw()));
        } else {
            approximated.add("shape " + i + ": mass " + num(fx(s.getMassRaw())) + " is not > 0; mass 1 written");
        }
        return "{" + geometry + mass + ", friction: " + num(unit(fx(s.getFrictionRaw()), "shape " + i + " friction"))
                + ", elasticity: " + num(unit(fx(s.getElasticityRaw()), "shape " + i + " elasticity")) + "}";
    }

    private String multiShape(int i, PhyMultiShape m) {
        StringBuilder b = new StringBuilder("{type: multiShape, parts: [");
        int[] parts = m.getParts();
        if (parts.length == 0) {
            notConverted.add("shape " + i + ": a multishape without parts");
            return null;
        }
        for (int k = 0; k < parts.length; k++) {
            if (shapeNames[parts[k]] == null) {
                notConverted.add("shape " + i + ": a multishape whose part " + parts[k] + " is not converted");
                return null;
            }
            b.append(k == 0 ? "" : ", ").append("{shape: ").append(shapeNames[parts[k]]).append('}');
        }
        return b.append("]}").toString();
    }

    private static String vertices(double[] xy) {
        StringBuilder b = new StringBuilder("[");
        for (int k = 0; k < xy.length; k += 2) {
            b.append(k == 0 ? "" : ", ").append(vec(xy[k], xy[k + 1]));
        }
        return b.append(']').toString();
    }

    private void bodies() {
        Set<String> taken = new HashSet<>();
        for (int i = 0; i < bodyNames.length; i++) {
            String wanted = wantedName(doc.getBodies().get(i));
            if (wanted != null && !taken.add(wanted)) {
                wanted = null;
            }
            bodyNames[i] = wanted;
        }
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < bodyNames.length; i++) {
            PhyBody b = doc.getBodies().get(i);
            if (shapeNames[b.getShapeIndex()] == null) {
                notConverted.add("body " + i + ": its shape " + b.getShapeIndex() + " is not converted");
                bodyNames[i] = null;
                continue;
            }
            if (bodyNames[i] == null) {
                String n = "body" + i;
                while (!taken.add(n)) {
                    n = n + "_";
                }
                bodyNames[i] = n;
            }
            lines.add("  - " + body(i, b));
            if (!b.getUserData().equals(ScenarioToWorld.NAME_KEY + bodyNames[i])) {
                note(b.getUserData(), bodyLabel(i));
            }
        }
        if (!lines.isEmpty()) {
            out.append("bodies:\n");
            lines.forEach(l -> out.append(l).append('\n'));
        }
    }

    /** A body whose user data is a single "name=..." line keeps that name (the reverse conversion writes it). */
    private static String wantedName(PhyBody b) {
        String u = b.getUserData();
        return u.startsWith(ScenarioToWorld.NAME_KEY) && u.indexOf('\n') < 0
                && u.length() > ScenarioToWorld.NAME_KEY.length() ? u.substring(ScenarioToWorld.NAME_KEY.length()) : null;
    }

    private String body(int i, PhyBody b) {
        StringBuilder s = new StringBuilder("{name: ").append(name(bodyNames[i]));
        s.append(", shape: ").append(shapeNames[b.getShapeIndex()]);
        s.append(", position: ").append(vecFx(b.getPosition()));
        if (!b.isDynamic()) {
            s.append(", static: true");
        }
        if (b.getAngleRaw() != 0) {
            s.append(", angle: ").append(num(fx2(PhyFixed.wrapAngle2fx(b.getAngleRaw()))));
        }
        // The original ignores motion stored on a static body (as the engine's loader does); the scene
        // format refuses it.
        if (b.isDynamic() && !b.getVelocity().equals(PhyVector.ZERO)) {
            s.append(", velocity: ").append(vecFx(b.getVelocity()));
        }
        if (b.isDynamic() && b.getAngularVelocityRaw() != 0) {
            s.append(", angularVelocity: ").append(num(-fx2(b.getAngularVelocityRaw())));
        }
        if (!b.canRotate()) {
            s.append(", rotatable: false");
        }
        if (!b.isInteracting()) {
            s.append(", interacting: false");
        }
        if (!b.isAffectedByGravity()) {
            s.append(", gravity: false");
        }
        if (b.getCollisionLayers() != 0) {
            s.append(", layers: [");
            String sep = "";
            for (int k = 0; k < 32; k++) {
                if ((b.getCollisionLayers() >>> k & 1) != 0) {
                    s.append(sep).append(k);
                    sep = ", ";
                }
            }
            s.append(']');
        }
        return s.append('}').toString();
    }

    private void constraints() {
        List<String> joints = new ArrayList<>();
        List<String> springs = new ArrayList<>();
        List<String> motors = new ArrayList<>();
        for (int i = 0; i < doc.getConstraints().size(); i++) {
            PhyConstraint c = doc.getConstraints().get(i);
            String label = "constraint " + i;
            note(c.getUserData(), label);
            if (c instanceof PhyPairConstraint p) {
                if (bodyNames[p.getBody1()] == null || bodyNames[p.getBody2()] == null) {
                    notConverted.add(label + ": a body it joins is not converted");
                    continue;
                }
                String pair = "bodyA: " + name(bodyNames[p.getBody1()]) + ", bodyB: " + name(bodyNames[p.getBody2()])
                        + ", anchorA: " + vecFx(p.getAnchor1()) + ", anchorB: " + vecFx(p.getAnchor2());
                if (c instanceof PhyJoint j) {
                    // The original never stops jointed bodies colliding by itself (layers do that).
                    joints.add("{" + pair + (j.isFixed() ? ", fixed: true" : "") + ", collide: true}");
                } else {
                    PhySpring s = (PhySpring) c;
                    if (s.getRestLengthRaw() < 0) {
                        notConverted.add(label + ": a spring with a negative rest length");
                        continue;
                    }
                    springs.add("{" + pair + ", restLength: " + num(fx(s.getRestLengthRaw())) + ", stiffness: "
                            + num(fx(Math.max(0, s.getCoefficientRaw()))) + ", collide: true}");
                }
            } else {
                String m = motor(label, (PhyMotor) c);
                if (m != null) {
                    motors.add(m);
                }
            }
        }
        list("joints", joints);
        list("springs", springs);
        list("motors", motors);
    }

    private String motor(String label, PhyMotor m) {
        if (bodyNames[m.getBody()] == null) {
            notConverted.add(label + ": its body is not converted");
            return null;
        }
        if (m.getMaxForceRaw() <= 0) {
            notConverted.add(label + ": a motor with cap " + num(fx(m.getMaxForceRaw())) + " (it never acts)");
            return null;
        }
        if ((m.getFlags() & PhyMotor.FLAG_RELATIVE) != 0) {
            approximated.add(label + ": the target relative to the body's rotation is written as absolute");
        }
        if (!m.isRotational() && (m.getFlags() & PhyMotor.FLAG_FIX_ORTHOGONAL) != 0) {
            approximated.add(label + ": braking the velocity orthogonal to the target is not written");
        }
        String target = m.isRotational() ? "angularVelocity: " + num(-fx2(m.getTargetARaw()))
                : "velocity: " + vecFx(m.getTargetVelocity());
        return "{body: " + name(bodyNames[m.getBody()]) + ", " + target + ", maxImpulse: " + num(fx(m.getMaxForceRaw())) + "}";
    }

    private void landscape() {
        PhyLandscape l = doc.getLandscape();
        if (l == null) {
            return;
        }
        if (l.getSegments().isEmpty()) {
            notConverted.add("landscape: no segments (its material alone has no effect)");
            return;
        }
        out.append("landscape:\n");
        out.append("  friction: ").append(num(unit(fx(l.getMaterial().getFrictionRaw()), "landscape friction"))).append('\n');
        out.append("  elasticity: ").append(num(unit(fx(l.getMaterial().getElasticityRaw()), "landscape elasticity")))
                .append('\n');
        out.append("  segments:\n");
        for (int i = 0; i < l.getSegments().size(); i++) {
            PhySegment s = l.getSegments().get(i);
            String face = s.getFace() == PhySegment.FACE_LEFT ? "left" : s.getFace() == PhySegment.FACE_RIGHT ? "right"
                    : "none";
            if (s.getFace() > PhySegment.FACE_RIGHT) {
                approximated.add("landscape segment " + i + ": face byte " + s.getFace() + " written as none");
            }
            out.append("    - {from: ").append(vecFx(s.getStart())).append(", to: ").append(vecFx(s.getEnd()))
                    .append(", face: ").append(face).append("}\n");
        }
    }

    private void particles() {
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < doc.getParticleEmitters().size(); i++) {
            PhyParticleEmitter p = doc.getParticleEmitters().get(i);
            String label = "particle emitter " + i;
            note(p.getUserData(), label);
            if (p.getBody() != PhyWorld.NONE && bodyNames[p.getBody()] == null) {
                notConverted.add(label + ": its body is not converted");
                continue;
            }
            if (p.getMaxParticles() < 1 || p.getLifetimeRaw() <= 0) {
                notConverted.add(label + ": capacity " + p.getMaxParticles() + ", lifetime " + num(fx(p.getLifetimeRaw()))
                        + " s: it never shows a particle");
                continue;
            }
            StringBuilder s = new StringBuilder("{name: emitter" + i);
            if (p.getBody() != PhyWorld.NONE) {
                s.append(", body: ").append(name(bodyNames[p.getBody()]));
            }
            s.append(", from: ").append(vecFx(p.getPosition1())).append(", to: ").append(vecFx(p.getPosition2()));
            s.append(", maxCount: ").append(p.getMaxParticles());
            s.append(", rate: ").append(num(atLeast0(fx(p.getRateRaw()), label + " rate")));
            s.append(", rateSpread: ").append(num(atLeast0(fx(p.getRateSpreadRaw()), label + " rate spread")));
            s.append(", lifetime: ").append(num(fx(p.getLifetimeRaw())));
            s.append(", lifetimeSpread: ").append(num(atLeast0(fx(p.getLifetimeSpreadRaw()), label + " lifetime spread")));
            s.append(", speed: ").append(num(atLeast0(fx(p.getSpeedRaw()), label + " speed")));
            s.append(", speedSpread: ").append(num(atLeast0(fx(p.getSpeedSpreadRaw()), label + " speed spread")));
            s.append(", angleDeg: ").append(num(Math.toDegrees(fx2(p.getEmitAngleRaw()))));
            s.append(", angleSpreadDeg: ").append(num(atLeast0(Math.toDegrees(fx2(p.getEmitAngleSpreadRaw())),
                    label + " angle spread")));
            s.append(", axesFixed: ").append(p.isAxesFixed());
            s.append(", elasticity: ").append(num(unit(fx(p.getElasticityRaw()), label + " elasticity")));
            s.append(", gravityFactor: ").append(num(fx(p.getGravityFactorRaw())));
            s.append(", damping: ").append(num(unit(fx(p.getDampingRaw()), label + " damping")));
            lines.add(s.append('}').toString());
        }
        list("particles", lines);
    }

    private void list(String key, List<String> items) {
        if (!items.isEmpty()) {
            out.append(key).append(":\n");
            items.forEach(l -> out.append("  - ").append(l).append('\n'));
        }
    }

    private String bodyLabel(int i) {
        return bodyNames[i] != null ? "body " + i + " (" + bodyNames[i] + ")" : "body " + i;
    }

    private String describe(int index, PhyEvent e) {
        StringBuilder b = new StringBuilder();
        int[] t = {e.getTargetRaw(0), e.getTargetRaw(1), e.getTargetRaw(2), e.getTargetRaw(3)};
        switch (e.getType()) {
            case PhyEvent.TYPE_BODY_POSITION -> b.append("body position in x ").append(num(fx(t[0])))
                    .append("..").append(num(fx(t[2]))).append(", y ").append(num(fx(t[1])))
                    .append("..").append(num(fx(t[3]))).append(" px");
            case PhyEvent.TYPE_BODY_VELOCITY -> b.append("body squared speed ").append(num(fx(t[0])))
                    .append("..").append(num(fx(t[1]))).append(" px²/s²");
            case PhyEvent.TYPE_BODY_ROTATION -> b.append("body angle ").append(num(fx2(t[0]))).append("..")
                    .append(num(fx2(t[1]))).append(" rad");
            case PhyEvent.TYPE_BODY_ANGULAR_VELOCITY -> b.append("body angular velocity ")
                    .append(num(-fx2(t[1]))).append("..").append(num(-fx2(t[0])))
                    .append(" rad/s (engine sign)");
            case PhyEvent.TYPE_BODY_COLLISION -> b.append("body collision (above, right, below, left: ")
                    .append(t[0] > 0).append(", ").append(t[1] > 0).append(", ").append(t[2] > 0).append(", ")
                    .append(t[3] > 0).append(')');
            case PhyEvent.TYPE_BODY_SENSOR -> b.append("body sensor");
            case PhyEvent.TYPE_BODY_COLLISION_RELATIVE -> b.append("relative collision at ")
                    .append(num(fx2(t[0]))).append(" rad, min cosine ").append(num(fx(t[1])));
            case PhyEvent.TYPE_CONSTRAINT_FORCE -> b.append("constraint impulse ").append(num(fx(t[0])))
                    .append("..").append(num(fx(t[1])));
            default -> b.append("type ").append(e.getType());
        }
        if (e.getBodyFilter() != PhyWorld.NONE) {
            b.append(", ").append(bodyLabel(e.getBodyFilter()));
        }
        if (e.getShapeFilter() != PhyWorld.NONE) {
            b.append(", shape ").append(e.getShapeFilter());
        }
        if (e.getConstraintFilter() != PhyWorld.NONE) {
            b.append(", constraint ").append(e.getConstraintFilter());
        }
        if (e.isTriggerOnce()) {
            b.append(", trigger once");
        }
        note(e.getUserData(), "event " + index);
        return b.toString();
    }

    private void note(String data, String owner) {
        if (!data.isEmpty()) {
            userData.add(owner + ": " + quote(data));
        }
    }

    private double unit(double v, String what) {
        if (v >= 0 && v <= 1) {
            return v;
        }
        double c = v < 0 ? 0 : 1;
        approximated.add(what + " " + num(v) + " clamped to " + num(c));
        return c;
    }

    private double atLeast0(double v, String what) {
        if (v >= 0) {
            return v;
        }
        approximated.add(what + " " + num(v) + " written as 0");
        return 0;
    }

    private static String vecFx(PhyVector v) {
        return YamlText.vec(fx(v.getXRaw()), fx(v.getYRaw()));
    }

    /** FX to double, exact (the engine's float getters round beyond 2^24 raw). */
    static double fx(int raw) {
        return raw / (double) PhyFixed.FX_ONE;
    }

    /** 2FX to double, exact. */
    static double fx2(int raw) {
        return raw / (double) PhyFixed.FX2_ONE;
    }
}
