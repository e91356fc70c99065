package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.Flavour;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Where nothing acts on a body its motion is exact in real arithmetic (x = x0 + v·t, angle = ω·t), so
 * every bit of error is round-off: about 1e-4 of the motion in float, and in the double flavour about
 * 1e-13. A rule of the double flavour's generator that left a float in the integration path fails here.
 */
class RoundOffTest {
    @Test
    void aFreeBodyDriftsOnlyByTheRoundOffOfItsNumberType() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setGravity(0f, 0f);
        Body box = new Body(100f, 50f, Shape.createRectangle(20f, 10f), true);
        world.addBody(box);
        double vx = 33.3f;
        double vy = -12.7f;
        double omega = 1.3f;
        box.setVelocity((float) vx, (float) vy);
        box.setAngularVelocity((float) omega);
        int ticks = 600;
        for (int t = 0; t < ticks; t++) {
            world.tick();
        }
        double time = ticks / 60.0;
        double error = Math.max(Math.abs(box.getX() - (100 + vx * time)), Math.abs(box.getY() - (50 + vy * time)));
        double angleError = Math.abs(box.getAngle() - omega * time);
        // Measured: float 0.026 px and 4.0e-4 rad, double 3.0e-11 px and 3.7e-13 rad (433 px and 13 rad
        // travelled in 6,000 substeps).
        double bound = Flavour.DOUBLE ? 1e-9 : 0.1;
        assertTrue(error < bound && angleError < bound, "position error " + error + ", angle error " + angleError);
        assertTrue(Flavour.DOUBLE || error > 1e-9, "the float engine shows float round-off: " + error);
    }
}
