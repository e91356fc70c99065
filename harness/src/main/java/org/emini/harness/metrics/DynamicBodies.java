package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/** The dynamic bodies of a world as an array (static bodies carry no energy or momentum). */
final class DynamicBodies {
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

    /** ½·I·ω², zero for a body that cannot rotate (its inertia may be infinite). */
    static double rotationalEnergy(Body b) {
        double w = b.getAngularVelocity();
        if (w == 0 || !b.canRotate()) {
            return 0;
        }
        return 0.5 * b.getInertia() * w * w;
    }

    /** I·ω, zero for a body that cannot rotate. */
    static double spin(Body b) {
        double w = b.getAngularVelocity();
        return w == 0 || !b.canRotate() ? 0 : b.getInertia() * w;
    }
}
