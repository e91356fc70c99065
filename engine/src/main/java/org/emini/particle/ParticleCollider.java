package org.emini.particle;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Bounces particles off the bodies of a {@link BodyGrid}.
 *
 * <p>Each particle's motion of the tick is a segment, tested as a whole so a fast particle cannot
 * pass through a thin wall: against a polygon by clipping it to the face half-planes, against a
 * circle by solving for where it meets the rim. A moving body is tested in its own frame, the
 * segment's start taken against the body's pose at the start of the tick and its end against the
 * pose at the end, so a body that sweeps over a particle meets it on the face that swept it. The
 * earliest hit among all bodies wins; the particle is put on the surface there (a hair outside, at
 * the end-of-tick pose), the normal part of its velocity relative to the surface is reflected and
 * scaled by the elasticity, the tangential part kept, and it moves on for the rest of the tick from
 * there, up to {@link #MAX_HITS} times; after the last it stays on the surface.
 *
 * <p>A bounce slower than one tick of gravity gives is a rest: the normal speed is dropped and the
 * rest of the tick slides along the surface, so resting particles neither jitter nor cost repeated
 * bounces. A particle that starts inside a body (emitted inside it, a body moved over it, or
 * squeezed where a dynamic body overlaps another) meets it at once, on the face nearest to it
 * (radially on a circle), as the original pushed particles out along the shallowest axis. A
 * particle left on a surface after its last bounce is finally moved out of any static body, so
 * walls hold even where a dynamic body presses into them.
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

    private final BodyGrid grid;

    // The result of the last shape test, in the body's frame.
    private float hitT;
    private float hitX;
    private float hitY;
    private float hitNx;
    private float hitNy;

    // The result of leaveStaticBodies.
    private float settledX;
    private float settledY;
    private float settledVx;
    private float settledVy;

    ParticleCollider(BodyGrid grid) {
        this.grid = grid;
    }

    /** Bounces every particle of an emitter whose motion this tick met a body. */
    void collide(ParticleEmitter e, float dt, float gravityX, float gravityY) {
        BodyGrid g = grid;
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
                int k = earliestHit(ax, ay, bx, by, relative);
                if (k < 0) {
                    break;
                }
                // The hit, back in the world at the body's end pose.
                float c = g.c1[k];
                float s = g.s1[k];
                float wx = g.x1[k] + c * hitX - s * hitY;
                float wy = g.y1[k] + s * hitX + c * hitY;
                float nx = c * hitNx - s * hitNy;
                float ny = s * hitNx + c * hitNy;
                float surfaceVx = g.vx[k] - g.w[k] * (wy - g.y1[k]);
                float surfaceVy = g.vy[k] + g.w[k] * (wx - g.x1[k]);
                float rest = h * (1f - hitT);
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
                        || !g.covers(Math.min(ax, bx), Math.min(ay, by), Math.max(ax, bx), Math.max(ay, by))) {
                    // Wedged, out of bounces, or the rest of the way leaves the bodies gathered: stay
                    // here, but never inside a static body (a dynamic one may overlap the wall here).
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
     * dropping the velocity into that face; leaves the result in the settled fields.
     */
    private void leaveStaticBodies(float x, float y, float vx, float vy) {
        BodyGrid g = grid;
        for (int pass = 0; pass < MAX_HITS; pass++) {
            g.gather(x, y, x, y);
            int k = -1;
            for (int j = 0, n = g.foundCount; j < n && k < 0; j++) {
                int b = g.found[j];
                if (g.bodies[b].isDynamic()) {
                    continue;
                }
                float c = g.c1[b];
                float s = g.s1[b];
                float lx = c * (x - g.x1[b]) + s * (y - g.y1[b]);
                float ly = -s * (x - g.x1[b]) + c * (y - g.y1[b]);
                Shape shape = g.shapes[b];
                if (shape.getType() == Shape.TYPE_CIRCLE ? insideCircle((Circle) shape, lx, ly) : insidePolygon((Polygon) shape, lx, ly)) {
                    k = b;
                }
            }
            if (k < 0) {
                break;
            }
            float c = g.c1[k];
            float s = g.s1[k];
            x = g.x1[k] + c * hitX - s * hitY;
            y = g.y1[k] + s * hitX + c * hitY;
            float nx = c * hitNx - s * hitNy;
            float ny = s * hitNx + c * hitNy;
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
     * Finds the body the segment meets first and leaves its hit in the fields.
     *
     * @param relative whether the start is taken against the bodies' start-of-tick poses
     * @return the body's index in the grid, or −1
     */
    private int earliestHit(float ax, float ay, float bx, float by, boolean relative) {
        BodyGrid g = grid;
        g.gather(Math.min(ax, bx), Math.min(ay, by), Math.max(ax, bx), Math.max(ay, by));
        int best = -1;
        float bestT = Float.POSITIVE_INFINITY;
        float bestX = 0f;
        float bestY = 0f;
        float bestNx = 0f;
        float bestNy = 0f;
        int[] found = g.found;
        for (int j = 0, n = g.foundCount; j < n; j++) {
            int k = found[j];
            // Both ends in the body's frame.
            float x0 = relative ? g.x0[k] : g.x1[k];
            float y0 = relative ? g.y0[k] : g.y1[k];
            float c0 = relative ? g.c0[k] : g.c1[k];
            float s0 = relative ? g.s0[k] : g.s1[k];
            float lax = c0 * (ax - x0) + s0 * (ay - y0);
            float lay = -s0 * (ax - x0) + c0 * (ay - y0);
            float c1 = g.c1[k];
            float s1 = g.s1[k];
            float lbx = c1 * (bx - g.x1[k]) + s1 * (by - g.y1[k]);
            float lby = -s1 * (bx - g.x1[k]) + c1 * (by - g.y1[k]);
            if (hitShape(g.shapes[k], lax, lay, lbx, lby) && hitT < bestT) {
                best = k;
                bestT = hitT;
                bestX = hitX;
                bestY = hitY;
                bestNx = hitNx;
                bestNy = hitNy;
            }
        }
        hitT = bestT;
        hitX = bestX;
        hitY = bestY;
        hitNx = bestNx;
        hitNy = bestNy;
        return best;
    }

    private boolean hitShape(Shape shape, float ax, float ay, float bx, float by) {
        if (shape.getType() == Shape.TYPE_CIRCLE) {
            return hitCircle((Circle) shape, ax, ay, bx, by);
        }
        return hitPolygon((Polygon) shape, ax, ay, bx, by);
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
