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
 *
 * <p>Growth can look like that too: arrays that double as the world fills (the particles' obstacle
 * grid, an event's set of bodies, the colouring's adjacency, the hot contacts' index) each reach
 * 64 entries once, in different ticks, so four of them make "272 B in 4 ticks" (world passive:713 of
 * seed 11). A run that looks steady is therefore {@link #continued}: the world ticks as long again,
 * already warm, and only allocation that goes on there is reported. Growth does not recur once the
 * arrays are large enough; a per-tick object does.
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

    private AllocationCheck(AllocationCheck before) {
        warmUp = 0;
        peakContacts = before.peakContacts;
        peakParticles = before.peakParticles;
    }

    /** A check for more ticks of the same world, warm already, keeping the peaks seen so far. */
    AllocationCheck continued() {
        return new AllocationCheck(this);
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
        return new Violation(ViolationKind.ALLOCATION, (int) allocating.get(0)[0], describe(after, size, repeated));
    }

    /** What allocated: the ticks and sizes, for a violation's message. */
    private String describe(int after, long size, int repeated) {
        StringBuilder b = new StringBuilder();
        long total = 0;
        for (long[] a : allocating) {
            total += a[1];
            if (b.length() < 240) {
                b.append(b.length() == 0 ? "" : ", ").append(a[1]).append(" B in tick ").append(a[0]);
            }
        }
        return String.format(
                "%d of %d ticks after warm-up allocated at no new peak of contacts or particles (%d B in all; "
                        + "%d B in %d ticks; %d more ticks allocated at new peaks): %s",
                allocating.size(), after, total, size, repeated, atPeaks, b);
    }
}
