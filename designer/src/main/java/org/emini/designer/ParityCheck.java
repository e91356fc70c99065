package org.emini.designer;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;
import org.emini.io.PhyReader;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;

/**
 * The JVM half of the page's parity test (JVM only; the page never reaches it). Each library scene
 * is converted to a world file as {@code harness convert} does, read back, turned into the page's
 * document and built by {@link Play} with the scene's timestep and iterations, exactly as the page
 * does it; it is ticked and every tick's body state (x, y, angle, velocities, sleeping) is hashed
 * over the floats' bits. The scenes, the hashes and the last tick's bits go to check-data.js, which
 * the page's self-test loads to repeat the run in the browser and compare bit for bit. The first
 * scene is also timed (milliseconds per tick on this JVM, after a warm-up) for the page to print
 * beside its own.
 *
 * <pre>java ... org.emini.designer.ParityCheck OUT_DIR TICKS TIMED_TICKS SCENE...</pre>
 */
public final class ParityCheck {
    private ParityCheck() {
    }

    /**
     * Writes OUT_DIR/check-data.js.
     *
     * @param args OUT_DIR, TICKS (per scene), TIMED_TICKS (for the first scene's timing), scene files
     * @throws IOException if a file cannot be read or written
     */
    public static void main(String[] args) throws IOException {
        if (args.length < 4) {
            System.err.println("usage: ParityCheck OUT_DIR TICKS TIMED_TICKS SCENE...");
            System.exit(2);
        }
        Path out = Path.of(args[0]);
        int ticks = Integer.parseInt(args[1]);
        int timed = Integer.parseInt(args[2]);
        Path schema = Path.of("scenarios", "scenario.schema.json");
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(schema), schema.toAbsolutePath().getParent());
        StringBuilder js = new StringBuilder("var EMINI_CHECK = {\"ticks\":").append(ticks).append(",\"scenes\":[");
        for (int s = 3; s < args.length; s++) {
            Path file = Path.of(args[s]);
            ScenarioLoader.Loaded loaded = loader.load(file);
            if (!loaded.ok()) {
                throw new IllegalArgumentException(file + ": " + loaded.problems());
            }
            Scenario scene = loaded.scenario();
            ScenarioToWorld.Result converted = ScenarioToWorld.convert(scene);
            byte[] phy = new PhyWriter().write(converted.world());
            int tps = (int) Math.round(1 / scene.world().timestep());
            int iterations = scene.world().iterations();
            Play play = play(phy, tps, iterations);
            int[] hashes = new int[ticks];
            for (int t = 0; t < ticks; t++) {
                play.tick(1);
                hashes[t] = hash(play.frame(), play.particles());
            }
            float[] last = play.frame();
            double msPerTick = s == 3 ? time(phy, tps, iterations, timed) : -1;
            if (s > 3) {
                js.append(',');
            }
            js.append("{\"file\":");
            Json.quote(js, args[s]);
            js.append(",\"ticksPerSecond\":").append(tps).append(",\"iterations\":").append(iterations)
                    .append(",\"bodies\":").append(last.length / 7).append(",\"jvmMsPerTick\":").append(msPerTick)
                    .append(",\"timedTicks\":").append(timed).append(",\"phy\":\"")
                    .append(Base64.getEncoder().encodeToString(phy)).append("\",\"hashes\":[");
            for (int t = 0; t < ticks; t++) {
                js.append(t > 0 ? "," : "").append(hashes[t]);
            }
            js.append("],\"lastBits\":[");
            for (int i = 0; i < last.length; i++) {
                js.append(i > 0 ? "," : "").append(Float.floatToRawIntBits(last[i]));
            }
            js.append("],\"notConverted\":");
            strings(js, converted.notConverted());
            js.append('}');
            System.out.printf("designer parity: %s, %d bodies, %d ticks on the JVM%s%n", args[s], last.length / 7, ticks,
                    msPerTick >= 0 ? String.format(", %.3f ms/tick", msPerTick) : "");
        }
        js.append("]};\n");
        Files.createDirectories(out);
        Files.write(out.resolve("check-data.js"), js.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** The page's route: world file → document JSON → world file → world. */
    private static Play play(byte[] phy, int tps, int iterations) throws IOException {
        PhyWorld read = new PhyReader().setSkipUnknownSections(true).read(new ByteArrayInputStream(phy));
        return new Play(DocJson.read(DocJson.write(read), null), tps, iterations);
    }

    /** Milliseconds per tick over {@code ticks} ticks, after as many ticks of warm-up in another world. */
    private static double time(byte[] phy, int tps, int iterations, int ticks) throws IOException {
        play(phy, tps, iterations).tick(ticks);
        Play p = play(phy, tps, iterations);
        long t0 = System.nanoTime();
        p.tick(ticks);
        return (System.nanoTime() - t0) / 1e6 / ticks;
    }

    /** FNV-1a over the floats' bits (bodies, then particles); the page computes the same with Math.imul. */
    static int hash(float[] frame, float[] particles) {
        int h = 0x811C9DC5;
        for (float f : frame) {
            h = (h ^ Float.floatToRawIntBits(f)) * 0x01000193;
        }
        for (float f : particles) {
            h = (h ^ Float.floatToRawIntBits(f)) * 0x01000193;
        }
        return h;
    }

    private static void strings(StringBuilder sb, List<String> items) {
        sb.append('[');
        List<String> copy = new ArrayList<>(items);
        for (int i = 0; i < copy.size(); i++) {
            if (i > 0) {
                sb.append(',');
            }
            Json.quote(sb, copy.get(i));
        }
        sb.append(']');
    }
}
