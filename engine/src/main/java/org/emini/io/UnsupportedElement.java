package org.emini.io;

/**
 * A record of a world file that {@link WorldBuilder} could not build as stored: either left out of
 * the world (its engine feature is missing, or the record is unusable) or built in an
 * approximated form. Immutable.
 */
public final class UnsupportedElement {
    /** The kinds of records. */
    public enum Kind {
        /** A circle, line or polygon shape record. */
        SHAPE,
        /** A multishape record. */
        MULTI_SHAPE,
        /** A body record. */
        BODY,
        /** A landscape segment. */
        LANDSCAPE_SEGMENT,
        /** A joint. */
        JOINT,
        /** A spring. */
        SPRING,
        /** A motor. */
        MOTOR,
        /** A script. */
        SCRIPT,
        /** A row of the script-body table. */
        SCRIPT_BINDING,
        /** An event. */
        EVENT,
        /** A particle emitter. */
        PARTICLE_EMITTER,
        /** The world record. */
        WORLD_SETTINGS
    }

    private final Kind kind;
    private final int index;
    private final String reason;

    /**
     * Describes a record.
     *
     * @param kind the kind of record
     * @param index its index in its document list (the shape list for shapes and multishapes),
     *     or 0 for the world record
     * @param reason why it is not built as stored
     */
    public UnsupportedElement(Kind kind, int index, String reason) {
        this.kind = PhyWorld.checkNotNull("UnsupportedElement", "kind", kind);
        this.index = index;
        this.reason = PhyWorld.checkNotNull("UnsupportedElement", "reason", reason);
    }

    /**
     * The kind of record.
     *
     * @return the kind
     */
    public Kind getKind() {
        return kind;
    }

    /**
     * The record's index in its document list.
     *
     * @return the index, &ge; 0
     */
    public int getIndex() {
        return index;
    }

    /**
     * Why the record is not built as stored.
     *
     * @return a short explanation
     */
    public String getReason() {
        return reason;
    }

    @Override
    public String toString() {
        return kind.name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ') + " " + index + ": " + reason;
    }
}
