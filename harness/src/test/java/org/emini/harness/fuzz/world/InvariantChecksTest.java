package org.emini.harness.fuzz.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.function.Consumer;
import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Each invariant catches a defect planted in a small world that otherwise keeps them all: a box
 * dropped on a static floor, 20 ticks/s, 10 fixed iterations.
 */
class InvariantChecksTest {
    /** A 20 px box 100 px above a static floor whose top is at y = 0. */
    static Recipe drop() {
        Recipe r = new Recipe();
        r.profile = Profile.PASSIVE;
        r.ticks = 80;
        ShapeRecipe floor = new ShapeRecipe();
        floor.kind = ShapeRecipe.Kind.rectangle;
        floor.width = 400;
        floor.height = 20;
        ShapeRecipe box = new ShapeRecipe();
        box.id = 1;
        box.kind = ShapeRecipe.Kind.rectangle;
        box.width = 20;
        box.height = 20;
        r.shapes.add(floor);
        r.shapes.add(box);
        BodyRecipe f = new BodyRecipe();
        f.y = 10;
        f.dynamic = false;
        BodyRecipe b = new BodyRecipe();
        b.id = 1;
        b.shape = 1;
        b.y = -110;
        r.bodies.add(f);
        r.bodies.add(b);
        return r;
    }

    private static WorldCheck.Result run(Recipe r, ViolationKind kind, Consumer<FuzzWorld> plant) {
        return WorldCheck.run(r, Set.of(kind), r.ticks, plant);
    }

    private static Body box(FuzzWorld w) {
        return w.bodies()[1];
    }

    /**
     * Zero gravity, at rest: a joint made where both bodies were sets a body creeping at 8·10⁻⁸ px/s
     * (rounding of its anchors), which the energy bound of a world with neither gravity nor motion once
     * counted as created energy; a launch at 1 px/s still is.
     */
    @Test
    void aCreepNoOneSeesIsNoEnergyCreatedButAOnePixelASecondLaunchIs() {
        Recipe r = WorldGenerator.generate(3, 177, Profile.PASSIVE);
        assertNull(WorldCheck.run(r, Set.of(ViolationKind.ENERGY), r.ticks).of(ViolationKind.ENERGY));
        Recipe still = drop();
        still.gravityY = 0;
        still.bodies.get(1).y = -50;
        assertNull(run(still, ViolationKind.ENERGY, w -> { }).of(ViolationKind.ENERGY));
        assertNotNull(run(still, ViolationKind.ENERGY, w -> w.world().addExternalForce((world, dt) -> {
            if (world.getTickCount() == 10) {
                box(w).setVelocity(1f, 0f);
            }
        })).of(ViolationKind.ENERGY));
    }

    @Test
    void theUnplantedDropKeepsEveryInvariant() {
        assertEquals(java.util.List.of(), WorldCheck.run(drop()).violations());
    }

    /** The engine now stops the tick itself on a non-finite constraint force, with its documented error. */
    @Test
    void aNonFiniteConstraintForceIsCaught() {
        Violation v = run(drop(), ViolationKind.EXCEPTION, w -> w.world().addConstraint(new Planted(w.world(), 0) {
            @Override
            public float getForce() {
                return Float.NaN;
            }
        })).of(ViolationKind.EXCEPTION);
        assertNotNull(v);
        assertTrue(v.message().contains("exerted a force of NaN"), v.message());
    }

    @Test
    void anExceptionFromATickIsCaughtWithTheFrameThatThrewIt() {
        Violation v = run(drop(), ViolationKind.EXCEPTION, w -> w.world().addConstraint(new Planted(w.world(), 5) {
            @Override
            void act() {
                throw new IndexOutOfBoundsException("planted");
            }
        })).of(ViolationKind.EXCEPTION);
        assertEquals(5, v.tick());
        assertTrue(v.message().startsWith("java.lang.IndexOutOfBoundsException: planted at dynamics.Solver.solve"), v.message());
    }

    @Test
    void aClearErrorEndsAWorldThatRemovesBodiesWithoutAViolation() {
        Recipe r = drop();
        RemovalRecipe m = new RemovalRecipe();
        m.body = 1;
        m.tick = 50;
        m.via = RemovalRecipe.Via.constraint;
        r.removals.add(m);
        WorldCheck.Result result = WorldCheck.run(r, Set.of(ViolationKind.values()), r.ticks, w -> w.world().addConstraint(
                new Planted(w.world(), 3) {
                    @Override
                    void act() {
                        throw new IllegalStateException("World.removeBody: not during a tick");
                    }
                }));
        assertEquals(java.util.List.of(), result.violations());
        assertTrue(result.clearError().contains("not during a tick"));
    }

    @Test
    void energyPumpedIntoAPassiveWorldIsCaught() {
        // An upward push on the resting box: a world that looks passive gains energy.
        Violation v = run(drop(), ViolationKind.ENERGY, w -> w.world().addExternalForce((world, dt) -> {
            if (world.getTickCount() > 40) {
                box(w).applyForce(0f, -300f);
            }
        })).of(ViolationKind.ENERGY);
        assertNotNull(v);
        assertTrue(v.tick() > 40);
    }

    @Test
    void aBodyMovedThroughTheFloorIsCaught() {
        Violation v = run(drop(), ViolationKind.PASS_THROUGH, w -> w.world().addExternalForce((world, dt) -> {
            if (world.getTickCount() == 60) {
                box(w).setPosition(0f, 40f);
            }
        })).of(ViolationKind.PASS_THROUGH);
        assertNotNull(v);
        assertEquals(60, v.tick());
    }

    @Test
    void aBodyHeldInsideAnotherIsCaughtOnlyOnceItPersists() {
        // Held 3 px deep in the floor: past the 2 px bound for longer than 0.25 s (5 ticks).
        Violation v = run(drop(), ViolationKind.OVERLAP, w -> w.world().addExternalForce((world, dt) -> {
            if (world.getTickCount() >= 40) {
                box(w).setPosition(0f, -7f);
                box(w).setVelocity(0f, 0f);
            }
        })).of(ViolationKind.OVERLAP);
        assertNotNull(v);
        assertTrue(v.tick() >= 45 && v.tick() <= 47, v.toString());
    }

    @Test
    void allocationInEveryTickIsCaughtAndNoneIsNot() {
        Consumer<FuzzWorld> allocating = w -> w.world().addExternalForce((world, dt) -> box(w).applyForce(new float[] {0f}[0], 0f));
        Violation v = run(drop(), ViolationKind.ALLOCATION, allocating).of(ViolationKind.ALLOCATION);
        assertNotNull(v);
        assertNull(run(drop(), ViolationKind.ALLOCATION, w -> { }).of(ViolationKind.ALLOCATION));
    }

    @Test
    void arraysThatGrowOnceEachAreNotSteadyAllocation() {
        // Four arrays of the same size made once each after warm-up, as doubling arrays reach the same
        // capacity in different ticks: the same size four times, but nothing more once the world goes on.
        int[][] grown = new int[4][];
        Consumer<FuzzWorld> growing = w -> w.world().addExternalForce((world, dt) -> {
            long t = world.getTickCount();
            if (t >= 60 && t < 80 && t % 5 == 0) {
                grown[(int) (t - 60) / 5] = new int[64];
            }
        });
        assertNull(run(drop(), ViolationKind.ALLOCATION, growing).of(ViolationKind.ALLOCATION));
    }

    @Test
    void twoBuildsThatDifferAreCaught() {
        int[] builds = {0};
        Violation v = run(drop(), ViolationKind.NONDETERMINISM, w -> {
            float push = ++builds[0];
            w.world().addExternalForce((world, dt) -> box(w).applyForce(push, 0f));
        }).of(ViolationKind.NONDETERMINISM);
        assertNotNull(v);
        assertEquals(0, v.tick());
    }

    /** A constraint that does nothing but {@link #act} in its prepare of one tick. */
    abstract static class Planted extends IdleConstraint {
        private final World world;
        private final long tick;

        Planted(World world, long tick) {
            this.world = world;
            this.tick = tick;
        }

        void act() {
        }

        @Override
        public void prepare(SolverStep step) {
            if (world.getTickCount() == tick) {
                act();
            }
        }
    }
}
