package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.EverythingScene;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The narrowphase and the contact solve shared among threads ({@link Simulation#setWorkerCount}) give
 * the results of one thread bit for bit: the narrowphase's contacts and every colour are split among
 * the threads (the smallest part lowered to one contact), in the scene that uses every element, with
 * fixed and dynamic iterations, and in a pile with impacts that runs the hot relax passes. The
 * application's collision filter is still asked on the thread that ticks.
 */
class WorkerCountTest {
    private static long everything(boolean dynamicIterations, int workers, int ticks) {
        EverythingScene scene = new EverythingScene(dynamicIterations);
        scene.world.setWorkerCount(workers);
        scene.world.setSplitAlways(true);
        try {
            scene.run(ticks);
            return scene.hash();
        } finally {
            scene.world.setWorkerCount(1);
        }
    }

    @Test
    void theEverythingSceneIsTheSameForAnyThreadCount() {
        for (boolean dynamic : new boolean[] {false, true}) {
            long one = everything(dynamic, 1, 400);
            assertEquals(one, everything(dynamic, 2, 400), "2 threads, dynamic iterations " + dynamic);
            assertEquals(one, everything(dynamic, 3, 400), "3 threads, dynamic iterations " + dynamic);
        }
    }

    /** A world at 60 ticks/s whose solve is shared among this many threads, every colour split. */
    private static World threaded(int workers) {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setWorkerCount(workers);
        world.setSplitAlways(true);
        return world;
    }

    private static long pile(int workers) {
        World world = threaded(workers);
        try {
            Scenes.ground(world, 0f, 2000f);
            Scenes.pyramid(world, 15, 20f);
            Shape heavy = Shape.createRectangle(30f, 30f);
            heavy.setMass(50f);
            for (int t = 0; t < 240; t++) {
                if (t % 40 == 0) {
                    // Heavy boxes dropped on the pile: impacts that run the hot relax passes.
                    world.addBody(new Body(-100f + t, -600f, heavy, true));
                }
                world.tick();
            }
            return EverythingScene.bodyHash(world);
        } finally {
            world.setWorkerCount(1);
        }
    }

    /**
     * A hash of every contact event of a rain of mixed bodies, in the order the step data lists them:
     * began (pair, points, first separation), ended (pair) and hits (speed, place).
     */
    private static long contactEvents(int workers) {
        World world = threaded(workers);
        try {
            Scenes.ground(world, 300f, 2000f);
            java.util.Random random = new java.util.Random(5);
            for (int i = 0; i < 120; i++) {
                Shape s = i % 2 == 0 ? Shape.createCircle(6 + random.nextInt(8))
                    : Shape.createRectangle(10 + random.nextInt(10), 10 + random.nextInt(10));
                s.setElasticity(random.nextFloat());
                world.addBody(new Body(-300 + random.nextInt(600), -random.nextInt(600), s, true));
            }
            world.setHitEventThreshold(20f);
            long h = 0;
            int events = 0;
            for (int t = 0; t < 400; t++) {
                world.tick();
                StepData d = ((Simulation) world).getStepData();
                for (int i = 0; i < d.getBeginCount(); i++) {
                    Contact c = d.getBeginContact(i);
                    h = 31 * h + c.getBodyA().getId() * 1000L + c.getBodyB().getId() + 7L * c.getPointCount()
                        + Float.floatToIntBits(c.getSeparation(0));
                }
                for (int i = 0; i < d.getEndCount(); i++) {
                    h = 31 * h + d.getEndBodyA(i).getId() * 1000L + d.getEndBodyB(i).getId();
                }
                for (int i = 0; i < d.getHitCount(); i++) {
                    h = 31 * h + Float.floatToIntBits(d.getHitSpeed(i)) + Float.floatToIntBits(d.getHitX(i));
                }
                events += d.getBeginCount() + d.getEndCount() + d.getHitCount();
            }
            assertTrue(events > 100, "the rain makes events: " + events);
            return h;
        } finally {
            world.setWorkerCount(1);
        }
    }

    @Test
    void contactEventsComeInTheSameOrderForAnyThreadCount() {
        // The narrowphase's threads set each contact's touching flag; the events are listed after, in
        // the contacts' order.
        long one = contactEvents(1);
        assertEquals(one, contactEvents(2));
        assertEquals(one, contactEvents(3));
    }

    /** A resting pyramid whose thread count changes every 30 ticks, or stays 1 (switchThreads false). */
    private static long switching(boolean switchThreads) {
        World world = threaded(1);
        int[] counts = {1, 2, 1, 3, 2};
        try {
            Scenes.ground(world, 0f, 2000f);
            Scenes.pyramid(world, 12, 20f);
            for (int t = 0; t < 150; t++) {
                if (switchThreads && t % 30 == 0) {
                    world.setWorkerCount(counts[t / 30]);
                }
                world.tick();
            }
            return EverythingScene.bodyHash(world);
        } finally {
            world.setWorkerCount(1);
        }
    }

    @Test
    void changingTheThreadCountBetweenTicksChangesNothing() {
        // A resting pile keeps its colouring from tick to tick; the order of its slots and bodies
        // depends on whether threads share the solve, so a change of count must colour afresh.
        assertEquals(switching(false), switching(true));
    }

    @Test
    void aPileTakingImpactsIsTheSameForAnyThreadCount() {
        long one = pile(1);
        assertEquals(one, pile(2));
        assertEquals(one, pile(4));
    }

    /**
     * Twelve separate piles of boxes, each with elastic balls dropped on it: small islands, which the
     * threads solve whole (SolveIslands), and the wide one across the ground at the end joins four of
     * them into a large one, solved colour by colour. A hash of the bodies and of every begin and hit
     * event, in the order the step data lists them. With sleeping on, the piles fall asleep after the
     * drops and the plank wakes four of them.
     */
    private static long islands(int workers, int[] runs, boolean sleeping) {
        World world = threaded(workers);
        ((Simulation) world).setSleepingEnabled(sleeping);
        try {
            Scenes.ground(world, 0f, 6000f);
            Shape box = Shape.createRectangle(20f, 20f);
            Shape ball = Shape.createCircle(8f);
            ball.setElasticity(0.8f);
            for (int pile = 0; pile < 12; pile++) {
                float x = -2600f + pile * 400f;
                for (int row = 0; row < 6; row++) {
                    for (int j = 0; j < 6 - row; j++) {
                        world.addBody(new Body(x + (j - 0.5f * (5 - row)) * 21f, -10f - row * 20f, box, true));
                    }
                }
            }
            world.setHitEventThreshold(10f);
            long h = 0;
            for (int t = 0; t < 420; t++) {
                if (t % 25 == 0 && t < 150) {
                    for (int pile = 0; pile < 12; pile++) {
                        world.addBody(new Body(-2600f + pile * 400f + (t % 50 == 0 ? -9f : 9f), -300f, ball, true));
                    }
                }
                if (t == 300) {
                    // A plank across four piles: one island of them.
                    world.addBody(new Body(-2000f, -400f, Shape.createRectangle(1300f, 10f), true));
                }
                world.tick();
                int asleep = 0;
                for (Body b : world.getBodies()) {
                    asleep += b.isSleeping() ? 1 : 0;
                }
                runs[1] = Math.max(runs[1], asleep);
                StepData d = ((Simulation) world).getStepData();
                for (int i = 0; i < d.getBeginCount(); i++) {
                    Contact c = d.getBeginContact(i);
                    h = 31 * h + c.getBodyA().getId() * 1000L + c.getBodyB().getId();
                }
                for (int i = 0; i < d.getHitCount(); i++) {
                    h = 31 * h + Float.floatToIntBits(d.getHitSpeed(i)) + Float.floatToIntBits(d.getHitX(i));
                }
                runs[0] = Math.max(runs[0], ((Simulation) world).solver.contactSolver().islandRuns());
            }
            return 31 * h + EverythingScene.bodyHash(world);
        } finally {
            world.setWorkerCount(1);
        }
    }

    @Test
    void separatePilesSolvedIslandByIslandAreTheSameForAnyThreadCount() {
        for (boolean sleeping : new boolean[] {false, true}) {
            int[] runs = new int[2];
            long one = islands(1, runs, sleeping);
            assertEquals(sleeping, runs[1] > 100, "bodies asleep at once: " + runs[1]);
            assertEquals(0, runs[0], "one thread: the colours' layout");
            assertEquals(one, islands(2, runs, sleeping), "2 threads, sleeping " + sleeping);
            assertEquals(2, runs[0], "2 threads: a run of islands each");
            assertEquals(one, islands(3, runs, sleeping), "3 threads, sleeping " + sleeping);
            assertEquals(3, runs[0], "3 threads: a run of islands each");
        }
    }

    @Test
    void aWorldOfFewBodiesTicksOnTheCallingThreadAlone() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setWorkerCount(2);
        try {
            Scenes.ground(world, 0f, 20000f);
            int below = Simulation.MIN_THREADED_BODIES - 1;
            for (int i = 0; i < below; i++) {
                world.addBody(new Body(-9000f + 45f * i, -100f, Shape.createRectangle(20f, 20f), true));
            }
            world.tick();
            assertTrue(!((Simulation) world).sharedLastTick(), below + " bodies: alone");
            // Split always, the same world shares its tick; back off, it no longer does.
            world.setSplitAlways(true);
            world.tick();
            assertTrue(((Simulation) world).sharedLastTick() && world.isSplitAlways(), below + " bodies, split always: shared");
            world.setSplitAlways(false);
            world.tick();
            assertTrue(!((Simulation) world).sharedLastTick() && !world.isSplitAlways(), below + " bodies, split no longer: alone");
            world.addBody(new Body(-9000f, -200f, Shape.createRectangle(20f, 20f), true));
            world.tick();
            assertTrue(((Simulation) world).sharedLastTick(), (below + 1) + " bodies: shared");
        } finally {
            world.setWorkerCount(1);
        }
    }

    @Test
    void theCollisionFilterIsAskedOnTheTickingThreadOnly() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setWorkerCount(2);
        world.setSplitAlways(true);
        Thread ticking = Thread.currentThread();
        int[] asked = new int[2];
        world.setCollisionFilter((a, b) -> {
            asked[Thread.currentThread() == ticking ? 0 : 1]++;
            return true;
        });
        try {
            Scenes.ground(world, 0f, 2000f);
            Body[] boxes = Scenes.pyramid(world, 8, 20f);
            for (int t = 0; t < 120; t++) {
                // A layer change makes the filter of each of the box's contacts be asked again.
                boxes[t % boxes.length].setCollisionLayers(t % 2 == 0 ? 2 : 4);
                world.tick();
            }
        } finally {
            world.setWorkerCount(1);
        }
        assertTrue(asked[0] > 120, "asked on the ticking thread: " + asked[0]);
        assertEquals(0, asked[1], "asked on a worker thread");
    }

    /**
     * Forty boxes falling apart from one another, two of them (the 10th and the 31st) given the same
     * extreme value; the tick's error (or none) and every body's state after it.
     */
    private static String leaving(int workers, java.util.function.BiConsumer<Body, Float> change, float value) {
        World world = threaded(workers);
        try {
            Scenes.ground(world, 0f, 4000f);
            Body[] boxes = new Body[40];
            for (int i = 0; i < boxes.length; i++) {
                boxes[i] = new Body(-1500f + 75f * i, -300f - 10f * (i % 7), Shape.createRectangle(20f, 20f), true);
                world.addBody(boxes[i]);
            }
            String error = "none";
            for (int t = 0; t < 3; t++) {
                if (t == 1) {
                    change.accept(boxes[9], value);
                    change.accept(boxes[30], value);
                }
                try {
                    world.tick();
                } catch (IllegalStateException e) {
                    error = e.getMessage();
                    // Both left it in the same tick: the error names the first in the world's order.
                    assertTrue(error.startsWith("World.tick: Body#" + boxes[9].getId() + " "), error);
                    break;
                }
            }
            return error + " / " + EverythingScene.bodyHash(world);
        } finally {
            world.setWorkerCount(1);
        }
    }

    @Test
    void theFirstBodyToLeaveTheFiniteRangeIsNamedForAnyThreadCount() {
        // The per-body loops that look for a body outside the finite range (the proxies' update, the
        // fast-body marks, the write-back's backstop) are split among the threads; the error names the
        // first. The marks find these; with them disabled by hand, the write-back named the same body.
        java.util.List<java.util.function.BiConsumer<Body, Float>> changes = java.util.Arrays.asList(
            (b, v) -> b.setVelocity(v, v),
            (b, v) -> b.applyForce(v, -v),
            (b, v) -> b.setAngularVelocity(v),
            (b, v) -> {
                b.setPosition(v, v);
                b.setVelocity(-v, -v);
            });
        int errors = 0;
        for (float v : new float[] {1e30f, 3.4e38f, Float.MAX_VALUE}) {
            for (int c = 0; c < changes.size(); c++) {
                String one = leaving(1, changes.get(c), v);
                assertEquals(one, leaving(2, changes.get(c), v), "change " + c + ", value " + v + ", 2 threads");
                assertEquals(one, leaving(3, changes.get(c), v), "change " + c + ", value " + v + ", 3 threads");
                if (!one.startsWith("none")) {
                    errors++;
                }
            }
        }
        assertTrue(errors >= 4, "errors: " + errors);
    }

    @Test
    void theCountIsCheckedAndReadBack() {
        World world = new World();
        assertEquals(1, world.getWorkerCount());
        world.setWorkerCount(2);
        assertEquals(2, world.getWorkerCount());
        world.setWorkerCount(1);
        assertEquals(1, world.getWorkerCount());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> world.setWorkerCount(0));
        assertTrue(e.getMessage().contains("setWorkerCount"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> world.setWorkerCount(65));
    }
}
