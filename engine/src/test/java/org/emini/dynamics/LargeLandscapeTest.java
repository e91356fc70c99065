package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A 10,000-segment landscape carries a rain of bodies: nothing falls through, every body but the
 * balls ends up resting on the terrain, and each body only ever holds contacts with the few segments under it.
 */
class LargeLandscapeTest {
    @Test
    void tenThousandSegmentTerrainCarriesARainOfBodies() {
        World world = Terrain.rain(10_000, 150, 1500f, 1);
        assertEquals(10_000, world.getLandscape().getSegmentCount());
        // 30 s: a heap in a valley may still slide at 20 s (the double flavour's heap near x = 1200 slides
        // 100 px between 15 and 25 s, then rests).
        Scenes.run(world, 30f);
        // Balls may still roll to and fro in a valley (nothing brakes rolling) and now and then knock
        // a box: every other body is at rest in at least 4 of 5 samples a second apart. At exactly
        // 30 s one box was moving (knocked at 29.5 s), at rest at 25 and 35 s.
        int[] restingSamples = new int[world.getBodyCount()];
        for (int sample = 0; sample < 5; sample++) {
            Scenes.run(world, 1f);
            for (int i = 0; i < world.getBodyCount(); i++) {
                Body b = world.getBody(i);
                if (Math.abs(b.getVelocityX()) + Math.abs(b.getVelocityY()) < 5f) {
                    restingSamples[i]++;
                }
            }
        }
        int touching = 0;
        int maxSegments = 0;
        Contact[] cs = new Contact[64];
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            assertTrue(b.getY() < Terrain.height(b.getX()), b + " is above the terrain surface at its x");
            if (b.getShape().getType() != org.emini.shape.Shape.TYPE_CIRCLE) {
                assertTrue(restingSamples[i] >= 4, b + " has come to rest: at rest in " + restingSamples[i] + " of 5 samples");
            }
            int n = b.getContacts(cs);
            int segments = 0;
            boolean touches = false;
            for (int k = 0; k < n; k++) {
                if (cs[k].isLandscape()) {
                    segments++;
                    touches |= cs[k].isTouching();
                }
            }
            maxSegments = Math.max(maxSegments, segments);
            touching += touches ? 1 : 0;
        }
        assertTrue(touching > 100, touching + " bodies touch the terrain (the rest lie on other bodies)");
        // An L of two parts over 4 px segments holds about 16 (one per part and segment near it).
        assertTrue(maxSegments <= 30, "a body's segment contacts stay local: at most " + maxSegments);
    }
}
