package org.emini.harness.build;

import java.util.Arrays;
import java.util.Comparator;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.load.Limits;

/**
 * The checks of {@link Limits} that need the built world: how many bodies overlap at the start, and
 * whether a dynamic body left the coordinates a float resolves. {@code validate} applies both to the
 * starting world; {@code run} (and the fuzzer) applies the second after every tick.
 */
public final class WorldLimits {
    /** Comparisons one sweep may make before the other axis is tried (a column of bodies along x). */
    private static final long SWEEP_COMPARISONS = 100_000_000;

    private WorldLimits() {
    }

    /** The first dynamic body beyond ±{@link Limits#POSITION} px, or -1. */
    public static int farBody(World w) {
        for (int i = 0; i < w.getBodyCount(); i++) {
            Body b = w.getBody(i);
            if (b.isDynamic() && !(Math.abs(b.getX()) <= Limits.POSITION && Math.abs(b.getY()) <= Limits.POSITION)) {
                return i;
            }
        }
        return -1;
    }

    /** Why a body is out of bounds, for a message. */
    public static String far(Body b) {
        return "is at (" + b.getX() + ", " + b.getY() + "), beyond ±" + Limits.POSITION
                + " px, where a float no longer resolves a pixel";
    }

    /**
     * Bodies whose bounding boxes overlap at the start, as far as {@link Limits#STARTING_OVERLAPS}.
     *
     * @param pairs pairs counted, stopped one past the limit
     * @param worst the body whose box meets the most others so far (where to point)
     * @param counted false when neither axis could be swept within a bounded number of comparisons
     */
    public record Overlaps(long pairs, int worst, boolean counted) {
        /** Whether the scene passes the limit. */
        public boolean tooMany() {
            return !counted || pairs > Limits.STARTING_OVERLAPS;
        }
    }

    /** The starting world's overlapping pairs (sort and sweep along x, or along y for a column). */
    public static Overlaps startingOverlaps(World w) {
        int n = w.getBodyCount();
        float[] x = new float[n];
        float[] y = new float[n];
        float[] r = new float[n];
        for (int i = 0; i < n; i++) {
            Body b = w.getBody(i);
            x[i] = b.getX();
            y[i] = b.getY();
            r[i] = b.getShape().getBoundingRadius();
        }
        Overlaps along = sweep(x, y, r);
        return along.counted() ? along : sweep(y, x, r);
    }

    private static Overlaps sweep(float[] a, float[] b, float[] r) {
        int n = a.length;
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, Comparator.comparingDouble(i -> a[i] - r[i]));
        int[] count = new int[n];
        int worst = 0;
        long pairs = 0;
        long comparisons = 0;
        for (int s = 0; s < n && pairs <= Limits.STARTING_OVERLAPS; s++) {
            int i = order[s];
            for (int t = s + 1; t < n && pairs <= Limits.STARTING_OVERLAPS; t++) {
                int j = order[t];
                if (a[j] - r[j] > a[i] + r[i]) {
                    break;
                }
                if (++comparisons > SWEEP_COMPARISONS) {
                    return new Overlaps(pairs, worst, false);
                }
                if (Math.abs(b[i] - b[j]) <= r[i] + r[j]) {
                    pairs++;
                    worst = ++count[i] > count[worst] ? i : worst;
                    worst = ++count[j] > count[worst] ? j : worst;
                }
            }
        }
        return new Overlaps(pairs, worst, true);
    }
}
