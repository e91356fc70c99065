package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Scale;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Narrowphase properties over random convex polygons and circles at random poses, checked
 * against {@link BruteForce}. Polygons are points on a random ellipse at jittered, increasing
 * angles (points on a convex curve are in convex position), rotated and moved off the origin.
 */
class CollisionProperties {
    private final Collider collider = new Collider();
    private final Manifold m = new Manifold();

    // ---------------------------------------------------------------------------------- shapes

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Shape> polygons = Combinators.combine(
                Arbitraries.integers().between(3, Shape.MAX_VERTICES),
                Arbitraries.floats().between(2f, 60f).ofScale(5),
                Arbitraries.floats().between(0.2f, 1f).ofScale(5),
                Arbitraries.floats().between(0f, 6.28f).ofScale(5),
                Arbitraries.floats().between(-0.35f, 0.35f).ofScale(5).list().ofSize(Shape.MAX_VERTICES),
                Arbitraries.floats().between(-0.5f, 0.5f).ofScale(5),
                Arbitraries.floats().between(-0.5f, 0.5f).ofScale(5))
                .as(CollisionProperties::polygon)
                // Polygons narrower than Shape.MIN_SIZE are refused by the factory.
                .filter(java.util.Objects::nonNull);
        Arbitrary<Shape> circles = Combinators.combine(
                Arbitraries.floats().between(2f, 60f).ofScale(5),
                Arbitraries.floats().between(-0.5f, 0.5f).ofScale(5),
                Arbitraries.floats().between(-0.5f, 0.5f).ofScale(5),
                Arbitraries.integers().between(0, 2))
                .as((r, ox, oy, offset) -> offset == 0 ? new Circle(r, ox * r, oy * r)
                        : new Circle(r));
        return Arbitraries.frequencyOf(Tuple.of(3, polygons), Tuple.of(1, circles));
    }

    private static Shape polygon(int n, float size, float aspect, float rotation,
            List<Float> jitter, float offsetX, float offsetY) {
        float[] xy = new float[2 * n];
        double step = 2 * Math.PI / n;
        double c = Math.cos(rotation);
        double s = Math.sin(rotation);
        for (int i = 0; i < n; i++) {
            double angle = step * (i + jitter.get(i));
            double ex = size * Math.cos(angle);
            double ey = size * aspect * Math.sin(angle);
            xy[2 * i] = (float) (c * ex - s * ey + offsetX * size);
            xy[2 * i + 1] = (float) (s * ex + c * ey + offsetY * size);
        }
        try {
            return Shape.createPolygon(xy);
        } catch (org.emini.shape.InvalidShapeException e) {
            if (e.getRule() == org.emini.shape.InvalidShapeException.Rule.TOO_SMALL) {
                return null;
            }
            throw e;
        }
    }

    @Provide
    Arbitrary<Float> angles() {
        return Arbitraries.floats().between(0f, 6.28318f).ofScale(5);
    }

    @Provide
    Arbitrary<Float> coordinates() {
        return Arbitraries.floats().between(-500f, 500f).ofScale(5);
    }

    private static double scale(Placed a, Placed b) {
        return Math.min(a.boundingRadius(), b.boundingRadius());
    }

    /** B moved along (dx, dy) so that its projection starts `gap` beyond A's (negative: overlap). */
    private static Placed besideAlong(Placed a, Placed b, double dx, double dy, double gap) {
        double shift = a.max(dx, dy) - b.min(dx, dy) + gap;
        return b.movedTo((float) (b.x() + shift * dx), (float) (b.y() + shift * dy));
    }

    /** B moved so that an inner point of B lands on an inner point of A: they overlap. */
    private static Placed overlapping(Placed a, Placed b, float ta, float tb, int vertex,
            float angle) {
        double[] qa = a.innerPoint(ta, vertex, angle);
        double[] qb = b.innerPoint(tb, vertex + 1, angle + 1);
        return b.movedTo((float) (b.x() + qa[0] - qb[0]), (float) (b.y() + qa[1] - qb[1]));
    }

    private void collide(Placed a, Placed b, float speculative) {
        collider.collide(a.shape(), a.x(), a.y(), a.c(), a.s(), b.shape(), b.x(), b.y(), b.c(),
                b.s(), speculative, m);
    }

    private double deepest() {
        double d = Double.POSITIVE_INFINITY;
        for (int k = 0; k < m.pointCount; k++) {
            d = Math.min(d, m.separation[k]);
        }
        return d;
    }

    // ------------------------------------------------------------------------------ properties

    @Property
    void separatedShapesGiveNoPoints(@ForAll("shapes") Shape sa, @ForAll("shapes") Shape sb,
            @ForAll("coordinates") float x, @ForAll("coordinates") float y,
            @ForAll("angles") float angleA, @ForAll("angles") float angleB,
            @ForAll("angles") float direction,
            @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.2f) float speculativeFraction,
            @ForAll @Scale(6) @FloatRange(min = 0.002f, max = 0.5f) float gapFraction) {
        Placed a = Placed.at(sa, x, y, angleA);
        Placed b0 = Placed.at(sb, x, y, angleB);
        double scale = scale(a, b0);
        float speculative = (float) (speculativeFraction * scale);
        double dx = Math.cos(direction);
        double dy = Math.sin(direction);
        Placed b = besideAlong(a, b0, dx, dy, speculative + gapFraction * scale);
        // The float position rounds; the gap actually built must still exceed the distance.
        Assume.that(b.min(dx, dy) - a.max(dx, dy) > speculative + 1e-4 * scale);

        collide(a, b, speculative);
        assertEquals(0, m.pointCount, () -> a + " / " + b + " -> " + m);
    }

    @Property
    void overlappingShapesReportTheTruePenetrationDepth(@ForAll("shapes") Shape sa,
            @ForAll("shapes") Shape sb, @ForAll("coordinates") float x,
            @ForAll("coordinates") float y, @ForAll("angles") float angleA,
            @ForAll("angles") float angleB, @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.98f) float ta,
            @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.98f) float tb,
            @ForAll @IntRange(min = 0, max = 11) int vertex, @ForAll("angles") float innerAngle,
            @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.2f) float speculativeFraction) {
        Placed a = Placed.at(sa, x, y, angleA);
        Placed b = overlapping(a, Placed.at(sb, 0f, 0f, angleB), ta, tb, vertex, innerAngle);
        double scale = scale(a, b);
        double depth = BruteForce.depth(a, b);
        Assume.that(depth > 1e-3 * scale);

        collide(a, b, (float) (speculativeFraction * scale));
        assertTrue(m.pointCount >= 1, () -> a + " / " + b + " depth " + depth);
        assertEquals(1.0, Math.hypot(m.normalX, m.normalY), 1e-5, m::toString);
        // The reference face may be A's while B's separates by up to 1e-3 × scale more (A is
        // preferred for stability); the rest is float rounding.
        double tolerance = 1.2e-3 * scale + 1e-4 * (scale + depth);
        assertEquals(-depth, deepest(), tolerance, () -> a + " / " + b + " -> " + m);
    }

    @Property
    void swappingTheShapesFlipsTheNormal(@ForAll("shapes") Shape sa, @ForAll("shapes") Shape sb,
            @ForAll("coordinates") float x, @ForAll("coordinates") float y,
            @ForAll("angles") float angleA, @ForAll("angles") float angleB,
            @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.98f) float ta,
            @ForAll @Scale(6) @FloatRange(min = 0f, max = 0.98f) float tb,
            @ForAll @IntRange(min = 0, max = 11) int vertex, @ForAll("angles") float innerAngle) {
        Placed a = Placed.at(sa, x, y, angleA);
        Placed b = overlapping(a, Placed.at(sb, 0f, 0f, angleB), ta, tb, vertex, innerAngle);
        double scale = scale(a, b);
        Assume.that(BruteForce.depth(a, b) > 1e-3 * scale);
        // Near-ties between axes may legitimately resolve differently; skip them.
        Assume.that(BruteForce.ambiguityMargin(a, b) > 0.01 * scale);
        float speculative = (float) (0.05 * scale);

        collide(a, b, speculative);
        float nx = m.normalX;
        float ny = m.normalY;
        double depthAb = deepest();
        collide(b, a, speculative);
        assertEquals(-nx, m.normalX, 1e-4, () -> a + " / " + b + " -> " + m);
        assertEquals(-ny, m.normalY, 1e-4, () -> a + " / " + b + " -> " + m);
        assertEquals(depthAb, deepest(), 1e-4 * scale + 1e-5 * Math.abs(depthAb));
    }

    @Property
    void contactPointsLieInTheShapesBoxesInflatedByTheDepth(@ForAll("shapes") Shape sa,
            @ForAll("shapes") Shape sb, @ForAll("coordinates") float x,
            @ForAll("coordinates") float y, @ForAll("angles") float angleA,
            @ForAll("angles") float angleB, @ForAll("angles") float direction,
            @ForAll @Scale(6) @FloatRange(min = -0.5f, max = 0.1f) float gapFraction) {
        Placed a = Placed.at(sa, x, y, angleA);
        Placed b0 = Placed.at(sb, x, y, angleB);
        double scale = scale(a, b0);
        Placed b = besideAlong(a, b0, Math.cos(direction), Math.sin(direction),
                gapFraction * scale);

        collide(a, b, (float) (0.1 * scale));
        double[] boxA = a.box();
        double[] boxB = b.box();
        double slack = 1e-4 * (scale + Math.abs(x) + Math.abs(y));
        for (int k = 0; k < m.pointCount; k++) {
            double inflate = Math.abs(m.separation[k]) + slack;
            int point = k;
            assertTrue(inside(boxA, m.pointX[k], m.pointY[k], inflate),
                    () -> "point " + point + " outside A's box: " + a + " / " + b + " -> " + m);
            assertTrue(inside(boxB, m.pointX[k], m.pointY[k], inflate),
                    () -> "point " + point + " outside B's box: " + a + " / " + b + " -> " + m);
        }
    }

    private static boolean inside(double[] box, double px, double py, double inflate) {
        return px >= box[0] - inflate && px <= box[2] + inflate
                && py >= box[1] - inflate && py <= box[3] + inflate;
    }

    @Property
    void polygonBoxesContainEveryRotatedVertex(@ForAll("shapes") Shape shape,
            @ForAll("coordinates") float x, @ForAll("coordinates") float y,
            @ForAll("angles") float angle) {
        Placed p = Placed.at(shape, x, y, angle);
        float[] box = new float[4];
        shape.computeAabb(x, y, p.c(), p.s(), box);
        double[] expected = p.box();
        double slack = 1e-5 * (Math.abs(x) + Math.abs(y) + shape.getBoundingRadius());
        for (int i = 0; i < 4; i++) {
            assertEquals(expected[i], box[i], slack);
        }
        if (shape instanceof Polygon) {
            assertTrue(shape.getBoundingRadius() > 0);
        }
    }
}
