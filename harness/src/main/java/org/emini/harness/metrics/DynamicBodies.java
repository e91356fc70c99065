package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/**
 * The dynamic bodies of a world as an array (static bodies carry no energy or momentum), and what a
 * body's rotation adds to energy and angular momentum: the harness's metrics, and the World
 * Designer's live ones, share these definitions.
 */
public final class DynamicBodies {
    private DynamicBodies() {
    }

    static Body[] of(BuiltWorld world) {
        List<Body> out = new ArrayList<>();
        for (Body b : world.bodies().values()) {
            if (b.isDynamic()) {
                out.add(b);
            }
        }
        return out.toArray(new Body[0]);
    }

    /**
     * ½·I·ω², zero for a body that cannot rotate (its inertia may be infinite).
     *
     * @param b a body
     * @return its rotational kinetic energy
     */
    public static double rotationalEnergy(Body b) {
        double w = b.getAngularVelocity();
        if (w == 0 || !b.canRotate()) {
            return 0;
        }
        return 0.5 * b.getInertia() * w * w;
    }

    /**
     * I·ω, zero for a body that cannot rotate.
     *
     * @param b a body
     * @return its spin angular momentum
     */
    public static double spin(Body b) {
        double w = b.getAngularVelocity();
        return w == 0 || !b.canRotate() ? 0 : b.getInertia() * w;
    }
}
