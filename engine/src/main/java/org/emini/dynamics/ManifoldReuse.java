package org.emini.dynamics;

/**
 * Keeps a contact's points while its two bodies barely move relative to each other, instead of
 * colliding their shapes again (see {@link SolverSettings#getManifoldReuseDistance()}). Each point
 * is remembered as its two surface points, one fixed on each body; a reused point is the midpoint of
 * where those are now, its separation their distance along the normal, which turns with A. A
 * landscape contact's B is the world itself.
 *
 * <p>The test bounds how far any point of B has moved in A's frame since the points were found
 * (A's points are fixed there), plus what the bodies can close in the coming tick: B's origin's
 * displacement, plus the relative turn times B's bounding radius, plus the tick's sweep.
 *
 * <p>A pair found apart (no points, its fat boxes still overlapping) keeps the gap the collider
 * measured, and is not collided again while that gap, less a bound on how far B's points have moved
 * in A's frame, still exceeds the tick's margin: the collider would find it apart again, so this
 * skip, unlike the reuse of points, changes nothing. A third of the ten 20-row pyramids' contacts
 * are such pairs (neighbours in a row, 1 px apart), and more of a rain's.
 */
final class ManifoldReuse {
    // Relative to the pair's extent in A's frame: many times the rounding of a separation computed there.
    private static final float APART_SLACK = 1e-4f;

    private ManifoldReuse() {
    }

    /**
     * Remembers the points the narrowphase just found, for a body pair (b not null) or a landscape
     * contact, if their shapes have corners: a circle's contact point does not turn with the circle
     * but stays under its centre as it rolls, and circles are cheap to collide anyway.
     */
    static void remember(Contact c, Body a, Body b, boolean corners, float sweep, float tolerance) {
        // No points: a gap beyond the margin, and the next tick must look again or it could close
        // unseen. A pair that can close the tolerance in one tick will not be reused next tick either.
        if (c.pointCount == 0 || !corners || !(sweep < tolerance)) {
            c.reusable = false;
            return;
        }
        c.reusable = true;
        float ac = a.c;
        float as = a.s;
        if (b != null) {
            storePose(c, a, b);
            c.frameNormalX = ac * c.normalX + as * c.normalY;
            c.frameNormalY = ac * c.normalY - as * c.normalX;
        } else {
            c.poseX = a.x;
            c.poseY = a.y;
            c.poseC = ac;
            c.poseS = as;
            c.frameNormalX = c.normalX;
            c.frameNormalY = c.normalY;
        }
        for (int p = 0; p < c.pointCount; p++) {
            float half = 0.5f * c.separation(p);
            float px = c.pointX(p);
            float py = c.pointY(p);
            // A's surface point lies half the separation behind the midpoint along the normal, B's ahead.
            float qx = px - half * c.normalX - a.x;
            float qy = py - half * c.normalY - a.y;
            float lax = ac * qx + as * qy;
            float lay = ac * qy - as * qx;
            float wx = px + half * c.normalX;
            float wy = py + half * c.normalY;
            float lbx = wx;
            float lby = wy;
            if (b != null) {
                float rx = wx - b.x;
                float ry = wy - b.y;
                lbx = b.c * rx + b.s * ry;
                lby = b.c * ry - b.s * rx;
            }
            if (p == 0) {
                c.surfaceAX0 = lax;
                c.surfaceAY0 = lay;
                c.surfaceBX0 = lbx;
                c.surfaceBY0 = lby;
            } else {
                c.surfaceAX1 = lax;
                c.surfaceAY1 = lay;
                c.surfaceBX1 = lbx;
                c.surfaceBY1 = lby;
            }
        }
    }

    /**
     * Updates the remembered points to the bodies' poses if the pair moved less than the tolerance
     * (counting the sweep, the distance it can close this tick); otherwise leaves the contact alone.
     *
     * @return whether the points were reused
     */
    static boolean reuse(Contact c, Body a, Body b, float sweep, float tolerance) {
        if (!c.reusable) {
            return false;
        }
        float ac = a.c;
        float as = a.s;
        float moved;
        float turnSin;
        float turnCos;
        if (b != null) {
            float px = frameX(a, b);
            float py = frameY(a, b);
            float rc = frameC(a, b);
            float rs = frameS(a, b);
            turnSin = rs * c.poseC - rc * c.poseS;
            turnCos = rc * c.poseC + rs * c.poseS;
            moved = Math.abs(px - c.poseX) + Math.abs(py - c.poseY) + Math.abs(turnSin) * b.getShape().getBoundingRadius();
        } else {
            turnSin = as * c.poseC - ac * c.poseS;
            turnCos = ac * c.poseC + as * c.poseS;
            moved = Math.abs(a.x - c.poseX) + Math.abs(a.y - c.poseY) + Math.abs(turnSin) * a.getShape().getBoundingRadius();
        }
        // The sine bounds a point's travel for turns under a quarter; a half-turn has a small sine too.
        if (!(moved + sweep < tolerance) || !(turnCos > 0f)) {
            return false;
        }
        // The normal turns with A; a landscape contact keeps it in the world, where it was found.
        float nx = b != null ? ac * c.frameNormalX - as * c.frameNormalY : c.frameNormalX;
        float ny = b != null ? as * c.frameNormalX + ac * c.frameNormalY : c.frameNormalY;
        c.normalX = nx;
        c.normalY = ny;
        for (int p = 0; p < c.pointCount; p++) {
            float lax = p == 0 ? c.surfaceAX0 : c.surfaceAX1;
            float lay = p == 0 ? c.surfaceAY0 : c.surfaceAY1;
            float lbx = p == 0 ? c.surfaceBX0 : c.surfaceBX1;
            float lby = p == 0 ? c.surfaceBY0 : c.surfaceBY1;
            float wax = a.x + ac * lax - as * lay;
            float way = a.y + as * lax + ac * lay;
            float wbx = lbx;
            float wby = lby;
            if (b != null) {
                wbx = b.x + b.c * lbx - b.s * lby;
                wby = b.y + b.s * lbx + b.c * lby;
            }
            float sep = (wbx - wax) * nx + (wby - way) * ny;
            float mx = 0.5f * (wax + wbx);
            float my = 0.5f * (way + wby);
            if (p == 0) {
                c.pointX0 = mx;
                c.pointY0 = my;
                c.separation0 = sep;
            } else {
                c.pointX1 = mx;
                c.pointY1 = my;
                c.separation1 = sep;
            }
        }
        return true;
    }

    /**
     * Remembers a body pair the narrowphase just collided, with the collider's gap
     * ({@link org.emini.collision.Collider#getApartGap()}), for {@link #staysApart}: a pair found
     * touching, or apart by no gap, is not remembered.
     */
    static void rememberApart(Contact c, Body a, Body b, float gap) {
        if (!(gap > 0f)) {
            c.apartGap = 0f;
            return;
        }
        c.apartGap = gap;
        storePose(c, a, b);
    }

    /** B's pose in A's frame, into the contact's pose fields. */
    private static void storePose(Contact c, Body a, Body b) {
        c.poseX = frameX(a, b);
        c.poseY = frameY(a, b);
        c.poseC = frameC(a, b);
        c.poseS = frameS(a, b);
    }

    // B's pose in A's frame: its origin, and the cosine and sine of its angle there.
    private static float frameX(Body a, Body b) {
        return a.c * (b.x - a.x) + a.s * (b.y - a.y);
    }

    private static float frameY(Body a, Body b) {
        return a.c * (b.y - a.y) - a.s * (b.x - a.x);
    }

    private static float frameC(Body a, Body b) {
        return a.c * b.c + a.s * b.s;
    }

    private static float frameS(Body a, Body b) {
        return a.c * b.s - a.s * b.c;
    }

    /**
     * Whether a pair remembered apart is still so far apart that colliding it again would find no
     * points: no point of B (within radiusB of its origin) has moved, in A's frame, by the gap less
     * the margin (the speculative distance plus the tick's sweep). Unlike {@link #reuse}, this
     * changes no result, so it needs no tolerance: a slack covers the float rounding of the
     * collider's separations, a few steps of the pair's extent.
     */
    static boolean staysApart(Contact c, Body a, Body b, float radiusA, float radiusB, float margin) {
        return staysApart(c.apartGap, c.poseX, c.poseY, c.poseC, c.poseS, a, b, radiusA, radiusB, margin);
    }

    /** {@link #staysApart(Contact, Body, Body, float, float, float)} from a copy of the contact's gap and pose. */
    static boolean staysApart(float gap, float poseX, float poseY, float poseC, float poseS, Body a, Body b, float radiusA,
            float radiusB, float margin) {
        if (gap == 0f) {
            return false;
        }
        float px = frameX(a, b);
        float py = frameY(a, b);
        float rc = frameC(a, b);
        float rs = frameS(a, b);
        float turnSin = rs * poseC - rc * poseS;
        float turnCos = rc * poseC + rs * poseS;
        // A point at distance r from B's origin moves r times the chord of the turn, at most
        // r (|sin| + |1 − cos|); the translation's two components bound its length too.
        float moved = Math.abs(px - poseX) + Math.abs(py - poseY) + (Math.abs(turnSin) + Math.abs(1f - turnCos)) * radiusB;
        float slack = APART_SLACK * (1f + Math.abs(px) + Math.abs(py) + radiusA + radiusB);
        return moved + margin + slack < gap;
    }
}
