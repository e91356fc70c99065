package org.emini.particle;

import java.util.Arrays;
import org.emini.collision.IndexList;
import org.emini.collision.QueryCallback;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.dynamics.Simulation;
import org.emini.dynamics.StepData;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * The bodies and landscape segments particles can hit in one tick, in a uniform grid rebuilt every
 * tick.
 *
 * <p>Obstacles are numbered bodies first ({@code 0 .. bodyCount − 1}), then segments. Only
 * interacting bodies (circles, polygons, multi-shapes) whose motion over the tick overlaps the
 * particles' region are taken, whatever their layers (as in the original). Each keeps its pose at
 * the end of the tick (the solver's result) and its pose at the start (from the tick's
 * {@link StepData}), so a particle's motion can be tested relative to a moving body; a body the
 * tick did not simulate (static, or frozen outside the simulation area) stands still. The bodies
 * come from {@link Simulation#queryBodies} (exact current boxes: the simulated bodies one by one, the
 * others through the broadphase), so the cost follows the simulated bodies and those near the
 * particles, never the frozen ones elsewhere; particles then query the grid, which measured 2 to 20
 * times faster here than querying the broadphase per particle. The per-tick counting sort costs
 * O(bodies taken) and allocates nothing once its arrays have grown. The landscape's segments near
 * the region come from its own index.
 *
 * <p>The cell size is the mean body size, but at least 1/128 of the region, so the grid has at most
 * 128 × 128 cells. Bodies that would cover more than {@link #MAX_CELLS_PER_BODY} cells (walls, the
 * ground) go to a short list that every query scans.
 */
final class ObstacleGrid implements QueryCallback {
    private static final int MAX_CELLS_PER_SIDE = 128;
    /** Obstacles covering more cells than this are scanned by every query instead. */
    static final int MAX_CELLS_PER_BODY = 64;

    /** Bodies, numbered first. */
    int bodyCount;
    /** Bodies and segments. */
    int count;
    Body[] bodies = new Body[16];
    Shape[] shapes = new Shape[16];
    // Pose at the start (0) and end (1) of the tick: position and rotation (cos, sin).
    float[] x0 = new float[16];
    float[] y0 = new float[16];
    float[] c0 = new float[16];
    float[] s0 = new float[16];
    float[] x1 = new float[16];
    float[] y1 = new float[16];
    float[] c1 = new float[16];
    float[] s1 = new float[16];
    float[] vx = new float[16];
    float[] vy = new float[16];
    float[] w = new float[16];
    // Segments, by obstacle number − bodyCount.
    float[] segX1 = new float[16];
    float[] segY1 = new float[16];
    float[] segX2 = new float[16];
    float[] segY2 = new float[16];
    // Box around each obstacle over the whole tick.
    float[] minX = new float[16];
    float[] minY = new float[16];
    float[] maxX = new float[16];
    float[] maxY = new float[16];
    private int[] stamp = new int[16];
    private int stampNow;

    /** The region the bodies were selected for; a query outside it may miss bodies. */
    float regionMinX;
    float regionMinY;
    float regionMaxX;
    float regionMaxY;

    private float originX;
    private float originY;
    private float invCell;
    private int cellsX;
    private int cellsY;
    // Allocated at the largest grid on first use, so that a spreading cloud never grows them late.
    private int[] cellStart;
    private int[] cellFill;
    private int[] items = new int[16];
    private int[] large = new int[4];
    private int largeCount;

    /** The obstacles found by the last {@link #gather}. */
    int[] found = new int[16];
    int foundCount;

    private final float[] box = new float[4];
    private float sizeSum;
    /** The tick's step data, during {@link #build}. */
    private StepData step;
    /** The landscape being queried in {@link #build}. */
    private Landscape landscape;
    /** The world indices of the bodies a query found. */
    private final IndexList candidates = new IndexList();
    /** Bodies looked at by the last {@link #build} (simulated ones and those queries found). */
    int visited;

    /**
     * Takes the world's bodies that may meet a particle moving inside the region this tick.
     *
     * <p>A particle found inside a body is moved out through the nearest face, which may take it
     * out of the region by up to half the body's narrower side; the region is grown by the largest
     * such distance among the bodies it touches, so that the bodies where it may land are known too.
     *
     * <p>Bodies are found with {@link Simulation#queryBodies}, the region grown by the farthest a
     * simulated body moved this tick, so the cost follows the simulated bodies and the bodies near
     * the particles: bodies frozen or static elsewhere cost nothing.
     */
    void build(Simulation world, float rMinX, float rMinY, float rMaxX, float rMaxY) {
        count = 0;
        largeCount = 0;
        step = world.getStepData();
        float maxReach = 0f;
        int simulated = step.getBodyCount();
        for (int i = 0; i < simulated; i++) {
            maxReach = Math.max(maxReach, reach(step.getBody(i)));
        }
        visited = simulated;
        // First the bodies that touch the region, for the margin.
        query(world, rMinX - maxReach, rMinY - maxReach, rMaxX + maxReach, rMaxY + maxReach);
        float margin = 0f;
        for (int j = 0; j < candidates.count(); j++) {
            Body b = world.getBody(candidates.get(j));
            if (collides(b) && mayReach(b, rMinX, rMinY, rMaxX, rMaxY)) {
                shapeBox(b);
                margin = Math.max(margin, 0.5f * Math.min(box[2] - box[0], box[3] - box[1]));
            }
        }
        rMinX -= margin;
        rMinY -= margin;
        rMaxX += margin;
        rMaxY += margin;
        regionMinX = rMinX;
        regionMinY = rMinY;
        regionMaxX = rMaxX;
        regionMaxY = rMaxY;
        if (margin > 0f) {
            query(world, rMinX - maxReach, rMinY - maxReach, rMaxX + maxReach, rMaxY + maxReach);
        }
        // Then the bodies in reach of the grown region, with both poses, in world order.
        sizeSum = 0f;
        for (int j = 0; j < candidates.count(); j++) {
            Body b = world.getBody(candidates.get(j));
            if (!collides(b) || !mayReach(b, rMinX, rMinY, rMaxX, rMaxY)) {
                continue;
            }
            Shape shape = b.getShape();
            float bx = b.getX();
            float by = b.getY();
            float bc = b.getCos();
            float bs = b.getSin();
            shape.computeAabb(bx, by, bc, bs, box);
            int at = step.indexOf(b);
            boolean still = at < 0;
            float bvx = still ? 0f : b.getVelocityX();
            float bvy = still ? 0f : b.getVelocityY();
            float bw = still ? 0f : b.getAngularVelocity();
            float lowX = box[0];
            float lowY = box[1];
            float highX = box[2];
            float highY = box[3];
            float sx = bx;
            float sy = by;
            float sc = bc;
            float ss = bs;
            if (!still) {
                sx = step.getStartX(at);
                sy = step.getStartY(at);
                float a = step.getStartAngle(at);
                if (a != b.getAngle()) {
                    sc = EMath.cos(a);
                    ss = EMath.sin(a);
                }
                shape.computeAabb(sx, sy, sc, ss, box);
                lowX = Math.min(lowX, box[0]);
                lowY = Math.min(lowY, box[1]);
                highX = Math.max(highX, box[2]);
                highY = Math.max(highY, box[3]);
            }
            if (lowX > rMaxX || highX < rMinX || lowY > rMaxY || highY < rMinY) {
                continue;
            }
            int k = append(lowX, lowY, highX, highY);
            bodies[k] = b;
            shapes[k] = shape;
            x0[k] = sx;
            y0[k] = sy;
            c0[k] = sc;
            s0[k] = ss;
            x1[k] = bx;
            y1[k] = by;
            c1[k] = bc;
            s1[k] = bs;
            vx[k] = bvx;
            vy[k] = bvy;
            w[k] = bw;
        }
        for (int k = count; k < bodies.length && bodies[k] != null; k++) {
            bodies[k] = null;
            shapes[k] = null;
        }
        bodyCount = count;
        // The landscape's segments near the particles (from its index); faces do not matter to particles.
        landscape = world.getLandscape();
        if (landscape.getSegmentCount() > 0) {
            landscape.querySegments(rMinX, rMinY, rMaxX, rMaxY, this);
        }
        landscape = null;
        step = null;
        if (count > 0) {
            index(sizeSum / count);
        }
    }

    /** Whether particles bounce off the body: interacting, and a shape they can be tested against. */
    private static boolean collides(Body b) {
        int type = b.getShape().getType();
        return b.isInteracting() && (type == Shape.TYPE_CIRCLE || type == Shape.TYPE_POLYGON || type == Shape.TYPE_MULTI);
    }

    /** How far any point of a body moved this tick (a bound): nothing unless the tick simulated it. */
    private float reach(Body b) {
        int at = step.indexOf(b);
        return at < 0 ? 0f : Math.abs(b.getX() - step.getStartX(at)) + Math.abs(b.getY() - step.getStartY(at))
            + Math.abs(b.getAngle() - step.getStartAngle(at)) * b.getShape().getBoundingRadius();
    }

    /** Puts the body's current box in {@link #box}. */
    private void shapeBox(Body b) {
        b.getShape().computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), box);
    }

    /** Whether a cheap box around the body's motion this tick overlaps the rectangle. */
    private boolean mayReach(Body b, float minX, float minY, float maxX, float maxY) {
        shapeBox(b);
        float reach = reach(b);
        return box[0] - reach <= maxX && box[2] + reach >= minX && box[1] - reach <= maxY && box[3] + reach >= minY;
    }

    /** Collects in {@link #candidates} the bodies whose box overlaps the rectangle, in world order. */
    private void query(Simulation world, float minX, float minY, float maxX, float maxY) {
        candidates.clear();
        world.queryBodies(minX, minY, maxX, maxY, candidates);
        visited += candidates.count();
    }

    /** Takes a landscape segment reported by {@link Landscape#querySegments}. */
    @Override
    public boolean reportProxy(int index) {
        Landscape land = landscape;
        float ax = land.getStartX(index);
        float ay = land.getStartY(index);
        float bx = land.getEndX(index);
        float by = land.getEndY(index);
        int s = append(Math.min(ax, bx), Math.min(ay, by), Math.max(ax, bx), Math.max(ay, by)) - bodyCount;
        if (s == segX1.length) {
            int size = 2 * s;
            segX1 = Arrays.copyOf(segX1, size);
            segY1 = Arrays.copyOf(segY1, size);
            segX2 = Arrays.copyOf(segX2, size);
            segY2 = Arrays.copyOf(segY2, size);
        }
        segX1[s] = ax;
        segY1[s] = ay;
        segX2[s] = bx;
        segY2[s] = by;
        return true;
    }

    /** Adds an obstacle with its box and counts its size; returns its number. */
    private int append(float lowX, float lowY, float highX, float highY) {
        int k = count;
        if (k == minX.length) {
            grow();
        }
        minX[k] = lowX;
        minY[k] = lowY;
        maxX[k] = highX;
        maxY[k] = highY;
        // Size as seen inside the region, so one huge ground does not coarsen the grid.
        sizeSum += Math.max(Math.min(highX, regionMaxX) - Math.max(lowX, regionMinX),
            Math.min(highY, regionMaxY) - Math.max(lowY, regionMinY));
        count = k + 1;
        return k;
    }

    /** Sorts the bodies into cells (a counting sort: count, prefix sums, fill). */
    private void index(float meanSize) {
        float spanX = regionMaxX - regionMinX;
        float spanY = regionMaxY - regionMinY;
        float cell = Math.max(meanSize, Math.max(spanX, spanY) / MAX_CELLS_PER_SIDE);
        if (!(cell > 0f) || !EMath.isFinite(cell)) {
            cell = 1f;
        }
        originX = regionMinX;
        originY = regionMinY;
        invCell = 1f / cell;
        cellsX = Math.min(MAX_CELLS_PER_SIDE, 1 + (int) (spanX * invCell));
        cellsY = Math.min(MAX_CELLS_PER_SIDE, 1 + (int) (spanY * invCell));
        int cells = cellsX * cellsY;
        if (cellStart == null) {
            cellStart = new int[MAX_CELLS_PER_SIDE * MAX_CELLS_PER_SIDE + 1];
            cellFill = new int[MAX_CELLS_PER_SIDE * MAX_CELLS_PER_SIDE];
        }
        Arrays.fill(cellStart, 0, cells + 1, 0);
        int total = 0;
        for (int k = 0; k < count; k++) {
            int ix0 = cellX(minX[k]);
            int ix1 = cellX(maxX[k]);
            int iy0 = cellY(minY[k]);
            int iy1 = cellY(maxY[k]);
            int covered = (ix1 - ix0 + 1) * (iy1 - iy0 + 1);
            if (covered > MAX_CELLS_PER_BODY) {
                if (largeCount == large.length) {
                    large = Arrays.copyOf(large, 2 * largeCount);
                }
                large[largeCount++] = k;
                continue;
            }
            total += covered;
            for (int iy = iy0; iy <= iy1; iy++) {
                for (int ix = ix0; ix <= ix1; ix++) {
                    cellStart[iy * cellsX + ix + 1]++;
                }
            }
        }
        for (int c = 0; c < cells; c++) {
            cellStart[c + 1] += cellStart[c];
            cellFill[c] = cellStart[c];
        }
        if (items.length < total) {
            items = new int[Math.max(total, 2 * items.length)];
        }
        // Large bodies were counted nowhere; placing the rest again in body order keeps cells sorted.
        int nextLarge = 0;
        for (int k = 0; k < count; k++) {
            if (nextLarge < largeCount && large[nextLarge] == k) {
                nextLarge++;
                continue;
            }
            int ix0 = cellX(minX[k]);
            int ix1 = cellX(maxX[k]);
            int iy0 = cellY(minY[k]);
            int iy1 = cellY(maxY[k]);
            for (int iy = iy0; iy <= iy1; iy++) {
                for (int ix = ix0; ix <= ix1; ix++) {
                    items[cellFill[iy * cellsX + ix]++] = k;
                }
            }
        }
    }

    private int cellX(float v) {
        int i = (int) ((v - originX) * invCell);
        return i < 0 ? 0 : i >= cellsX ? cellsX - 1 : i;
    }

    private int cellY(float v) {
        int i = (int) ((v - originY) * invCell);
        return i < 0 ? 0 : i >= cellsY ? cellsY - 1 : i;
    }

    /** Whether the box around the path a→b lies inside the region the obstacles were selected for. */
    boolean covers(float ax, float ay, float bx, float by) {
        return Math.min(ax, bx) >= regionMinX && Math.max(ax, bx) <= regionMaxX
            && Math.min(ay, by) >= regionMinY && Math.max(ay, by) <= regionMaxY;
    }

    /** {@link #gather} for the box around the path a→b. */
    void gatherPath(float ax, float ay, float bx, float by) {
        gather(Math.min(ax, bx), Math.min(ay, by), Math.max(ax, bx), Math.max(ay, by));
    }

    /**
     * Collects into {@link #found} each body whose box over the tick overlaps the given box, once,
     * in a deterministic order.
     */
    void gather(float lowX, float lowY, float highX, float highY) {
        foundCount = 0;
        if (count == 0) {
            return;
        }
        for (int j = 0; j < largeCount; j++) {
            take(large[j], lowX, lowY, highX, highY);
        }
        if (stampNow == Integer.MAX_VALUE) {
            Arrays.fill(stamp, 0);
            stampNow = 0;
        }
        int now = ++stampNow;
        int ix0 = cellX(lowX);
        int ix1 = cellX(highX);
        int iy0 = cellY(lowY);
        int iy1 = cellY(highY);
        boolean single = ix0 == ix1 && iy0 == iy1;
        for (int iy = iy0; iy <= iy1; iy++) {
            for (int ix = ix0; ix <= ix1; ix++) {
                int c = iy * cellsX + ix;
                for (int j = cellStart[c], end = cellStart[c + 1]; j < end; j++) {
                    int k = items[j];
                    if (!single) {
                        // A body in several of the cells must be taken once.
                        if (stamp[k] == now) {
                            continue;
                        }
                        stamp[k] = now;
                    }
                    take(k, lowX, lowY, highX, highY);
                }
            }
        }
    }

    private void take(int k, float lowX, float lowY, float highX, float highY) {
        if (minX[k] <= highX && lowX <= maxX[k] && minY[k] <= highY && lowY <= maxY[k]) {
            found[foundCount++] = k;
        }
    }

    private void grow() {
        int n = 2 * minX.length;
        bodies = Arrays.copyOf(bodies, n);
        shapes = Arrays.copyOf(shapes, n);
        x0 = Arrays.copyOf(x0, n);
        y0 = Arrays.copyOf(y0, n);
        c0 = Arrays.copyOf(c0, n);
        s0 = Arrays.copyOf(s0, n);
        x1 = Arrays.copyOf(x1, n);
        y1 = Arrays.copyOf(y1, n);
        c1 = Arrays.copyOf(c1, n);
        s1 = Arrays.copyOf(s1, n);
        vx = Arrays.copyOf(vx, n);
        vy = Arrays.copyOf(vy, n);
        w = Arrays.copyOf(w, n);
        minX = Arrays.copyOf(minX, n);
        minY = Arrays.copyOf(minY, n);
        maxX = Arrays.copyOf(maxX, n);
        maxY = Arrays.copyOf(maxY, n);
        stamp = Arrays.copyOf(stamp, n);
        found = new int[n];
    }
}
