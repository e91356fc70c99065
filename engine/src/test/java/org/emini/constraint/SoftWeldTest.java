package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A fixed joint with stiffness, at a disc's centre (so that its point and its angle do not
 * couple): the angle swings with period 1/f of its angular frequency, the point sags g/ω² under the
 * disc's weight and bounces with period 1/f of its linear frequency. Loose joints refuse it.
 */
class SoftWeldTest {
    private static Body disc;
    private static Joint weld;

    private static World welded(float ticksPerSecond, float linearHertz, float angularHertz) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body wall = Rigs.anchor(world, 0f, 0f);
        disc = new Body(0f, 0f, Shape.createCircle(10f), true);
        world.addBody(disc);
        weld = Joint.atWorldPoint(wall, disc, 0f, 0f, true);
        weld.setCollisionLayer(1);
        weld.setStiffness(linearHertz, angularHertz, 0f);
        world.addConstraint(weld);
        return world;
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void angleSwingsAtTheAngularFrequency(float ticksPerSecond) {
        World world = welded(ticksPerSecond, 0f, 2f);
        world.setGravity(0f, 0f);
        disc.setAngularVelocity(2f);
        double period = Oscillation.period(world, () -> disc.getAngle(), 0.0, 5);
        System.out.printf("soft weld angle %.0f ticks/s: period %.5f s vs 0.5 s, centre drift %.4f px%n", ticksPerSecond,
            period, Math.hypot(disc.getX(), disc.getY()));
        assertEquals(0.5, period, 0.005);
        assertEquals(0.0, Math.hypot(disc.getX(), disc.getY()), 0.01);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void pointSagsAndBouncesAtTheLinearFrequency(float ticksPerSecond) {
        World world = welded(ticksPerSecond, 2f, 0f);
        double sag = world.getGravityY() / Math.pow(2 * Math.PI * 2, 2);
        double period = Oscillation.period(world, () -> disc.getY(), sag, 5);
        weld.setStiffness(2f, 0f, 1f);
        Rigs.run(world, (int) Math.round(3 * ticksPerSecond));
        System.out.printf("soft weld point %.0f ticks/s: period %.5f s vs 0.5 s, sag %.4f px vs g/ω² %.4f px%n",
            ticksPerSecond, period, disc.getY(), sag);
        assertEquals(0.5, period, 0.005);
        assertEquals(sag, disc.getY(), 0.005 * sag);
        assertEquals(0.0, disc.getAngle(), 1e-5);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f})
    void looseJointsHaveNoStiffness(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body wall = Rigs.anchor(world, 0f, 0f);
        Body b = new Body(0f, 0f, Shape.createCircle(10f), true);
        world.addBody(b);
        Joint loose = Joint.atWorldPoint(wall, b, 0f, 0f, false);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> loose.setStiffness(1f, 1f, 1f));
        assertEquals(true, e.getMessage().startsWith("Joint.setStiffness: "), e.getMessage());
    }
}
