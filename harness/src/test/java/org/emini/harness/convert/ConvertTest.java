package org.emini.harness.convert;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import org.emini.harness.Repo;
import org.emini.harness.cli.Main;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;
import org.emini.io.PhyBody;
import org.emini.io.PhyFixed;
import org.emini.io.PhyPairConstraint;
import org.emini.io.PhyReader;
import org.emini.io.PhyShape;
import org.emini.io.PhySpring;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code convert}: original world files to scenes and back. */
class ConvertTest {
    private static final ScenarioLoader LOADER = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());

    /** The original's real files, beside the repository as in CI (Repo.referenceWorlds). */
    private static List<Path> worlds() throws Exception {
        Path dir = Repo.referenceWorlds();
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted().toList();
        }
    }

    private static Scenario load(String yaml) {
        ScenarioLoader.Loaded loaded = LOADER.load("converted.yaml", yaml, "converted");
        assertTrue(loaded.ok(), () -> loaded.problems() + "\n" + yaml);
        return loaded.scenario();
    }

    @Test
    void everyReferenceWorldBecomesAValidSceneWithItsElements() throws Exception {
        for (Path p : worlds()) {
            PhyWorld doc = new PhyReader().read(Files.readAllBytes(p));
            WorldToScenario.Result r = WorldToScenario.convert(doc, p.getFileName().toString(), 30);
            Scenario scene = load(r.yaml());
            assertEquals(doc.getBodies().size(), scene.bodies().size(), p + ": every body (none has an unusable shape)");
            assertEquals(doc.getConstraints().size(), count(scene, "joints") + count(scene, "springs")
                    + count(scene, "motors"), p + ": constraints");
            int segments = doc.getLandscape() == null ? 0 : doc.getLandscape().getSegments().size();
            assertEquals(segments, scene.elements().containsKey("landscape")
                    ? scene.elements().get("landscape").node().get("segments").size() : 0, p + ": segments");
            assertEquals(doc.getEvents().size(), r.notConverted().stream().filter(s -> s.startsWith("event ")).count(),
                    p + ": each event is listed as not converted");
            for (String line : r.notConverted()) {
                assertTrue(r.yaml().contains("#   " + line), p + ": listed in the file's comments: " + line);
            }
            assertEquals(30 * 20, scene.ticks());
        }
    }

    private static int count(Scenario scene, String key) {
        return scene.elements().containsKey(key) ? scene.elements().get(key).node().size() : 0;
    }

    @Test
    void aWorldComesBackWithEveryValueTheSceneHolds() throws Exception {
        for (Path p : worlds()) {
            PhyWorld doc = new PhyReader().read(Files.readAllBytes(p));
            PhyWorld back = ScenarioToWorld.convert(load(WorldToScenario.convert(doc, "w", 30).yaml())).world();
            assertEquals(doc.getBodies().size(), back.getBodies().size(), p.toString());
            for (int i = 0; i < doc.getBodies().size(); i++) {
                PhyBody a = doc.getBodies().get(i);
                PhyBody b = back.getBodies().get(i);
                String at = p + " body " + i;
                assertEquals(a.getPosition(), b.getPosition(), at);
                assertEquals(a.getVelocity(), b.getVelocity(), at);
                assertEquals(PhyFixed.wrapAngle2fx(a.getAngleRaw()), b.getAngleRaw(), at);
                assertEquals(a.getAngularVelocityRaw(), b.getAngularVelocityRaw(), at);
                assertEquals(a.getFlags() & 15, b.getFlags(), at);
                assertEquals(a.getCollisionLayers(), b.getCollisionLayers(), at);
                PhyShape sa = (PhyShape) doc.getShapes().get(a.getShapeIndex());
                PhyShape sb = (PhyShape) back.getShapes().get(b.getShapeIndex());
                if (sa.getVertexCount() == 1) {
                    assertEquals(sa.getCircleRadius(), sb.getCircleRadius(), at);
                } else if (sa.getVertexCount() > 2) {
                    assertArrayEquals(sa.getVertices(), sb.getVertices(), at);
                }
                assertEquals(sa.getMassRaw(), sb.getMassRaw(), at);
                assertEquals(sa.getFrictionRaw(), sb.getFrictionRaw(), at);
                assertEquals(sa.getElasticityRaw(), sb.getElasticityRaw(), at);
            }
            for (int i = 0; i < doc.getConstraints().size(); i++) {
                PhyPairConstraint a = (PhyPairConstraint) doc.getConstraints().get(i);
                PhyPairConstraint b = (PhyPairConstraint) back.getConstraints().get(i);
                assertEquals(List.of(a.getBody1(), a.getAnchor1(), a.getBody2(), a.getAnchor2()),
                        List.of(b.getBody1(), b.getAnchor1(), b.getBody2(), b.getAnchor2()), p + " constraint " + i);
                if (a instanceof PhySpring s) {
                    assertEquals(s.getRestLengthRaw(), ((PhySpring) b).getRestLengthRaw());
                    assertEquals(Math.max(0, s.getCoefficientRaw()), ((PhySpring) b).getCoefficientRaw());
                }
            }
            if (doc.getLandscape() != null) {
                assertEquals(doc.getLandscape().getSegments(), back.getLandscape().getSegments(), p.toString());
                assertEquals(doc.getLandscape().getMaterial().getFrictionRaw(),
                        back.getLandscape().getMaterial().getFrictionRaw());
            }
            if (doc.getSettings() != null) {
                assertEquals(doc.getSettings().getGravity(), back.getSettings().getGravity());
                assertEquals(doc.getSettings().getDampingLinearRaw(), back.getSettings().getDampingLinearRaw());
            }
        }
    }

    @Test
    void aSecondRoundTripChangesNoByte() throws Exception {
        for (Path p : worlds()) {
            PhyWorld doc = new PhyReader().read(Files.readAllBytes(p));
            PhyWorld once = ScenarioToWorld.convert(load(WorldToScenario.convert(doc, "w", 30).yaml())).world();
            PhyWorld twice = ScenarioToWorld.convert(load(WorldToScenario.convert(once, "w", 30).yaml())).world();
            assertArrayEquals(new PhyWriter().write(once), new PhyWriter().write(twice), p.toString());
        }
    }

    @Test
    void aSceneBecomesAWorldFileAndListsWhatItCannotHold() throws Exception {
        Path file = Repo.scenarios().resolve("examples/every-element.yaml");
        Scenario scene = LOADER.load(file).scenario();
        ScenarioToWorld.Result r = ScenarioToWorld.convert(scene);
        PhyWorld w = new PhyReader().read(new PhyWriter().write(r.world()));
        assertEquals(scene.bodies().size(), w.getBodies().size());
        assertEquals("name=hex", w.getBodies().get(2).getUserData());
        assertEquals(3, w.getConstraints().size());
        assertEquals(1, w.getLandscape().getSegments().size());
        assertEquals(1, w.getParticleEmitters().size());
        assertEquals(1, w.getMultiShapeCount());
        // hex turns at +1 rad/s (growing angle): stored with the original's sign.
        assertEquals(-PhyFixed.FX2_ONE, w.getBodies().get(2).getAngularVelocityRaw());
        String notes = String.join("\n", r.notConverted()) + "\n" + String.join("\n", r.approximated());
        for (String expected : List.of("world timestep", "world solver settings", "world sleeping", "world.simulationArea",
                "action at 1 s: impulse on ball", "damping 0.5 is not stored", "run, record, expectations")) {
            assertTrue(notes.contains(expected), expected + " in\n" + notes);
        }
        // Back to a scene: the same world again, byte for byte.
        Scenario again = load(WorldToScenario.convert(w, "every.phy", 5).yaml());
        assertEquals("hammer", again.bodies().get(4).name());
        assertArrayEquals(new PhyWriter().write(r.world()),
                new PhyWriter().write(ScenarioToWorld.convert(again).world()));
    }

    @Test
    void theCommandConvertsBothWaysAndRefusesADamagedFile(@TempDir Path dir) throws Exception {
        Path world = dir.resolve("level.phy");
        Path scene = Repo.scenarios().resolve("closed-form/projectile-20hz.yaml");
        String[] out = new String[1];
        assertEquals(0, capture(out, "convert", "--schema", Repo.schema().toString(), "-o", world.toString(),
                scene.toString()));
        assertTrue(out[0].contains("-> " + world), out[0]);
        assertEquals(0, capture(out, "convert", "--schema", Repo.schema().toString(), "--duration", "2",
                world.toString()));
        Path yaml = dir.resolve("level.yaml");
        assertEquals(2 * 20, load(Files.readString(yaml)).ticks());
        byte[] bytes = Files.readAllBytes(world);
        Files.write(world, Arrays.copyOf(bytes, bytes.length - 3));
        assertEquals(1, capture(out, "convert", "--schema", Repo.schema().toString(), world.toString()));
        // The file ends with the world record's empty user data: its 4-byte length is cut to 1 byte.
        assertTrue(out[0].contains("byte " + (bytes.length - 4) + ": expected world user data"), out[0]);
    }

    @Test
    void convertedDesignerWorldsRunThroughTheHarness(@TempDir Path dir) throws Exception {
        List<Path> worlds = worlds();
        for (Path p : worlds) {
            assertEquals(0, Main.execute("convert", "--schema", Repo.schema().toString(), "--duration", "5", "-o",
                    dir.resolve(p.getFileName() + ".yaml").toString(), p.toString()));
        }
        assertEquals(0, Main.execute("run", "--schema", Repo.schema().toString(), "--reports",
                dir.resolve("reports").toString(), "--no-progress", "--no-traces", dir.toString()));
        String summary = Files.readString(dir.resolve("reports/summary.txt"));
        assertTrue(summary.contains(worlds.size() + " scenes") && summary.contains("0 errors"), summary);
    }

    /** Runs the command line, capturing what it prints (stdout and stderr). */
    private static int capture(String[] out, String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        PrintStream p = new PrintStream(buf, true, StandardCharsets.UTF_8);
        System.setOut(p);
        System.setErr(p);
        try {
            return Main.execute(args);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
            out[0] = buf.toString(StandardCharsets.UTF_8);
        }
    }
}
