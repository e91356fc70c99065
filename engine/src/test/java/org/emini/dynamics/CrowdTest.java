package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.IdentityHashMap;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Bodies created in one spot: every pair overlaps, n(n − 1)/2 contacts. Each pair gets one
 * contact, the crowd pushes itself apart, and a world at its contact capacity stays within it.
 */
class CrowdTest {
    static final int N = 200;
    static final float R = 10f;

    static World crowd(int maxContacts) {
        World world = new World();
        world.setGravity(0f, 0f);
        world.getSolverSettings().setMaxContacts(maxContacts);
        for (int i = 0; i < N; i++) {
            world.addBody(new Body(0f, 0f, Shape.createCircle(R), true));
        }
        return world;
    }

    /** The smallest distance between two bodies' centres. */
    static float closest(World world) {
        float best = Float.MAX_VALUE;
        for (int i = 0; i < world.getBodyCount(); i++) {
            for (int j = i + 1; j < world.getBodyCount(); j++) {
                Body a = world.getBody(i);
                Body b = world.getBody(j);
                best = Math.min(best, (float) Math.hypot(a.getX() - b.getX(), a.getY() - b.getY()));
            }
        }
        return best;
    }

    @Test
    void everyPairOfACrowdGetsOneContactAndTheCrowdSpreads() {
        World world = crowd(SolverSettings.DEFAULT_MAX_CONTACTS);
        world.tick();
        assertEquals(N * (N - 1) / 2, world.getContactCount());
        assertFalse(world.isContactCapacityReached());
        Contact[] out = new Contact[N];
        for (int i = 0; i < N; i++) {
            Body b = world.getBody(i);
            assertEquals(N - 1, b.getContacts(out));
            IdentityHashMap<Body, Boolean> others = new IdentityHashMap<>();
            for (int k = 0; k < N - 1; k++) {
                others.put(out[k].getOther(b), Boolean.TRUE);
            }
            assertEquals(N - 1, others.size(), "distinct partners of body " + i);
        }
        for (int t = 0; t < 200; t++) {
            world.tick();
        }
        assertTrue(closest(world) > 2f * R - 1f, "closest centres " + closest(world));
    }

    @Test
    void aCrowdBeyondTheContactCapacityStaysWithinItAndSaysSo() {
        int capacity = 2000;
        World world = crowd(capacity);
        world.tick();
        assertTrue(world.isContactCapacityReached());
        assertTrue(world.getContactCount() <= capacity, "contacts " + world.getContactCount());
        int peak = 0;
        int lastFull = -1;
        for (int t = 0; t < 600; t++) {
            world.tick();
            peak = Math.max(peak, world.getContactCount());
            if (world.isContactCapacityReached()) {
                lastFull = t;
            }
        }
        assertTrue(peak <= capacity, "peak contacts " + peak);
        // The crowd still spreads: contacts end and make room for the pairs left out.
        assertTrue(lastFull < 500, "at capacity until tick " + lastFull);
        assertFalse(world.isContactCapacityReached());
        assertTrue(closest(world) > 2f * R - 1f, "closest centres " + closest(world));
    }
}
