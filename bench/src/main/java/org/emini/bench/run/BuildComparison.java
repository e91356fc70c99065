package org.emini.bench.run;

import com.sun.management.ThreadMXBean;
import java.io.File;
import java.lang.management.ManagementFactory;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Two builds of the engine timed on one scene in one JVM, without a feature flag: each build's
 * class folders ({@code engine/}, {@code harness/}, {@code bench/} under its directory, as
 * {@code target/classes} of each module) get their own class loader over the shared third-party
 * jars, each builds its own world, and their ticks alternate (A then B, then B then A), each timed by
 * the thread's CPU clock. Both worlds meet the same machine load, so the ratio B/A is steady where
 * wall times on this shared machine are not.
 *
 * <p>Whichever build is loaded first measured about 1.5% slower in runs of two identical builds
 * of some scenes, and a JVM's compiled code varies by a few percent from run to run: run it in both
 * orders, a few times each, and take the geometric mean of B/A and 1/(A/B).
 *
 * <pre>
 * java -cp "bench/target/classes:bench/target/lib/*" org.emini.bench.run.BuildComparison \
 *   bench/target/lib bench/tumbler 600 300 4 /tmp/main-build /tmp/my-build
 * </pre>
 *
 * Arguments: the folder of third-party jars, the scene id, untimed ticks first, ticks per window,
 * windows, the two build folders, and optionally a thread count: above 1, both worlds solve with
 * that many threads ({@code World.setWorkerCount}) and each tick is timed by the wall clock, since
 * the thread's CPU clock misses the workers. Each world's idle workers spin a while after its tick,
 * during the other's: compare builds that park their workers alike, and time threaded changes in
 * separate JVMs too ({@link TickTimer}).
 */
public final class BuildComparison {
    private BuildComparison() {
    }

    /**
     * Runs the comparison and prints each window's CPU ms per tick and the median ratio.
     *
     * @param args see the class comment
     * @throws Exception when a build cannot be loaded or the scene built
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 7 && args.length != 8) {
            throw new IllegalArgumentException("arguments: libDir scene preroll windowTicks windows buildA buildB [threads]");
        }
        int workers = args.length == 8 ? Integer.parseInt(args[7]) : 1;
        String scene = args[1];
        int preroll = Integer.parseInt(args[2]);
        int window = Integer.parseInt(args[3]);
        int windows = Integer.parseInt(args[4]);
        ClassLoader shared = new URLClassLoader(thirdPartyJars(new File(args[0])), ClassLoader.getPlatformClassLoader());
        Build a = new Build(new File(args[5]), shared, scene, workers);
        Build b = new Build(new File(args[6]), shared, scene, workers);
        // The preroll, then one window untimed, so that both builds are compiled.
        for (int i = 0; i < preroll + window; i++) {
            a.tick();
            b.tick();
        }
        ThreadMXBean threads = (ThreadMXBean) ManagementFactory.getThreadMXBean();
        boolean wall = workers > 1;
        double[] ratios = new double[windows];
        for (int w = 0; w < windows; w++) {
            long[] cpu = new long[2];
            for (int i = 0; i < window; i++) {
                boolean aFirst = (i & 1) == 0;
                long t0 = wall ? System.nanoTime() : threads.getCurrentThreadCpuTime();
                (aFirst ? a : b).tick();
                long t1 = wall ? System.nanoTime() : threads.getCurrentThreadCpuTime();
                (aFirst ? b : a).tick();
                long t2 = wall ? System.nanoTime() : threads.getCurrentThreadCpuTime();
                cpu[aFirst ? 0 : 1] += t1 - t0;
                cpu[aFirst ? 1 : 0] += t2 - t1;
            }
            double ma = cpu[0] / 1e6 / window;
            double mb = cpu[1] / 1e6 / window;
            ratios[w] = mb / ma;
            System.out.printf("window %d: A %.4f ms/tick, B %.4f ms/tick, B/A %.3f (contacts A %s, B %s)%n", w, ma, mb,
                ratios[w], a.contacts(), b.contacts());
        }
        a.close();
        b.close();
        Arrays.sort(ratios);
        System.out.printf("%s: median B/A %.3f over %d windows of %d ticks%s%n", scene, ratios[windows / 2], windows, window,
            wall ? ", " + workers + " threads, wall clock" : "");
    }

    private static URL[] thirdPartyJars(File lib) throws MalformedURLException {
        List<URL> urls = new ArrayList<>();
        File[] files = lib.listFiles();
        if (files == null) {
            throw new IllegalArgumentException("no folder of jars: " + lib);
        }
        Arrays.sort(files);
        for (File f : files) {
            // The project's own jars come from each build instead.
            if (f.getName().endsWith(".jar") && !f.getName().startsWith("emini")) {
                urls.add(f.toURI().toURL());
            }
        }
        return urls.toArray(new URL[0]);
    }

    /** One build's world, reached by reflection (its classes are not this loader's). */
    private static final class Build {
        private final Object world;
        private final Method tick;
        private final Method contactCount;
        private final Method setWorkers;

        Build(File dir, ClassLoader shared, String scene, int workers) throws Exception {
            URL[] urls = {new File(dir, "engine/").toURI().toURL(), new File(dir, "harness/").toURI().toURL(),
                new File(dir, "bench/").toURI().toURL()};
            ClassLoader loader = new URLClassLoader(urls, shared);
            Object scenes = loader.loadClass("org.emini.bench.scene.BenchScenes").getMethod("open").invoke(null);
            Object scenario = scenes.getClass().getMethod("load", String.class).invoke(scenes, scene);
            Class<?> builder = loader.loadClass("org.emini.harness.build.WorldBuilder");
            Object built = builder.getMethod("build", loader.loadClass("org.emini.harness.scenario.Scenario"))
                .invoke(null, scenario);
            world = built.getClass().getMethod("world").invoke(built);
            tick = world.getClass().getMethod("tick");
            contactCount = world.getClass().getMethod("getContactCount");
            setWorkers = world.getClass().getMethod("setWorkerCount", int.class);
            if (workers > 1) {
                setWorkers.invoke(world, workers);
            }
        }

        /** Stops the world's workers, if it has any. */
        void close() throws Exception {
            setWorkers.invoke(world, 1);
        }

        void tick() throws Exception {
            tick.invoke(world);
        }

        Object contacts() throws Exception {
            return contactCount.invoke(world);
        }
    }
}
