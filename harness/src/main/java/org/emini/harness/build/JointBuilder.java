package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.emini.constraint.DistanceJoint;
import org.emini.constraint.Joint;
import org.emini.constraint.MotorJoint;
import org.emini.constraint.MouseJoint;
import org.emini.constraint.PrismaticJoint;
import org.emini.constraint.RevoluteJoint;
import org.emini.constraint.TwoBodyConstraint;
import org.emini.constraint.WheelJoint;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.Section;

/**
 * The {@code joints} section: each entry's {@code type} picks the engine's class (the manual's pin
 * joint by default, or a game joint of issue 18), built through its public API. A value the engine
 * refuses is reported at the key that gave it. Which joined bodies may not collide is
 * {@link ConnectedPairs}'s work, done before this runs.
 */
final class JointBuilder implements ElementBuilder {
    private static final Set<String> PAIR = Set.of("name", "type", "bodyA", "bodyB", "collide", "breakForce");
    private static final Set<String> ANCHORED = union(PAIR, "at", "anchorA", "anchorB");
    private static final Set<String> SLIDE = union(ANCHORED, "axis", "limits", "motor", "spring");

    /** The keys each type reads; the schema says the same with propertyNames. */
    static final Map<String, Set<String>> KEYS = Map.of(
        "pin", union(ANCHORED, "fixed", "stiffness"),
        "revolute", union(ANCHORED, "limits", "motor", "spring"),
        "prismatic", SLIDE,
        "wheel", SLIDE,
        "distance", union(ANCHORED, "length", "range", "spring"),
        "rope", union(ANCHORED, "length"),
        "motorJoint", union(PAIR, "offset", "angularOffset", "maxForce", "maxTorque", "spring"),
        "mouse", Set.of("name", "type", "body", "at", "target", "maxForce", "spring", "breakForce"));

    private static Set<String> union(Set<String> base, String... more) {
        Set<String> s = new HashSet<>(base);
        s.addAll(Set.of(more));
        return Set.copyOf(s);
    }

    @Override
    public void build(Section section, BuiltWorld world) throws UnsupportedElementException {
        for (int i = 0; i < section.node().size(); i++) {
            JsonNode j = section.node().get(i);
            JsonPath p = section.path().index(i);
            String type = j.path("type").asText("pin");
            Set<String> known = KEYS.get(type);
            if (known == null) {
                throw new UnsupportedElementException("joint type " + type, p.key("type"));
            }
            SectionKeys.only("joints (" + type + ")", j, p, known);
            Constraint c = type.equals("mouse") ? mouse(j, p, world) : pair(type, j, p, world);
            if (j.has("breakForce")) {
                float max = f(j.get("breakForce"));
                Located.at(p.key("breakForce"), () -> {
                    if (c instanceof TwoBodyConstraint t) {
                        t.setBreakForce(max);
                    } else {
                        ((MouseJoint) c).setBreakForce(max);
                    }
                });
            }
            world.world().addConstraint(c);
        }
    }

    private static float f(JsonNode v) {
        return (float) v.asDouble();
    }

    private static float x(JsonNode v) {
        return f(v.get(0));
    }

    private static float y(JsonNode v) {
        return f(v.get(1));
    }

    private static Constraint mouse(JsonNode j, JsonPath p, BuiltWorld world) {
        Body body = world.body(j.get("body").asText());
        float max = j.has("maxForce") ? f(j.get("maxForce")) : Float.POSITIVE_INFINITY;
        MouseJoint m = Located.at(p, () -> new MouseJoint(body, x(j.get("at")), y(j.get("at")), max));
        if (j.has("target")) {
            Located.at(p.key("target"), () -> m.setTarget(x(j.get("target")), y(j.get("target"))));
        }
        spring(j, p, m::setSpring);
        return m;
    }

    private static void spring(JsonNode j, JsonPath p, FloatPair setter) {
        JsonNode s = j.get("spring");
        if (s != null) {
            Located.at(p.key("spring"), () -> setter.set(f(s.get("hertz")), f(s.path("dampingRatio"))));
        }
    }

    /** An engine setter of two floats: (hertz, dampingRatio), (lower, upper), (speed, cap). */
    private interface FloatPair {
        void set(float first, float second);
    }

    private static void range(JsonNode j, JsonPath p, String key, FloatPair setter) {
        JsonNode r = j.get(key);
        if (r != null) {
            Located.at(p.key(key), () -> setter.set(x(r), y(r)));
        }
    }

    /** The motor's cap is a torque for a hinge or a wheel, a force for a slide. */
    private static void motor(JsonNode j, JsonPath p, String cap, FloatPair setter) {
        JsonNode m = j.get("motor");
        if (m != null) {
            Located.at(p.key("motor"), () -> setter.set(f(m.get("speed")), f(m.get(cap))));
        }
    }

    /** The anchors in each body's frame: {@code at} seen from each body, or as written (default 0, 0). */
    private static float[] anchors(JsonNode j, Body a, Body b) {
        if (j.has("at")) {
            float wx = x(j.get("at"));
            float wy = y(j.get("at"));
            return new float[] {a.toLocalX(wx, wy), a.toLocalY(wx, wy), b.toLocalX(wx, wy), b.toLocalY(wx, wy)};
        }
        JsonNode pa = j.path("anchorA");
        JsonNode pb = j.path("anchorB");
        return new float[] {pa.isArray() ? x(pa) : 0f, pa.isArray() ? y(pa) : 0f,
            pb.isArray() ? x(pb) : 0f, pb.isArray() ? y(pb) : 0f};
    }

    private static Constraint pair(String type, JsonNode j, JsonPath p, BuiltWorld world) {
        Body a = world.body(j.get("bodyA").asText());
        Body b = world.body(j.get("bodyB").asText());
        return switch (type) {
            case "pin" -> pin(j, p, a, b);
            case "revolute" -> revolute(j, p, a, b);
            case "prismatic", "wheel" -> slide(type, j, p, a, b);
            case "distance", "rope" -> distance(type, j, p, a, b);
            default -> motorJoint(j, p, a, b);
        };
    }

    private static Constraint pin(JsonNode j, JsonPath p, Body a, Body b) {
        boolean fixed = j.path("fixed").asBoolean(false);
        // Joint.atWorldPoint, not anchors(): the manual's pin joint keeps its results bit for bit.
        Joint joint = Located.at(p, () -> {
            if (j.has("at")) {
                return Joint.atWorldPoint(a, b, x(j.get("at")), y(j.get("at")), fixed);
            }
            float[] r = anchors(j, a, b);
            return new Joint(a, b, r[0], r[1], r[2], r[3], fixed);
        });
        JsonNode s = j.get("stiffness");
        if (s != null) {
            if (!fixed) {
                // The engine says so with an IllegalStateException, which Located leaves to crash.
                throw new BuildRefusedException(p.key("stiffness"), "only a fixed joint (fixed: true) has a stiffness;"
                    + " a hinge's spring is a revolute joint's", null);
            }
            Located.at(p.key("stiffness"), () -> joint.setStiffness(f(s.path("linearHertz")),
                f(s.path("angularHertz")), f(s.path("dampingRatio"))));
        }
        return joint;
    }

    private static Constraint revolute(JsonNode j, JsonPath p, Body a, Body b) {
        RevoluteJoint r = Located.at(p, () -> {
            float[] q = anchors(j, a, b);
            return new RevoluteJoint(a, b, q[0], q[1], q[2], q[3]);
        });
        range(j, p, "limits", r::setLimits);
        motor(j, p, "maxTorque", r::setMotor);
        spring(j, p, r::setSpring);
        return r;
    }

    /** Prismatic and wheel joints: the axis is a world direction at the start, carried by A. */
    private static Constraint slide(String type, JsonNode j, JsonPath p, Body a, Body b) {
        float wx = x(j.get("axis"));
        float wy = y(j.get("axis"));
        float c = (float) Math.cos(a.getAngle());
        float s = (float) Math.sin(a.getAngle());
        float lx = c * wx + s * wy;
        float ly = -s * wx + c * wy;
        if (type.equals("prismatic")) {
            PrismaticJoint pj = Located.at(p, () -> {
                float[] q = anchors(j, a, b);
                return new PrismaticJoint(a, b, q[0], q[1], q[2], q[3], lx, ly);
            });
            range(j, p, "limits", pj::setLimits);
            motor(j, p, "maxForce", pj::setMotor);
            spring(j, p, pj::setSpring);
            return pj;
        }
        WheelJoint w = Located.at(p, () -> {
            float[] q = anchors(j, a, b);
            return new WheelJoint(a, b, q[0], q[1], q[2], q[3], lx, ly);
        });
        range(j, p, "limits", w::setLimits);
        motor(j, p, "maxTorque", w::setMotor);
        spring(j, p, w::setSpring);
        return w;
    }

    private static Constraint distance(String type, JsonNode j, JsonPath p, Body a, Body b) {
        float[] q = anchors(j, a, b);
        if (type.equals("rope")) {
            return Located.at(p, () -> DistanceJoint.rope(a, b, q[0], q[1], q[2], q[3], f(j.get("length"))));
        }
        DistanceJoint d = Located.at(p, () -> new DistanceJoint(a, b, q[0], q[1], q[2], q[3]));
        if (j.has("length")) {
            Located.at(p.key("length"), () -> d.setLength(f(j.get("length"))));
        }
        range(j, p, "range", d::setLengthRange);
        spring(j, p, d::setSpring);
        return d;
    }

    private static Constraint motorJoint(JsonNode j, JsonPath p, Body a, Body b) {
        float maxForce = j.has("maxForce") ? f(j.get("maxForce")) : Float.POSITIVE_INFINITY;
        float maxTorque = j.has("maxTorque") ? f(j.get("maxTorque")) : Float.POSITIVE_INFINITY;
        MotorJoint m = Located.at(p, () -> new MotorJoint(a, b, maxForce, maxTorque));
        if (j.has("offset")) {
            Located.at(p.key("offset"), () -> m.setLinearOffset(x(j.get("offset")), y(j.get("offset"))));
        }
        if (j.has("angularOffset")) {
            Located.at(p.key("angularOffset"), () -> m.setAngularOffset(f(j.get("angularOffset"))));
        }
        spring(j, p, m::setSpring);
        return m;
    }
}
