package org.emini.bench.jmh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.bench.scene.BenchScenes;
import org.emini.world.World;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.junit.jupiter.api.Test;

/** The idle variant holds every feature, and its pyramid is the plain one, bit for bit. */
class FeatureCostBenchmarkTest {
    @Test
    void theIdleWorldHasEveryFeatureAndThePlainPyramid() throws Exception {
        Path lib = BenchScenes.findRoot().resolve("scenarios");
        String text = Files.readString(lib.resolve("bench/pyramid-20.yaml"));
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(lib.resolve("scenario.schema.json")), lib);
        ScenarioLoader.Loaded idle = loader.load("idle", FeatureCostBenchmark.withIdleFeatures(text), "idle");
        assertTrue(idle.ok(), idle.problems().toString());
        World p = WorldBuilder.build(loader.load("plain", text, "plain").scenario()).world();
        World q = WorldBuilder.build(idle.scenario()).world();
        assertEquals(1, q.getLandscape().getSegmentCount());
        assertEquals(1, q.getParticleEmitterCount());
        assertEquals(2, q.getConstraintCount());
        assertEquals(p.getBodyCount() + 2, q.getBodyCount());
        for (int k = 0; k < 60; k++) {
            p.tick();
            q.tick();
        }
        assertEquals(0, q.getParticleEmitter(0).getParticleCount());
        for (int i = 0; i < p.getBodyCount(); i++) {
            assertEquals(p.getBody(i).getX(), q.getBody(i).getX());
            assertEquals(p.getBody(i).getY(), q.getBody(i).getY());
        }
    }
}
