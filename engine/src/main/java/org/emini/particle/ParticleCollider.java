package org.emini.particle;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Bounces particles off the bodies and landscape segments of an {@link ObstacleGrid}.
 *
 * <p>Each particle's motion of the tick is a segment, tested as a whole so a fast particle cannot
 * pass through a thin wall: against a polygon by clipping it to the face half-planes, against a
 * circle by solving for where it meets the rim, against a landscape segment (from either side) by
 * intersecting the two. A moving body is tested in its own frame, the segment's start taken against
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

    // The result of the last shape test: in the body's frame for bodies, in the world for segments.
    private float hitT;
    private float hitX;
    private float hitY;
    private float hitNx;
    private float hitNy;

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
                Shape shape = g.shapes[b];
                if (insideShape(shape, lx, ly)) {
                    k = b;
                }
            }
            if (k < 0) {
                break;
            }
            float c = g.c1[k];
            float s = g.s1[k];
            float nx = c * hitNx - s * hitNy;
            float ny = s * hitNx + c * hitNy;
            clipToSegments(x, y, g.x1[k] + c * hitX - s * hitY, g.y1[k] + s * hitX + c * hitY);
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
     */
    private void clipToSegments(float fromX, float fromY, float toX, float toY) {
        ObstacleGrid g = grid;
        settledX = toX;
        settledY = toY;
        if (g.count == g.bodyCount) {
            return;
        }
        g.gatherPath(fromX, fromY, toX, toY);
        float first = Float.POSITIVE_INFINITY;
        for (int j = 0, n = g.foundCount; j < n; j++) {
            int k = g.found[j];
            if (k >= g.bodyCount && hitSegment(k - g.bodyCount, fromX, fromY, toX, toY) && hitT < first) {
                first = hitT;
                settledX = hitX;
                settledY = hitY;
            }
        }
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
                if (hitSegment(k - g.bodyCount, ax, ay, bx, by) && hitT < bestT) {
                    best = k;
                    bestT = hitT;
                    bestX = hitX;
                    bestY = hitY;
                    bestNx = hitNx;
                    bestNy = hitNy;
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
            if (hitShape(g.shapes[k], lax, lay, lbx, lby) && hitT < bestT) {
                best = k;
                bestT = hitT;
                // Back in the world, at the body's end pose.
                bestX = x1 + c1 * hitX - s1 * hitY;
                bestY = y1 + s1 * hitX + c1 * hitY;
                bestNx = c1 * hitNx - s1 * hitNy;
                bestNy = s1 * hitNx + c1 * hitNy;
                bestVx = g.vx[k] - g.w[k] * (bestY - y1);
                bestVy = g.vy[k] + g.w[k] * (bestX - x1);
            }
        }
        if (best < 0) {
            return false;
        }
        if (best < g.bodyCount && g.count > g.bodyCount) {
            // Moved onto a body's surface: not across the landscape (clipToSegments keeps best*).
            clipToSegments(ax + bestT * (bx - ax), ay + bestT * (by - ay), bestX, bestY);
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
    boolean hitSegment(int s, float ax, float ay, float bx, float by) {
        ObstacleGrid g = grid;
        float px = g.segX1[s];
        float py = g.segY1[s];
        float ex = g.segX2[s] - px;
        float ey = g.segY2[s] - py;
        // Twice the signed areas: the sides of a and b, scaled by the segment's length.
        float da = ex * (ay - py) - ey * (ax - px);
        float db = ex * (by - py) - ey * (bx - px);
        if (da == 0f || da > 0f && db > 0f || da < 0f && db < 0f) {
            return false;
        }
        float len2 = ex * ex + ey * ey;
        if (!(len2 > 0f)) {
            return false;
        }
        float t = da / (da - db);
        float qx = ax + t * (bx - ax);
        float qy = ay + t * (by - ay);
        float len = EMath.sqrt(len2);
        float along = ((qx - px) * ex + (qy - py) * ey) / len;
        if (along < -SKIN || along > len + SKIN) {
            return false;
        }
        // The normal on a's side; the hit on the line, then a skin out.
        float nx = -ey / len;
        float ny = ex / len;
        if (da < 0f) {
            nx = -nx;
            ny = -ny;
        }
        float out = SKIN - (nx * (qx - px) + ny * (qy - py));
        hitT = t;
        hitX = qx + out * nx;
        hitY = qy + out * ny;
        hitNx = nx;
        hitNy = ny;
        return true;
    }

    private boolean hitShape(Shape shape, float ax, float ay, float bx, float by) {
        int type = shape.getType();
        if (type == Shape.TYPE_CIRCLE) {
            return hitCircle((Circle) shape, ax, ay, bx, by);
        }
        if (type == Shape.TYPE_POLYGON) {
            return hitPolygon((Polygon) shape, ax, ay, bx, by);
        }
        // A multi-shape: the earliest hit among its parts, which share the body's frame.
        MultiShape multi = (MultiShape) shape;
        float t = Float.POSITIVE_INFINITY;
        float x = 0f;
        float y = 0f;
        float nx = 0f;
        float ny = 0f;
        for (int i = 0, n = multi.getShapeCount(); i < n; i++) {
            if (hitShape(multi.getShape(i), ax, ay, bx, by) && hitT < t) {
                t = hitT;
                x = hitX;
                y = hitY;
                nx = hitNx;
                ny = hitNy;
            }
        }
        hitT = t;
        hitX = x;
        hitY = y;
        hitNx = nx;
        hitNy = ny;
        return t <= 1f;
    }

    /** Whether a body-local point is inside a shape (for a multi-shape: in one of its parts). */
    private boolean insideShape(Shape shape, float x, float y) {
        int type = shape.getType();
        if (type == Shape.TYPE_CIRCLE) {
            return insideCircle((Circle) shape, x, y);
        }
        if (type == Shape.TYPE_POLYGON) {
            return insidePolygon((Polygon) shape, x, y);
        }
        MultiShape multi = (MultiShape) shape;
        for (int i = 0, n = multi.getShapeCount(); i < n; i++) {
            if (insideShape(multi.getShape(i), x, y)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Clips the segment a→b to the polygon's face half-planes (Cyrus–Beck). The segment enters at
     * the largest entering parameter, through that face, if that is not after it leaves. A start
     * inside is a hit at t = 0 through the face nearest to the start.
     */
    boolean hitPolygon(Polygon p, float ax, float ay, float bx, float by) {
        int face = -1;
        float enter = 0f;
        float leave = 1f;
        int nearest = 0;
        float nearestDepth = Float.NEGATIVE_INFINITY;
        for (int i = 0, n = p.getVertexCount(); i < n; i++) {
            float nx = p.getNormalX(i);
            float ny = p.getNormalY(i);
            float d = nx * p.getVertexX(i) + ny * p.getVertexY(i);
            float da = nx * ax + ny * ay - d;
            float db = nx * bx + ny * by - d;
            if (da > 0f) {
                if (db > 0f) {
                    return false;
                }
                float t = da / (da - db);
                if (face < 0 || t > enter) {
                    enter = t;
                    face = i;
                }
            } else {
                if (da > nearestDepth) {
                    nearestDepth = da;
                    nearest = i;
                }
                if (db > 0f) {
                    float t = da / (da - db);
                    if (t < leave) {
                        leave = t;
                    }
                }
            }
        }
        float qx = ax;
        float qy = ay;
        if (face < 0) {
            face = nearest;
            hitT = 0f;
        } else {
            if (enter > leave) {
                return false;
            }
            hitT = enter;
            qx += enter * (bx - ax);
            qy += enter * (by - ay);
        }
        surface(p, face, qx, qy);
        return true;
    }

    /** Puts the hit on a face's line exactly, then a skin outside it, whatever the rounding so far. */
    private void surface(Polygon p, int face, float qx, float qy) {
        float nx = p.getNormalX(face);
        float ny = p.getNormalY(face);
        float out = SKIN - (nx * (qx - p.getVertexX(face)) + ny * (qy - p.getVertexY(face)));
        hitX = qx + out * nx;
        hitY = qy + out * ny;
        hitNx = nx;
        hitNy = ny;
    }

    /** Whether a point is inside a polygon; if so, leaves the way out through the nearest face. */
    boolean insidePolygon(Polygon p, float x, float y) {
        int nearest = 0;
        float nearestDepth = Float.NEGATIVE_INFINITY;
        for (int i = 0, n = p.getVertexCount(); i < n; i++) {
            float nx = p.getNormalX(i);
            float ny = p.getNormalY(i);
            float depth = nx * (x - p.getVertexX(i)) + ny * (y - p.getVertexY(i));
            if (depth > 0f) {
                return false;
            }
            if (depth > nearestDepth) {
                nearestDepth = depth;
                nearest = i;
            }
        }
        hitT = 0f;
        surface(p, nearest, x, y);
        return true;
    }

    /**
     * Meets the segment a→b with the circle's rim: the smaller root of |a + t(b − a) − c|² = r². A
     * start inside is a hit at t = 0, out along the radius.
     */
    boolean hitCircle(Circle circle, float ax, float ay, float bx, float by) {
        float cx = circle.getCenterX();
        float cy = circle.getCenterY();
        float r = circle.getRadius();
        float fx = ax - cx;
        float fy = ay - cy;
        float c = fx * fx + fy * fy - r * r;
        if (c <= 0f) {
            hitT = 0f;
            radial(circle, fx, fy);
            return true;
        }
        float dx = bx - ax;
        float dy = by - ay;
        float half = fx * dx + fy * dy;
        if (half >= 0f) {
            return false;
        }
        float aa = dx * dx + dy * dy;
        float disc = half * half - aa * c;
        if (disc < 0f) {
            return false;
        }
        float t = (-half - EMath.sqrt(disc)) / aa;
        if (t > 1f) {
            return false;
        }
        hitT = Math.max(0f, t);
        radial(circle, fx + hitT * dx, fy + hitT * dy);
        return true;
    }

    /** Whether a point is inside a circle; if so, leaves the way out along the radius. */
    boolean insideCircle(Circle circle, float x, float y) {
        float fx = x - circle.getCenterX();
        float fy = y - circle.getCenterY();
        float r = circle.getRadius();
        if (fx * fx + fy * fy > r * r) {
            return false;
        }
        hitT = 0f;
        radial(circle, fx, fy);
        return true;
    }

    /** Puts the hit a skin outside the rim along the direction (qx, qy) from the centre. */
    private void radial(Circle circle, float qx, float qy) {
        float len = EMath.sqrt(qx * qx + qy * qy);
        float nx = 0f;
        float ny = -1f;
        if (len > 0f) {
            nx = qx / len;
            ny = qy / len;
        }
        float r = circle.getRadius() + SKIN;
        hitX = circle.getCenterX() + nx * r;
        hitY = circle.getCenterY() + ny * r;
        hitNx = nx;
        hitNy = ny;
    }
}
