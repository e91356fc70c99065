package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.emini.harness.Scenes;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.emini.particle.ParticleEmitter;
import org.junit.jupiter.api.Test;

/** The particles section through the engine's public API: every key, and the defaults. */
class ParticleBuilderTest {
    private static BuiltWorld build(String... particles) throws Exception {
        String[] lines = new String[particles.length + 3];
        lines[0] = "bodies: [{name: cannon, shape: {type: circle, radius: 5}, position: [50, -50]}]";
        lines[1] = "particles:";
        System.arraycopy(particles, 0, lines, 2, particles.length);
        lines[lines.length - 1] = "run: {duration: 1}";
        Scenario s = Scenes.valid("p.yaml", lines);
        return WorldBuilder.build(s);
    }

    @Test
    void everyKeyReachesTheEmitter() throws Exception {
        BuiltWorld w = build("  - {name: jet, body: cannon, from: [1, 2], to: [3, 4], maxCount: 7, rate: 30,"
                + " rateSpread: 2, lifetime: 1.5, lifetimeSpread: 0.5, speed: 80, speedSpread: 4, angleDeg: -90,"
                + " angleSpreadDeg: 30, axesFixed: true, elasticity: 0.5, gravityFactor: -1, damping: 0.1,"
                + " collide: false, seed: 9}");
        ParticleEmitter e = w.emitters().get("jet");
        assertSame(e, w.world().getParticleEmitter(0));
        assertSame(w.body("cannon"), e.getBody());
        assertEquals(7, e.getMaxParticles());
        assertEquals(1f, e.getEmitX1());
        assertEquals(2f, e.getEmitY1());
        assertEquals(3f, e.getEmitX2());
        assertEquals(4f, e.getEmitY2());
        assertEquals(30f, e.getCreationRate());
        assertEquals(2f, e.getCreationRateDeviation());
        assertEquals(1.5f, e.getLifetime());
        assertEquals(0.5f, e.getLifetimeDeviation());
        assertEquals(80f, e.getSpeed());
        assertEquals(4f, e.getSpeedDeviation());
        assertEquals(-Math.PI / 2, e.getAngle(), 1e-6);
        assertEquals(Math.PI / 6, e.getAngleDeviation(), 1e-6);
        assertTrue(e.isAxesFixed());
        assertEquals(0.5f, e.getElasticity());
        assertEquals(-1f, e.getGravityFactor());
        assertEquals(0.1f, e.getDamping(), 1e-7);
        assertEquals(false, e.canCollide());
        assertEquals(9L, e.getSeed());
    }

    @Test
    void defaultsAreTheDesignersAndSeedsDiffer() throws Exception {
        BuiltWorld w = build("  - {from: [0, 0]}", "  - {from: [10, 0]}");
        ParticleEmitter e = w.emitters().get("emitter0");
        assertEquals(null, e.getBody());
        assertEquals(100, e.getMaxParticles());
        assertEquals(0f, e.getEmitX2());
        assertEquals(20f, e.getCreationRate());
        assertEquals(2f, e.getLifetime());
        assertEquals(10f, e.getSpeed());
        assertEquals(0f, e.getAngle());
        assertEquals(0f, e.getAngleDeviation());
        assertEquals(false, e.isAxesFixed());
        assertEquals(1f, e.getElasticity());
        assertEquals(1f, e.getGravityFactor());
        assertEquals(0f, e.getDamping());
        assertTrue(e.canCollide());
        assertEquals(ParticleEmitter.DEFAULT_SEED, e.getSeed());
        assertEquals(ParticleEmitter.DEFAULT_SEED + 1, w.emitters().get("emitter1").getSeed());
    }

    @Test
    void duplicateEmitterNamesAreRefused() {
        assertTrue(Scenes.load("d.yaml", "particles: [{name: emitter1, from: [0, 0]}, {from: [1, 1]}]",
                "run: {duration: 1}").problems().toString().contains("duplicate emitter name 'emitter1'"));
    }

    @Test
    void aKeyTheBuilderDoesNotReadMakesTheSceneUnsupported() throws Exception {
        // The schema refuses unknown keys; this is the guard for a key it gains before the builder does.
        BuiltWorld w = build("  - {from: [0, 0]}");
        ArrayNode list = new ObjectMapper().createArrayNode();
        ObjectNode e = list.addObject();
        e.putArray("from").add(0).add(0);
        e.put("burst", 5);
        UnsupportedElementException x = assertThrows(UnsupportedElementException.class,
                () -> new ParticleBuilder().build(new Section(list, JsonPath.ROOT.key("particles")), w));
        assertEquals("$.particles[0].burst", x.getMessage().replaceAll(".*\\(at (.*)\\).*", "$1"));
    }

    @Test
    void anEmitActionIsABurstOnTopOfTheRate() {
        SceneResult r = ScenarioRunner.run(Scenes.valid("burst.yaml",
                "particles: [{name: jet, from: [0, 0], rate: 0, maxCount: 50}]",
                "actions: [{at: 0.1, type: emit, emitter: jet, count: 30}, {at: 0.2, type: emit, emitter: jet, count: 30}]",
                "run: {duration: 0.5, record: {metrics: [particles]}}"), n -> { });
        double[] count = r.trace().column("particles.count");
        assertEquals(0, count[2], "before tick 2 (t = 0.1 s) nothing");
        assertEquals(30, count[3]);
        assertEquals(50, count[5], "the second burst stops when the pool of 50 is full");
        assertTrue(Scenes.load("e.yaml", "particles: [{from: [0, 0]}]",
                "actions: [{at: 0, type: emit, emitter: jet, count: 1}]", "run: {duration: 1}").problems().toString()
                .contains("no emitter named 'jet'"));
    }
}
