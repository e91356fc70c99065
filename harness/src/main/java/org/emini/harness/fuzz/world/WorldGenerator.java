package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.List;

/**
 * Seeded random worlds. The same (run seed, index, profile) gives the same recipe on every machine:
 * a single SplitMix64 stream, and values rounded to binary fractions.
 */
public final class WorldGenerator {
    private WorldGenerator() {
    }

    /** World {@code index} of run {@code seed}. */
    public static Recipe generate(long seed, int index, Profile profile) {
        Rand rand = new Rand(Rand.worldSeed(seed, index) ^ profile.ordinal());
        Recipe r = switch (profile) {
            case SEPARATED -> LaneGenerator.generate(rand);
            case SMOOTH -> SmoothGenerator.generate(rand);
            default -> general(rand, Features.of(profile));
        };
        r.seed = seed;
        r.index = index;
        r.profile = profile;
        return r;
    }

    private static Recipe general(Rand rand, Features f) {
        Recipe r = new Recipe();
        settings(rand, r, f);
        ShapeGenerator shapes = new ShapeGenerator(rand, f.sceneOnly(), 0);
        Placement placement = new Placement(r, 1f);
        ArenaGenerator arena = new ArenaGenerator(rand, r, placement, shapes, 0);
        float half = arena.build();
        if (!f.energySources()) {
            r.landscapeElasticity = 0f;
        } else if (rand.chance(0.3)) {
            r.landscapeElasticity = rand.factor(0.6);
        }
        List<ShapeRecipe> pool = new ArrayList<>();
        for (int i = rand.between(2, 7); i > 0; i--) {
            ShapeRecipe s = shapes.any(4, 50, f.energySources() ? 0.9 : 0);
            r.shapes.add(s);
            pool.add(s);
        }
        int wanted = rand.chance(0.2) ? rand.between(1, 3) : rand.between(4, 40);
        int id = arena.nextBodyId();
        for (int attempt = 0, placed = 0; placed < wanted && attempt < 8 * wanted; attempt++) {
            BodyRecipe b = dynamicBody(rand, pool.get((int) (rand.unit() * pool.size())), half, f);
            b.id = id;
            if (placement.tryAdd(b)) {
                id++;
                placed++;
            }
        }
        if (!f.sceneOnly() || rand.chance(0.5)) {
            area(rand, r, half);
        }
        new ElementGenerator(rand, r, f).all();
        if (f.extreme()) {
            Extremes.apply(rand, r);
        }
        return r;
    }

    private static void settings(Rand rand, Recipe r, Features f) {
        r.ticksPerSecond = rand.chance(0.5) ? 20 : 60;
        r.ticks = r.ticksPerSecond == 20 ? 120 : 180;
        r.iterations = rand.pick(1, 2, 4, 6, 8, 10, 10, 10, 12, 16, 20);
        r.dynamicIterations = rand.chance(0.4);
        double g = rand.unit();
        if (g < 0.15) {
            r.gravityX = rand.length(-40, 40);
            r.gravityY = rand.length(60, 150);
        } else if (g < 0.25) {
            r.gravityY = 0f;
        } else if (g < 0.3) {
            r.gravityY = 400f;
        }
        if (rand.chance(0.3)) {
            r.dampingLateral = rand.factor(0.05);
            r.dampingRotational = rand.factor(0.05);
        }
        // Features a scene file and a world file do not share (SCENE worlds go through both).
        r.sleeping = !f.sceneOnly() && rand.chance(0.3);
    }

    private static BodyRecipe dynamicBody(Rand rand, ShapeRecipe shape, float half, Features f) {
        BodyRecipe b = new BodyRecipe();
        b.shape = shape.id;
        b.x = rand.length(-half + 30, half - 30);
        b.y = rand.length(-450, -60);
        b.angle = rand.chance(0.7) ? rand.angle(-Math.PI, Math.PI) : 0f;
        if (rand.chance(0.5)) {
            b.vx = rand.length(-150, 150);
            b.vy = rand.length(-150, 150);
            b.omega = rand.range(-4, 4, Rand.ANGLE);
        }
        b.bullet = !f.sceneOnly() && rand.chance(0.1);
        b.rotatable = !rand.chance(0.1);
        b.interacting = !rand.chance(0.05);
        b.gravity = !rand.chance(0.08);
        if (rand.chance(0.15)) {
            b.layers = 1 << rand.between(0, 2);
        }
        if (!f.sceneOnly()) {
            if (rand.chance(0.1)) {
                b.categories = 1 << rand.between(0, 3);
                b.mask = ~(1 << rand.between(0, 3));
                b.group = rand.pick(-1, 0, 0, 1);
            }
            b.sensor = rand.chance(0.03);
            b.sleepingAllowed = !rand.chance(0.05);
        }
        return b;
    }

    /** A simulation area over part of the world (a rectangle, or the original's x range), a quarter of the time. */
    private static void area(Rand rand, Recipe r, float half) {
        if (!rand.chance(0.25)) {
            return;
        }
        AreaRecipe a = new AreaRecipe();
        a.range = rand.chance(0.5);
        a.minX = rand.length(-half - 50, 0);
        a.maxX = rand.length(0, half + 50);
        a.minY = rand.length(-600, -100);
        a.maxY = rand.length(0, 100);
        r.area = a;
    }
}
