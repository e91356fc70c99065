package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;

/** Scene builders and measures shared by the constraint tests. */
final class Rigs {
    private Rigs() {
    }

    static World world(float ticksPerSecond, int iterations) {
        World world = new World();
        world.setTicksPerSecond(ticksPerSecond);
        world.setConstraintIterations(iterations);
        return world;
    }

    /** A small static body to hang things from. */
    static Body anchor(World world, float x, float y) {
        Body b = new Body(x, y, Shape.createRectangle(4f, 4f), false);
        world.addBody(b);
        return b;
    }

    /** Distance between the two anchors of a joint or spring where the bodies are now. */
    static double gap(TwoBodyConstraint c) {
        return Math.hypot(c.getAnchorBX() - c.getAnchorAX(), c.getAnchorBY() - c.getAnchorAY());
    }

    /** Complete elliptic integral of the first kind K(m), m = k², by the arithmetic-geometric mean. */
    static double ellipticK(double m) {
        double a = 1.0;
        double b = Math.sqrt(1.0 - m);
        while (Math.abs(a - b) > 1e-15) {
            double an = 0.5 * (a + b);
            b = Math.sqrt(a * b);
            a = an;
        }
        return Math.PI / (2.0 * a);
    }

    static void run(World world, int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }
}
