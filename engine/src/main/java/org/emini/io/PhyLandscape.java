package org.emini.io;

import java.util.ArrayList;
import java.util.List;

/**
 * The landscape record: static line segments and one material for all of them. The material is a
 * shape record (the designer writes it without vertices); only its elasticity and friction are
 * used, and the original discards its user-data string.
 */
public final class PhyLandscape {
    /** The fewest bytes a segment takes: two vectors and a face byte. */
    static final int SEGMENT_BYTES = 17;

    private final List<PhySegment> segments = new ArrayList<PhySegment>();
    private PhyShape material = new PhyShape();

    /** Creates an empty landscape with the default material (elasticity 0, friction 0.25). */
    public PhyLandscape() {
    }

    /**
     * The segments in file order (as stored, not normalized). The list is live: edit it to change
     * the landscape.
     *
     * @return the segment list
     */
    public List<PhySegment> getSegments() {
        return segments;
    }

    /**
     * The material record.
     *
     * @return the shape record holding elasticity and friction
     */
    public PhyShape getMaterial() {
        return material;
    }

    /**
     * Replaces the material record.
     *
     * @param material the shape record holding elasticity and friction
     */
    public void setMaterial(PhyShape material) {
        this.material = PhyWorld.checkNotNull("PhyLandscape.setMaterial", "material", material);
    }

    static PhyLandscape read(PhyInput in) throws PhyFormatException {
        PhyLandscape l = new PhyLandscape();
        int at = in.position();
        in.record("landscape", -1);
        int n = in.i32("segment count");
        in.checkCount(at, "segment count", n, SEGMENT_BYTES);
        for (int i = 0; i < n; i++) {
            in.record("landscape segment", i);
            l.segments.add(PhySegment.read(in));
        }
        in.record("landscape material", -1);
        l.material = PhyShape.read(in);
        return l;
    }

    void write(PhyOutput out) {
        out.i32(segments.size());
        for (PhySegment s : segments) {
            s.write(out);
        }
        material.write(out);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyLandscape && segments.equals(((PhyLandscape) o).segments)
                && material.equals(((PhyLandscape) o).material);
    }

    @Override
    public int hashCode() {
        return segments.hashCode() * 31 + material.hashCode();
    }

    @Override
    public String toString() {
        return "PhyLandscape[" + segments.size() + " segments]";
    }
}
