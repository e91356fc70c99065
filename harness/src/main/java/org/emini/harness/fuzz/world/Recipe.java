package org.emini.harness.fuzz.world;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import java.util.ArrayList;
import java.util.List;

/**
 * A generated world as plain data: settings and element lists, every element with the id it was
 * generated with, bodies referred to by id. It is what the fuzzer shrinks, transforms (mirrors,
 * moves, re-times) and writes out, and it builds the same engine world every time
 * ({@link RecipeBuilder}); its JSON form is a complete, Java-free description of the world.
 */
public final class Recipe {
    /** The fuzz run's seed and the world's index in it (the generator's input). */
    public long seed;
    /** The world's index in its run. */
    public int index;
    /** The generator profile that made it ({@link Profile}). */
    public Profile profile = Profile.GENERAL;
    /** Ticks per second: 20 (the original's) or 60 in generated worlds. */
    public int ticksPerSecond = 20;
    /** Constraint iterations (substeps). */
    public int iterations = 10;
    /** Whether the solver stops once converged. */
    public boolean dynamicIterations;
    /** Whether resting bodies fall asleep. */
    public boolean sleeping;
    /** Gravity (px/s²). */
    public float gravityX;
    /** Gravity (px/s²). */
    public float gravityY = 100f;
    /** Fraction of linear velocity removed per tick. */
    public float dampingLateral;
    /** Fraction of angular velocity removed per tick. */
    public float dampingRotational;
    /** The simulation area, or null. */
    public AreaRecipe area;
    /** Whether a listener is set (events fire only then). */
    public boolean listener;
    /** Landscape material. */
    public float landscapeFriction = 0.25f;
    /** Landscape material. */
    public float landscapeElasticity;
    /** Ticks the world runs. */
    public int ticks = 200;
    /** Shapes, referred to by bodies and event filters. */
    public List<ShapeRecipe> shapes = new ArrayList<>();
    /** Bodies in creation order. */
    public List<BodyRecipe> bodies = new ArrayList<>();
    /** Landscape segments in insertion order. */
    public List<SegmentRecipe> segments = new ArrayList<>();
    /** Pin and fixed joints. */
    public List<JointRecipe> joints = new ArrayList<>();
    /** Rigid and soft springs. */
    public List<SpringRecipe> springs = new ArrayList<>();
    /** Motors. */
    public List<MotorRecipe> motors = new ArrayList<>();
    /** Particle emitters. */
    public List<EmitterRecipe> emitters = new ArrayList<>();
    /** External forces. */
    public List<ForceRecipe> forces = new ArrayList<>();
    /** Events (they fire only with a listener). */
    public List<EventRecipe> events = new ArrayList<>();
    /** Bodies removed during a tick, from a listener or a constraint. */
    public List<RemovalRecipe> removals = new ArrayList<>();

    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues().create();

    /** The recipe as JSON. */
    public String toJson() {
        return GSON.toJson(this);
    }

    /** A recipe from its JSON. */
    public static Recipe fromJson(String json) {
        return GSON.fromJson(json, Recipe.class);
    }

    /** A deep copy, to transform without touching this one. */
    public Recipe copy() {
        return GSON.fromJson(GSON.toJson(this), Recipe.class);
    }

    /** The body with an id, or null. */
    public BodyRecipe body(int id) {
        for (BodyRecipe b : bodies) {
            if (b.id == id) {
                return b;
            }
        }
        return null;
    }

    /** The shape with an id, or null. */
    public ShapeRecipe shape(int id) {
        for (ShapeRecipe s : shapes) {
            if (s.id == id) {
                return s;
            }
        }
        return null;
    }

    /** The timestep as the harness computes it from ticks per second. */
    public float timestep() {
        return (float) (1.0 / ticksPerSecond);
    }

    /** Short description: profile, settings and element counts. */
    public String summary() {
        return profile + " " + ticksPerSecond + " ticks/s, " + iterations + (dynamicIterations ? " dynamic" : " fixed")
                + " iterations, " + ticks + " ticks; " + bodies.size() + " bodies, " + segments.size() + " segments, "
                + joints.size() + " joints, " + springs.size() + " springs, " + motors.size() + " motors, "
                + emitters.size() + " emitters, " + forces.size() + " forces, " + events.size() + " events"
                + (listener ? " (listener)" : "") + ", " + removals.size() + " removals" + (area != null ? ", area" : "");
    }
}
