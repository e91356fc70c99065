package org.emini.harness.oracle;

import java.util.List;

/**
 * What the oracle said about one scene file (an entry of its {@code oracle-results.json}).
 *
 * @param file the scene file as given
 * @param scene the scene id, or null when the file is invalid
 * @param status {@code ok}, {@code skipped} (the scene's reference.oracle.skip), {@code unsupported}
 *     (pymunk cannot run it at all), {@code invalid} or {@code error}
 * @param message why, for any status but ok
 * @param unsupported elements pymunk cannot express, left out of its run
 * @param approximations elements pymunk runs with different semantics
 * @param trace the trace file, or null
 */
public record OracleScene(String file, String scene, String status, String message, List<Note> unsupported,
                          List<Note> approximations, String trace) {

    /**
     * One element pymunk cannot express (or expresses differently).
     *
     * @param element what ({@code particles}, {@code linear motor}, ...)
     * @param path where the scene uses it
     * @param reason what pymunk does instead
     * @param affectsBodies whether leaving it out changes the bodies' motion
     */
    public record Note(String element, String path, String reason, boolean affectsBodies) {
    }

    /** Whether the oracle ran the scene and wrote a trace. */
    public boolean ok() {
        return status.equals("ok") && trace != null;
    }

    /** Whether something left out of the oracle's run changes the bodies' motion. */
    public boolean incomplete() {
        return unsupported.stream().anyMatch(Note::affectsBodies);
    }
}
