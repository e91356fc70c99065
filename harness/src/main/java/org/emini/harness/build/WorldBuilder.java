package org.emini.harness.build;

import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.dynamics.SolverSettings;
import org.emini.dynamics.World;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.emini.harness.scenario.WorldSpec;

/**
 * Builds an engine world from a scene through the engine's public API only, in the order a program
 * would: world settings, shapes, bodies, then the other elements (each by its {@link ElementBuilder}).
 */
public final class WorldBuilder {
    private WorldBuilder() {
    }

    /**
     * Builds the world.
     *
     * @throws UnsupportedElementException if the scene uses something the engine cannot express
     * @throws IllegalArgumentException if the engine refuses a value (an invalid polygon, ...)
     */
    public static BuiltWorld build(Scenario scenario) throws UnsupportedElementException {
        Map<String, ElementBuilder> builders = ElementBuilders.all();
        for (String element : scenario.elements().keySet()) {
            if (!builders.containsKey(element)) {
                throw new UnsupportedElementException(element, scenario.elements().get(element).path());
            }
        }
        World world = new World();
        settings(world, scenario.world());
        BuiltWorld built = new BuiltWorld(scenario, world);
        ShapeFactory shapes = new ShapeFactory();
        for (BodySpec spec : scenario.bodies()) {
            Body body = body(spec, shapes);
            world.addBody(body);
            built.add(spec.name(), body);
        }
        for (Map.Entry<String, ElementBuilder> e : builders.entrySet()) {
            Section section = scenario.elements().get(e.getKey());
            if (section != null) {
                e.getValue().build(section, built);
            }
        }
        return built;
    }

    static void settings(World world, WorldSpec w) {
        world.setTimestep((float) w.timestep());
        world.setConstraintIterations(w.iterations());
        world.setConstraintIterationDynamic(w.dynamicIterations());
        world.setGravity((float) w.gravityX(), (float) w.gravityY());
        world.setDampingLateral((float) w.dampingLateral());
        world.setDampingRotational((float) w.dampingRotational());
        SolverSettings s = world.getSolverSettings();
        for (Map.Entry<String, Double> e : w.solver().entrySet()) {
            float v = e.getValue().floatValue();
            switch (e.getKey()) {
                case "linearSlop" -> s.setLinearSlop(v);
                case "speculativeDistance" -> s.setSpeculativeDistance(v);
                case "aabbMargin" -> s.setAabbMargin(v);
                case "contactHertz" -> s.setContactHertz(v);
                case "contactDampingRatio" -> s.setContactDampingRatio(v);
                case "contactPushMaxVelocity" -> s.setContactPushMaxVelocity(v);
                case "restitutionThreshold" -> s.setRestitutionThreshold(v);
                case "convergenceTolerance" -> s.setConvergenceTolerance(v);
                default -> throw new IllegalArgumentException("unknown solver setting " + e.getKey());
            }
        }
    }

    private static Body body(BodySpec spec, ShapeFactory shapes) throws UnsupportedElementException {
        BodyState s = spec.state();
        Body body = new Body((float) spec.x(), (float) spec.y(), shapes.shape(spec.shape()), !s.isStatic());
        body.setRotatable(s.rotatable());
        body.setInteracting(s.interacting());
        body.setGravityAffected(s.gravity());
        for (int layer : s.layers()) {
            body.addCollisionLayer(layer);
        }
        body.setAngle((float) s.angle());
        body.setVelocity((float) s.vx(), (float) s.vy());
        body.setAngularVelocity((float) s.angularVelocity());
        return body;
    }
}
