package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.cli.Main;
import org.emini.harness.scenario.ExpectationSpec;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A world file's expectations file beside it: its run and expectations join the converted scene. */
class WorldExpectationsTest {
    @Test
    void theExpectationsBesideAWorldFileAreAddedToItsScene(@TempDir Path dir) throws Exception {
        Path phy = dir.resolve("level.phy");
        assertEquals(0, Main.execute("convert", "--schema", Repo.schema().toString(), "-o", phy.toString(),
                Repo.scenarios().resolve("closed-form/projectile-20hz.yaml").toString()));
        ScenarioLoader.Loaded plain = Scenes.loader().load(phy);
        assertTrue(plain.ok(), plain.problems().toString());
        assertEquals(1, plain.scenario().run().expect().size(), "converted: it stays stable");

        Files.writeString(dir.resolve("level.expect.yaml"), String.join("\n",
                "description: the projectile as a world file",
                "run:",
                "  duration: 2",
                "  expect:",
                "    - {metric: 'body.*.displacement', of: final, atLeast: 100}",
                ""));
        ScenarioLoader.Loaded withFile = Scenes.loader().load(phy);
        assertTrue(withFile.ok(), withFile.problems().toString());
        assertEquals(2, withFile.scenario().run().expect().size());
        ExpectationSpec added = withFile.scenario().run().expect().get(1);
        assertEquals("body.*.displacement", added.channel());
        assertEquals(40, withFile.scenario().ticks(), "2 s at the original's 20 ticks/s");
        assertFalse(ScenarioFiles.isScene(dir.resolve("level.expect.yaml")), "not a scene of its own in a folder run");

        Files.writeString(dir.resolve("level.expect.yaml"), "run: {bogus: 1}\n");
        ScenarioLoader.Loaded bad = Scenes.loader().load(phy);
        assertFalse(bad.ok());
        assertTrue(bad.problems().get(0).message().contains("unknown key 'run.bogus'"), bad.problems().toString());
    }
}
