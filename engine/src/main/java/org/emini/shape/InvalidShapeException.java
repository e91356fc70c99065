package org.emini.shape;

/**
 * Thrown when coordinates do not describe a valid shape: the {@link Rule} says which check failed,
 * the message names the offending vertex (index in the caller's input and coordinates) when there
 * is one.
 */
public final class InvalidShapeException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    /** The validation rule a shape broke. */
    public enum Rule {
        /** A coordinate or a radius is NaN or infinite. */
        NOT_FINITE,
        /** Fewer than three distinct vertices (after merging near-duplicates). */
        TOO_FEW_VERTICES,
        /** More than {@link Shape#MAX_VERTICES} vertices remain after cleaning. */
        TOO_MANY_VERTICES,
        /** Zero size: all vertices on one line, zero area, or a radius that is not positive. */
        DEGENERATE,
        /** Narrower than {@link Shape#MIN_SIZE} somewhere: too small to collide reliably. */
        TOO_SMALL,
        /** Reaches farther than {@link Shape#MAX_EXTENT} from its origin: its boxes would overflow. */
        TOO_LARGE,
        /** The outline turns both ways: it has a recess. */
        NOT_CONVEX,
        /** The outline crosses or doubles back on itself (for example a pentagram). */
        SELF_INTERSECTING
    }

    /** The rule that was broken. */
    private final Rule rule;
    /** The offending vertex's index in the caller's input, or -1. */
    private final int vertexIndex;

    /**
     * Creates the exception.
     *
     * @param rule the rule that was broken
     * @param vertexIndex the index of the offending vertex in the caller's input, or -1 when no
     *     single vertex is to blame
     * @param message the full message, naming the rule and, if any, the vertex and its coordinates
     */
    public InvalidShapeException(Rule rule, int vertexIndex, String message) {
        super(message);
        if (rule == null) {
            throw new IllegalArgumentException("InvalidShapeException: rule is null");
        }
        this.rule = rule;
        this.vertexIndex = vertexIndex;
    }

    /**
     * The rule that was broken.
     *
     * @return the rule, never null
     */
    public Rule getRule() {
        return rule;
    }

    /**
     * The offending vertex.
     *
     * @return its index in the caller's input (pairs of coordinates count as one vertex), or -1
     *     when no single vertex is to blame
     */
    public int getVertexIndex() {
        return vertexIndex;
    }
}
