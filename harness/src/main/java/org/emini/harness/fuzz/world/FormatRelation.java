package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.convert.WorldToScenario;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.scenario.Scenario;
import org.emini.io.PhyReader;
import org.emini.io.PhyWriter;
import org.emini.particle.ParticleEmitter;

/**
 * A scene as YAML, as JSON, and converted to a world file and back builds the same world:
 *
 * <ul>
 *   <li>the recipe as YAML and as JSON, each loaded and built by the harness, runs bit-identically to
 *   the recipe built directly (so also to each other), tick after tick;</li>
 *   <li>the scene converted to a world file (harness convert), written, read back and converted to a
 *   scene again builds a world equal in structure (WorldDiff) within the world file's resolution: 2⁻¹²
 *   px for lengths (FX), hence 0.001 px and 10⁻⁴ relative for masses and inertias computed from
 *   rounded vertices. The scene is first given what a world file keeps (20 ticks/s, 10 fixed
 *   iterations, no simulation area, no spring damping, joints and springs that collide, multi-shapes of default
 *   material weighing their parts' sum, emitters with the builder's seeds whose particles collide);</li>
 *   <li>that world file converted to a scene and back gives the same bytes (the converter's promise
 *   from the second round on).</li>
 * </ul>
 */
final class FormatRelation implements Relation {
    /** Length tolerance of the world-file leg (px). */
    static final double LENGTH = 1e-3;
    /** Relative tolerance of the world-file leg. */
    static final double RELATIVE = 1e-4;

    @Override
    public ViolationKind kind() {
        return ViolationKind.FORMAT;
    }

    @Override
    public Profile profile() {
        return Profile.SCENE;
    }

    @Override
    public Violation check(Recipe r) {
        if (!SceneText.inexpressible(r).isEmpty()) {
            return null;
        }
        Trajectory direct = Trajectory.run(r, r.ticks);
        String[] forms = {"YAML", "JSON"};
        String[] texts = {SceneText.yaml(r, List.of(), List.of()), SceneText.json(r)};
        for (int i = 0; i < forms.length; i++) {
            Scenario scene = load(forms[i], texts[i]);
            Trajectory t = Trajectory.run(wrap(r, build(scene)), r.ticks);
            String d = direct.firstDifference(t, r.ticks);
            if (d != null) {
                return new Violation(kind(), -1, "the scene as " + forms[i] + " builds another world: " + d);
            }
        }
        return worldFile(r);
    }

    private Violation worldFile(Recipe original) {
        Recipe r = storable(original);
        Scenario scene = load("YAML", SceneText.yaml(r, List.of(), List.of()));
        ScenarioToWorld.Result phy = ScenarioToWorld.convert(scene);
        byte[] first = new PhyWriter().write(phy.world());
        double seconds = r.ticks / (double) r.ticksPerSecond;
        String back = WorldToScenario.convert(readPhy(first), "fuzz.phy", seconds).yaml();
        Scenario again = load("scene from the world file", back);
        String d = WorldDiff.of(build(scene).world(), build(again).world(), LENGTH, RELATIVE);
        if (d != null) {
            return new Violation(kind(), -1, "converted to a world file and back, the scene builds another world: " + d
                    + "; the converter listed " + phy.notConverted() + " and approximated " + phy.approximated());
        }
        byte[] second = new PhyWriter().write(ScenarioToWorld.convert(again).world());
        String third = WorldToScenario.convert(readPhy(second), "fuzz.phy", seconds).yaml();
        byte[] fourth = new PhyWriter().write(ScenarioToWorld.convert(load("second round", third)).world());
        if (!Arrays.equals(second, fourth)) {
            return new Violation(kind(), -1, "a world file converted to a scene and back changed its bytes ("
                    + second.length + " bytes against " + fourth.length + ")");
        }
        return null;
    }

    /** The recipe with only what a world file keeps. */
    static Recipe storable(Recipe original) {
        Recipe r = original.copy();
        r.ticksPerSecond = 20;
        r.ticks = Math.min(r.ticks, 120);
        r.iterations = 10;
        r.dynamicIterations = false;
        r.area = null;
        r.joints.forEach(j -> j.collide = true);
        r.springs.forEach(s -> {
            s.damping = 0f;
            s.collide = true;
        });
        for (ShapeRecipe s : r.shapes) {
            if (s.kind == ShapeRecipe.Kind.multiShape) {
                s.friction = 0.25f;
                s.elasticity = 0f;
                s.mass = 0f;
                s.parts.forEach(p -> s.mass += p.shape.mass);
            }
        }
        for (int i = 0; i < r.emitters.size(); i++) {
            r.emitters.get(i).seed = ParticleEmitter.DEFAULT_SEED + i;
            r.emitters.get(i).collide = true;
        }
        return r;
    }

    private static org.emini.io.PhyWorld readPhy(byte[] bytes) {
        try {
            return new PhyReader().read(bytes);
        } catch (org.emini.io.PhyFormatException e) {
            throw new IllegalStateException("the world file written from a scene does not read back: " + e.getMessage(), e);
        }
    }

    private static Scenario load(String form, String text) {
        ScenarioLoader.Loaded loaded = Schema.loader().load("fuzz." + form.toLowerCase().replace(' ', '-'), text, "fuzz");
        if (!loaded.ok()) {
            throw new IllegalStateException("the scene as " + form + " does not load: " + loaded.problems() + "\n" + text);
        }
        return loaded.scenario();
    }

    private static BuiltWorld build(Scenario scene) {
        try {
            return WorldBuilder.build(scene);
        } catch (org.emini.harness.build.UnsupportedElementException e) {
            throw new IllegalStateException("the scene does not build: " + e.getMessage(), e);
        }
    }

    /** A harness-built world seen as the recipe's (bodies, constraints and emitters in the same order). */
    static FuzzWorld wrap(Recipe r, BuiltWorld built) {
        Body[] bodies = built.bodies().values().toArray(new Body[0]);
        Map<Integer, Body> byId = new LinkedHashMap<>();
        for (int i = 0; i < bodies.length && i < r.bodies.size(); i++) {
            byId.put(r.bodies.get(i).id, bodies[i]);
        }
        Map<String, Constraint> constraints = new LinkedHashMap<>();
        for (int i = 0; i < built.world().getConstraintCount(); i++) {
            constraints.put("c" + i, built.world().getConstraint(i));
        }
        List<ParticleEmitter> emitters = new ArrayList<>(built.emitters().values());
        return new FuzzWorld(r, built.world(), bodies, byId, constraints, emitters, null);
    }
}
