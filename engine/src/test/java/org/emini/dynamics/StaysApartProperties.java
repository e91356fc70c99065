package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.statistics.Statistics;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.shape.Circle;
import org.emini.shape.Shape;

/**
 * The narrowphase skips a pair it found apart while {@link ManifoldReuse#staysApart} says colliding
 * it again would find it apart; that must be exact, or the skip changes the physics. Random pairs of
 * polygons and circles, near each other at large and small coordinates, found apart, then moved and
 * turned a little: whenever the check skips, a collide at the new poses finds no points either.
 */
class StaysApartProperties {
    private final Collider collider = new Collider();
    private final Manifold manifold = new Manifold();

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Shape> boxes = Combinators.combine(Arbitraries.floats().between(2f, 80f), Arbitraries.floats().between(2f, 80f))
            .as(Shape::createRectangle);
        Arbitrary<Shape> regular = Combinators.combine(Arbitraries.integers().between(3, 8), Arbitraries.floats().between(2f, 40f))
            .as((sides, radius) -> Shape.createRegularPolygon(radius, sides));
        // Off their body's origin: a multi-shape's parts are placed so.
        Arbitrary<Shape> circles = Combinators.combine(Arbitraries.floats().between(1f, 40f), Arbitraries.floats().between(-30f, 30f),
            Arbitraries.floats().between(-30f, 30f)).as(Circle::new);
        return Arbitraries.frequencyOf(Tuple.of(2, boxes), Tuple.of(2, regular), Tuple.of(1, circles));
    }

    @Property(tries = 4000)
    void aPairTheCheckSkipsIsFoundApartByTheCollider(@ForAll("shapes") Shape shapeA, @ForAll("shapes") Shape shapeB,
            @ForAll @FloatRange(min = -20000f, max = 20000f) float x, @ForAll @FloatRange(min = -20000f, max = 20000f) float y,
            @ForAll @FloatRange(min = -3.2f, max = 3.2f) float angleA, @ForAll @FloatRange(min = -3.2f, max = 3.2f) float angleB,
            @ForAll @FloatRange(min = -3.2f, max = 3.2f) float direction, @ForAll @FloatRange(min = -2f, max = 4f) float gap,
            @ForAll @FloatRange(min = -1.5f, max = 1.5f) float moveX, @ForAll @FloatRange(min = -1.5f, max = 1.5f) float moveY,
            @ForAll @FloatRange(min = -0.08f, max = 0.08f) float turnA, @ForAll @FloatRange(min = -0.08f, max = 0.08f) float turnB,
            @ForAll @FloatRange(min = 0f, max = 1f) float margin, @ForAll @FloatRange(min = 0f, max = 1f) float nextMargin) {
        float reach = shapeA.getBoundingRadius() + shapeB.getBoundingRadius() + gap;
        Body a = new Body(x, y, shapeA, true);
        a.setAngle(angleA);
        Body b = new Body(x + reach * (float) Math.cos(direction), y + reach * (float) Math.sin(direction), shapeB, true);
        b.setAngle(angleB);
        collider.collide(shapeA, a.x, a.y, a.c, a.s, shapeB, b.x, b.y, b.c, b.s, margin, manifold);
        boolean apart = manifold.pointCount == 0;
        Contact c = new Contact();
        ManifoldReuse.rememberApart(c, a, b, apart ? collider.getApartGap() : 0f);
        a.setAngle(angleA + turnA);
        b.setPosition(b.getX() + moveX, b.getY() + moveY);
        b.setAngle(angleB + turnB);
        boolean skipped = apart && ManifoldReuse.staysApart(c, a, b, shapeA.getBoundingRadius(), shapeB.getBoundingRadius(), nextMargin);
        Statistics.label("skipped").collect(skipped);
        Statistics.label("skipped").coverage(coverage -> coverage.check(true).percentage(p -> p > 5.0));
        if (skipped) {
            collider.collide(shapeA, a.x, a.y, a.c, a.s, shapeB, b.x, b.y, b.c, b.s, nextMargin, manifold);
            assertEquals(0, manifold.pointCount, "a skipped pair touches: " + manifold);
        }
    }
}
