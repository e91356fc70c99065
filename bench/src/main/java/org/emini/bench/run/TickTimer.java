package org.emini.bench.run;

import org.emini.bench.scene.BenchScenes;
import org.emini.harness.build.WorldBuilder;
import org.emini.world.World;

/**
 * Times one benchmark scene's ticks by the wall clock in a JVM of its own, with a given thread count:
 * the way to compare two builds of the threaded solve. {@link BuildComparison} with a thread count
 * puts both builds' worlds in one JVM, and each world's idle workers spin during the other's tick, so
 * on a 2-core machine it measures three busy threads. Run this alternately on the two builds' class
 * folders, several times each, and compare the minimum and the median: runs of one build at two
 * threads on this project's VM spread by 10% or more.
 *
 * <pre>
 * java -cp "BUILD/engine:harness/target/classes:harness/target/lib/*:bench/target/classes:bench/target/lib/*" \
 *   org.emini.bench.run.TickTimer bench/pyramids-10x20 2 1500 1500
 * </pre>
 *
 * Arguments: the scene id, the thread count, the timed ticks and the untimed ticks before them.
 */
public final class TickTimer {
    private TickTimer() {
    }

    /**
     * Builds the scene, ticks it untimed, then prints the timed ticks' wall ms per tick.
     *
     * @param args see the class comment
     * @throws Exception when the scene cannot be read or built
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 4) {
            throw new IllegalArgumentException("arguments: scene threads timedTicks untimedTicks");
        }
        int threads = Integer.parseInt(args[1]);
        int timed = Integer.parseInt(args[2]);
        int untimed = Integer.parseInt(args[3]);
        World world = WorldBuilder.build(BenchScenes.open().load(args[0])).world();
        world.setWorkerCount(threads);
        try {
            for (int i = 0; i < untimed; i++) {
                world.tick();
            }
            long start = System.nanoTime();
            for (int i = 0; i < timed; i++) {
                world.tick();
            }
            System.out.printf("%s, %d threads: %.3f ms/tick over %d ticks%n", args[0], threads,
                (System.nanoTime() - start) / 1e6 / timed, timed);
        } finally {
            world.setWorkerCount(1);
        }
    }
}
