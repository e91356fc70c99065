package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.Section;

/**
 * Builders of the springs and motors sections ({@link JointBuilder} builds the joints), through the engine's public API.
 * Which joined bodies may not collide is {@link ConnectedPairs}'s work, done before these run.
 */
final class ConstraintBuilders {
    private ConstraintBuilders() {
    }

    private static float x(JsonNode v) {
        return (float) v.get(0).asDouble();
    }

    private static float y(JsonNode v) {
        return (float) v.get(1).asDouble();
    }

    /** Springs: rigid links without a stiffness, Hooke springs with one. */
    static final class Springs implements ElementBuilder {
        @Override
        public void build(Section section, BuiltWorld world) {
            for (int i = 0; i < section.node().size(); i++) {
                JsonNode s = section.node().get(i);
                JsonPath p = section.path().index(i);
                Body a = world.body(s.get("bodyA").asText());
                Body b = world.body(s.get("bodyB").asText());
                JsonNode pa = s.path("anchorA");
                JsonNode pb = s.path("anchorB");
                float ax = pa.isArray() ? x(pa) : 0f;
                float ay = pa.isArray() ? y(pa) : 0f;
                float bx = pb.isArray() ? x(pb) : 0f;
                float by = pb.isArray() ? y(pb) : 0f;
                Spring spring = Located.at(p, () -> s.has("restLength")
                    ? new Spring(a, b, ax, ay, bx, by, (float) s.get("restLength").asDouble())
                    : new Spring(a, b, ax, ay, bx, by));
                float k = (float) s.path("stiffness").asDouble(0);
                if (k > 0f) {
                    Located.at(p.key("stiffness"), () -> spring.setCoefficient(k));
                    Located.at(p.key("damping"), () -> spring.setDamping((float) s.path("damping").asDouble(0)));
                }
                world.world().addConstraint(spring);
            }
        }
    }

    /** Motors: the scene's cap is an impulse per tick; the engine's is a force, so divide by dt. */
    static final class Motors implements ElementBuilder {
        @Override
        public void build(Section section, BuiltWorld world) {
            float dt = world.world().getTimestep();
            for (int i = 0; i < section.node().size(); i++) {
                JsonNode m = section.node().get(i);
                Body body = world.body(m.get("body").asText());
                float max = (float) m.get("maxImpulse").asDouble() / dt;
                Motor motor = Located.at(section.path().index(i), () -> m.has("velocity")
                    ? new Motor(body, x(m.get("velocity")), y(m.get("velocity")), max)
                    : new Motor(body, (float) m.path("angularVelocity").asDouble(0), max));
                world.world().addConstraint(motor);
            }
        }
    }
}
