package org.emini.io;

import java.util.Arrays;

/**
 * A multishape record (version words above 0x0800): a compound of earlier shape-list entries whose
 * vertices share one local frame. It stores no material: its mass is the sum of the parts', its
 * elasticity and friction are the shape defaults (0 and 0.25), which its contacts use.
 */
public final class PhyMultiShape extends PhyShapeBase {
    private int[] parts = new int[0];

    /** Creates a multishape without parts. */
    public PhyMultiShape() {
    }

    /**
     * Creates a multishape.
     *
     * @param parts the parts' indices in the shape list, each 0 to 254 and below this entry's index
     */
    public PhyMultiShape(int... parts) {
        setParts(parts);
    }

    @Override
    public boolean isMultiShape() {
        return true;
    }

    /**
     * The parts' indices in the shape list.
     *
     * @return a copy of the indices
     */
    public int[] getParts() {
        return parts.clone();
    }

    /**
     * Replaces the parts.
     *
     * @param parts the indices (copied), at most 255, each 0 to 255
     * @throws IllegalArgumentException if there are too many or an index is out of the byte range
     */
    public void setParts(int... parts) {
        if (parts == null || parts.length > 255) {
            throw new IllegalArgumentException("PhyMultiShape.setParts: 0 to 255 parts, got "
                    + (parts == null ? "null" : Integer.toString(parts.length)));
        }
        for (int p : parts) {
            PhyWorld.checkU8("PhyMultiShape.setParts", "part index", p);
        }
        this.parts = parts.clone();
    }

    static PhyMultiShape read(PhyInput in, int shapesSoFar) throws PhyFormatException {
        int k = in.u8("part count");
        int[] ps = new int[k];
        for (int i = 0; i < k; i++) {
            ps[i] = in.index("part # shape index", i, shapesSoFar);
        }
        PhyMultiShape m = new PhyMultiShape();
        m.parts = ps;
        m.readUserData(in, true);
        return m;
    }

    void write(PhyOutput out) {
        out.u8(parts.length);
        for (int i = 0; i < parts.length; i++) {
            out.index("part shape index", parts[i], out.shapes);
        }
        out.string(userDataBytes());
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyMultiShape && Arrays.equals(parts, ((PhyMultiShape) o).parts)
                && userDataEquals((PhyMultiShape) o);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(parts) * 31 + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyMultiShape" + Arrays.toString(parts);
    }
}
