package org.emini.harness.load;

import java.util.HashMap;
import java.util.Map;

/**
 * Where each node of a parsed document starts in its file, so validation errors that only know a
 * path inside the document can still name a line.
 *
 * <p>For an object member the recorded position is that of its key (the line a person would look
 * at); for an array element it is the element's own start.
 */
public final class SourceMap {
    private final Map<JsonPath, int[]> positions = new HashMap<>();

    void put(JsonPath path, int line, int column) {
        positions.put(path, new int[] {line, column});
    }

    /**
     * The 1-based line and column of the node at a path, or of its nearest enclosing node that has
     * one; {0, 0} when nothing is known.
     */
    public int[] locate(JsonPath path) {
        JsonPath p = path;
        while (true) {
            int[] at = positions.get(p);
            if (at != null) {
                return at.clone();
            }
            if (p.elements().isEmpty()) {
                return new int[] {0, 0};
            }
            p = p.parent();
        }
    }

    /** Whether the path itself (not an enclosing node) was in the document. */
    public boolean contains(JsonPath path) {
        return positions.containsKey(path);
    }
}
