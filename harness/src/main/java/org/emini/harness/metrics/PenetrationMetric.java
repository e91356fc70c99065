package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.collision.Segment;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.dynamics.Landscape;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.scenario.MetricSpec;
import org.emini.world.World;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;

/**
 * Overlap at the end of the tick, measured by running the narrow phase again on the current poses of
 * every pair the world has a contact for (a contact's own separation is from before the solve):
 * two bodies (part by part for multi-shapes, as the contact says), or a body and a landscape segment.
 * penetration.points = number of manifold points with separation &lt; 0; penetration.max = the largest
 * depth (−separation) among them, 0 if none; penetration.mean = their mean depth, 0 if none.
 *
 * <p>A landscape contact is measured against its segment from the side the body touched it from (the
 * side opposite the contact normal, which points from the body to the segment), so a body pushed past
 * the line of a thin segment reads as deep, not as lying on the far side; a contact without points
 * lets the body's position decide. The segment's neighbours in its chain (one other segment with an
 * end within {@link Landscape#JOIN_TOLERANCE}) are given to the narrow phase as the engine does, so a
 * body crossing a joint is measured against the smooth chain.
 *
 * <p>Each overlapping point also goes to its pair of bodies, named ({@link PairPenetration}): the run's
 * figures per pair ({@link #pairs()}) and the channels of the scene's pair filters ({@code between}).
 */
final class PenetrationMetric implements Metric {
    private final World world;
    private final List<String> channels;
    private final Map<Body, Integer> party = new IdentityHashMap<>();
    private final PairPenetration pairs;
    private final Collider collider = new Collider();
    private final Manifold manifold = new Manifold();
    private final Segment segment = new Segment();
    private Joins joins;

    PenetrationMetric(BuiltWorld built, MetricSpec spec) {
        this.world = built.world();
        this.channels = spec.channels();
        List<String> names = new ArrayList<>(built.bodies().keySet());
        for (int i = 0; i < names.size(); i++) {
            party.put(built.body(names.get(i)), i);
        }
        pairs = new PairPenetration(names, spec.pairs());
    }

    @Override
    public List<String> channels() {
        return channels;
    }

    /** Every pair that overlapped at a sample so far, deepest first. */
    List<PenetrationPair> pairs() {
        return pairs.pairs();
    }

    @Override
    public void sample(double[] out, int offset) {
        double max = 0;
        double sum = 0;
        int points = 0;
        int n = world.getContactCount();
        pairs.begin();
        for (int i = 0; i < n; i++) {
            Contact c = world.getContact(i);
            Body a = c.getBodyA();
            Integer pa = party.get(a);
            Integer pb = c.isLandscape() ? Integer.valueOf(pairs.landscape()) : party.get(c.getBodyB());
            Shape sa = part(a.getShape(), c.getPartA());
            if (c.isLandscape()) {
                int index = c.getSegment();
                if (index < 0) {
                    continue;
                }
                landscapeSegment(index, c);
                // The body's centre of mass decides the side, as in the engine.
                Shape whole = a.getShape();
                collider.collideSegment(segment, sa, a.getX(), a.getY(), a.getCos(), a.getSin(),
                        a.toWorldX(whole.getCentroidX(), whole.getCentroidY()),
                        a.toWorldY(whole.getCentroidX(), whole.getCentroidY()), 0f, manifold);
            } else {
                Body b = c.getBodyB();
                collider.collide(sa, a.getX(), a.getY(), a.getCos(), a.getSin(),
                        part(b.getShape(), c.getPartB()), b.getX(), b.getY(), b.getCos(), b.getSin(), 0f, manifold);
            }
            for (int k = 0; k < manifold.pointCount; k++) {
                double s = manifold.separation[k];
                if (s < 0) {
                    points++;
                    sum -= s;
                    max = Math.max(max, -s);
                    if (pa != null && pb != null) {
                        pairs.point(pa, pb, -s);
                    }
                }
            }
        }
        out[offset] = max;
        out[offset + 1] = points == 0 ? 0 : sum / points;
        out[offset + 2] = points;
        pairs.end(out, offset + 3);
    }

    private static Shape part(Shape shape, int part) {
        return shape instanceof MultiShape m ? m.getShape(part) : shape;
    }

    private void landscapeSegment(int index, Contact c) {
        Landscape l = world.getLandscape();
        if (joins == null || joins.landscape != l || joins.count != l.getSegmentCount()) {
            joins = new Joins(l);
        }
        float x1 = l.getStartX(index);
        float y1 = l.getStartY(index);
        float x2 = l.getEndX(index);
        float y2 = l.getEndY(index);
        segment.set(x1, y1, x2, y2, l.getFace(index));
        if (joins.hasPrev[index]) {
            segment.hasPrev = true;
            segment.prevX = joins.prevX[index];
            segment.prevY = joins.prevY[index];
        }
        if (joins.hasNext[index]) {
            segment.hasNext = true;
            segment.nextX = joins.nextX[index];
            segment.nextY = joins.nextY[index];
        }
        if (c.getPointCount() > 0) {
            // The body is on the side −normal points to: side = sign((end − start) × (−normal)).
            double cross = (x2 - x1) * -c.getNormalY() - (y2 - y1) * -c.getNormalX();
            segment.side = cross > 0 ? 1 : cross < 0 ? -1 : 0;
        }
    }

    /** Each segment's single neighbour at either end, as the engine's chains join them. */
    private static final class Joins {
        final Landscape landscape;
        final int count;
        final boolean[] hasPrev;
        final boolean[] hasNext;
        final float[] prevX;
        final float[] prevY;
        final float[] nextX;
        final float[] nextY;

        Joins(Landscape l) {
            landscape = l;
            count = l.getSegmentCount();
            hasPrev = new boolean[count];
            hasNext = new boolean[count];
            prevX = new float[count];
            prevY = new float[count];
            nextX = new float[count];
            nextY = new float[count];
            float[] far = new float[2];
            for (int i = 0; i < count; i++) {
                hasPrev[i] = neighbour(l, i, l.getStartX(i), l.getStartY(i), far);
                prevX[i] = far[0];
                prevY[i] = far[1];
                hasNext[i] = neighbour(l, i, l.getEndX(i), l.getEndY(i), far);
                nextX[i] = far[0];
                nextY[i] = far[1];
            }
        }

        /** Whether exactly one other segment (not a point) ends at (x, y); its far end goes to far. */
        private static boolean neighbour(Landscape l, int self, float x, float y, float[] far) {
            float tolerance = Math.max(Landscape.JOIN_TOLERANCE, 1e-6f * Math.max(Math.abs(x), Math.abs(y)));
            int found = 0;
            for (int j = 0; j < l.getSegmentCount(); j++) {
                if (j == self) {
                    continue;
                }
                float ax = l.getStartX(j);
                float ay = l.getStartY(j);
                float bx = l.getEndX(j);
                float by = l.getEndY(j);
                boolean atStart = Math.abs(ax - x) <= tolerance && Math.abs(ay - y) <= tolerance;
                boolean atEnd = Math.abs(bx - x) <= tolerance && Math.abs(by - y) <= tolerance;
                if ((!atStart && !atEnd) || Math.hypot(bx - ax, by - ay) <= tolerance) {
                    continue;
                }
                found++;
                far[0] = atStart ? bx : ax;
                far[1] = atStart ? by : ay;
            }
            return found == 1;
        }
    }
}
