package org.emini.io;

/**
 * A cursor over the bytes of a world file. Every read checks the bytes it needs first, so a cut
 * file ends in a {@link PhyFormatException} at the right offset rather than in the original's
 * garbage values.
 */
final class PhyInput {
    private final byte[] data;
    private final int length;
    private final int version;
    private int pos;
    // The record being read, named in error messages only (no strings are built while reading).
    private String kind = "";
    private int index = -1;

    PhyInput(byte[] data, int length, int version, int pos) {
        this.data = data;
        this.length = length;
        this.version = version;
        this.pos = pos;
    }

    /** Names the record the next reads belong to, e.g. ("body", 3); an index below 0 is left out. */
    void record(String kind, int index) {
        this.kind = kind;
        this.index = index;
    }

    int recordIndex() {
        return index;
    }

    /**
     * "kind index field": the item number, when given, replaces a '#' in the field name or is
     * appended to it.
     */
    String describe(String field, int item) {
        StringBuilder b = new StringBuilder();
        if (!kind.isEmpty()) {
            b.append(kind);
            if (index >= 0) {
                b.append(' ').append(index);
            }
            b.append(' ');
        }
        int hash = field.indexOf('#');
        if (item >= 0 && hash >= 0) {
            b.append(field, 0, hash).append(item).append(field, hash + 1, field.length());
        } else {
            b.append(field);
            if (item >= 0) {
                b.append(' ').append(item);
            }
        }
        return b.toString();
    }

    int version() {
        return version;
    }

    int position() {
        return pos;
    }

    int remaining() {
        return length - pos;
    }

    private void need(int n, String field, int item) throws PhyFormatException {
        if (length - pos < n) {
            throw new PhyFormatException(pos, describe(field, item) + " (" + n + (n == 1 ? " byte)" : " bytes)"),
                    "end of data after " + (length - pos) + (length - pos == 1 ? " byte" : " bytes"));
        }
    }

    /** An unsigned byte, 0 to 255. */
    int u8(String field) throws PhyFormatException {
        return u8(field, -1);
    }

    /** An unsigned byte, the item-th of its kind in the record. */
    int u8(String field, int item) throws PhyFormatException {
        need(1, field, item);
        return data[pos++] & 0xFF;
    }

    /** A big-endian signed 32-bit integer. */
    int i32(String field) throws PhyFormatException {
        return i32(field, -1);
    }

    /** A big-endian signed 32-bit integer, the item-th of its kind in the record. */
    int i32(String field, int item) throws PhyFormatException {
        need(4, field, item);
        int v = (data[pos] & 0xFF) << 24 | (data[pos + 1] & 0xFF) << 16 | (data[pos + 2] & 0xFF) << 8
                | data[pos + 3] & 0xFF;
        pos += 4;
        return v;
    }

    /** A vector: two FX values, x then y. */
    PhyVector vector(String field) throws PhyFormatException {
        return vector(field, -1);
    }

    /** A vector, the item-th of its kind in the record. */
    PhyVector vector(String field, int item) throws PhyFormatException {
        need(8, field, item);
        int x = i32(field, item);
        return new PhyVector(x, i32(field, item));
    }

    /** The raw bytes of a string: an i32 byte length, then that many bytes. */
    byte[] string(String field) throws PhyFormatException {
        int at = pos;
        int n = i32(field);
        if (n < 0) {
            throw new PhyFormatException(at, describe(field, -1) + " length >= 0", Integer.toString(n));
        }
        need(n, field, -1);
        byte[] b = new byte[n];
        System.arraycopy(data, pos, b, 0, n);
        pos += n;
        return b;
    }

    /** The rest of the data, consumed. */
    byte[] rest() {
        byte[] b = new byte[length - pos];
        System.arraycopy(data, pos, b, 0, b.length);
        pos = length;
        return b;
    }

    /** A u8 index that must name one of the count entries read so far. */
    int index(String field, int count) throws PhyFormatException {
        return index(field, -1, count);
    }

    /** A u8 index, the item-th of its kind in the record, that must name an entry read so far. */
    int index(String field, int item, int count) throws PhyFormatException {
        int at = pos;
        int i = u8(field, item);
        if (i >= count) {
            throw new PhyFormatException(at, describe(field, item) + " below " + count, Integer.toString(i));
        }
        return i;
    }

    /** A u8 index that is either {@link PhyWorld#NONE} or names one of the count entries read so far. */
    int optionalIndex(String field, int count) throws PhyFormatException {
        int at = pos;
        int i = u8(field);
        if (i != PhyWorld.NONE && i >= count) {
            throw new PhyFormatException(at, describe(field, -1) + " below " + count + " or 255 (none)",
                    Integer.toString(i));
        }
        return i;
    }

    /**
     * A count whose records take at least minBytes each: refused when the data left cannot hold
     * them, so an absurd count never allocates.
     */
    void checkCount(int at, String field, long count, int minBytes) throws PhyFormatException {
        if (count < 0) {
            throw new PhyFormatException(at, describe(field, -1) + " >= 0", Long.toString(count));
        }
        if (count * minBytes > length - pos) {
            throw new PhyFormatException(at, describe(field, -1) + " that fits the " + (length - pos)
                    + " bytes left (" + minBytes + " bytes each)", Long.toString(count));
        }
    }
}
