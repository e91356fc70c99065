package org.emini.harness.fuzz.world;

import com.google.gson.GsonBuilder;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A recipe as a scene file of the harness's scenario language (scenarios/README.md), in YAML or JSON,
 * when the scene language can say everything the recipe holds ({@link #inexpressible}). Numbers are
 * written exactly (the decimal of each float), bodies are {@code bID}, shapes {@code sID}, emitters
 * {@code eID}; the harness builds the same world from it bit for bit (FormatRelation checks that).
 */
public final class SceneText {
    private SceneText() {
    }

    /** What keeps the recipe out of a scene file; empty when it fits. */
    public static List<String> inexpressible(Recipe r) {
        List<String> why = new ArrayList<>();
        add(why, !r.events.isEmpty(), r.events.size() + " events");
        add(why, r.listener, "an event listener");
        add(why, !r.forces.isEmpty(), r.forces.size() + " external forces");
        add(why, !r.removals.isEmpty(), "bodies removed during a tick");
        add(why, r.bodies.stream().anyMatch(b -> b.bullet), "bullet bodies");
        add(why, r.motors.stream().anyMatch(m -> m.relative || m.orthogonal), "relative or orthogonal motors");
        add(why, r.springs.stream().anyMatch(s -> s.hertz > 0f), "springs tuned by frequency");
        add(why, r.shapes.stream().anyMatch(ShapeRecipe::offCentreCircle), "off-centre circles");
        add(why, r.shapes.stream().anyMatch(s -> s.centred), "shapes moved by centred()");
        return why;
    }

    private static void add(List<String> why, boolean when, String what) {
        if (when) {
            why.add(what);
        }
    }

    /** The scene as YAML, with comment lines first and the given expectations. */
    public static String yaml(Recipe r, List<String> comments, List<Map<String, Object>> expect) {
        StringBuilder b = new StringBuilder();
        for (String c : comments) {
            b.append("# ").append(c.replace("\n", "\n# ")).append('\n');
        }
        for (Map.Entry<String, Object> e : tree(r, expect).entrySet()) {
            b.append(e.getKey()).append(':');
            if (e.getValue() instanceof List<?> list) {
                b.append('\n');
                list.forEach(item -> b.append("  - ").append(flow(item)).append('\n'));
            } else if (e.getValue() instanceof Map<?, ?> map) {
                b.append('\n');
                map.forEach((k, v) -> b.append("  ").append(k).append(": ").append(flow(v)).append('\n'));
            } else {
                b.append(' ').append(flow(e.getValue())).append('\n');
            }
        }
        return b.toString();
    }

    /** The scene as JSON. */
    public static String json(Recipe r) {
        return new GsonBuilder().setPrettyPrinting().create().toJson(tree(r, List.of()));
    }

    private static String flow(Object v) {
        if (v instanceof Map<?, ?> map) {
            StringBuilder b = new StringBuilder("{");
            map.forEach((k, x) -> b.append(b.length() > 1 ? ", " : "").append(k).append(": ").append(flow(x)));
            return b.append('}').toString();
        }
        if (v instanceof List<?> list) {
            StringBuilder b = new StringBuilder("[");
            list.forEach(x -> b.append(b.length() > 1 ? ", " : "").append(flow(x)));
            return b.append(']').toString();
        }
        if (v instanceof Double d) {
            return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString(d.longValue())
                    : new BigDecimal(Double.toString(d)).stripTrailingZeros().toPlainString();
        }
        if (v instanceof String s) {
            return s.matches("[A-Za-z_][A-Za-z0-9_]*") ? s : new com.google.gson.Gson().toJson(s);
        }
        return String.valueOf(v);
    }

    private static Map<String, Object> tree(Recipe r, List<Map<String, Object>> expect) {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("world", world(r));
        Map<String, Object> shapes = new LinkedHashMap<>();
        r.shapes.forEach(s -> shapes.put("s" + s.id, shape(s)));
        root.put("shapes", shapes);
        List<Object> bodies = new ArrayList<>();
        r.bodies.forEach(b -> bodies.add(body(b)));
        root.put("bodies", bodies);
        if (!r.joints.isEmpty()) {
            root.put("joints", map(r.joints, SceneText::joint));
        }
        if (!r.springs.isEmpty()) {
            root.put("springs", map(r.springs, SceneText::spring));
        }
        if (!r.motors.isEmpty()) {
            root.put("motors", map(r.motors, SceneText::motor));
        }
        if (!r.segments.isEmpty()) {
            Map<String, Object> land = new LinkedHashMap<>();
            land.put("friction", (double) r.landscapeFriction);
            land.put("elasticity", (double) r.landscapeElasticity);
            land.put("segments", map(r.segments, s -> obj("from", vec(s.x1, s.y1), "to", vec(s.x2, s.y2),
                    "face", s.face == 1 ? "left" : s.face == 2 ? "right" : "none")));
            root.put("landscape", land);
        }
        if (!r.emitters.isEmpty()) {
            root.put("particles", map(r.emitters, SceneText::emitter));
        }
        Map<String, Object> run = new LinkedHashMap<>();
        run.put("duration", r.ticks / (double) r.ticksPerSecond);
        if (!expect.isEmpty()) {
            run.put("expect", expect);
        }
        root.put("run", run);
        return root;
    }

    private static Map<String, Object> world(Recipe r) {
        Map<String, Object> w = obj("ticksPerSecond", r.ticksPerSecond, "iterations", r.iterations,
                "dynamicIterations", r.dynamicIterations, "gravity", vec(r.gravityX, r.gravityY),
                "damping", obj("lateral", (double) r.dampingLateral, "rotational", (double) r.dampingRotational));
        if (r.sleeping) {
            w.put("sleeping", true);
        }
        if (r.area != null) {
            w.put("simulationArea", r.area.range ? obj("start", (double) r.area.minX, "end", (double) r.area.maxX)
                    : obj("min", vec(r.area.minX, r.area.minY), "max", vec(r.area.maxX, r.area.maxY)));
        }
        return w;
    }

    private static Map<String, Object> shape(ShapeRecipe s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("type", s.kind.name());
        switch (s.kind) {
            case circle -> m.put("radius", (double) s.radius);
            case rectangle -> {
                m.put("width", (double) s.width);
                m.put("height", (double) s.height);
            }
            case regularPolygon -> {
                m.put("radius", (double) s.radius);
                m.put("sides", s.sides);
            }
            case polygon -> {
                List<Object> vs = new ArrayList<>();
                for (int i = 0; i + 1 < s.vertices.length; i += 2) {
                    vs.add(vec(s.vertices[i], s.vertices[i + 1]));
                }
                m.put("vertices", vs);
            }
            default -> m.put("parts", map(s.parts, p -> obj("shape", shape(p.shape), "offset", vec(p.offsetX, p.offsetY),
                    "angle", (double) p.angle)));
        }
        m.put("mass", (double) s.mass);
        m.put("friction", (double) s.friction);
        m.put("elasticity", (double) s.elasticity);
        return m;
    }

    private static Map<String, Object> body(BodyRecipe b) {
        Map<String, Object> m = obj("name", "b" + b.id, "shape", "s" + b.shape, "position", vec(b.x, b.y),
                "static", !b.dynamic, "angle", (double) b.angle, "velocity", b.dynamic ? vec(b.vx, b.vy) : vec(0, 0),
                "angularVelocity", b.dynamic ? (double) b.omega : 0.0);
        if (b.sensor) {
            m.put("sensor", true);
        }
        if (!b.sleepingAllowed) {
            m.put("sleepingAllowed", false);
        }
        if (b.categories != 1 || b.mask != -1 || b.group != 0) {
            m.put("categories", bits(b.categories));
            m.put("mask", bits(b.mask));
            m.put("group", b.group);
        }
        m.put("rotatable", b.rotatable);
        m.put("interacting", b.interacting);
        m.put("gravity", b.gravity);
        if (b.layers != 0) {
            List<Object> layers = new ArrayList<>();
            for (int k = 0; k < 32; k++) {
                if ((b.layers & (1 << k)) != 0) {
                    layers.add(k);
                }
            }
            m.put("layers", layers);
        }
        return m;
    }

    private static List<Object> bits(int set) {
        List<Object> out = new ArrayList<>();
        for (int k = 0; k < 32; k++) {
            if ((set & (1 << k)) != 0) {
                out.add(k);
            }
        }
        return out;
    }

    private static Map<String, Object> joint(JointRecipe j) {
        Map<String, Object> m = obj("bodyA", "b" + j.a, "bodyB", "b" + j.b);
        if (j.atPoint) {
            m.put("at", vec(j.x, j.y));
        } else {
            m.put("anchorA", vec(j.ax, j.ay));
            m.put("anchorB", vec(j.bx, j.by));
        }
        m.put("fixed", j.fixed);
        m.put("collide", j.collide);
        return m;
    }

    private static Map<String, Object> spring(SpringRecipe s) {
        Map<String, Object> m = obj("bodyA", "b" + s.a, "bodyB", "b" + s.b, "anchorA", vec(s.ax, s.ay), "anchorB", vec(s.bx, s.by));
        if (s.restLength >= 0f) {
            m.put("restLength", (double) s.restLength);
        }
        m.put("stiffness", (double) s.stiffness);
        m.put("damping", (double) s.damping);
        m.put("collide", s.collide);
        return m;
    }

    private static Map<String, Object> motor(MotorRecipe m) {
        return m.rotational ? obj("body", "b" + m.body, "angularVelocity", (double) m.omega, "maxImpulse", (double) m.maxImpulse)
                : obj("body", "b" + m.body, "velocity", vec(m.vx, m.vy), "maxImpulse", (double) m.maxImpulse);
    }

    private static Map<String, Object> emitter(EmitterRecipe e) {
        Map<String, Object> m = obj("name", "e" + e.id);
        if (e.body >= 0) {
            m.put("body", "b" + e.body);
        }
        m.put("from", vec(e.x1, e.y1));
        m.put("to", vec(e.x2, e.y2));
        m.put("maxCount", e.maxCount);
        m.putAll(obj("rate", (double) e.rate, "rateSpread", (double) e.rateSpread, "lifetime", (double) e.lifetime,
                "lifetimeSpread", (double) e.lifetimeSpread, "speed", (double) e.speed, "speedSpread", (double) e.speedSpread,
                "angleDeg", (double) e.angleDeg, "angleSpreadDeg", (double) e.angleSpreadDeg, "axesFixed", e.axesFixed,
                "elasticity", (double) e.elasticity, "gravityFactor", (double) e.gravityFactor, "damping", (double) e.damping,
                "collide", e.collide, "seed", e.seed));
        return m;
    }

    private static <T> List<Object> map(List<T> items, java.util.function.Function<T, Object> f) {
        List<Object> out = new ArrayList<>();
        items.forEach(i -> out.add(f.apply(i)));
        return out;
    }

    private static List<Object> vec(float x, float y) {
        return List.of((double) x, (double) y);
    }

    private static Map<String, Object> obj(Object... kv) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            m.put((String) kv[i], kv[i + 1]);
        }
        return m;
    }
}
