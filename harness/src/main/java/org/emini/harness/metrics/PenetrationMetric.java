package org.emini.harness.metrics;

import java.util.List;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.dynamics.World;

/**
 * Overlap at the end of the tick, measured by running the narrow phase again on the current poses of
 * every pair the world has a contact for (a contact's own separation is from before the solve).
 * penetration.points = number of manifold points with separation &lt; 0; penetration.max = the largest
 * depth (−separation) among them, 0 if none; penetration.mean = their mean depth, 0 if none.
 */
final class PenetrationMetric implements Metric {
    private final World world;
    private final Collider collider = new Collider();
    private final Manifold manifold = new Manifold();

    PenetrationMetric(World world) {
        this.world = world;
    }

    @Override
    public List<String> channels() {
        return List.of("penetration.max", "penetration.mean", "penetration.points");
    }

    @Override
    public void sample(double[] out, int offset) {
        double max = 0;
        double sum = 0;
        int points = 0;
        int n = world.getContactCount();
        for (int i = 0; i < n; i++) {
            Contact c = world.getContact(i);
            Body a = c.getBodyA();
            Body b = c.getBodyB();
            collider.collide(a.getShape(), a.getX(), a.getY(), a.getCos(), a.getSin(),
                    b.getShape(), b.getX(), b.getY(), b.getCos(), b.getSin(), 0f, manifold);
            for (int k = 0; k < manifold.pointCount; k++) {
                double s = manifold.separation[k];
                if (s < 0) {
                    points++;
                    sum -= s;
                    max = Math.max(max, -s);
                }
            }
        }
        out[offset] = max;
        out[offset + 1] = points == 0 ? 0 : sum / points;
        out[offset + 2] = points;
    }
}
