package org.emini.io;

/**
 * A landscape segment: start and end point (px) and its face. Immutable.
 */
public final class PhySegment {
    /** Face 0: solid from both sides. */
    public static final int FACE_NONE = 0;
    /**
     * Face 1: blocks bodies on the left of start→end as seen on a y-down screen, where
     * (end − start) × (p − start) &lt; 0 (above a segment running in +x).
     */
    public static final int FACE_LEFT = 1;
    /** Face 2: blocks bodies on the other side (below a segment running in +x). */
    public static final int FACE_RIGHT = 2;

    private final PhyVector start;
    private final PhyVector end;
    private final int face;

    /**
     * Creates a segment.
     *
     * @param start the start point (px)
     * @param end the end point (px)
     * @param face the face byte as stored, 0 to 255 ({@link #FACE_NONE}, {@link #FACE_LEFT},
     *     {@link #FACE_RIGHT}; the original keeps other values and treats them as neither)
     */
    public PhySegment(PhyVector start, PhyVector end, int face) {
        this.start = PhyWorld.checkNotNull("PhySegment", "start", start);
        this.end = PhyWorld.checkNotNull("PhySegment", "end", end);
        this.face = PhyWorld.checkU8("PhySegment", "face", face);
    }

    /**
     * The start point as stored.
     *
     * @return the start (px)
     */
    public PhyVector getStart() {
        return start;
    }

    /**
     * The end point as stored.
     *
     * @return the end (px)
     */
    public PhyVector getEnd() {
        return end;
    }

    /**
     * The face byte as stored.
     *
     * @return 0 to 255
     */
    public int getFace() {
        return face;
    }

    /**
     * The segment as the original inserts it: when end.x ≤ start.x the points are swapped and a
     * face other than {@link #FACE_NONE} becomes {@link #FACE_LEFT} if it was
     * {@link #FACE_RIGHT} and {@link #FACE_RIGHT} otherwise. This keeps the solid side, and
     * applies to vertical segments too.
     *
     * @return this segment, or the swapped one
     */
    public PhySegment normalized() {
        if (start.getXRaw() < end.getXRaw()) {
            return this;
        }
        int f = face == FACE_NONE ? FACE_NONE : face == FACE_RIGHT ? FACE_LEFT : FACE_RIGHT;
        return new PhySegment(end, start, f);
    }

    static PhySegment read(PhyInput in) throws PhyFormatException {
        PhyVector s = in.vector("start");
        PhyVector e = in.vector("end");
        return new PhySegment(s, e, in.u8("face"));
    }

    void write(PhyOutput out) {
        out.vector(start);
        out.vector(end);
        out.u8(face);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhySegment)) {
            return false;
        }
        PhySegment s = (PhySegment) o;
        return start.equals(s.start) && end.equals(s.end) && face == s.face;
    }

    @Override
    public int hashCode() {
        return (start.hashCode() * 31 + end.hashCode()) * 31 + face;
    }

    @Override
    public String toString() {
        return "PhySegment[" + start + " to " + end + ", face " + face + "]";
    }
}
