package org.emini.io;

/**
 * One section of a world file as it was laid out: its tag and how many records it held. The
 * reader records the layout so the writer can reproduce a file byte for byte; a document built or
 * edited in code is written in the designer's order instead. Immutable.
 */
public final class PhySection {
    /** Tag 1: shapes (and, above version word 0x0800, multishapes). */
    public static final int SHAPES = 1;
    /** Tag 2: bodies. */
    public static final int BODIES = 2;
    /** Tag 3: constraints. */
    public static final int CONSTRAINTS = 3;
    /** Tag 4: scripts and the script-body table. */
    public static final int SCRIPTS = 4;
    /** Tag 5: events. */
    public static final int EVENTS = 5;
    /** Tag 6: the landscape. */
    public static final int LANDSCAPE = 6;
    /** Tag 7: the world record. */
    public static final int WORLD = 7;
    /** Tag 8: particle emitters. */
    public static final int PARTICLES = 8;

    private final int tag;
    private final int count;
    private final int extraCount;

    /**
     * Describes a section.
     *
     * @param tag the tag byte, 0 to 255 (other than 1 to 8: an unknown tag the original skips)
     * @param count the records: shapes, bodies, constraints, scripts, events or emitters, 0 to 255
     *     (0 for a landscape, world or unknown section)
     * @param extraCount multishapes of a shapes section, rows of a scripts section, else 0; 0 to 255
     */
    public PhySection(int tag, int count, int extraCount) {
        this.tag = PhyWorld.checkU8("PhySection", "tag", tag);
        this.count = PhyWorld.checkU8("PhySection", "count", count);
        this.extraCount = PhyWorld.checkU8("PhySection", "extraCount", extraCount);
    }

    /**
     * The tag byte.
     *
     * @return 0 to 255
     */
    public int getTag() {
        return tag;
    }

    /**
     * The number of records the section held.
     *
     * @return 0 to 255
     */
    public int getCount() {
        return count;
    }

    /**
     * The multishapes of a shapes section, or the script-body rows of a scripts section.
     *
     * @return 0 to 255
     */
    public int getExtraCount() {
        return extraCount;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhySection && ((PhySection) o).tag == tag && ((PhySection) o).count == count
                && ((PhySection) o).extraCount == extraCount;
    }

    @Override
    public int hashCode() {
        return (tag * 256 + count) * 256 + extraCount;
    }

    @Override
    public String toString() {
        return "PhySection[tag " + tag + ", " + count + (extraCount > 0 ? " + " + extraCount + "]" : "]");
    }
}
