package org.emini.designer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.io.PhyReader;
import org.emini.io.PhyScript;
import org.emini.io.PhyScriptBinding;
import org.emini.io.PhyScriptElement;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import org.junit.jupiter.api.Test;

/** The page's document is the world file: JSON and back loses nothing the writer stores. */
class DocJsonTest {
    private static final Path LIBRARY = Path.of("..", "scenarios");

    @Test
    void everyLibrarySceneAsAWorldFileSurvivesTheDocument() throws IOException {
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(LIBRARY.resolve("scenario.schema.json")), LIBRARY);
        List<Path> scenes = new ArrayList<>();
        try (Stream<Path> files = Files.walk(LIBRARY)) {
            files.filter(f -> f.toString().endsWith(".yaml") && !f.toString().contains("-10000") && !f.toString().contains("-20000"))
                    .sorted().forEach(scenes::add);
        }
        assertTrue(scenes.size() > 50, "library scenes found: " + scenes.size());
        for (Path scene : scenes) {
            ScenarioLoader.Loaded loaded = loader.load(scene);
            assertTrue(loaded.ok(), scene + ": " + loaded.problems());
            PhyWorld world = ScenarioToWorld.convert(loaded.scenario()).world();
            byte[] file = new PhyWriter().write(world);
            PhyWorld back = DocJson.read(DocJson.write(world), null);
            assertArrayEquals(file, new PhyWriter().write(back), scene.toString());
        }
    }

    @Test
    void theOriginalsWorldFilesKeepTheirDocument() throws IOException {
        Path worlds = Path.of("..", "..", "shared", "reference", "worlds");
        if (!Files.isDirectory(worlds)) {
            return;  // the reference files lie beside the repository, not in it
        }
        try (Stream<Path> files = Files.list(worlds)) {
            for (Path f : (Iterable<Path>) files.sorted()::iterator) {
                PhyWorld read;
                try (InputStream in = Files.newInputStream(f)) {
                    read = new PhyReader().setSkipUnknownSections(true).read(in);
                }
                String json = DocJson.write(read);
                PhyWorld back = DocJson.read(json, read);
                assertEquals(json, DocJson.write(back), f.toString());
                assertEquals(read.getBodies(), back.getBodies(), f.toString());
                assertEquals(read.getShapes(), back.getShapes(), f.toString());
                assertEquals(read.getConstraints(), back.getConstraints(), f.toString());
                assertEquals(read.getEvents(), back.getEvents(), f.toString());
                assertEquals(read.getParticleEmitters(), back.getParticleEmitters(), f.toString());
                assertEquals(read.getScripts(), back.getScripts(), f.toString());
                // A document that did not come from the file (a new one) does not inherit its scripts.
                assertTrue(DocJson.read("{}", read).getScripts().isEmpty(), f.toString());
            }
        }
    }

    @Test
    void aFileKeepsItsScriptsThroughTheDocumentAndANewDocumentHasNone() {
        PhyWorld file = DocJson.read("{\"shapes\":[{\"kind\":\"circle\",\"vertices\":[40960,0]}],"
                + "\"bodies\":[{\"shape\":0,\"position\":[0,0]}]}", null);
        PhyScript script = new PhyScript();
        script.getElements().add(new PhyScriptElement(0, 4096, 0, 20));
        file.getScripts().add(script);
        file.getScriptBindings().add(new PhyScriptBinding(0, 0));
        String json = DocJson.write(file);
        PhyWorld back = DocJson.read(json, file);
        assertEquals(file.getScripts(), back.getScripts());
        assertEquals(file.getScriptBindings(), back.getScriptBindings());
        assertArrayEquals(new PhyWriter().write(file), new PhyWriter().write(back));
        PhyWorld fresh = DocJson.read(json.replace("\"scripts\":1", "\"scripts\":0"), file);
        assertTrue(fresh.getScripts().isEmpty() && fresh.getScriptBindings().isEmpty());
    }

    @Test
    void aFractionIsRefusedWithItsPlace() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DocJson.read("{\"bodies\":[{\"shape\":0,\"position\":[1.5,0]}]}", null));
        assertTrue(e.getMessage().contains("offset 35") && e.getMessage().contains("integer"), e.getMessage());
    }

    @Test
    void aMissingFieldIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> DocJson.read("{\"bodies\":[{\"position\":[1,0]}]}", null));
        assertEquals("bodies[0].shape: missing", e.getMessage());
    }

    @Test
    void theJvmAndThePageBuildTheSameWorldFromTheDocument() throws IOException {
        Path scene = LIBRARY.resolve("examples/every-element.yaml");
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(LIBRARY.resolve("scenario.schema.json")), LIBRARY);
        PhyWorld world = ScenarioToWorld.convert(loader.load(scene).scenario()).world();
        Play direct = new Play(world, 60, 10);
        Play viaDocument = new Play(DocJson.read(DocJson.write(world), null), 60, 10);
        direct.tick(90);
        viaDocument.tick(90);
        assertArrayEquals(direct.frame(), viaDocument.frame());
        assertFalse(direct.geometry().isEmpty());
        // Its non-rotating bodies (infinite inertia) do not make the metrics NaN.
        for (double m : direct.metrics()) {
            assertTrue(Double.isFinite(m), java.util.Arrays.toString(direct.metrics()));
        }
    }
}
