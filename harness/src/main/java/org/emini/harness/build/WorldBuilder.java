package org.emini.harness.build;

import java.util.List;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.dynamics.SolverSettings;
import org.emini.world.World;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.emini.harness.scenario.SleepSpec;
import org.emini.harness.scenario.WorldSpec;
import org.emini.shape.Shape;

/**
 * Builds an engine world from a scene through the engine's public API only, in the order a program
 * would: world settings, shapes, bodies, then the other elements (each by its {@link ElementBuilder}).
 */
public final class WorldBuilder {
    private WorldBuilder() {
    }

    /** The engine's default speculative distance, which {@code run --nudge} scales in a scene that sets none. */
    public static double defaultSpeculativeDistance() {
        return new SolverSettings().getSpeculativeDistance();
    }

    /**
     * Builds the world.
     *
     * @throws UnsupportedElementException if the scene uses something the engine cannot express
     * @throws BuildRefusedException if the engine refuses a value (an invalid polygon, ...), naming where the
     *     scene writes it
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
        ConnectedPairs.apply(built);
        for (Map.Entry<String, ElementBuilder> e : builders.entrySet()) {
            Section section = scenario.elements().get(e.getKey());
            if (section != null) {
                e.getValue().build(section, built);
            }
        }
        return built;
    }

    static void settings(World world, WorldSpec w) {
        JsonPath p = JsonPath.ROOT.key("world");
        Located.at(p, () -> world.setTimestep((float) w.timestep()));
        Located.at(p.key("iterations"), () -> world.setConstraintIterations(w.iterations()));
        world.setConstraintIterationDynamic(w.dynamicIterations());
        Located.at(p.key("gravity"), () -> world.setGravity((float) w.gravityX(), (float) w.gravityY()));
        Located.at(p.key("damping").key("lateral"), () -> world.setDampingLateral((float) w.dampingLateral()));
        Located.at(p.key("damping").key("rotational"), () -> world.setDampingRotational((float) w.dampingRotational()));
        SolverSettings s = world.getSolverSettings();
        // The length scale first: it scales the tolerances, including those the scene sets after it.
        Double scale = w.solver().get("lengthScale");
        if (scale != null) {
            Located.at(p.key("solver").key("lengthScale"), () -> s.setLengthScale(scale.floatValue()));
        }
        for (Map.Entry<String, Double> e : w.solver().entrySet()) {
            if (e.getKey().equals("lengthScale")) {
                continue;
            }
            float v = e.getValue().floatValue();
            Located.at(p.key("solver").key(e.getKey()), () -> solver(s, e.getKey(), v));
        }
        SleepSpec sleep = w.sleeping();
        JsonPath sp = p.key("sleeping");
        if (!Double.isNaN(sleep.linearTolerance())) {
            Located.at(sp.key("linearTolerance"), () -> s.setSleepLinearTolerance((float) sleep.linearTolerance()));
        }
        if (!Double.isNaN(sleep.angularTolerance())) {
            Located.at(sp.key("angularTolerance"), () -> s.setSleepAngularTolerance((float) sleep.angularTolerance()));
        }
        if (!Double.isNaN(sleep.timeToSleep())) {
            Located.at(sp.key("timeToSleep"), () -> s.setTimeToSleep((float) sleep.timeToSleep()));
        }
        world.setSleepingEnabled(sleep.enabled());
    }

    private static void solver(SolverSettings s, String key, float v) {
        switch (key) {
            case "linearSlop" -> s.setLinearSlop(v);
            case "speculativeDistance" -> s.setSpeculativeDistance(v);
            case "speculativeSweep" -> s.setSpeculativeSweep(v);
            case "manifoldReuseDistance" -> s.setManifoldReuseDistance(v);
            case "aabbMargin" -> s.setAabbMargin(v);
            case "contactHertz" -> s.setContactHertz(v);
            case "contactDampingRatio" -> s.setContactDampingRatio(v);
            case "contactPushMaxVelocity" -> s.setContactPushMaxVelocity(v);
            case "restitutionThreshold" -> s.setRestitutionThreshold(v);
            case "convergenceTolerance" -> s.setConvergenceTolerance(v);
            case "impactTolerance" -> s.setImpactTolerance(v);
            case "impactRelaxPasses" -> s.setImpactRelaxPasses((int) Math.round(v));
            case "sinkLimit" -> s.setSinkLimit(v);
            case "sinkSubstepFactor" -> s.setSinkSubstepFactor(v);
            default -> throw new IllegalArgumentException("unknown solver setting " + key);
        }
    }

    private static Body body(BodySpec spec, ShapeFactory shapes) {
        BodyState s = spec.state();
        Shape shape = shapes.shape(spec.shape());
        // A written body's values have their own keys; a generated body's come from its generator.
        boolean written = spec.path().parent().elements().equals(List.of("bodies"));
        Body body = Located.at(written ? spec.path().key("position") : spec.path(),
                () -> new Body((float) spec.x(), (float) spec.y(), shape, !s.isStatic() && !s.kinematic()));
        if (s.kinematic()) {
            body.setKinematic(true);
        }
        body.setRotatable(s.rotatable());
        body.setInteracting(s.interacting());
        body.setGravityAffected(s.gravity());
        body.setSleepingAllowed(s.sleepingAllowed());
        body.setSensor(s.sensor());
        for (int layer : s.layers()) {
            Located.at(key(spec, written, "layers"), () -> body.addCollisionLayer(layer));
        }
        body.setCategoryBits(s.categoryBits());
        body.setMaskBits(s.maskBits());
        body.setGroupIndex(s.group());
        Located.at(key(spec, written, "angle"), () -> body.setAngle((float) s.angle()));
        Located.at(key(spec, written, "velocity"), () -> body.setVelocity((float) s.vx(), (float) s.vy()));
        Located.at(key(spec, written, "angularVelocity"), () -> body.setAngularVelocity((float) s.angularVelocity()));
        return body;
    }

    private static JsonPath key(BodySpec spec, boolean written, String key) {
        return written ? spec.path().key(key) : spec.path().key("body").key(key);
    }
}
