package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Ticks stop allocating after warm-up. The bytes each tick allocates are measured around
 * {@code World.tick()} alone (HotSpot's per-thread allocation counter); the first quarter of the run
 * (at least 10 ticks) is warm-up. After it, one-off growth is allowed: the engine grows an array by
 * doubling or refills its contact pool when the world reaches a new peak, so a tick where the world
 * holds more contacts or live particles than ever before may allocate. Of the other ticks, a few may
 * (a body with more contacts than ever grows its own list, a class loads the first time a code path
 * runs), and their sizes differ. Steady allocation is either many such ticks (more than {@link #FEW}
 * and more than a fifth of the ticks after warm-up), or the same size allocated again and again
 * ({@link #REPEATS} ticks or more): what a per-tick object, boxing or a lambda looks like.
 */
final class AllocationCheck {
    /** Allocating ticks always allowed after warm-up. */
    static final int FEW = 6;
    /** Ticks allocating the very same size that make a pattern. */
    static final int REPEATS = 4;

    private final int warmUp;
    private final List<long[]> allocating = new ArrayList<>();
    private final Map<Long, Integer> sizes = new HashMap<>();
    private int atPeaks;
    private long peakContacts;
    private long peakParticles;

    AllocationCheck(int ticks) {
        this.warmUp = Math.max(10, ticks / 4);
    }

    void record(FuzzWorld w, int tick, long bytes) {
        long contacts = w.world().getContactCount();
        long particles = 0;
        for (int i = 0; i < w.emitters().size(); i++) {
            particles += w.emitters().get(i).getParticleCount();
        }
        boolean peak = contacts > peakContacts || particles > peakParticles;
        peakContacts = Math.max(peakContacts, contacts);
        peakParticles = Math.max(peakParticles, particles);
        if (peak && bytes > 0) {
            atPeaks++;
        } else if (tick >= warmUp && bytes > 0) {
            allocating.add(new long[] {tick, bytes});
            sizes.merge(bytes, 1, Integer::sum);
        }
    }

    /** The verdict after the run. */
    Violation verdict(int ticksRun) {
        int repeated = 0;
        long size = 0;
        for (Map.Entry<Long, Integer> e : sizes.entrySet()) {
            if (e.getValue() > repeated) {
                repeated = e.getValue();
                size = e.getKey();
            }
        }
        int after = Math.max(1, ticksRun - warmUp);
        boolean many = allocating.size() > FEW && allocating.size() > after / 5;
        if (!many && repeated < REPEATS || ticksRun < 2 * warmUp) {
            return null;
        }
        StringBuilder b = new StringBuilder();
        long total = 0;
        for (long[] a : allocating) {
            total += a[1];
            if (b.length() < 240) {
                b.append(b.length() == 0 ? "" : ", ").append(a[1]).append(" B in tick ").append(a[0]);
            }
        }
        return new Violation(ViolationKind.ALLOCATION, (int) allocating.get(0)[0], String.format(
                "%d of %d ticks after warm-up allocated at no new peak of contacts or particles (%d B in all; "
                        + "%d B in %d ticks; %d more ticks allocated at new peaks): %s",
                allocating.size(), after, total, size, repeated, atPeaks, b));
    }
}
