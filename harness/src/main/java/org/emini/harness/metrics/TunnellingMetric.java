package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.scenario.MetricSpec;

/**
 * tunnelling.count = how many times, so far, the centre of a watched body crossed a declared wall line
 * during one tick (its path from the previous tick's position to the new one intersects the line).
 * A wall given as a body is the long axis of its shape's bounding box through the box's centre, moving
 * with the body; a body that hits a wall and is pushed back out never crosses that line, one that ends
 * on the far side did pass through. A centre that lands exactly on the line counts as still on its
 * previous side, so a crossing is counted once, when the centre reaches the other side. Checked after
 * every tick.
 */
final class TunnellingMetric implements Metric {
    private final Body[] watched;
    // Per (wall, body): the last position that was strictly on one side of the wall line.
    private final double[][] previous;
    private final List<Wall> walls = new ArrayList<>();
    private int count;

    TunnellingMetric(BuiltWorld built, MetricSpec spec) {
        List<Body> list = new ArrayList<>();
        if (spec.bodies().isEmpty()) {
            list.addAll(List.of(DynamicBodies.of(built)));
        } else {
            for (String name : spec.bodies()) {
                list.add(built.body(name));
            }
        }
        for (MetricSpec.WallSpec w : spec.walls()) {
            walls.add(w.body() != null ? Wall.ofBody(built.body(w.body())) : Wall.fixed(w.from(), w.to()));
            if (w.body() != null) {
                list.remove(built.body(w.body()));
            }
        }
        watched = list.toArray(new Body[0]);
        previous = new double[walls.size()][watched.length * 2];
        for (double[] p : previous) {
            for (int i = 0; i < watched.length; i++) {
                p[2 * i] = watched[i].getX();
                p[2 * i + 1] = watched[i].getY();
            }
        }
    }

    @Override
    public List<String> channels() {
        return List.of("tunnelling.count");
    }

    @Override
    public void afterTick() {
        for (int w = 0; w < walls.size(); w++) {
            double[] line = walls.get(w).line();
            double[] p = previous[w];
            for (int i = 0; i < watched.length; i++) {
                double x = watched[i].getX();
                double y = watched[i].getY();
                if (Segments.cross(p[2 * i], p[2 * i + 1], x, y, line[0], line[1], line[2], line[3])) {
                    count++;
                }
                if (Segments.side(line[0], line[1], line[2], line[3], x, y) != 0) {
                    p[2 * i] = x;
                    p[2 * i + 1] = y;
                }
            }
        }
    }

    @Override
    public void sample(double[] out, int offset) {
        out[offset] = count;
    }

    /** A wall line, fixed or carried by a body. */
    private static final class Wall {
        private final Body body;
        private final double[] local;

        private Wall(Body body, double[] local) {
            this.body = body;
            this.local = local;
        }

        static Wall fixed(double[] from, double[] to) {
            return new Wall(null, new double[] {from[0], from[1], to[0], to[1]});
        }

        static Wall ofBody(Body body) {
            float[] box = new float[4];
            body.getShape().computeAabb(0f, 0f, 1f, 0f, box);
            double cx = (box[0] + box[2]) / 2;
            double cy = (box[1] + box[3]) / 2;
            boolean wide = box[2] - box[0] >= box[3] - box[1];
            double[] local = wide ? new double[] {box[0], cy, box[2], cy} : new double[] {cx, box[1], cx, box[3]};
            return new Wall(body, local);
        }

        double[] line() {
            if (body == null) {
                return local;
            }
            float ax = (float) local[0];
            float ay = (float) local[1];
            float bx = (float) local[2];
            float by = (float) local[3];
            return new double[] {body.toWorldX(ax, ay), body.toWorldY(ax, ay), body.toWorldX(bx, by), body.toWorldY(bx, by)};
        }
    }
}
