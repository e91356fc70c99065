package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.harness.run.StateHash;

/**
 * Runs a recipe and checks the invariants after every tick: finite state and ticks that throw only
 * documented clear errors, no energy created (worlds without energy sources), no pass-through and
 * bounded overlap (all but extreme worlds), no steady allocation, and a second build run in lockstep
 * that stays bit-identical. The first violation of each kind is kept.
 */
public final class WorldCheck {
    private static final AllocationMeter METER = new AllocationMeter();

    private WorldCheck() {
    }

    /**
     * The outcome of a run.
     *
     * @param violations the first violation of each kind, in the order found
     * @param ticksRun ticks run before the end or a throw
     * @param clearError a documented error that ended the run where one is acceptable, or null
     */
    public record Result(List<Violation> violations, int ticksRun, String clearError) {
        /** The violation of a kind, or null. */
        public Violation of(ViolationKind kind) {
            for (Violation v : violations) {
                if (v.kind() == kind) {
                    return v;
                }
            }
            return null;
        }
    }

    /** Runs every invariant for the recipe's ticks. */
    public static Result run(Recipe r) {
        return run(r, Set.of(ViolationKind.values()), r.ticks);
    }

    /**
     * Runs the invariants of the wanted kinds for at most {@code ticks} ticks (the shrinker asks for
     * one kind and stops at the tick where it was seen).
     */
    public static Result run(Recipe r, Set<ViolationKind> wanted, int ticks) {
        return run(r, wanted, ticks, w -> { });
    }

    /**
     * The same, with {@code plant} called on both builds before the first tick (tests plant defects
     * the checks must catch).
     */
    public static Result run(Recipe r, Set<ViolationKind> wanted, int ticks, java.util.function.Consumer<FuzzWorld> plant) {
        FuzzWorld a;
        FuzzWorld b = null;
        try {
            a = RecipeBuilder.build(r);
            plant.accept(a);
            if (wanted.contains(ViolationKind.NONDETERMINISM)) {
                b = RecipeBuilder.build(r);
                plant.accept(b);
            }
        } catch (RuntimeException e) {
            return new Result(List.of(new Violation(ViolationKind.BUILD, -1, TickFailure.describe(e))), 0, null);
        }
        // The twin ticks at two threads, every shared loop split however small the world: the engine promises
        // the same bits for any thread count, so the nondeterminism check covers the threads too.
        if (b != null) {
            b.world().setWorkerCount(2);
            b.world().setSplitAlways(true);
        }
        try {
            return check(r, wanted, ticks, a, b);
        } finally {
            if (b != null) {
                b.world().setWorkerCount(1);
            }
        }
    }

    /** Ticks the world (and its twin, when there is one) and runs the wanted checks after each tick. */
    private static Result check(Recipe r, Set<ViolationKind> wanted, int ticks, FuzzWorld a, FuzzWorld b) {
        Map<ViolationKind, Violation> found = new EnumMap<>(ViolationKind.class);
        Map<ViolationKind, TickCheck> checks = checks(r, wanted);
        for (TickCheck c : checks.values()) {
            c.start(a);
        }
        AllocationCheck allocation = wanted.contains(ViolationKind.ALLOCATION) && METER.supported() ? new AllocationCheck(ticks) : null;
        boolean tolerant = r.profile == Profile.EXTREME || !r.removals.isEmpty();
        String clearError = null;
        int tick = 0;
        for (; tick < ticks; tick++) {
            Throwable thrown = null;
            long before = METER.bytes();
            try {
                a.tick();
            } catch (RuntimeException | StackOverflowError e) {
                thrown = e;
            }
            long bytes = METER.between(before, METER.bytes());
            if (thrown != null) {
                if (tolerant && TickFailure.clear(thrown)) {
                    clearError = TickFailure.describe(thrown);
                } else if (wanted.contains(ViolationKind.EXCEPTION) || wanted.contains(ViolationKind.NON_FINITE)) {
                    found.putIfAbsent(TickFailure.violation(thrown, tick).kind(), TickFailure.violation(thrown, tick));
                }
                break;
            }
            if (allocation != null) {
                allocation.record(a, tick, bytes);
            }
            if (b != null && !found.containsKey(ViolationKind.NONDETERMINISM)) {
                twin(a, b, tick, found);
            }
            for (Map.Entry<ViolationKind, TickCheck> c : checks.entrySet()) {
                if (!found.containsKey(c.getKey())) {
                    Violation v = c.getValue().afterTick(a, tick);
                    if (v != null) {
                        found.put(v.kind(), v);
                    }
                }
            }
            if (found.containsKey(ViolationKind.NON_FINITE)) {
                tick++;
                break;
            }
        }
        if (allocation != null && clearError == null) {
            Violation v = allocation.verdict(tick);
            if (v != null && !found.containsKey(ViolationKind.EXCEPTION) && !found.containsKey(ViolationKind.NON_FINITE)) {
                v = stillAllocating(a, allocation, v, tick);
            }
            if (v != null) {
                found.put(v.kind(), v);
            }
        }
        List<Violation> list = new ArrayList<>(found.values());
        list.sort((x, y) -> Integer.compare(x.tick(), y.tick()));
        return new Result(list, tick, clearError);
    }

    /**
     * An allocation verdict stands only if the world, ticked as long again, allocates there too
     * ({@link AllocationCheck#continued}); a tick that throws there leaves the verdict as it was.
     */
    private static Violation stillAllocating(FuzzWorld a, AllocationCheck first, Violation v, int ticks) {
        AllocationCheck more = first.continued();
        for (int t = 0; t < ticks; t++) {
            long before = METER.bytes();
            try {
                a.tick();
            } catch (RuntimeException | StackOverflowError e) {
                return v;
            }
            more.record(a, ticks + t, METER.between(before, METER.bytes()));
        }
        Violation again = more.verdict(ticks);
        return again == null ? null
            : new Violation(ViolationKind.ALLOCATION, v.tick(), v.message() + "; again in " + ticks + " more ticks: " + again.message());
    }

    private static Map<ViolationKind, TickCheck> checks(Recipe r, Set<ViolationKind> wanted) {
        Map<ViolationKind, TickCheck> checks = new EnumMap<>(ViolationKind.class);
        if (wanted.contains(ViolationKind.NON_FINITE)) {
            checks.put(ViolationKind.NON_FINITE, new FiniteCheck());
        }
        if (wanted.contains(ViolationKind.ENERGY) && EnergyCheck.applies(r)) {
            checks.put(ViolationKind.ENERGY, new EnergyCheck());
        }
        if (r.profile != Profile.EXTREME) {
            if (wanted.contains(ViolationKind.PASS_THROUGH)) {
                checks.put(ViolationKind.PASS_THROUGH, new PassThroughCheck());
            }
            if (wanted.contains(ViolationKind.OVERLAP) && r.iterations >= OverlapCheck.MIN_ITERATIONS) {
                checks.put(ViolationKind.OVERLAP, new OverlapCheck());
            }
        }
        return checks;
    }

    /** Ticks the twin and compares the whole state's hash. */
    private static void twin(FuzzWorld a, FuzzWorld b, int tick, Map<ViolationKind, Violation> found) {
        String thrown = null;
        try {
            b.tick();
        } catch (RuntimeException e) {
            thrown = TickFailure.describe(e);
        }
        long ha = a.stateHash();
        long hb = thrown == null ? b.stateHash() : ha + 1;
        if (ha != hb) {
            found.put(ViolationKind.NONDETERMINISM, new Violation(ViolationKind.NONDETERMINISM, tick,
                    thrown != null ? "the second run threw " + thrown : String.format(
                            "two builds of the recipe differ after this tick (bodies %016x vs %016x, events %d vs %d)",
                            StateHash.bodies(a.world()),
                            StateHash.bodies(b.world()), a.eventCount(), b.eventCount())));
        }
    }
}
