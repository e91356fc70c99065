package org.emini.dynamics;

import java.util.Arrays;
import org.emini.collision.Collider;
import org.emini.collision.IndexList;
import org.emini.collision.Manifold;

/**
 * The world's sensor bodies and what overlaps each. After every solve each sensor asks the
 * broadphase for the bodies whose boxes meet its own, tests those exactly, and compares the result
 * (sorted by body id) with the last tick's: the differences are the tick's sensor begin and end
 * events. A sensor so costs in proportion to what is near it; a world without sensors pays nothing.
 * Visitors are the bodies a sensor would collide with if it were solid (layers, collision
 * switches), sensors excepted.
 */
final class SensorSet {
    private Body[] sensors = new Body[4];
    private int count;
    private final IndexList near = new IndexList();
    private final float[] box = new float[4];
    private final Collider collider = new Collider();
    private final Manifold scratch = new Manifold();
    private Body[] found = new Body[16];

    boolean isEmpty() {
        return count == 0;
    }

    void add(Body sensor) {
        if (count == sensors.length) {
            sensors = Arrays.copyOf(sensors, 2 * count);
        }
        sensors[count++] = sensor;
    }

    /** Forgets a sensor (removed, or no longer one), ending its overlaps. */
    void remove(Body sensor, StepData step) {
        for (int i = 0; i < count; i++) {
            if (sensors[i] == sensor) {
                System.arraycopy(sensors, i + 1, sensors, i, count - i - 1);
                sensors[--count] = null;
                break;
            }
        }
        for (int i = 0; i < sensor.visitorCount; i++) {
            step.sensorEnded(sensor, sensor.visitors[i]);
            sensor.visitors[i] = null;
        }
        sensor.visitorCount = 0;
    }

    void update(Simulation world, StepData step) {
        for (int s = 0; s < count; s++) {
            Body sensor = sensors[s];
            sensor.getShape().computeAabb(sensor.x, sensor.y, sensor.c, sensor.s, box);
            near.clear();
            world.queryBodies(box[0], box[1], box[2], box[3], near);
            int n = 0;
            for (int j = 0, m = near.count(); j < m; j++) {
                Body b = world.getBody(near.get(j));
                if (b != sensor && !b.sensor && ContactManager.filterAllows(sensor, b)
                    && collider.overlaps(sensor.getShape(), sensor.x, sensor.y, sensor.c, sensor.s, b.getShape(), b.x, b.y,
                        b.c, b.s, scratch)) {
                    if (n == found.length) {
                        found = Arrays.copyOf(found, 2 * n);
                    }
                    found[n++] = b;
                }
            }
            compare(sensor, n, step);
        }
    }

    /** Reports the difference of two lists sorted by id, then keeps the new one. */
    private void compare(Body sensor, int n, StepData step) {
        Body[] old = sensor.visitors;
        int oldCount = sensor.visitorCount;
        int i = 0;
        int j = 0;
        while (i < oldCount || j < n) {
            int cmp = i == oldCount ? 1 : j == n ? -1 : Integer.compare(old[i].getId(), found[j].getId());
            if (cmp < 0) {
                step.sensorEnded(sensor, old[i++]);
            } else if (cmp > 0) {
                step.sensorBegan(sensor, found[j++]);
            } else {
                i++;
                j++;
            }
        }
        if (old.length < n) {
            old = new Body[Math.max(n, 2 * old.length)];
            sensor.visitors = old;
        }
        System.arraycopy(found, 0, old, 0, n);
        Arrays.fill(old, n, Math.max(n, oldCount), null);
        Arrays.fill(found, 0, n, null);
        sensor.visitorCount = n;
    }
}
