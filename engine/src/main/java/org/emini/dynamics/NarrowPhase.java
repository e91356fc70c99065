package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.collision.Segment;
import org.emini.shape.Shape;

/**
 * One thread's share of the narrowphase: each contact's new manifold (or its kept one,
 * {@link ManifoldReuse}) from the bodies' poses at the start of the tick, with scratch of its own.
 * It writes only the contact it is given, so the contacts of a tick can be split among threads;
 * what touches shared state (destroying a contact, events, the application's collision filter) is
 * left to {@link ContactManager}, which does it afterwards in contact order.
 */
final class NarrowPhase {
    /** The contact is updated and stays. */
    static final byte ALIVE = 0;
    /** The parts' boxes no longer overlap (or the landscape changed): the contact is to be destroyed. */
    static final byte DEAD = 1;
    /** Its filter must be asked again, which only the calling thread does: not collided yet. */
    static final byte FILTER = 2;
    /** Not decided without reading the contact object: {@link #collideBodies} must. */
    static final byte UNKNOWN = -1;

    private final Collider collider = new Collider();
    private final Manifold manifold = new Manifold();
    private final Segment segment = new Segment();

    /** Collides a contact between two bodies' parts, unless its filter must be asked first. */
    byte collideBodies(Contact c, PartKeys parts, BroadPhase broadPhase, float sweepTime, float speculative, float reuseTolerance) {
        if (c.filterDirty) {
            return FILTER;
        }
        return collideParts(c, parts, broadPhase, sweepTime, speculative, reuseTolerance);
    }

    /** Collides a contact between two bodies' parts whose filter allows them. */
    byte collideParts(Contact c, PartKeys parts, BroadPhase broadPhase, float sweepTime, float speculative, float reuseTolerance) {
        Body a = c.bodyA;
        Body b = c.bodyB;
        if (!broadPhase.testOverlap(parts.proxy(c.keyA), parts.proxy(c.keyB))) {
            return DEAD;
        }
        float sweep = sweepTime * (sweepSpeed(a) + sweepSpeed(b));
        Shape sa = a.getShape();
        Shape sb = b.getShape();
        Shape pa = ContactManager.part(sa, c.partA);
        Shape pb = ContactManager.part(sb, c.partB);
        // Still apart, as colliding would find, or points reused: only the factors are set again.
        if (c.pointCount == 0 && ManifoldReuse.staysApart(c, a, b, pa.getBoundingRadius(), pb.getBoundingRadius(),
            speculative + sweep) || ManifoldReuse.reuse(c, a, b, sweep, reuseTolerance)) {
            c.friction = sa.getFriction() * sb.getFriction();
            c.restitution = sa.getElasticity() * sb.getElasticity();
        } else {
            collider.collide(pa, a.x, a.y, a.c, a.s, pb, b.x, b.y, b.c, b.s, speculative + sweep, manifold);
            update(c, manifold, sa.getFriction() * sb.getFriction(), sa.getElasticity() * sb.getElasticity());
            ManifoldReuse.remember(c, a, b, pa.getType() != Shape.TYPE_CIRCLE && pb.getType() != Shape.TYPE_CIRCLE, sweep,
                reuseTolerance);
            ManifoldReuse.rememberApart(c, a, b, collider.getApartGap());
        }
        return ALIVE;
    }

    /**
     * A pair left apart and unchanged since ({@link ApartPairs}), decided from its copy as
     * {@link #collideParts} would decide from the contact: DEAD when the fat boxes no longer overlap,
     * ALIVE when it stays apart with the same friction and elasticity (nothing to write), else UNKNOWN.
     */
    byte collideApart(ApartPairs apart, int index, PartKeys parts, BroadPhase broadPhase, float sweepTime, float speculative) {
        int keyA = apart.keyA(index);
        int keyB = apart.keyB(index);
        if (!broadPhase.testOverlap(parts.proxy(keyA), parts.proxy(keyB))) {
            return DEAD;
        }
        Body a = parts.body(keyA);
        Body b = parts.body(keyB);
        float sweep = sweepTime * (sweepSpeed(a) + sweepSpeed(b));
        Shape sa = a.getShape();
        Shape sb = b.getShape();
        Shape pa = ContactManager.part(sa, parts.part(keyA));
        Shape pb = ContactManager.part(sb, parts.part(keyB));
        if (apart.staysApart(index, a, b, pa.getBoundingRadius(), pb.getBoundingRadius(), speculative + sweep)
            && apart.sameFactors(index, sa.getFriction() * sb.getFriction(), sa.getElasticity() * sb.getElasticity())) {
            return ALIVE;
        }
        return UNKNOWN;
    }

    /** Collides a contact between a body's part and a landscape segment. */
    byte collideLandscape(Contact c, PartKeys parts, BroadPhase broadPhase, float sweepTime, float speculative, float reuseTolerance) {
        Body a = c.bodyA;
        Landscape l = c.landscape;
        int slot = c.segmentSlot;
        int p = parts.proxy(c.keyA);
        if ((c.filterDirty && (!a.isDynamic() || a.sensor)) || l.stampOf(slot) != c.segmentStamp
            || !l.overlaps(slot, broadPhase.getFatMinX(p), broadPhase.getFatMinY(p), broadPhase.getFatMaxX(p),
                broadPhase.getFatMaxY(p))) {
            return DEAD;
        }
        c.filterDirty = false;
        float sweep = sweepTime * sweepSpeed(a);
        Shape whole = a.getShape();
        if (ManifoldReuse.reuse(c, a, null, sweep, reuseTolerance)) {
            c.friction = whole.getFriction() * l.getFriction();
            c.restitution = whole.getElasticity() * l.getElasticity();
            return ALIVE;
        }
        l.fill(slot, segment);
        segment.side = c.pointCount > 0 ? c.segmentSide : 0;
        // The body's centre of mass decides the side, for every part alike.
        float cx = whole.getCentroidX();
        float cy = whole.getCentroidY();
        Shape pa = ContactManager.part(whole, c.partA);
        collider.collideSegment(segment, pa, a.x, a.y, a.c, a.s, a.x + a.c * cx - a.s * cy,
            a.y + a.s * cx + a.c * cy, speculative + sweep, manifold);
        c.segmentSide = collider.getSegmentSide();
        // The collider's normal points from the segment to the body; the contact's from A, the body.
        manifold.normalX = -manifold.normalX;
        manifold.normalY = -manifold.normalY;
        update(c, manifold, whole.getFriction() * l.getFriction(), whole.getElasticity() * l.getElasticity());
        ManifoldReuse.remember(c, a, null, pa.getType() != Shape.TYPE_CIRCLE, sweep, reuseTolerance);
        return ALIVE;
    }

    private static float sweepSpeed(Body b) {
        if (!b.awake) {
            return 0f;
        }
        // |v| ≤ |vx| + |vy|: a cheap, conservative bound.
        return Math.abs(b.vx) + Math.abs(b.vy) + Math.abs(b.w) * b.getShape().getBoundingRadius();
    }

    private static void update(Contact c, Manifold m, float friction, float restitution) {
        int oldCount = c.pointCount;
        float n0 = c.normalImpulse0;
        float n1 = c.normalImpulse1;
        float t0 = c.tangentImpulse0;
        float t1 = c.tangentImpulse1;
        int id0 = c.id0;
        int id1 = c.id1;
        c.pointCount = m.pointCount;
        // Apart, the collider leaves the normal of whatever it collided before: the contact keeps its own.
        if (m.pointCount > 0) {
            c.normalX = m.normalX;
            c.normalY = m.normalY;
        }
        c.friction = friction;
        c.restitution = restitution;
        for (int p = 0; p < m.pointCount; p++) {
            int key = m.id[p];
            if (p == 0) {
                c.pointX0 = m.pointX[0];
                c.pointY0 = m.pointY[0];
                c.separation0 = m.separation[0];
                c.id0 = key;
            } else {
                c.pointX1 = m.pointX[1];
                c.pointY1 = m.pointY[1];
                c.separation1 = m.separation[1];
                c.id1 = key;
            }
            // Carry the impulse of the same feature pair over for warm starting.
            float ni = 0f;
            float ti = 0f;
            if (oldCount > 0 && key == id0) {
                ni = n0;
                ti = t0;
            } else if (oldCount > 1 && key == id1) {
                ni = n1;
                ti = t1;
            }
            c.setImpulses(p, ni, ti, 0f);
        }
    }
}
