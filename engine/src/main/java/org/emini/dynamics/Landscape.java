package org.emini.dynamics;

import java.util.Arrays;
import org.emini.collision.QueryCallback;
import org.emini.collision.Segment;
import org.emini.collision.StaticAabbTree;
import org.emini.collision.SweptBox;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * The world's border and fixed obstacles: many line segments, each with a facing, and one material
 * for all of them. Cheaper than static bodies, and meant for thousands of segments: they are kept in
 * a bounding-box tree, so a body only ever looks at the segments near it.
 *
 * <p>The landscape collides with dynamic bodies only, whatever their collision layers and their
 * interacting flag (as in the original engine). A contact's friction and elasticity are the body
 * shape's factors times the landscape's.
 *
 * <p>Facing ({@link #FACE_LEFT}, {@link #FACE_RIGHT}) makes a segment one-sided, with the
 * original's meaning on a y-down screen: a left-faced segment stops bodies on the left-hand side of
 * its direction start → end (where (end − start) × (p − start) &lt; 0, a × b = a.x·b.y − a.y·b.x)
 * and lets bodies on the right-hand side pass; a right-faced one the reverse; {@link #FACE_NONE}
 * stops bodies from both sides. Which side a body is on is decided by one point of it: for a faced
 * segment its position (its shapes' origin, as in the original engine's one-way platforms), for an
 * unfaced one its centre of mass; a body exactly on the line is blocked, as in the original. So a
 * body coming from the open side passes through and is never pushed out on the blocking side; a
 * multi-shape body passes or is stopped as a whole. A body whose origin lies outside its shapes (an
 * off-centre multi-shape) is let through a faced segment once its origin crosses the line, even while
 * its shapes rest on the blocking side. Segments that share an end point (within
 * {@link #JOIN_TOLERANCE}) form a smooth chain: bodies slide across the joints without catching.
 *
 * <p>As in the original, segments are stored with start x ≤ end x: a segment given the other way
 * (or vertical) has its ends swapped and its facing flipped, which keeps the same blocking side.
 * Zero-length segments are kept but collide with nothing.
 *
 * <p>Change the landscape only between ticks. Removing a segment shifts the indices of the later
 * ones. A few segments added or removed cost little; after many, the index is rebuilt at the next
 * tick, in O(n log n) for n segments. A landscape may be shared by worlds ticked on one thread.
 */
public final class Landscape {
    /** Solid from both sides. */
    public static final int FACE_NONE = Segment.FACE_NONE;
    /** Stops bodies on the left of start → end (as seen on a y-down screen). */
    public static final int FACE_LEFT = Segment.FACE_LEFT;
    /** Stops bodies on the right of start → end (as seen on a y-down screen). */
    public static final int FACE_RIGHT = Segment.FACE_RIGHT;
    /** Friction factor of a new landscape. */
    public static final float DEFAULT_FRICTION = 0.25f;
    /** Elasticity of a new landscape. */
    public static final float DEFAULT_ELASTICITY = 0f;
    /** End points closer than this (px) join two segments into a chain. */
    public static final float JOIN_TOLERANCE = 0.01f;
    // Segments added (or removed from the tree) since the last build before the tree is rebuilt,
    // at least; 2·√n for n segments when that is more.
    private static final int REBUILD_EDITS = 64;

    // Segments live in slots that keep their number while other segments come and go, so contacts
    // can refer to them; stamp tells a slot's successive occupants apart (0 when free).
    private float[] x1 = new float[16];
    private float[] y1 = new float[16];
    private float[] x2 = new float[16];
    private float[] y2 = new float[16];
    private int[] face = new int[16];
    private int[] stamp = new int[16];
    private int[] slotIndex = new int[16];
    private boolean[] hasPrev = new boolean[16];
    private boolean[] hasNext = new boolean[16];
    private float[] prevX = new float[16];
    private float[] prevY = new float[16];
    private float[] nextX = new float[16];
    private float[] nextY = new float[16];
    private int slotHigh;
    private int[] freeSlots = new int[16];
    private int freeCount;
    // Slots freed since the tree was built: the tree may still hold their old boxes, so they are
    // reused only after the next build.
    private int[] pendingFree = new int[16];
    private int pendingFreeCount;
    private int nextStamp;
    /** Slot of each segment, in index order. */
    private int[] order = new int[16];
    private int count;

    private float friction = DEFAULT_FRICTION;
    private float elasticity = DEFAULT_ELASTICITY;

    /** Bumped by every change of the segments; a world re-queries its bodies when it moves. */
    int modCount;
    private boolean dirty;
    // The index: a static tree built from the segments present at the last build, plus the few
    // added since (scanned one by one) and minus those removed since (skipped). Small edits thus
    // cost little; the tree is rebuilt once enough of them have piled up.
    private final StaticAabbTree tree = new StaticAabbTree();
    private boolean[] inTree = new boolean[16];
    private int treeCount;
    private int treeDead;
    private int[] recent = new int[16];
    private int recentCount;
    private boolean built;
    // End points of the segments added or removed since the last prepare, whose joins may change.
    private float[] touched = new float[16];
    private int touchedCount;
    private final JoinFinder joins = new JoinFinder();
    private final LiveFilter live = new LiveFilter();
    private final SlotsToIndices indices = new SlotsToIndices();
    // Build input, by slot.
    private float[] boxMinX = new float[0];
    private float[] boxMinY = new float[0];
    private float[] boxMaxX = new float[0];
    private float[] boxMaxY = new float[0];
    private int[] boxSlot = new int[0];

    /** Creates an empty landscape with the default material (friction 0.25, elasticity 0). */
    public Landscape() {
    }

    /**
     * Creates a copy of a landscape: the same segments in the same order, and the same material.
     *
     * @param other the landscape to copy
     */
    public Landscape(Landscape other) {
        Check.notNull("Landscape(Landscape)", "other", other);
        for (int i = 0; i < other.count; i++) {
            int s = other.order[i];
            store(other.x1[s], other.y1[s], other.x2[s], other.y2[s], other.face[s]);
        }
        friction = other.friction;
        elasticity = other.elasticity;
    }

    /**
     * Adds a segment at the end of the list.
     *
     * @param startX start x (px)
     * @param startY start y (px)
     * @param endX end x (px)
     * @param endY end y (px)
     * @param face {@link #FACE_NONE}, {@link #FACE_LEFT} or {@link #FACE_RIGHT}
     * @return the new segment's index
     * @throws IllegalArgumentException if a coordinate is not finite or the face is unknown
     */
    public int addSegment(float startX, float startY, float endX, float endY, int face) {
        String where = "Landscape.addSegment";
        Check.finite(where, "startX", startX);
        Check.finite(where, "startY", startY);
        Check.finite(where, "endX", endX);
        Check.finite(where, "endY", endY);
        if (face < FACE_NONE || face > FACE_RIGHT) {
            throw new IllegalArgumentException(where + ": face must be 0 (none), 1 (left) or 2 (right), was " + face);
        }
        if (endX <= startX) {
            // The original's storage order; flipping the face keeps the same blocking side.
            return store(endX, endY, startX, startY, face == FACE_NONE ? FACE_NONE : 3 - face);
        }
        return store(startX, startY, endX, endY, face);
    }

    /**
     * Adds a segment solid from both sides.
     *
     * @param startX start x (px)
     * @param startY start y (px)
     * @param endX end x (px)
     * @param endY end y (px)
     * @return the new segment's index
     * @throws IllegalArgumentException if a coordinate is not finite
     */
    public int addSegment(float startX, float startY, float endX, float endY) {
        return addSegment(startX, startY, endX, endY, FACE_NONE);
    }

    private int store(float sx, float sy, float ex, float ey, int f) {
        int slot;
        if (freeCount > 0) {
            slot = freeSlots[--freeCount];
        } else {
            if (slotHigh == x1.length) {
                growSlots(2 * slotHigh);
            }
            slot = slotHigh++;
        }
        x1[slot] = sx;
        y1[slot] = sy;
        x2[slot] = ex;
        y2[slot] = ey;
        face[slot] = f;
        stamp[slot] = ++nextStamp;
        inTree[slot] = false;
        recent = push(recent, recentCount++, slot);
        touch(sx, sy);
        touch(ex, ey);
        if (count == order.length) {
            order = Arrays.copyOf(order, 2 * count);
        }
        slotIndex[slot] = count;
        order[count++] = slot;
        changed();
        return count - 1;
    }

    private void growSlots(int n) {
        x1 = Arrays.copyOf(x1, n);
        y1 = Arrays.copyOf(y1, n);
        x2 = Arrays.copyOf(x2, n);
        y2 = Arrays.copyOf(y2, n);
        face = Arrays.copyOf(face, n);
        stamp = Arrays.copyOf(stamp, n);
        slotIndex = Arrays.copyOf(slotIndex, n);
        hasPrev = Arrays.copyOf(hasPrev, n);
        inTree = Arrays.copyOf(inTree, n);
        hasNext = Arrays.copyOf(hasNext, n);
        prevX = Arrays.copyOf(prevX, n);
        prevY = Arrays.copyOf(prevY, n);
        nextX = Arrays.copyOf(nextX, n);
        nextY = Arrays.copyOf(nextY, n);
    }

    /**
     * Removes a segment; the later segments' indices drop by one. Contacts with it end at the next
     * tick.
     *
     * @param index 0 to {@link #getSegmentCount()} − 1
     * @throws IndexOutOfBoundsException if the index is out of range
     */
    public void removeSegment(int index) {
        checkIndex("Landscape.removeSegment", index);
        int slot = order[index];
        System.arraycopy(order, index + 1, order, index, count - index - 1);
        count--;
        for (int i = index; i < count; i++) {
            slotIndex[order[i]] = i;
        }
        slotIndex[slot] = -1;
        stamp[slot] = 0;
        if (inTree[slot]) {
            treeDead++;
        }
        touch(x1[slot], y1[slot]);
        touch(x2[slot], y2[slot]);
        pendingFree = push(pendingFree, pendingFreeCount++, slot);
        changed();
    }

    /** Removes every segment; the material stays. */
    public void clear() {
        while (count > 0) {
            removeSegment(count - 1);
        }
    }

    private static int[] push(int[] a, int at, int value) {
        int[] b = at == a.length ? Arrays.copyOf(a, 2 * at) : a;
        b[at] = value;
        return b;
    }

    private void touch(float x, float y) {
        if (2 * touchedCount + 2 > touched.length) {
            touched = Arrays.copyOf(touched, 2 * touched.length);
        }
        touched[2 * touchedCount] = x;
        touched[2 * touchedCount + 1] = y;
        touchedCount++;
    }

    private void changed() {
        modCount++;
        dirty = true;
    }

    /**
     * The number of segments.
     *
     * @return the count
     */
    public int getSegmentCount() {
        return count;
    }

    /**
     * The x of a segment's start point (start x ≤ end x).
     *
     * @param index the segment
     * @return x (px)
     */
    public float getStartX(int index) {
        return x1[order[checkIndex("Landscape.getStartX", index)]];
    }

    /**
     * The y of a segment's start point.
     *
     * @param index the segment
     * @return y (px)
     */
    public float getStartY(int index) {
        return y1[order[checkIndex("Landscape.getStartY", index)]];
    }

    /**
     * The x of a segment's end point.
     *
     * @param index the segment
     * @return x (px)
     */
    public float getEndX(int index) {
        return x2[order[checkIndex("Landscape.getEndX", index)]];
    }

    /**
     * The y of a segment's end point.
     *
     * @param index the segment
     * @return y (px)
     */
    public float getEndY(int index) {
        return y2[order[checkIndex("Landscape.getEndY", index)]];
    }

    /**
     * A segment's facing, relative to its stored direction.
     *
     * @param index the segment
     * @return {@link #FACE_NONE}, {@link #FACE_LEFT} or {@link #FACE_RIGHT}
     */
    public int getFace(int index) {
        return face[order[checkIndex("Landscape.getFace", index)]];
    }

    /**
     * Reports the index of every segment whose bounding box overlaps a box (touching counts), in
     * a deterministic order, until the callback returns false. Uses the landscape's index, so it
     * costs in proportion to the segments near the box, and allocates nothing. The particles use
     * it to find the segments near them.
     *
     * @param minX the left of the box (px)
     * @param minY the top of the box (px)
     * @param maxX the right of the box (px)
     * @param maxY the bottom of the box (px)
     * @param callback receives the segment indices; it must not change the landscape
     */
    public void querySegments(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        Check.notNull("Landscape.querySegments", "callback", callback);
        prepare();
        indices.forward = callback;
        query(minX, minY, maxX, maxY, indices);
        indices.forward = null;
    }

    /**
     * Like {@link #querySegments(float, float, float, float, QueryCallback)}, for a box swept along
     * a translation (the world's ray and shape casts): the segments whose box the sweep meets,
     * walking only the part of the index it passes through.
     */
    void querySegments(SweptBox sweep, QueryCallback callback) {
        prepare();
        indices.forward = callback;
        live.forward = indices;
        live.stopped = false;
        tree.querySwept(sweep, live);
        live.forward = null;
        for (int i = 0; i < recentCount && !live.stopped; i++) {
            int s = recent[i];
            if (stamp[s] != 0 && sweep.meets(Math.min(x1[s], x2[s]), Math.min(y1[s], y2[s]), Math.max(x1[s], x2[s]),
                    Math.max(y1[s], y2[s])) && !indices.reportProxy(s)) {
                break;
            }
        }
        indices.forward = null;
    }

    /** Turns the slots {@link #query} reports into segment indices, for {@link #querySegments}. */
    private final class SlotsToIndices implements QueryCallback {
        QueryCallback forward;

        @Override
        public boolean reportProxy(int slot) {
            return forward.reportProxy(slotIndex[slot]);
        }
    }

    private int checkIndex(String where, int index) {
        if (index < 0 || index >= count) {
            throw new IndexOutOfBoundsException(where + ": index " + index + " of " + count);
        }
        return index;
    }

    /**
     * The friction factor of every segment; a contact uses the body shape's factor times this.
     *
     * @return the factor in [0, 1]
     */
    public float getFriction() {
        return friction;
    }

    /**
     * Sets the friction factor.
     *
     * @param friction the factor in [0, 1]
     * @throws IllegalArgumentException if the value is NaN or outside [0, 1]
     */
    public void setFriction(float friction) {
        this.friction = Check.unit("Landscape.setFriction", "friction", friction);
    }

    /**
     * Sets the friction factor in percent, like the original engine's integer setter.
     *
     * @param percent 0 to 100
     * @throws IllegalArgumentException if the value is outside [0, 100]
     */
    public void setFrictionPercent(int percent) {
        setFriction(percent("Landscape.setFrictionPercent", percent));
    }

    /**
     * The elasticity of every segment; a contact uses the body shape's elasticity times this.
     *
     * @return the elasticity in [0, 1]
     */
    public float getElasticity() {
        return elasticity;
    }

    /**
     * Sets the elasticity.
     *
     * @param elasticity the elasticity in [0, 1]
     * @throws IllegalArgumentException if the value is NaN or outside [0, 1]
     */
    public void setElasticity(float elasticity) {
        this.elasticity = Check.unit("Landscape.setElasticity", "elasticity", elasticity);
    }

    /**
     * Sets the elasticity in percent, like the original engine's integer setter.
     *
     * @param percent 0 to 100
     * @throws IllegalArgumentException if the value is outside [0, 100]
     */
    public void setElasticityPercent(int percent) {
        setElasticity(percent("Landscape.setElasticityPercent", percent));
    }

    private static float percent(String where, int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException(where + ": percent must be in [0, 100], was " + percent);
        }
        return percent / 100f;
    }

    @Override
    public String toString() {
        return "Landscape[" + count + " segments, friction " + friction + ", elasticity " + elasticity + "]";
    }

    // ---------------------------------------------------------------------------------------------
    // For the world

    /**
     * Brings the index and the chain joins up to date after changes: a full rebuild once many
     * segments were added or removed since the last one, otherwise only the joins around the
     * changed end points.
     */
    void prepare() {
        if (!dirty) {
            return;
        }
        dirty = false;
        // Edits left in the list cost every query a box test each; a rebuild costs O(n log n).
        int allowed = Math.max(REBUILD_EDITS, 2 * (int) EMath.sqrt(count));
        if (!built || recentCount > allowed || treeDead > Math.max(allowed, treeCount / 2)) {
            rebuild();
        } else {
            for (int k = 0; k < touchedCount; k++) {
                joins.update(touched[2 * k], touched[2 * k + 1]);
            }
        }
        touchedCount = 0;
    }

    private void rebuild() {
        built = true;
        if (boxMinX.length < count) {
            int n = Math.max(count, 2 * boxMinX.length);
            boxMinX = new float[n];
            boxMinY = new float[n];
            boxMaxX = new float[n];
            boxMaxY = new float[n];
            boxSlot = new int[n];
        }
        for (int i = 0; i < count; i++) {
            int s = order[i];
            boxMinX[i] = Math.min(x1[s], x2[s]);
            boxMinY[i] = Math.min(y1[s], y2[s]);
            boxMaxX[i] = Math.max(x1[s], x2[s]);
            boxMaxY[i] = Math.max(y1[s], y2[s]);
            boxSlot[i] = s;
            inTree[s] = true;
        }
        tree.build(count, boxMinX, boxMinY, boxMaxX, boxMaxY, boxSlot);
        treeCount = count;
        treeDead = 0;
        recentCount = 0;
        for (int i = 0; i < pendingFreeCount; i++) {
            freeSlots = push(freeSlots, freeCount++, pendingFree[i]);
        }
        pendingFreeCount = 0;
        for (int i = 0; i < count; i++) {
            int s = order[i];
            joins.set(s, true, x1[s], y1[s]);
            joins.set(s, false, x2[s], y2[s]);
        }
    }

    /** Reports the slots of the segments whose boxes overlap a box; call {@link #prepare} first. */
    void query(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        live.forward = callback;
        live.stopped = false;
        tree.query(minX, minY, maxX, maxY, live);
        live.forward = null;
        for (int i = 0; i < recentCount && !live.stopped; i++) {
            int s = recent[i];
            if (stamp[s] != 0 && overlaps(s, minX, minY, maxX, maxY) && !callback.reportProxy(s)) {
                return;
            }
        }
    }

    /** Passes on the tree's slots that still hold a segment. */
    private final class LiveFilter implements QueryCallback {
        QueryCallback forward;
        boolean stopped;

        @Override
        public boolean reportProxy(int slot) {
            if (stamp[slot] == 0) {
                return true;
            }
            stopped = !forward.reportProxy(slot);
            return !stopped;
        }
    }

    /** The stamp of a slot's current segment, 0 when the slot is free. */
    int stampOf(int slot) {
        return slot < slotHigh ? stamp[slot] : 0;
    }

    /** The index of the segment in a slot, −1 if the slot is free. */
    int indexOfSlot(int slot) {
        return stamp[slot] != 0 ? slotIndex[slot] : -1;
    }

    /** Whether the segment in a slot has a box overlapping the given box. */
    boolean overlaps(int slot, float minX, float minY, float maxX, float maxY) {
        return Math.min(x1[slot], x2[slot]) <= maxX && minX <= Math.max(x1[slot], x2[slot])
            && Math.min(y1[slot], y2[slot]) <= maxY && minY <= Math.max(y1[slot], y2[slot]);
    }

    /** Copies a slot's segment, with its chain neighbours, into the narrowphase's struct. */
    void fill(int slot, Segment out) {
        out.set(x1[slot], y1[slot], x2[slot], y2[slot], face[slot]);
        out.hasPrev = hasPrev[slot];
        out.prevX = prevX[slot];
        out.prevY = prevY[slot];
        out.hasNext = hasNext[slot];
        out.nextX = nextX[slot];
        out.nextY = nextY[slot];
    }

    /**
     * Finds the one other segment that has an end at a point, and its far end; sets the joins of
     * the segments ending at a changed point.
     */
    private final class JoinFinder implements QueryCallback {
        private int self;
        private float px;
        private float py;
        private float tolerance;
        private int found;
        private float farX;
        private float farY;
        // In update mode the query collects the segments ending at the point instead.
        private boolean collecting;
        private int[] ending = new int[8];
        private int endingCount;

        /** Sets the join at one end of a slot's segment. */
        void set(int slot, boolean start, float x, float y) {
            begin(slot, x, y);
            query(x - tolerance, y - tolerance, x + tolerance, y + tolerance, this);
            if (start) {
                hasPrev[slot] = found == 1;
                prevX[slot] = farX;
                prevY[slot] = farY;
            } else {
                hasNext[slot] = found == 1;
                nextX[slot] = farX;
                nextY[slot] = farY;
            }
        }

        /** Sets the joins of every segment with an end at a point. */
        void update(float x, float y) {
            begin(-1, x, y);
            collecting = true;
            endingCount = 0;
            query(x - tolerance, y - tolerance, x + tolerance, y + tolerance, this);
            collecting = false;
            for (int i = 0; i < endingCount; i++) {
                int s = ending[i];
                if (near(x1[s], y1[s])) {
                    set(s, true, x1[s], y1[s]);
                }
                if (near(x2[s], y2[s])) {
                    set(s, false, x2[s], y2[s]);
                }
                // set() moved the point; restore it for the next near().
                begin(-1, x, y);
            }
        }

        private void begin(int slot, float x, float y) {
            self = slot;
            px = x;
            py = y;
            tolerance = Math.max(JOIN_TOLERANCE, 1e-6f * Math.max(Math.abs(x), Math.abs(y)));
            found = 0;
            farX = 0f;
            farY = 0f;
        }

        @Override
        public boolean reportProxy(int slot) {
            if (slot == self) {
                return true;
            }
            float ax = x1[slot];
            float ay = y1[slot];
            float bx = x2[slot];
            float by = y2[slot];
            boolean atStart = near(ax, ay);
            if (!atStart && !near(bx, by)) {
                return true;
            }
            if (collecting) {
                ending = push(ending, endingCount++, slot);
                return true;
            }
            float dx = bx - ax;
            float dy = by - ay;
            if (EMath.sqrt(dx * dx + dy * dy) <= tolerance) {
                return true;
            }
            found++;
            farX = atStart ? bx : ax;
            farY = atStart ? by : ay;
            return true;
        }

        private boolean near(float x, float y) {
            return Math.abs(x - px) <= tolerance && Math.abs(y - py) <= tolerance;
        }
    }
}
