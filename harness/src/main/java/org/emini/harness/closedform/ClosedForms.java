package org.emini.harness.closedform;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Map;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.WorldSpec;

/** Creates the closed-form model a scene's {@code reference.closedForm} names. */
public final class ClosedForms {
    private ClosedForms() {
    }

    /**
     * The model of the scene's {@code reference.closedForm}, or null when it has none or the model
     * cannot be made (the engine refuses the bodies, so the pendulum lacks its bob's inertia).
     *
     * <p>Made on a world of the scene's bodies alone: a model reads the bodies, the gravity and its own
     * parameters (the pendulum also the engine's inertia of its bob), never the other elements. So a
     * scene with an element the engine lacks keeps its truth, and the oracle's run of it is judged
     * against the model, in every command alike.
     */
    public static ClosedForm of(Scenario scenario) {
        if (scenario.closedForm() == null) {
            return null;
        }
        Scenario bodiesOnly = scenario.withElements(Map.of());
        BuiltWorld built;
        try {
            built = WorldBuilder.build(bodiesOnly);
        } catch (Exception e) {
            built = null;
        }
        try {
            return create(bodiesOnly, built);
        } catch (RuntimeException e) {
            return null;
        }
    }

    private static ClosedForm create(Scenario scenario, BuiltWorld built) {
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
