package org.emini.harness.closedform;

import com.fasterxml.jackson.databind.JsonNode;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.WorldSpec;

/** Creates the closed-form model a scene's {@code reference.closedForm} names. */
public final class ClosedForms {
    private ClosedForms() {
    }

    /**
     * The model, or null when the scene has none.
     *
     * @param scenario the scene
     * @param built its world (for inertias the engine computes)
     */
    public static ClosedForm create(Scenario scenario, BuiltWorld built) {
        if (scenario.closedForm() == null) {
            return null;
        }
        JsonNode c = scenario.closedForm().node();
        WorldSpec w = scenario.world();
        double g = Math.hypot(w.gravityX(), w.gravityY());
        switch (c.get("model").asText()) {
            case "projectile":
            case "freeRotation":
                return new Ballistic(body(scenario, c, "body"), w.gravityX(), w.gravityY());
            case "incline":
                return new Incline(body(scenario, c, "body"), g, c.get("slopeDeg").asDouble(),
                        c.path("friction").asDouble(0), 1, false);
            case "rollingDisc": {
                BodySpec b = body(scenario, c, "body");
                double r = c.has("radius") ? c.get("radius").asDouble() : b.shape().radius();
                return new Incline(b, g, c.get("slopeDeg").asDouble(), 0, r, true);
            }
            case "collision1d":
                return new Collision1d(body(scenario, c, "bodyA"), body(scenario, c, "bodyB"),
                        c.get("elasticity").asDouble());
            case "bouncingBall":
                return new BouncingBall(body(scenario, c, "body"), w.gravityY(), c.get("restY").asDouble(),
                        c.get("elasticity").asDouble());
            case "pendulum": {
                BodySpec b = body(scenario, c, "body");
                JsonNode pivot = c.get("pivot");
                return new Pendulum(b, built.body(b.name()).getShape().getInertia(), pivot.get(0).asDouble(),
                        pivot.get(1).asDouble(), w.gravityX(), w.gravityY(), scenario.run().duration());
            }
            case "dampedSpring": {
                JsonNode anchor = c.get("anchor");
                return new DampedSpring(body(scenario, c, "body"), anchor.get(0).asDouble(), anchor.get(1).asDouble(),
                        c.get("stiffness").asDouble(), c.path("damping").asDouble(0), c.get("restLength").asDouble(),
                        w.gravityX(), w.gravityY());
            }
            default:
                throw new IllegalArgumentException("unknown closed-form model " + c.get("model"));
        }
    }

    private static BodySpec body(Scenario s, JsonNode c, String key) {
        return s.body(c.get(key).asText());
    }
}
