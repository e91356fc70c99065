package org.emini.io;

import java.io.IOException;

/**
 * A world file that cannot be read: truncated, corrupt, of an unknown version, or with a count or
 * reference that does not fit. The message names the byte offset, what the format expected there
 * and what was found.
 */
public class PhyFormatException extends IOException {
    private static final long serialVersionUID = 1L;

    /** The offset of the offending byte from the start of the file. */
    private final long offset;
    /** What the format expects at that offset. */
    private final String expected;
    /** What the file holds instead. */
    private final String found;

    /**
     * Creates the exception.
     *
     * @param offset the offset of the offending byte from the start of the file
     * @param expected what the format expects at that offset
     * @param found what the file holds instead
     */
    public PhyFormatException(long offset, String expected, String found) {
        super("byte " + offset + ": expected " + expected + ", found " + found);
        this.offset = offset;
        this.expected = expected;
        this.found = found;
    }

    /**
     * The offset of the offending byte (or of the first byte of the offending value).
     *
     * @return the offset from the start of the file, &ge; 0
     */
    public long getOffset() {
        return offset;
    }

    /**
     * What the format expects at the offset.
     *
     * @return a short description, e.g. "shape index below 3"
     */
    public String getExpected() {
        return expected;
    }

    /**
     * What the file holds instead.
     *
     * @return a short description, e.g. "7" or "end of data"
     */
    public String getFound() {
        return found;
    }
}
