package org.emini.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The shaker's headless mode: the box stays nailed together while it is shaken, the balls stay in
 * it, and the springs carry its weight. No window is opened (the test runs headless).
 */
class ShakerTest {
    @BeforeAll
    static void headless() {
        System.setProperty("java.awt.headless", "true");
    }

    @Test
    void shakenBoxStaysTogetherWithTheBallsInside() {
        ShakerWorld shaker = new ShakerWorld();
        float worstGap = 0f;
        float worstAngle = 0f;
        for (int t = 0; t < 600; t++) {
            float[] a = ShakerWorld.scriptedShake(t);
            shaker.shake(a[0], a[1]);
            shaker.tick();
            worstGap = Math.max(worstGap, shaker.widestCornerGap());
            worstAngle = Math.max(worstAngle, shaker.worstCornerAngleError());
            assertEquals(9, shaker.ballsInside(), "tick " + t);
        }
        assertTrue(worstGap < 0.5f, "corner gap " + worstGap);
        assertTrue(worstAngle < 0.01f, "corner angle " + worstAngle);
        float[] c = shaker.boxCentre();
        assertTrue(Float.isFinite(c[0]) && Float.isFinite(c[1]) && Math.abs(c[0] - ShakerWorld.WIDTH / 2f) < 80f);
    }

    @Test
    void springsCarryTheWeightOfTheBoxAndBallsAtRest() {
        ShakerWorld shaker = new ShakerWorld();
        shaker.getWorld().setDampingLateral(0.05f);
        shaker.getWorld().setDampingRotational(0.05f);
        for (int t = 0; t < 2000; t++) {
            shaker.tick();
        }
        // Statics: the springs' pulls on the bars (tension along each spring, towards its anchor)
        // add up to the weight of 4 bars of 10 and 9 balls of 1, straight up.
        float fx = 0f;
        float fy = 0f;
        for (org.emini.constraint.Spring spring : shaker.getSprings()) {
            float dx = spring.getAnchorAX() - spring.getAnchorBX();
            float dy = spring.getAnchorAY() - spring.getAnchorBY();
            float length = (float) Math.sqrt(dx * dx + dy * dy);
            fx += spring.getTension() * dx / length;
            fy += spring.getTension() * dy / length;
        }
        float weight = (4 * 10f + 9 * 1f) * shaker.getWorld().getGravityY();
        assertEquals(-weight, fy, 0.01f * weight);
        assertEquals(0f, fx, 0.01f * weight);
        assertTrue(shaker.kineticEnergy() < 1f, "still moving: " + shaker.kineticEnergy());
    }

    @Test
    void headlessModePrintsTheSameStateEveryRun() {
        String first = print(120);
        String second = print(120);
        assertEquals(first, second);
        assertTrue(first.contains("  120 "), first);
        assertTrue(first.contains("widest corner gap"), first);
    }

    private static String print(int ticks) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        Shaker.runHeadless(ticks, new PrintStream(bytes, true));
        return bytes.toString(StandardCharsets.UTF_8);
    }
}
