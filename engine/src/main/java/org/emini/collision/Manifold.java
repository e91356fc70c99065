package org.emini.collision;

/**
 * The contact between two shapes A and B: up to two points sharing one normal. A reusable flat
 * struct: the collider overwrites it in place and nothing is allocated per use. Entries at indices
 * {@link #pointCount} and above are stale.
 */
public final class Manifold {
    /** The most points a manifold holds. */
    public static final int MAX_POINTS = 2;

    /** The number of valid points, 0 to 2; 0 means no contact. */
    public int pointCount;
    /** The world x of the unit normal, pointing from shape A to shape B. */
    public float normalX;
    /** The world y of the unit normal, pointing from shape A to shape B. */
    public float normalY;
    /** World x of each contact point, midway between the two surfaces (px). */
    public final float[] pointX = new float[MAX_POINTS];
    /** World y of each contact point, midway between the two surfaces (px). */
    public final float[] pointY = new float[MAX_POINTS];
    /**
     * Signed distance between the surfaces along the normal at each point (px): negative when
     * overlapping, positive for a speculative point that still has a gap.
     */
    public final float[] separation = new float[MAX_POINTS];
    /**
     * Feature key of each point, the same from tick to tick while the same features touch, for
     * matching points between ticks (warm starting).
     *
     * <p>Polygon–polygon: (vertex index on A) &lt;&lt; 8 | (vertex index on B), naming the vertex
     * pair the point sits between: a reference-face vertex and an incident-edge vertex. The key does
     * not record which polygon supplied the reference face: for parallel faces both choices give
     * the same two keys, so a change of reference face keeps the points matched. Circle contacts
     * have one point whose location moves continuously, so their key is always 0.
     */
    public final int[] id = new int[MAX_POINTS];

    /** Creates an empty manifold. */
    public Manifold() {
    }

    /** Resets to no contact and zeroes every field. */
    public void clear() {
        pointCount = 0;
        normalX = 0f;
        normalY = 0f;
        for (int i = 0; i < MAX_POINTS; i++) {
            pointX[i] = 0f;
            pointY[i] = 0f;
            separation[i] = 0f;
            id[i] = 0;
        }
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("Manifold[normal (").append(normalX).append(", ")
                .append(normalY).append(')');
        for (int i = 0; i < pointCount; i++) {
            b.append(", point (").append(pointX[i]).append(", ").append(pointY[i])
                    .append(") separation ").append(separation[i]).append(" id 0x")
                    .append(Integer.toHexString(id[i]));
        }
        return b.append(']').toString();
    }
}
