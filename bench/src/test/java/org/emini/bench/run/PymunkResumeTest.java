package org.emini.bench.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.bench.scene.BenchScenes;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --resume} reuses pymunk's kept figures only when they cover every scene asked for. */
class PymunkResumeTest {
    private static final String KEPT = "[{\"scene\": \"bench/pyramid-20\", \"engine\": \"pymunk\", \"status\": \"ok\", \"cpuMsPerTick\": 0.28},"
        + " {\"scene\": \"bench/rain-100\", \"engine\": \"pymunk\", \"status\": \"ok\", \"cpuMsPerTick\": 0.11},"
        + " {\"scene\": \"bench/tumbler\", \"engine\": \"pymunk\", \"status\": \"error\", \"message\": \"failed\"}]";

    @Test
    void keptFiguresAreReusedWhenTheyCoverEveryScene(@TempDir Path dir) throws Exception {
        Path f = Files.writeString(dir.resolve("pymunk.json"), KEPT, StandardCharsets.UTF_8);
        List<Measurement> kept = PymunkBench.kept(f, List.of("bench/rain-100", "bench/pyramid-20"));
        assertEquals(List.of("bench/rain-100", "bench/pyramid-20"), kept.stream().map(Measurement::scene).toList());
        assertEquals(0.11, kept.get(0).cost());

        PymunkBench.Outcome o = PymunkBench.run(BenchScenes.open(), BenchPlan.FULL, dir, List.of("bench/pyramid-20"), true);
        assertEquals("ran", o.status());
        assertTrue(o.message().contains("kept from an earlier run"), o.message());
        assertEquals(1, o.measurements().size());
        assertTrue(o.kept(), "the report says the run was resumed");
    }

    @Test
    void aMissingFailedOrDamagedFigureMeansRunningAgain(@TempDir Path dir) throws Exception {
        Path f = Files.writeString(dir.resolve("pymunk.json"), KEPT, StandardCharsets.UTF_8);
        assertNull(PymunkBench.kept(f, List.of("bench/pyramid-20", "bench/rain-5000")), "a scene it does not have");
        assertNull(PymunkBench.kept(f, List.of("bench/tumbler")), "a scene that failed");
        Files.writeString(f, "[{\"scene\": ", StandardCharsets.UTF_8);
        assertNull(PymunkBench.kept(f, List.of("bench/pyramid-20")), "a damaged file");
        assertNull(PymunkBench.kept(dir.resolve("none.json"), List.of("bench/pyramid-20")), "no file");
    }
}
