package org.emini.particle;

import org.emini.collision.RayCaster;
import org.emini.math.EMath;

/**
 * Bounces particles off the bodies and landscape segments of an {@link ObstacleGrid}.
 *
 * <p>Each particle's motion of the tick is a segment, tested as a whole so a fast particle cannot
 * pass through a thin wall: against a polygon by clipping it to the face half-planes, against a
 * circle by solving for where it meets the rim, against a landscape segment (from either side) by
 * intersecting the two; the geometry is the collision package's {@link RayCaster}, the one the
 * world's ray casts use, here with a skin of {@link #SKIN}. A moving body is tested in its own frame, the segment's start taken against
 * the body's pose at the start of the tick and its end against the pose at the end, so a body that
 * sweeps over a particle meets it on the face that swept it. The earliest hit wins; the particle is
 * put on the surface there (a hair outside, at the end-of-tick pose), the normal part of its
 * velocity relative to the surface is reflected and scaled by the elasticity, the tangential part
 * kept, and it moves on for the rest of the tick from there, up to {@link #MAX_HITS} times; after
 * the last it stays on the surface.
 *
 * <p>A bounce slower than one tick of gravity gives is a rest: the normal speed is dropped and the
 * rest of the tick slides along the surface, so resting particles neither jitter nor cost repeated
 * bounces. A particle that starts inside a body (emitted inside it, a body moved over it, or
 * squeezed where a dynamic body overlaps another) meets it at once, on the face nearest to it
 * (radially on a circle), as the original pushed particles out along the shallowest axis. Static
 * geometry wins over dynamic: a particle moved onto a body's surface never jumps across a landscape
 * segment on the way, and one left on a surface after its last bounce is finally moved out of any
 * static body, so walls hold even where a dynamic body presses into them.
 */
final class ParticleCollider {
    /** Bounces resolved per particle and tick before it is left on the surface. */
    static final int MAX_HITS = 4;
    /**
     * Two resting contacts in one tick whose normals differ by more than about 8° hold a particle
     * in a wedge: it stops there instead of sliding from one face to the other until out of hits.
     */
    static final float WEDGE_COS = 0.99f;
    /** How far outside the surface a bounced particle is put (px): far above float rounding. */
    static final float SKIN = 1f / 128f;

    private final ObstacleGrid grid;

    // The last shape test and its result: in the body's frame for bodies, in the world for segments.
    private final RayCaster ray = new RayCaster(SKIN);

    // The earliest hit found by earliestHit, in the world, with the surface's velocity there.
    private float bestT;
    private float bestX;
    private float bestY;
    private float bestNx;
    private float bestNy;
    private float bestVx;
    private float bestVy;

    // Where a point ends up in leaveStaticBodies and clipToSegments.
    private float settledX;
    private float settledY;
    private float settledVx;
    private float settledVy;

    ParticleCollider(ObstacleGrid grid) {
        this.grid = grid;
    }

    /** Bounces every particle of an emitter whose motion this tick met a body or a segment. */
    void collide(ParticleEmitter e, float dt, float gravityX, float gravityY) {
        ObstacleGrid g = grid;
        if (g.count == 0) {
            return;
        }
        float gx = gravityX * e.getGravityFactor();
        float gy = gravityY * e.getGravityFactor();
        float elasticity = e.getElasticity();
        float restSpeed = EMath.sqrt(gx * gx + gy * gy) * dt;
        float[] px = e.x;
        float[] py = e.y;
        float[] pvx = e.vx;
        float[] pvy = e.vy;
        float[] sx = e.startX;
        float[] sy = e.startY;
        float[] pa = e.age;
        int firstNew = e.firstNew;
        for (int i = 0, n = e.count; i < n; i++) {
            // Particles born this tick start at the emitter, with the bodies already at their end pose.
            boolean relative = i < firstNew;
            float h = relative ? dt : pa[i];
            float ax = sx[i];
            float ay = sy[i];
            float bx = px[i];
            float by = py[i];
            float ux = pvx[i];
            float uy = pvy[i];
            // The normal of the last resting contact in this tick.
            boolean rested = false;
            float restNx = 0f;
            float restNy = 0f;
            for (int hits = 0;; hits++) {
                if (!earliestHit(ax, ay, bx, by, relative)) {
                    break;
                }
                float wx = bestX;
                float wy = bestY;
                float nx = bestNx;
                float ny = bestNy;
                float surfaceVx = bestVx;
                float surfaceVy = bestVy;
                float rest = h * (1f - bestT);
                // Velocity when it got there, relative to the surface.
                float rx = ux - gx * rest - surfaceVx;
                float ry = uy - gy * rest - surfaceVy;
                float vn = rx * nx + ry * ny;
                float fx = gx;
                float fy = gy;
                boolean wedged = false;
                if (vn < 0f) {
                    if (-elasticity * vn < restSpeed) {
                        // Resting on two surfaces at an angle: wedged, it moves with the surface.
                        wedged = rested && restNx * nx + restNy * ny < WEDGE_COS;
                        rested = true;
                        restNx = nx;
                        restNy = ny;
                        rx -= vn * nx;
                        ry -= vn * ny;
                        float gn = gx * nx + gy * ny;
                        if (gn < 0f) {
                            fx -= gn * nx;
                            fy -= gn * ny;
                        }
                    } else {
                        float j = (1f + elasticity) * vn;
                        rx -= j * nx;
                        ry -= j * ny;
                    }
                }
                if (wedged) {
                    rx = 0f;
                    ry = 0f;
                }
                rx += surfaceVx;
                ry += surfaceVy;
                ax = wx;
                ay = wy;
                bx = wx + rx * rest + 0.5f * fx * rest * rest;
                by = wy + ry * rest + 0.5f * fy * rest * rest;
                ux = rx + fx * rest;
                uy = ry + fy * rest;
                h = rest;
                relative = false;
                if (wedged || hits + 1 == MAX_HITS || !(rest > 0f)
                        || !g.covers(ax, ay, bx, by)) {
                    // Wedged, out of bounces, or the rest of the way leaves the obstacles gathered:
                    // stay here, but never inside a static body (a dynamic one may overlap the wall).
                    leaveStaticBodies(wx, wy, rx, ry);
                    bx = settledX;
                    by = settledY;
                    ux = settledVx;
                    uy = settledVy;
                    break;
                }
            }
            px[i] = bx;
            py[i] = by;
            pvx[i] = ux;
            pvy[i] = uy;
        }
    }

    /**
     * Moves a point out of the static bodies that contain it, each time through the nearest face,
     * dropping the velocity into that face, and never across a segment; leaves the result in the
     * settled fields.
     */
    private void leaveStaticBodies(float x, float y, float vx, float vy) {
        ObstacleGrid g = grid;
        for (int pass = 0; pass < MAX_HITS; pass++) {
            g.gather(x, y, x, y);
            int k = -1;
            for (int j = 0, n = g.foundCount; j < n && k < 0; j++) {
                int b = g.found[j];
                if (b >= g.bodyCount || g.bodies[b].isDynamic()) {
                    continue;
                }
                float c = g.c1[b];
                float s = g.s1[b];
                float lx = c * (x - g.x1[b]) + s * (y - g.y1[b]);
                float ly = -s * (x - g.x1[b]) + c * (y - g.y1[b]);
                if (ray.contains(g.shapes[b], lx, ly)) {
                    k = b;
                }
            }
            if (k < 0) {
                break;
            }
            float c = g.c1[k];
            float s = g.s1[k];
            float nx = c * ray.normalX - s * ray.normalY;
            float ny = s * ray.normalX + c * ray.normalY;
            clipToSegments(x, y, g.x1[k] + c * ray.x - s * ray.y, g.y1[k] + s * ray.x + c * ray.y);
            x = settledX;
            y = settledY;
            float vn = vx * nx + vy * ny;
            if (vn < 0f) {
                vx -= vn * nx;
                vy -= vn * ny;
            }
        }
        settledX = x;
        settledY = y;
        settledVx = vx;
        settledVy = vy;
    }

    /**
     * Stops a jump from one point to another at the first landscape segment it would cross (a
     * skin short of it); leaves the end in settledX, settledY.
     *
     * @return whether it crossed one
     */
    private boolean clipToSegments(float fromX, float fromY, float toX, float toY) {
        ObstacleGrid g = grid;
        settledX = toX;
        settledY = toY;
        if (g.count == g.bodyCount) {
            return false;
        }
        g.gatherPath(fromX, fromY, toX, toY);
        float first = Float.POSITIVE_INFINITY;
        for (int j = 0, n = g.foundCount; j < n; j++) {
            int k = g.found[j];
            if (k >= g.bodyCount && hitSegment(k - g.bodyCount, fromX, fromY, toX, toY) && ray.t < first) {
                first = ray.t;
                settledX = ray.x;
                settledY = ray.y;
            }
        }
        return first != Float.POSITIVE_INFINITY;
    }

    /**
     * Finds the obstacle the segment a→b meets first and leaves its hit, in the world, in the best
     * fields.
     *
     * @param relative whether the start is taken against the bodies' start-of-tick poses
     * @return whether anything was hit
     */
    private boolean earliestHit(float ax, float ay, float bx, float by, boolean relative) {
        ObstacleGrid g = grid;
        g.gatherPath(ax, ay, bx, by);
        int best = -1;
        bestT = Float.POSITIVE_INFINITY;
        int[] found = g.found;
        for (int j = 0, n = g.foundCount; j < n; j++) {
            int k = found[j];
            if (k >= g.bodyCount) {
                if (hitSegment(k - g.bodyCount, ax, ay, bx, by) && ray.t < bestT) {
                    best = k;
                    bestT = ray.t;
                    bestX = ray.x;
                    bestY = ray.y;
                    bestNx = ray.normalX;
                    bestNy = ray.normalY;
                    bestVx = 0f;
                    bestVy = 0f;
                }
                continue;
            }
            // Both ends in the body's frame.
            float x0 = relative ? g.x0[k] : g.x1[k];
            float y0 = relative ? g.y0[k] : g.y1[k];
            float c0 = relative ? g.c0[k] : g.c1[k];
            float s0 = relative ? g.s0[k] : g.s1[k];
            float lax = c0 * (ax - x0) + s0 * (ay - y0);
            float lay = -s0 * (ax - x0) + c0 * (ay - y0);
            float x1 = g.x1[k];
            float y1 = g.y1[k];
            float c1 = g.c1[k];
            float s1 = g.s1[k];
            float lbx = c1 * (bx - x1) + s1 * (by - y1);
            float lby = -s1 * (bx - x1) + c1 * (by - y1);
            if (ray.shape(g.shapes[k], lax, lay, lbx, lby) && ray.t < bestT) {
                best = k;
                bestT = ray.t;
                // Back in the world, at the body's end pose.
                bestX = x1 + c1 * ray.x - s1 * ray.y;
                bestY = y1 + s1 * ray.x + c1 * ray.y;
                bestNx = c1 * ray.normalX - s1 * ray.normalY;
                bestNy = s1 * ray.normalX + c1 * ray.normalY;
                bestVx = g.vx[k] - g.w[k] * (bestY - y1);
                bestVy = g.vy[k] + g.w[k] * (bestX - x1);
            }
        }
        if (best < 0) {
            return false;
        }
        if (best < g.bodyCount && g.count > g.bodyCount) {
            // Moved onto a body's surface: not across the landscape (clipToSegments keeps best*). The
            // jump is also tested from the path's start: the point where the path met the body may
            // round onto a segment's line (a particle resting on a wall that a body pushes into),
            // and a jump starting on the line does not count as crossing it.
            if (!clipToSegments(ax + bestT * (bx - ax), ay + bestT * (by - ay), bestX, bestY)) {
                clipToSegments(ax, ay, bestX, bestY);
            }
            bestX = settledX;
            bestY = settledY;
        }
        return true;
    }

    /**
     * Crosses the path a→b with segment s of the grid, from either side (faces are ignored for
     * particles, as in the original). The segment is stretched by a skin at both ends so that a
     * path through a joint of a chain is caught by one of its segments despite rounding; a path
     * starting exactly on the line is not a crossing.
     */
    private boolean hitSegment(int s, float ax, float ay, float bx, float by) {
        ObstacleGrid g = grid;
        return ray.segment(g.segX1[s], g.segY1[s], g.segX2[s], g.segY2[s], ax, ay, bx, by);
    }
}
