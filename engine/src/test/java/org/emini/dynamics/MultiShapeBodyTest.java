package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * Concave multi-shapes at rest: they stand or tip as their centre of mass says, rest on each part
 * that touches, hold things in their hollows, and turn with the parallel-axis inertia.
 */
class MultiShapeBodyTest {
    /** A w × h rectangle spanning x in [x0, x0 + w], y in [y0, y0 + h]. */
    private static Polygon rect(float x0, float y0, float w, float h) {
        return Shape.createPolygon(x0, y0, x0 + w, y0, x0 + w, y0 + h, x0, y0 + h);
    }

    /** A floor whose top is y = 0: a landscape segment or a static box, friction 1. */
    private static World world(String ground) {
        World world = new World();
        if (ground.equals("landscape")) {
            world.getLandscape().addSegment(-1000f, 0f, 1000f, 0f);
            world.getLandscape().setFriction(1f);
        } else {
            Body g = Scenes.ground(world, 0f, 2000f);
            g.getShape().setFriction(1f);
        }
        return world;
    }

    /**
     * Adds a body with the shape centred on its centre of mass, placed so that the uncentred
     * shape's origin lies at (x, y); returns it.
     */
    private static Body place(World world, MultiShape uncentred, float x, float y) {
        MultiShape shape = uncentred.centred();
        shape.setFriction(1f);
        Body b = new Body(x + uncentred.getCentroidX(), y + uncentred.getCentroidY(), shape, true);
        world.addBody(b);
        return b;
    }

    /** An L on its foot: the centre of mass is over the foot, so it stands. */
    @ParameterizedTest(name = "on a {0}")
    @CsvSource({"landscape", "body"})
    void lStandingOnItsFootDoesNotTip(String ground) {
        World world = world(ground);
        MultiShape l = new MultiShape(rect(0f, -60f, 10f, 50f), rect(0f, -10f, 40f, 10f));
        Body b = place(world, l, 0f, 0f);
        float x0 = b.getX();
        float y0 = b.getY();
        Scenes.run(world, 5f);
        assertEquals(0f, b.getAngle(), 2e-3f);
        assertEquals(x0, b.getX(), 0.05f);
        assertEquals(y0, b.getY(), 0.1f);
    }

    /**
     * A Γ on its stem: the centre of mass (x = 22.5) is beyond the stem's foot (x ≤ 10), so it
     * tips about the foot's corner (10, 0) until the hull edge from there to the arm's end
     * (70, −50) lies on the floor: a clockwise turn of atan(50/60) = 0.695 rad, where the centre
     * of mass is over the new support and it rests.
     */
    @ParameterizedTest(name = "on a {0}")
    @CsvSource({"landscape", "body"})
    void gammaOnItsStemTipsOverOntoItsArmEnd(String ground) {
        World world = world(ground);
        MultiShape gamma = new MultiShape(rect(0f, -60f, 10f, 60f), rect(10f, -60f, 60f, 10f));
        assertEquals(22.5f, gamma.getCentroidX(), 1e-4f);
        Body b = place(world, gamma, 0f, 0f);
        Scenes.run(world, 6f);
        double expected = Math.atan2(50, 60);
        assertEquals(expected, b.getAngle(), 0.01, "resting on its hull edge");
        assertEquals(0f, b.getAngularVelocity(), 0.01f);
        // Both ends of that edge touch the floor: the stem's corner and the arm's end.
        float c = b.getCos();
        float s = b.getSin();
        for (float[] p : new float[][] {{10f, 0f}, {70f, -50f}}) {
            float lx = p[0] - gamma.getCentroidX();
            float ly = p[1] - gamma.getCentroidY();
            assertEquals(0f, b.getY() + s * lx + c * ly, 0.15f, "corner (" + p[0] + ", " + p[1] + ") on the floor");
        }
    }

    /** A ∩ stands on its two legs, one contact under each leg, each with two points. */
    @ParameterizedTest(name = "on a {0}")
    @CsvSource({"landscape", "body"})
    void archStandsOnBothLegsWithAContactUnderEach(String ground) {
        World world = world(ground);
        MultiShape arch = new MultiShape(rect(-30f, -40f, 10f, 40f), rect(20f, -40f, 10f, 40f), rect(-30f, -50f, 60f, 10f));
        Body b = place(world, arch, 0f, 0f);
        float y0 = b.getY();
        Scenes.run(world, 3f);
        assertEquals(0f, b.getAngle(), 1e-3f);
        assertEquals(y0, b.getY(), 0.1f);
        Contact[] cs = new Contact[8];
        int n = b.getContacts(cs);
        int touching = 0;
        boolean[] legs = new boolean[3];
        for (int i = 0; i < n; i++) {
            if (cs[i].isTouching()) {
                touching++;
                Contact k = cs[i];
                legs[k.getBodyA() == b ? k.getPartA() : k.getPartB()] = true;
                assertEquals(2, k.getPointCount());
            }
        }
        assertEquals(2, touching);
        assertTrue(legs[0] && legs[1] && !legs[2], "the legs touch, the bar does not");
    }

    /** A ball dropped into an upright U rests in the hollow, on the U's floor, not on a hull. */
    @ParameterizedTest(name = "on a {0}")
    @CsvSource({"landscape", "body"})
    void ballRestsInTheHollowOfAU(String ground) {
        World world = world(ground);
        MultiShape cup = new MultiShape(rect(-30f, -10f, 60f, 10f), rect(-30f, -50f, 10f, 40f), rect(20f, -50f, 10f, 40f));
        Body u = place(world, cup, 0f, 0f);
        Body ball = new Body(3f, -100f, new Circle(8f), true);
        world.addBody(ball);
        Scenes.run(world, 4f);
        assertEquals(-18f, ball.getY(), 0.2f, "on the U's inner floor, 10 px up");
        assertTrue(Math.abs(ball.getX()) < 12f, "between the walls");
        assertEquals(0f, u.getAngle(), 2e-3f);
    }

    /** Multi-shape on multi-shape: an arch stands on another arch's bar. */
    @Test
    void archStandsOnAnotherArch() {
        World world = world("landscape");
        MultiShape arch = new MultiShape(rect(-30f, -40f, 10f, 40f), rect(20f, -40f, 10f, 40f), rect(-30f, -50f, 60f, 10f));
        Body lower = place(world, arch, 0f, 0f);
        Body upper = place(world, arch, 0f, -50f);
        float y0 = upper.getY();
        Scenes.run(world, 4f);
        assertEquals(0f, lower.getAngle(), 1e-3f);
        assertEquals(0f, upper.getAngle(), 1e-3f);
        assertEquals(y0, upper.getY(), 0.2f);
    }

    /** ω = J / I with I the parallel-axis sum about the centre of mass. */
    @Test
    void angularImpulseTurnsTheBodyAtJOverTheParallelAxisInertia() {
        World world = new World();
        world.setGravity(0f, 0f);
        // Two 10 × 10 boxes of mass 1 whose centres are 20 px either side of the origin.
        MultiShape pair = new MultiShape(rect(-25f, -5f, 10f, 10f), rect(15f, -5f, 10f, 10f));
        double inertia = 2 * (1 * (100 + 100) / 12.0 + 1 * 400);
        assertEquals(inertia, pair.getInertia(), 1e-3);
        Body b = new Body(0f, 0f, pair, true);
        world.addBody(b);
        b.applyAngularImpulse(100f);
        assertEquals(100 / inertia, b.getAngularVelocity(), 1e-6);
        world.tick();
        assertEquals(100 / inertia * world.getTimestep(), b.getAngle(), 1e-6);
    }
}
