package org.emini.bench.run;

import java.util.Map;

/**
 * One scene in one engine: JMH's figures and the scene checks.
 *
 * @param scene scene id
 * @param engine engine id
 * @param status {@code ok}, {@code unsupported}, {@code error} or {@code pending}
 * @param message why, when not ok
 * @param bodies bodies in the scene (static ones included)
 * @param dynamicBodies moving bodies (with particles: plus the particles the emitters keep alive)
 * @param msPerTick JMH's score: mean wall time per tick (ms)
 * @param msPerTickError JMH's 99.9% confidence half-width (ms)
 * @param msPerTickMedian median of the measurement iterations' means (ms)
 * @param cpuMsPerTick the benchmark thread's CPU time per tick over the measurement iterations (ms)
 * @param usPerBody cpuMsPerTick per moving body or particle (µs)
 * @param allocBytesPerTick JMH's gc.alloc.rate.norm (bytes per tick, Java heap only)
 * @param threadBytesPerTick bytes the benchmark thread allocated per measured tick (its exact counter)
 * @param prerollMsPerTick wall time per tick of the untimed run from the scene's start (ms)
 * @param settings the engine's settings as used
 * @param check the scene check after the preroll (the same ticks in every engine)
 * @param afterRun the scene check after the timed ticks
 */
public record Measurement(String scene, String engine, String status, String message, int bodies, long dynamicBodies,
                          Double msPerTick, Double msPerTickError, Double msPerTickMedian, Double cpuMsPerTick,
                          Double usPerBody, Double allocBytesPerTick, Double threadBytesPerTick, Double prerollMsPerTick, String settings,
                          Map<String, Object> check, Map<String, Object> afterRun) {

    /** A scene or engine that did not run. */
    public static Measurement notRun(String scene, String engine, String status, String message) {
        return new Measurement(scene, engine, status, message, 0, 0, null, null, null, null, null, null, null, null, null, null, null);
    }

    /** The check's verdict, or null. */
    public String verdict() {
        return check == null ? null : (String) check.get("verdict");
    }

    /** The figure the comparisons use: CPU time per tick when measured, else wall time. */
    public Double cost() {
        return cpuMsPerTick != null ? cpuMsPerTick : msPerTick;
    }
}
