package org.emini.io;

/**
 * The writer's byte sink with the format's primitives, and the running counts of what it has
 * written so far (references may only name earlier entries).
 */
final class PhyOutput {
    private byte[] buf = new byte[1024];
    private int size;
    private final int version;
    int shapes;
    int bodies;
    int constraints;
    int scripts;

    // The record being written, named in error messages only.
    private String kind = "";
    private int index = -1;

    PhyOutput(int version) {
        this.version = version;
    }

    /** Names the record the next writes belong to, e.g. ("body", 3). */
    void record(String kind, int index) {
        this.kind = kind;
        this.index = index;
    }

    int recordIndex() {
        return index;
    }

    /** "kind index", e.g. "body 3". */
    String describe() {
        return index >= 0 ? kind + " " + index : kind;
    }

    int version() {
        return version;
    }

    private void ensure(int n) {
        if (buf.length - size < n) {
            byte[] grown = new byte[Math.max(buf.length * 2, size + n)];
            System.arraycopy(buf, 0, grown, 0, size);
            buf = grown;
        }
    }

    void u8(int v) {
        ensure(1);
        buf[size++] = (byte) v;
    }

    void i32(int v) {
        ensure(4);
        buf[size] = (byte) (v >>> 24);
        buf[size + 1] = (byte) (v >>> 16);
        buf[size + 2] = (byte) (v >>> 8);
        buf[size + 3] = (byte) v;
        size += 4;
    }

    void vector(PhyVector v) {
        i32(v.getXRaw());
        i32(v.getYRaw());
    }

    void bytes(byte[] b) {
        ensure(b.length);
        System.arraycopy(b, 0, buf, size, b.length);
        size += b.length;
    }

    void string(byte[] b) {
        i32(b.length);
        bytes(b);
    }

    /** A u8 index that must name one of the count entries written so far. */
    void index(String field, int i, int count) {
        if (i >= count) {
            throw new IllegalArgumentException("PhyWriter.write: " + describe() + " " + field + " " + i
                    + " names no entry written before it (" + count + " so far)");
        }
        u8(i);
    }

    /** A u8 index that is {@link PhyWorld#NONE} or names one of the count entries written so far. */
    void optionalIndex(String field, int i, int count) {
        if (i == PhyWorld.NONE) {
            u8(i);
        } else {
            index(field, i, count);
        }
    }

    /** Writes user data where the version stores it; refuses data the version cannot hold. */
    void userData(boolean present, PhyElement e) {
        if (present) {
            string(e.userDataBytes());
        } else if (e.userDataBytes().length > 0) {
            throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(version)
                    + " cannot store the user data of " + describe());
        }
    }

    byte[] toByteArray() {
        byte[] b = new byte[size];
        System.arraycopy(buf, 0, b, 0, size);
        return b;
    }
}
