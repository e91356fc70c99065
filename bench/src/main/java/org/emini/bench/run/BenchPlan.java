package org.emini.bench.run;

import java.util.List;

/**
 * What {@code ./emini bench} runs: the scenes of the comparison table (a scene whose file is
 * missing is listed as pending, with what it waits for), the rain scaling series, and the JMH
 * settings of the two modes.
 */
public final class BenchPlan {
    /**
     * A scene of the table.
     *
     * @param id scene id under scenarios/
     * @param title what it is
     * @param needs what it waits for while its file is missing (or null)
     */
    public record Scene(String id, String title, String needs) {
    }

    /** The comparison table. */
    public static final List<Scene> SCENES = List.of(
        new Scene("bench/pyramid-20", "20-row pyramid (210 boxes)", null),
        new Scene("bench/pyramids-10x20", "ten 20-row pyramids (2,100 boxes)", null),
        new Scene("bench/pyramid-100", "100-row pyramid (5,050 boxes)", null),
        new Scene("bench/rain-5000", "rain: 5,000 mixed shapes into a container", null),
        new Scene("bench/joint-grid", "joint grid: a 30 x 30 net of balls, 1,740 pin joints", null),
        new Scene("bench/tumbler", "tumbler: 1,024 boxes and balls in a motor-driven rotating box", null),
        new Scene("bench/particles-10000", "10,000 particles (the peers: 10,000 circle bodies)", null),
        new Scene("bench/game-level", "game level, sleeping on: 840 crates at rest, 7 pendulums and 2 players moving", null));

    /** Body counts of the scaling series (scene bench/rain-N). */
    public static final List<Integer> SCALING = List.of(100, 200, 500, 1000, 2000, 5000, 10000, 20000);
    /** Body counts of the scaling series in quick mode. */
    public static final List<Integer> SCALING_QUICK = List.of(100, 500, 2000);

    /**
     * JMH settings.
     *
     * @param quick quick (CI-sized) or full
     * @param forks JMH forks (0: in this JVM)
     * @param warmups warm-up iterations
     * @param warmupMillis length of one warm-up iteration
     * @param iterations measurement iterations
     * @param iterationMillis length of one measurement iteration
     * @param preroll untimed ticks before timing: -1 for each scene's run duration
     */
    public record Mode(boolean quick, int forks, int warmups, int warmupMillis, int iterations, int iterationMillis,
                       int preroll) {
    }

    /** Full mode: what the published figures use. */
    public static final Mode FULL = new Mode(false, 1, 3, 1000, 5, 1000, -1);
    /** Quick mode: seconds per scene, in this JVM; the figures are only indicative. */
    public static final Mode QUICK = new Mode(true, 0, 1, 100, 2, 150, 20);

    private BenchPlan() {
    }
}
