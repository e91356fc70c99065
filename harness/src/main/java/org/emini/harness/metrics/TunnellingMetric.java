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
 * every tick. With {@code points: shape} each vertex of a watched body's shape is watched as well (a rod
 * whose tip passes a wall), counted once per body and tick.
 */
final class TunnellingMetric implements Metric {
    // Each watched point: its body and its place in the body's frame (the centre (0, 0), and with
    // points: shape every vertex of the body's shape, so a rod's tip counts).
    private final Body[] watched;
    private final float[] localX;
    private final float[] localY;
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
        List<Body> points = new ArrayList<>();
        List<float[]> local = new ArrayList<>();
        for (Body b : list) {
            points.add(b);
            local.add(new float[] {0f, 0f});
            if (spec.wholeShape()) {
                for (float[] v : ShapePoints.vertices(b.getShape())) {
                    points.add(b);
                    local.add(v);
                }
            }
        }
        watched = points.toArray(new Body[0]);
        localX = new float[watched.length];
        localY = new float[watched.length];
        for (int i = 0; i < watched.length; i++) {
            localX[i] = local.get(i)[0];
            localY[i] = local.get(i)[1];
        }
        previous = new double[walls.size()][watched.length * 2];
        for (double[] p : previous) {
            for (int i = 0; i < watched.length; i++) {
                p[2 * i] = x(i);
                p[2 * i + 1] = y(i);
            }
        }
    }

    private double x(int i) {
        return localX[i] == 0f && localY[i] == 0f ? watched[i].getX() : watched[i].toWorldX(localX[i], localY[i]);
    }

    private double y(int i) {
        return localX[i] == 0f && localY[i] == 0f ? watched[i].getY() : watched[i].toWorldY(localX[i], localY[i]);
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
            // One count per body and tick, however many of its points crossed.
            Body counted = null;
            for (int i = 0; i < watched.length; i++) {
                double x = x(i);
                double y = y(i);
                if (Segments.cross(p[2 * i], p[2 * i + 1], x, y, line[0], line[1], line[2], line[3])
                        && counted != watched[i]) {
                    count++;
                    counted = watched[i];
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
