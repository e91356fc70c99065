package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.AllocationWindows;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Box2D's filter (categories, masks, groups) beside the original engine's layers, and the
 * application's filter callback.
 */
class CollisionFilterTest {

    /**
     * Box2D's rule table (b2ShouldShapesCollide): the same non-zero group decides alone, positive
     * collides and negative never does; otherwise each mask must hold a category of the other.
     * Hex bit sets; the last column is whether the pair collides.
     */
    @ParameterizedTest(name = "cat {0} mask {1} group {2} / cat {3} mask {4} group {5}: {6}")
    @CsvSource({
        // Defaults.
        "0x1, 0xFFFFFFFF, 0, 0x1, 0xFFFFFFFF, 0, true",
        // Masks, group 0.
        "0x1, 0x2, 0, 0x2, 0x1, 0, true",
        "0x1, 0x2, 0, 0x2, 0x4, 0, false",
        "0x1, 0x4, 0, 0x2, 0x1, 0, false",
        "0x1, 0x4, 0, 0x2, 0x8, 0, false",
        "0x3, 0x2, 0, 0x2, 0x2, 0, true",
        "0x0, 0xFFFFFFFF, 0, 0x1, 0xFFFFFFFF, 0, false",
        "0x1, 0x0, 0, 0x1, 0xFFFFFFFF, 0, false",
        "0x80000000, 0x80000000, 0, 0x80000000, 0x80000000, 0, true",
        // Same positive group: always, whatever the masks.
        "0x1, 0x0, 3, 0x2, 0x0, 3, true",
        "0x0, 0x0, 1, 0x0, 0x0, 1, true",
        "0x1, 0xFFFFFFFF, 2147483647, 0x1, 0xFFFFFFFF, 2147483647, true",
        // Same negative group: never, whatever the masks.
        "0x1, 0xFFFFFFFF, -1, 0x1, 0xFFFFFFFF, -1, false",
        "0x1, 0xFFFFFFFF, -2147483648, 0x1, 0xFFFFFFFF, -2147483648, false",
        // Different groups (or one 0): the masks decide.
        "0x1, 0xFFFFFFFF, 1, 0x1, 0xFFFFFFFF, 2, true",
        "0x1, 0x0, 1, 0x1, 0x0, 2, false",
        "0x1, 0xFFFFFFFF, -1, 0x1, 0xFFFFFFFF, -2, true",
        "0x1, 0xFFFFFFFF, -1, 0x1, 0xFFFFFFFF, 0, true",
        "0x1, 0x2, -1, 0x1, 0xFFFFFFFF, 0, false",
        "0x1, 0xFFFFFFFF, 1, 0x1, 0xFFFFFFFF, -1, true",
        "0x1, 0x0, 1, 0x1, 0xFFFFFFFF, -1, false",
    })
    void followsBox2dsRuleTable(String catA, String maskA, int groupA, String catB, String maskB, int groupB,
            boolean collide) {
        Body a = body(0f, catA, maskA, groupA);
        Body b = body(12f, catB, maskB, groupB);
        assertEquals(collide, Body.filterAllows(a, b));
        assertEquals(collide, Body.filterAllows(b, a), "symmetric");
        // In a world: two overlapping boxes are pushed apart only when they collide.
        World world = new World();
        world.setGravity(0f, 0f);
        world.addBody(a);
        world.addBody(b);
        Scenes.run(world, 1f);
        assertEquals(collide, b.getX() - a.getX() > 19.5f, "separation " + (b.getX() - a.getX()));
        assertEquals(collide, world.getContactCount() > 0);
    }

    private static Body body(float x, String cat, String mask, int group) {
        Body b = new Body(x, 0f, Shape.createRectangle(20f, 20f), true);
        b.setCategoryBits(Integer.parseUnsignedInt(cat.substring(2), 16));
        b.setMaskBits(Integer.parseUnsignedInt(mask.substring(2), 16));
        b.setGroupIndex(group);
        return b;
    }

    /** Both rules must allow a pair: a shared layer keeps apart even a shared positive group. */
    @ParameterizedTest
    @CsvSource({"0, 0, 1, true", "1, 2, 1, true", "1, 1, 1, false", "3, 2, 1, false", "0, 0, -1, false", "1, 2, -1, false"})
    void layersAndBox2dsFilterMustBothAllow(int layersA, int layersB, int group, boolean collide) {
        World world = new World();
        world.setGravity(0f, 0f);
        Body a = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        Body b = new Body(12f, 0f, Shape.createRectangle(20f, 20f), true);
        a.setCollisionLayers(layersA);
        b.setCollisionLayers(layersB);
        a.setGroupIndex(group);
        b.setGroupIndex(group);
        world.addBody(a);
        world.addBody(b);
        Scenes.run(world, 1f);
        assertEquals(collide, b.getX() - a.getX() > 19.5f);
    }

    @Test
    void defaultsAreBox2ds() {
        Body b = new Body(0f, 0f, Shape.createCircle(1f), true);
        assertEquals(1, b.getCategoryBits());
        assertEquals(0xFFFFFFFF, b.getMaskBits());
        assertEquals(0, b.getGroupIndex());
        b.setCategoryBits(6);
        b.setMaskBits(5);
        b.setGroupIndex(-4);
        Body copy = new Body(b);
        assertEquals(6, copy.getCategoryBits());
        assertEquals(5, copy.getMaskBits());
        assertEquals(-4, copy.getGroupIndex());
    }

    /** Setting the defaults explicitly, or a filter that lets everything collide, changes nothing. */
    @Test
    void defaultsAndAnAcceptingFilterKeepTheResultBitIdentical() {
        World plain = DeterminismTest.rain(5);
        World filtered = DeterminismTest.rain(5);
        for (int i = 0; i < filtered.getBodyCount(); i++) {
            Body b = filtered.getBody(i);
            b.setCategoryBits(Body.DEFAULT_CATEGORY_BITS);
            b.setMaskBits(Body.DEFAULT_MASK_BITS);
            b.setGroupIndex(0);
        }
        filtered.setCollisionFilter(new CollisionFilter() {
            @Override
            public boolean shouldCollide(Body a, Body b) {
                return true;
            }
        });
        for (int t = 0; t < 200; t++) {
            plain.tick();
            filtered.tick();
        }
        assertEquals(DeterminismTest.hash(plain), DeterminismTest.hash(filtered));
    }

    /** Ghosts pass through dynamic bodies but land on static ones. */
    private static final class GhostFilter implements CollisionFilter {
        int calls;
        boolean ghostsOn = true;

        @Override
        public boolean shouldCollide(Body a, Body b) {
            calls++;
            assertTrue(ContactManager.shouldCollide(a, b), "asked only about pairs the built-in rules allow");
            boolean ghost = a.getUserData() == "ghost" || b.getUserData() == "ghost";
            return !(ghostsOn && ghost && a.isDynamic() && b.isDynamic());
        }
    }

    @Test
    void theCallbackLetsAGhostFallThroughABoxOntoTheGround() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Scenes.ground(world, 0f, 400f);
        Body box = new Body(0f, -10f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        Body ghost = new Body(0f, -60f, Shape.createRectangle(16f, 16f), true);
        ghost.setUserData("ghost");
        world.addBody(ghost);
        // Shares a layer with the box: the callback is never asked about that pair.
        Body layered = new Body(40f, -10f, Shape.createRectangle(20f, 20f), true);
        layered.setCollisionLayers(1);
        box.setCollisionLayers(1);
        world.addBody(layered);
        GhostFilter filter = new GhostFilter();
        world.setCollisionFilter(filter);
        assertSame(filter, world.getCollisionFilter());
        Scenes.run(world, 2f);
        assertEquals(-8f, ghost.getY(), 0.3f, "the ghost fell through the box onto the ground");
        assertEquals(-10f, box.getY(), 0.3f);
        assertTrue(filter.calls > 0);
        // The application changes its mind: after refilter the ghost and the box push apart.
        filter.ghostsOn = false;
        world.refilter(ghost);
        Scenes.run(world, 2f);
        float dx = Math.abs(ghost.getX() - box.getX());
        float dy = Math.abs(ghost.getY() - box.getY());
        assertTrue(dx > 17.5f || dy > 17.5f, "pushed apart: " + dx + ", " + dy);
        world.setCollisionFilter(null);
        assertNull(world.getCollisionFilter());
        assertThrows(IllegalArgumentException.class, () -> world.refilter(new Body(0f, 0f, Shape.createCircle(1f), true)));
        assertThrows(IllegalArgumentException.class, () -> world.refilter(null));
    }

    /** Swapping the filter asks every pair again: a resting box drops through a body the new filter refuses. */
    @Test
    void settingTheFilterEndsTheContactsItRefuses() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Body shelf = new Body(0f, 10f, Shape.createRectangle(100f, 20f), false);
        world.addBody(shelf);
        Scenes.ground(world, 200f, 400f);
        Body box = new Body(0f, -10f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        Scenes.run(world, 1f);
        assertEquals(-10f, box.getY(), 0.3f);
        world.setCollisionFilter(new CollisionFilter() {
            @Override
            public boolean shouldCollide(Body a, Body b) {
                return a != shelf && b != shelf;
            }
        });
        Scenes.run(world, 3f);
        assertEquals(190f, box.getY(), 0.3f, "fell through the shelf onto the ground");
    }

    /** The fast-body sweep asks the callback too: a wall it refuses does not stop a fast ball. */
    @Test
    void theFastBodySweepFollowsTheCallback() {
        for (boolean refuse : new boolean[] {false, true}) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(20f);
            Body wall = new Body(1f, 0f, Shape.createRectangle(2f, 400f), false);
            world.addBody(wall);
            Body ball = new Body(-3040f, 0f, Shape.createCircle(2.5f), true);
            ball.setVelocity(20000f, 0f);
            world.addBody(ball);
            if (refuse) {
                world.setCollisionFilter(new CollisionFilter() {
                    @Override
                    public boolean shouldCollide(Body a, Body b) {
                        return a != wall && b != wall;
                    }
                });
            }
            Scenes.run(world, 0.5f);
            assertEquals(refuse, ball.getX() > 1f, "refused: " + refuse + ", ball at " + ball.getX());
        }
    }

    @Test
    void filteredTicksAllocateNothing() {
        World world = DeterminismTest.rain(4);
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            b.setCategoryBits(1 << (i % 3));
            b.setMaskBits(i % 5 == 0 ? ~2 : -1);
            b.setGroupIndex(i % 7 == 0 ? -1 : 0);
        }
        world.setCollisionFilter(new CollisionFilter() {
            @Override
            public boolean shouldCollide(Body a, Body b) {
                return ((a.getId() ^ b.getId()) & 15) != 0;
            }
        });
        for (int t = 0; t < 400; t++) {
            world.tick();
        }
        AllocationWindows allocated = AllocationWindows.measure(5, () -> {
            for (int t = 0; t < 100; t++) {
                world.tick();
            }
        });
        assertEquals(0L, allocated.least(), "100 ticks with filters, " + allocated);
        assertFalse(world.isContactCapacityReached());
    }
}
