package org.emini.harness.run;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.LongConsumer;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.build.WorldLimits;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.closedform.ClosedForms;
import org.emini.harness.load.Limits;
import org.emini.harness.expect.Evaluator;
import org.emini.harness.expect.Verdict;
import org.emini.harness.metrics.Metric;
import org.emini.harness.metrics.Metrics;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.RecordSpec;
import org.emini.harness.scenario.Scenario;

/**
 * Runs one scene: builds the world, ticks it for the run's duration applying scheduled actions,
 * samples the requested bodies and metrics, then judges the expectations (those on extremes on every
 * tick, {@link EveryTick}).
 */
public final class ScenarioRunner {
    private ScenarioRunner() {
    }

    /**
     * Runs a scene. Never throws for a problem of the scene or the engine: those become the result's
     * status (unsupported, error).
     *
     * @param scenario the scene
     * @param progress told how many ticks were just done (may be called often; cheap callbacks only)
     */
    public static SceneResult run(Scenario scenario, LongConsumer progress) {
        return run(scenario, progress, Limits.SCENE_SECONDS);
    }

    /**
     * Runs a scene with a time limit: a run still ticking after {@code maxSeconds} (wall clock, checked
     * after every tick) stops with {@code ERROR}, as does one that runs out of memory, so that one
     * scene cannot hang or take down a whole {@code run}.
     */
    public static SceneResult run(Scenario scenario, LongConsumer progress, double maxSeconds) {
        return run(scenario, progress, maxSeconds, 1);
    }

    /**
     * Runs a scene with a time limit, its world sharing each tick's contact solve among {@code workers}
     * threads ({@code World.setWorkerCount}, set once the world is built, before its first tick), every
     * shared loop split however little it holds ({@code World.setSplitAlways}): without that, a world of
     * fewer than 400 simulated bodies would tick on one thread, and most scenes would check nothing. The
     * engine promises the same bits for any count; the result's {@link SceneResult#stateHash} shows
     * whether it kept that promise. Slower than one thread: not a speed figure. The threads are stopped when the run ends, whatever its end, so a
     * long {@code run} of many scenes leaves none behind.
     *
     * @param workers the threads that share a tick, counting the ticking one: 1 (none) to
     *     {@code World.MAX_WORKERS}
     * @throws IllegalArgumentException for a worker count out of that range (the caller checks its option)
     */
    public static SceneResult run(Scenario scenario, LongConsumer progress, double maxSeconds, int workers) {
        long ticks = scenario.ticks();
        long t0 = System.nanoTime();
        BuiltWorld built;
        List<Metric> metrics;
        EveryTick everyTick;
        try {
            built = WorldBuilder.build(scenario);
            metrics = Metrics.create(scenario.run().record().metrics(), built);
            everyTick = EveryTick.of(scenario, built, samplingTicks(scenario.run().record(), scenario.world().timestep()));
        } catch (UnsupportedElementException e) {
            progress.accept(ticks);
            return result(scenario, Status.UNSUPPORTED, "uses " + e.getMessage(), List.of(), List.of(), 0, 0, 0, null, -1,
                    null, null);
        } catch (RuntimeException | OutOfMemoryError e) {
            progress.accept(ticks);
            return errorOrKnown(scenario, "building the world: " + e, 0, 0);
        }
        // After all that may refuse the scene, so that a refusal leaves no threads behind.
        World world = built.world();
        world.setWorkerCount(workers);
        world.setSplitAlways(workers > 1);
        try {
            return ticked(scenario, built, metrics, everyTick, progress, maxSeconds, t0);
        } finally {
            // Stops the pool's threads; the world itself is dropped with the result.
            world.setWorkerCount(1);
        }
    }

    /** The ticks of a built world, its samples and verdicts ({@code t0}: when the build began). */
    private static SceneResult ticked(Scenario scenario, BuiltWorld built, List<Metric> metrics, EveryTick everyTick,
                                      LongConsumer progress, double maxSeconds, long t0) {
        long ticks = scenario.ticks();
        long t1 = System.nanoTime();
        List<String> recorded = recordedBodies(scenario, built);
        List<String> metricChannels = new ArrayList<>();
        metrics.forEach(m -> metricChannels.addAll(m.channels()));
        World world = built.world();
        Trace trace = new Trace(scenario.world().timestep(), recorded, metricChannels, world.isSleepingEnabled());
        Body[] bodies = recorded.stream().map(built::body).toArray(Body[]::new);
        Schedule schedule = new Schedule(built, scenario.actions(), scenario.world().timestep());
        long every = samplingTicks(scenario.run().record(), scenario.world().timestep());
        long done = 0;
        // With sleeping on, how many bodies slept at once (at the samples): shows a run let bodies sleep.
        Body[] sleepers = world.isSleepingEnabled() ? built.bodies().values().stream().filter(Body::isDynamic)
                .toArray(Body[]::new) : null;
        int mostAsleep = sleepers == null ? -1 : 0;
        ReplayRecorder replay = ReplayRecorder.of(built, ticks);
        long stateHash;
        try {
            stateHash = StateHash.world(world);
            sample(trace, 0, bodies, metrics);
            if (everyTick != null) {
                everyTick.afterTick(0);
            }
            if (replay != null) {
                replay.after(0);
            }
            for (long k = 0; k < ticks; k++) {
                schedule.beforeTick(k);
                world.tick();
                int far = WorldLimits.farBody(world);
                if (far >= 0) {
                    progress.accept(ticks - done);
                    return errorOrKnown(scenario, "at tick " + world.getTickCount() + ": body '"
                            + scenario.bodies().get(far).name() + "' " + WorldLimits.far(world.getBody(far))
                            + "; the run stops here (scenarios/README.md, Limits)", millis(t1 - t0),
                            millis(System.nanoTime() - t1));
                }
                if (System.nanoTime() - t1 > maxSeconds * 1e9) {
                    progress.accept(ticks - done);
                    return errorOrKnown(scenario, String.format(java.util.Locale.ROOT, "over the time limit of %.0f s at "
                            + "tick %d of %d; the run stops here (--scene-timeout)", maxSeconds, k + 1, ticks),
                            millis(t1 - t0), millis(System.nanoTime() - t1));
                }
                stateHash = 31 * stateHash + StateHash.world(world);
                for (Metric m : metrics) {
                    m.afterTick();
                }
                if (everyTick != null) {
                    everyTick.afterTick(k + 1);
                }
                if (replay != null) {
                    replay.after(k + 1);
                }
                if ((k + 1) % every == 0 || k + 1 == ticks) {
                    sample(trace, k + 1, bodies, metrics);
                    if (sleepers != null) {
                        mostAsleep = Math.max(mostAsleep, asleep(sleepers));
                    }
                }
                if ((k & 63) == 63) {
                    progress.accept(64);
                    done += 64;
                }
            }
        } catch (RuntimeException | OutOfMemoryError e) {
            progress.accept(ticks - done);
            return errorOrKnown(scenario, "at tick " + world.getTickCount() + ": " + e, millis(t1 - t0),
                    millis(System.nanoTime() - t1));
        }
        progress.accept(ticks - done);
        double runMillis = millis(System.nanoTime() - t1);
        trace.setPenetrationPairs(Metrics.pairs(metrics));
        ClosedForm closedForm = ClosedForms.of(scenario);
        List<Verdict> verdicts = new ArrayList<>();
        for (ExpectationSpec e : scenario.run().expect()) {
            Trace judged = everyTick != null && e.readsExtremes() ? everyTick.trace() : trace;
            verdicts.add(Evaluator.evaluate(e, judged, closedForm));
        }
        List<String> stale = new ArrayList<>();
        StringBuilder message = new StringBuilder();
        Status status = Judge.judge(verdicts, scenario.knownFailure(), stale, message);
        return result(scenario, status, message.toString(), verdicts, stale, ticks, millis(t1 - t0), runMillis, trace,
                mostAsleep, replay, stateHash);
    }

    /**
     * Time of a scene's ticks alone.
     *
     * @param wallSeconds wall-clock seconds
     * @param cpuSeconds CPU seconds of the ticking thread (NaN where the JVM cannot tell)
     */
    public record TickTime(double wallSeconds, double cpuSeconds) {
    }

    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();

    /**
     * Times a scene's ticks alone, as a sweep's cost: a freshly built world, then per tick the scheduled
     * actions and {@code World.tick()}, timed as one block (wall clock and the thread's CPU time), with
     * no metrics and no samples. The pymunk oracle times the same loop ({@code emini_oracle.run.time_steps}).
     *
     * @throws UnsupportedElementException if the scene uses an element the engine lacks
     * @throws RuntimeException if the engine refuses the run (a non-finite state)
     */
    public static TickTime timeTicks(Scenario scenario) throws UnsupportedElementException {
        BuiltWorld built = WorldBuilder.build(scenario);
        World world = built.world();
        Schedule schedule = new Schedule(built, scenario.actions(), scenario.world().timestep());
        long ticks = scenario.ticks();
        boolean actions = !scenario.actions().isEmpty();
        boolean cpu = THREADS.isCurrentThreadCpuTimeSupported();
        long c0 = cpu ? THREADS.getCurrentThreadCpuTime() : 0;
        long t0 = System.nanoTime();
        for (long k = 0; k < ticks; k++) {
            if (actions) {
                schedule.beforeTick(k);
            }
            world.tick();
        }
        long t1 = System.nanoTime();
        long c1 = cpu ? THREADS.getCurrentThreadCpuTime() : 0;
        return new TickTime((t1 - t0) / 1e9, cpu ? (c1 - c0) / 1e9 : Double.NaN);
    }

    /** Ticks between samples: the record interval rounded to whole ticks (at least one). */
    public static long samplingTicks(RecordSpec record, double timestep) {
        return record.samplingTicks(timestep);
    }

    private static List<String> recordedBodies(Scenario scenario, BuiltWorld built) {
        Set<String> out = new LinkedHashSet<>();
        RecordSpec r = scenario.run().record();
        if (r.bodies() == null) {
            out.addAll(r.bodyNames());
        } else if (r.bodies().equals("all")) {
            out.addAll(built.bodies().keySet());
        } else if (r.bodies().equals("dynamic")) {
            for (BodySpec b : scenario.bodies()) {
                if (!b.state().isStatic()) {
                    out.add(b.name());
                }
            }
        }
        // Bodies an expectation reads are always recorded; with a group, all in creation order (inOrder reads it).
        boolean groups = false;
        for (ExpectationSpec e : scenario.run().expect()) {
            if (e.group() != null) {
                groups = true;
                for (String n : built.bodies().keySet()) {
                    if (Channels.matches(e.group(), n)) {
                        out.add(n);
                    }
                }
                continue;
            }
            if (e.body() != null) {
                out.add(e.body());
            }
            String[] bc = e.channel() != null ? Channels.bodyChannel(e.channel()) : null;
            if (bc != null) {
                out.add(bc[0]);
            }
            for (String extra : new String[] {e.minus(), e.relativeTo() != null ? e.relativeTo().channel() : null}) {
                String[] xc = extra != null ? Channels.bodyChannel(extra) : null;
                if (xc != null) {
                    out.add(xc[0]);
                }
            }
        }
        if (groups) {
            List<String> ordered = new ArrayList<>(built.bodies().keySet());
            ordered.retainAll(out);
            return ordered;
        }
        return new ArrayList<>(out);
    }

    static void sample(Trace trace, long tick, Body[] bodies, List<Metric> metrics) {
        double[] row = new double[trace.channels().size()];
        int i = 0;
        for (Body b : bodies) {
            row[i++] = b.getX();
            row[i++] = b.getY();
            row[i++] = b.getAngle();
            row[i++] = b.getVelocityX();
            row[i++] = b.getVelocityY();
            row[i++] = b.getAngularVelocity();
        }
        for (Metric m : metrics) {
            m.sample(row, i);
            i += m.channels().size();
        }
        if (!trace.recordsSleeping()) {
            trace.add(tick, row);
            return;
        }
        boolean[] asleep = new boolean[bodies.length];
        for (int k = 0; k < bodies.length; k++) {
            asleep[k] = bodies[k].isSleeping();
        }
        trace.add(tick, row, asleep);
    }

    private static SceneResult errorOrKnown(Scenario s, String message, double build, double run) {
        Status status = s.knownFailure() != null ? Status.KNOWN_FAILURE : Status.ERROR;
        String text = s.knownFailure() != null ? message + " [known: " + s.knownFailure().reason() + "]" : message;
        return result(s, status, text, List.of(), List.of(), 0, build, run, null, -1, null, null);
    }

    private static int asleep(Body[] bodies) {
        int n = 0;
        for (Body b : bodies) {
            n += b.isSleeping() ? 1 : 0;
        }
        return n;
    }

    private static SceneResult result(Scenario s, Status status, String message, List<Verdict> verdicts,
                                      List<String> stale, long ticks, double build, double run, Trace trace,
                                      int mostAsleep, ReplayRecorder replay, Long stateHash) {
        List<org.emini.harness.metrics.PenetrationPair> pairs = trace == null ? List.of() : trace.penetrationPairs();
        return new SceneResult(s.name(), s.file(), s.category(), status, message, verdicts, stale, s.knownFailure(),
                s.bodies().size(), ticks, s.world().timestep(), build, run, trace, mostAsleep, replay,
                pairs.subList(0, Math.min(SceneResult.TOP_PAIRS, pairs.size())), stateHash);
    }

    private static double millis(long nanos) {
        return nanos / 1e6;
    }
}
