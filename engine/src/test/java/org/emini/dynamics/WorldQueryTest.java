package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.AllocationWindows;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The edge cases of the world's queries, each against a closed form: rays that start inside, graze
 * a corner or a circle, have no length; bodies moved since the last tick, frozen outside the
 * simulation area, static; the callback's stop, clip and ignore; faced segments; a shape cast that
 * meets a corner head-on; the errors; and no allocation.
 */
class WorldQueryTest {
    private static final float EPS = 1e-4f;
    private final CastHit hit = new CastHit();

    private static World world() {
        World w = new World();
        w.setGravity(0f, 0f);
        return w;
    }

    private static Body box(World w, float x, float y, float size, boolean dynamic) {
        Body b = new Body(x, y, Shape.createRectangle(size, size), dynamic);
        w.addBody(b);
        return b;
    }

    private static List<CastHit> allHits(World w, float x1, float y1, float x2, float y2, float answer) {
        List<CastHit> hits = new ArrayList<>();
        w.rayCast(x1, y1, x2, y2, h -> {
            hits.add(new CastHit().set(h));
            return answer < 0f || answer > 1f ? answer : (answer == 0.5f ? h.getFraction() : answer);
        });
        return hits;
    }

    private void assertHit(Body body, float x, float y, float nx, float ny, float fraction) {
        assertTrue(hit.hasHit(), "no hit");
        assertSame(body, hit.getBody(), hit.toString());
        assertEquals(x, hit.getX(), EPS, hit.toString());
        assertEquals(y, hit.getY(), EPS, hit.toString());
        assertEquals(nx, hit.getNormalX(), EPS, hit.toString());
        assertEquals(ny, hit.getNormalY(), EPS, hit.toString());
        assertEquals(fraction, hit.getFraction(), EPS, hit.toString());
    }

    @Test
    void aRayHitsTheNearFaceOfABoxWithItsNormal() {
        World w = world();
        Body b = box(w, 0f, 0f, 20f, false);
        assertTrue(w.rayCastClosest(-50f, 0f, 50f, 0f, null, hit));
        assertHit(b, -10f, 0f, -1f, 0f, 0.4f);
        assertEquals(-1, hit.getSegment());
        assertEquals(0, hit.getPart());
    }

    @Test
    void aRayStartingInsideHitsAtFractionZeroWithTheShortestWayOut() {
        World w = world();
        Body b = box(w, 0f, 0f, 20f, true);
        // 3 px from the right face: out through it, the point on it.
        assertTrue(w.rayCastClosest(7f, 2f, -50f, 2f, null, hit));
        assertHit(b, 10f, 2f, 1f, 0f, 0f);
        Body ball = new Body(100f, 0f, Shape.createCircle(10f), false);
        w.addBody(ball);
        assertTrue(w.rayCastClosest(100f, 4f, 100f, 50f, null, hit));
        assertHit(ball, 100f, 10f, 0f, 1f, 0f);
        // A filter looks through the body the ray starts in.
        assertFalse(w.rayCastClosest(7f, 2f, -50f, 2f, (body, segment) -> body != b, hit));
        assertFalse(hit.hasHit());
        assertNull(hit.getBody());
    }

    @Test
    void tangentRaysHit() {
        World w = world();
        Body b = box(w, 0f, 0f, 20f, false);
        // Along the top face: it touches the box from its corner on.
        assertTrue(w.rayCastClosest(-50f, -10f, 50f, -10f, null, hit));
        assertSame(b, hit.getBody());
        assertEquals(0.4f, hit.getFraction(), EPS);
        assertEquals(-10f, hit.getY(), EPS);
        Body ball = new Body(200f, 0f, Shape.createCircle(10f), false);
        w.addBody(ball);
        // Tangent to the circle's top: one point, at x = 200.
        assertTrue(w.rayCastClosest(150f, -10f, 250f, -10f, null, hit));
        assertHit(ball, 200f, -10f, 0f, -1f, 0.5f);
        // A hair above: no hit.
        assertFalse(w.rayCastClosest(150f, -10.01f, 250f, -10.01f, null, hit));
    }

    @Test
    void aZeroLengthRayIsAPointTest() {
        World w = world();
        Body b = box(w, 0f, 0f, 20f, false);
        w.getLandscape().addSegment(-100f, 50f, 100f, 50f);
        assertTrue(w.rayCastClosest(1f, 9f, 1f, 9f, null, hit));
        assertHit(b, 1f, 10f, 0f, 1f, 0f);
        assertFalse(w.rayCastClosest(30f, 0f, 30f, 0f, null, hit));
        // On a segment: a segment has no inside.
        assertFalse(w.rayCastClosest(0f, 50f, 0f, 50f, null, hit));
        assertEquals(1, allHits(w, 1f, 9f, 1f, 9f, 1f).size());
    }

    @Test
    void bodiesAreFoundWhereTheyAreNowWhateverTheirKind() {
        World w = new World();
        Body ground = box(w, 0f, 100f, 40f, false);
        Body falling = box(w, 300f, 0f, 20f, true);
        Body moved = box(w, -300f, 0f, 20f, true);
        for (int t = 0; t < 20; t++) {
            w.tick();
        }
        // The solver moved the falling body; the ray finds it where it is, not where its broadphase box was.
        float y = falling.getY();
        assertTrue(y > 40f, "fell to " + y);
        assertTrue(w.rayCastClosest(250f, y, 350f, y, null, hit));
        assertSame(falling, hit.getBody());
        assertFalse(w.rayCastClosest(250f, 0f, 350f, 0f, null, hit));
        // Moved by the application since the last tick.
        moved.setPosition(-300f, -500f);
        assertTrue(w.rayCastClosest(-350f, -500f, -250f, -500f, null, hit));
        assertSame(moved, hit.getBody());
        assertFalse(w.rayCastClosest(-350f, moved.getY() + 500f, -250f, moved.getY() + 500f, null, hit));
        // Static.
        assertTrue(w.rayCastClosest(0f, 0f, 0f, 200f, null, hit));
        assertSame(ground, hit.getBody());
        assertEquals(80f, hit.getY(), EPS);
    }

    @Test
    void frozenBodiesOutsideTheSimulationAreaAreFound() {
        World w = new World();
        w.setGravity(0f, 0f);
        w.setSimulationArea(-100f, -100f, 100f, 100f);
        Body thrown = box(w, 0f, 0f, 10f, true);
        Body outside = box(w, 500f, 0f, 10f, true);
        outside.setVelocity(100f, 0f);
        w.tick();
        thrown.applyForce(1e6f, 0f);
        w.tick();
        w.tick();
        assertFalse(thrown.isSimulated());
        assertEquals(500f, outside.getX(), 0f, "frozen: does not move");
        float x = thrown.getX();
        assertTrue(x > 1000f, "thrown to " + x);
        assertTrue(w.rayCastClosest(x, -100f, x, 100f, null, hit));
        assertSame(thrown, hit.getBody());
        assertTrue(w.rayCastClosest(500f, -100f, 500f, 100f, null, hit));
        assertSame(outside, hit.getBody());
        assertSame(outside, w.findBodyAt(502f, 1f));
        CastHit cast = new CastHit();
        assertTrue(w.castShapeClosest(Shape.createCircle(2f), 400f, 0f, 0f, 200f, 0f, null, cast));
        assertSame(outside, cast.getBody());
        assertEquals((495f - 2f - 400f) / 200f, cast.getFraction(), EPS);
    }

    @Test
    void theCallbackStopsClipsAndIgnoresAsBox2DsDoes() {
        World w = world();
        // In world order: far, near, middle along the ray.
        Body far = box(w, 80f, 0f, 10f, false);
        Body near = box(w, 20f, 0f, 10f, false);
        Body middle = box(w, 50f, 0f, 10f, false);
        // 1: go on, every hit in world order.
        List<CastHit> all = allHits(w, 0f, 0f, 100f, 0f, 1f);
        assertEquals(3, all.size());
        assertSame(far, all.get(0).getBody());
        assertSame(near, all.get(1).getBody());
        assertSame(middle, all.get(2).getBody());
        // −1: ignore, go on.
        assertEquals(3, allHits(w, 0f, 0f, 100f, 0f, -1f).size());
        // 0: stop at the first.
        assertEquals(1, allHits(w, 0f, 0f, 100f, 0f, 0f).size());
        // The hit's fraction: clip there; the middle one is beyond the near one's clip.
        List<CastHit> clipped = allHits(w, 0f, 0f, 100f, 0f, 0.5f);
        assertEquals(2, clipped.size());
        assertSame(near, clipped.get(1).getBody());
        assertEquals(0.15f, clipped.get(1).getFraction(), EPS);
        // NaN is an error naming the call.
        IllegalStateException e = assertThrows(IllegalStateException.class,
            () -> w.rayCast(0f, 0f, 100f, 0f, h -> Float.NaN));
        assertTrue(e.getMessage().contains("World.rayCast") && e.getMessage().contains("NaN"), e.getMessage());
    }

    @Test
    void aLayerFilterLooksThroughBodiesSharingALayerAsCollisionsDo() {
        World w = world();
        Body glass = box(w, 20f, 0f, 10f, false);
        glass.addCollisionLayer(3);
        Body wall = box(w, 50f, 0f, 10f, false);
        int bits = 1 << 3;
        QueryFilter layers = (body, segment) -> body == null || (body.getCollisionLayers() & bits) == 0;
        assertTrue(w.rayCastClosest(0f, 0f, 100f, 0f, layers, hit));
        assertSame(wall, hit.getBody());
        assertTrue(w.castShapeClosest(Shape.createCircle(2f), 0f, 0f, 0f, 100f, 0f, layers, hit));
        assertSame(wall, hit.getBody());
        assertTrue(w.rayCastClosest(0f, 0f, 100f, 0f, null, hit));
        assertSame(glass, hit.getBody());
    }

    @Test
    void multiShapePartsAreHitOneByOne() {
        World w = world();
        // An L: a tall bar and a foot; the ray from the right passes the foot's end, then the bar.
        Shape l = new MultiShape(Shape.createPolygon(0, -60, 10, -60, 10, 0, 0, 0),
            Shape.createPolygon(10, -10, 40, -10, 40, 0, 10, 0));
        Body b = new Body(0f, 0f, l, false);
        w.addBody(b);
        assertTrue(w.rayCastClosest(100f, -5f, -100f, -5f, null, hit));
        assertEquals(1, hit.getPart());
        assertEquals(40f, hit.getX(), EPS);
        assertTrue(w.rayCastClosest(100f, -30f, -100f, -30f, null, hit));
        assertEquals(0, hit.getPart());
        assertEquals(10f, hit.getX(), EPS);
        List<CastHit> hits = allHits(w, 100f, -5f, -100f, -5f, 1f);
        assertEquals(2, hits.size());
        assertEquals(0, hits.get(0).getPart());
        assertEquals(1, hits.get(1).getPart());
        // The notch of the L is outside it.
        assertNull(w.findBodyAt(30f, -40f));
        assertSame(b, w.findBodyAt(30f, -5f));
    }

    @Test
    void facedSegmentsStopRaysAndShapesOnlyFromTheirBlockingSide() {
        World w = world();
        // Left-faced, left to right: on a y-down screen it stops what is above it (y < 0).
        int seg = w.getLandscape().addSegment(-100f, 0f, 100f, 0f, Landscape.FACE_LEFT);
        assertTrue(w.rayCastClosest(0f, -50f, 0f, 50f, null, hit));
        assertEquals(seg, hit.getSegment());
        assertNull(hit.getBody());
        assertEquals(0.5f, hit.getFraction(), EPS);
        assertEquals(-1f, hit.getNormalY(), EPS);
        assertFalse(w.rayCastClosest(0f, 50f, 0f, -50f, null, hit));
        Shape ball = Shape.createCircle(5f);
        assertTrue(w.castShapeClosest(ball, 0f, -50f, 0f, 0f, 100f, null, hit));
        assertEquals(0.45f, hit.getFraction(), EPS);
        assertEquals(0f, hit.getY(), EPS);
        assertFalse(w.castShapeClosest(ball, 0f, 50f, 0f, 0f, -100f, null, hit));
        // Zero-length segments collide with nothing.
        w.getLandscape().addSegment(200f, 0f, 200f, 0f);
        assertFalse(w.castShapeClosest(ball, 180f, 0f, 0f, 40f, 0f, null, hit));
        List<Integer> found = new ArrayList<>();
        w.overlapLandscape(ball, 0f, 3f, 0f, i -> found.add(i) || true);
        assertEquals(List.of(seg), found);
    }

    @Test
    void aShapeCastStopsWhereTheShapesTouch() {
        World w = world();
        Body ground = new Body(0f, 10f, Shape.createRectangle(400f, 20f), false);
        w.addBody(ground);
        assertTrue(w.castShapeClosest(Shape.createRectangle(20f, 20f), 0f, -100f, 0f, 0f, 200f, null, hit));
        assertSame(ground, hit.getBody());
        assertEquals(0.45f, hit.getFraction(), EPS);
        assertEquals(0f, hit.getY(), EPS);
        assertEquals(0f, hit.getNormalX(), EPS);
        assertEquals(-1f, hit.getNormalY(), EPS);
        // Two diamonds tip to tip, head-on: the tips meet after 100 − 2·10√2 px.
        World tips = world();
        Body right = new Body(50f, 0f, Shape.createRectangle(20f, 20f), false);
        right.setAngle((float) (Math.PI / 4));
        tips.addBody(right);
        float h = (float) (10 * Math.sqrt(2));
        assertTrue(tips.castShapeClosest(Shape.createRectangle(20f, 20f), -50f, 0f, (float) (Math.PI / 4), 100f, 0f,
            null, hit));
        assertEquals((100f - 2f * h) / 100f, hit.getFraction(), 1e-5f);
        assertEquals(50f - h, hit.getX(), 1e-3f);
        assertEquals(0f, hit.getY(), 1e-3f);
        // A circle against a corner.
        World corner = world();
        Body square = box(corner, 0f, 0f, 20f, false);
        assertTrue(corner.castShapeClosest(Shape.createCircle(5f), -40f, -40f, 0f, 60f, 60f, null, hit));
        assertSame(square, hit.getBody());
        float reach = (float) (40 - 10 - 5 / Math.sqrt(2)) / 60f;
        assertEquals(reach, hit.getFraction(), 1e-5f);
        assertEquals(-10f, hit.getX(), 1e-3f);
        assertEquals(-10f, hit.getY(), 1e-3f);
        assertEquals(-Math.sqrt(0.5), hit.getNormalX(), 1e-4);
    }

    @Test
    void aShapeOverlappingAtTheStartHitsAtZeroWithItsWayOut() {
        World w = world();
        Body b = box(w, 0f, 0f, 20f, false);
        // 2 px into the top face: out upwards.
        assertTrue(w.castShapeClosest(Shape.createRectangle(10f, 10f), 3f, -13f, 0f, 0f, -50f, null, hit));
        assertSame(b, hit.getBody());
        assertEquals(0f, hit.getFraction(), 0f);
        assertEquals(0f, hit.getNormalX(), EPS);
        assertEquals(-1f, hit.getNormalY(), EPS);
        assertEquals(-8f, hit.getY(), EPS);
        // A zero translation is an overlap test.
        assertTrue(w.castShapeClosest(Shape.createCircle(1f), 10.5f, 0f, 0f, 0f, 0f, null, hit));
        assertFalse(w.castShapeClosest(Shape.createCircle(1f), 11.5f, 0f, 0f, 0f, 0f, null, hit));
    }

    @Test
    void pointsAndOverlapsAreExactNotBoxes() {
        World w = world();
        Body square = box(w, 0f, 0f, 20f, false);
        Body ball = new Body(0f, 0f, Shape.createCircle(5f), true);
        w.addBody(ball);
        Body turned = box(w, 100f, 0f, 20f, false);
        turned.setAngle((float) (Math.PI / 4));
        // Both contain the origin: the first in world order is the body at that point.
        assertSame(square, w.findBodyAt(0f, 0f));
        List<Integer> found = new ArrayList<>();
        w.queryPoint(0f, 0f, i -> found.add(i) || true);
        assertEquals(List.of(0, 1), found);
        // On the boundary counts; in the turned square's box but outside the square does not.
        assertSame(square, w.findBodyAt(10f, 10f));
        assertNull(w.findBodyAt(108f, 8f));
        found.clear();
        w.queryPoint(0f, 0f, i -> found.add(i) && false);
        assertEquals(List.of(0), found, "stops when the callback says so");
        // A circle in the corner of the turned square's box, clear of the square.
        found.clear();
        w.overlapShape(Shape.createCircle(2f), 110f, -10f, 0f, i -> found.add(i) || true);
        assertEquals(List.of(), found);
        // Centre 4√2 = 5.66 px from the ball's: within 5 + 2; with 5√2 = 7.07 px, clear of it.
        w.overlapShape(new Circle(2f, 4f, 4f), 0f, 0f, 0f, i -> found.add(i) || true);
        assertEquals(List.of(0, 1), found);
        found.clear();
        w.overlapShape(new Circle(2f, 5f, 5f), 0f, 0f, 0f, i -> found.add(i) || true);
        assertEquals(List.of(0), found);
    }

    @Test
    void badArgumentsAreRefusedWithTheCallAndValueNamed() {
        World w = world();
        box(w, 0f, 0f, 20f, false);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> w.rayCastClosest(Float.NaN, 0f, 1f, 1f, null, hit));
        assertTrue(e.getMessage().contains("World.rayCastClosest") && e.getMessage().contains("x1")
            && e.getMessage().contains("NaN"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> w.rayCast(0f, 0f, Float.POSITIVE_INFINITY, 1f, h -> 1f));
        assertTrue(e.getMessage().contains("World.rayCast: x2"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> w.rayCastClosest(-0.9f * Float.MAX_VALUE, 0f, 0.9f * Float.MAX_VALUE, 0f, null, hit));
        assertTrue(e.getMessage().contains("longer than a float holds"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> w.rayCastClosest(0f, 0f, 1f, 1f, null, null));
        assertTrue(e.getMessage().contains("out"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
            () -> w.castShapeClosest(null, 0f, 0f, 0f, 1f, 1f, null, hit));
        assertTrue(e.getMessage().contains("World.castShapeClosest: shape"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
            () -> w.castShape(Shape.createCircle(1f), 0f, 0f, Float.NaN, 1f, 1f, h -> 1f));
        assertTrue(e.getMessage().contains("angle"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> w.queryPoint(0f, Float.NaN, i -> true));
        assertTrue(e.getMessage().contains("World.queryPoint: y"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> w.findBodyAt(Float.NEGATIVE_INFINITY, 0f));
        assertThrows(IllegalArgumentException.class, () -> w.overlapShape(Shape.createCircle(1f), 0f, 0f, 0f, null));
        IllegalStateException nested = assertThrows(IllegalStateException.class,
            () -> w.rayCast(-50f, 0f, 50f, 0f, h -> w.findBodyAt(0f, 0f) == null ? 1f : 1f));
        assertTrue(nested.getMessage().contains("World.findBodyAt") && nested.getMessage().contains("World.rayCast"),
            nested.getMessage());
        // The refused query left the world usable.
        assertTrue(w.rayCastClosest(-50f, 0f, 50f, 0f, null, hit));
    }

    @Test
    void queriesAllocateNothing() {
        World w = WorldQueryProperties.randomWorld(new java.util.Random(5));
        w.getLandscape().addSegment(-400f, 200f, 400f, 200f);
        Shape probe = new MultiShape(Shape.createCircle(5f), Shape.createRectangle(10f, 30f));
        CastCallback onward = h -> 1f;
        org.emini.collision.QueryCallback any = i -> true;
        Runnable queries = () -> {
            for (int i = 0; i < 50; i++) {
                float x = -300f + 12f * i;
                w.rayCastClosest(x, -300f, -x, 300f, null, hit);
                w.rayCast(x, -300f, -x, 300f, onward);
                w.castShapeClosest(probe, x, -300f, 0.3f, 0f, 600f, null, hit);
                w.castShape(probe, x, -300f, 0.3f, 0f, 600f, onward);
                w.queryPoint(x, 0f, any);
                w.findBodyAt(x, 10f);
                w.overlapShape(probe, x, 0f, 1f, any);
                w.overlapLandscape(probe, x, 200f, 1f, any);
            }
        };
        // Warm up until the JIT has compiled the queries (its one-off allocations, see AllocationWindows).
        for (int i = 0; i < 30; i++) {
            queries.run();
        }
        AllocationWindows allocated = AllocationWindows.measure(10, queries);
        assertEquals(0L, allocated.least(), "400 queries, " + allocated);
    }

    @Test
    void queriesSeeSleepingBodiesWhereTheyRest() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setSleepingEnabled(true);
        Body[] boxes = Scenes.pyramid(world, 5, 20f);
        Scenes.run(world, 3f);
        Body top = boxes[boxes.length - 1];
        assertTrue(top.isSleeping());
        CastHit hit = new CastHit();
        assertTrue(world.rayCastClosest(top.getX(), -500f, top.getX(), 0f, null, hit));
        assertSame(top, hit.getBody());
        assertEquals(top.getY() - 10f, hit.getY(), 0.01f);
        assertSame(top, world.findBodyAt(top.getX(), top.getY()));
        assertTrue(top.isSleeping(), "a query wakes nothing");
    }
}
