package org.emini.harness.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.xml.parsers.DocumentBuilderFactory;
import org.emini.harness.Repo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The runnable jar as another project's CI uses it: {@code java -jar emini-harness-VERSION-cli.jar} in a
 * folder outside this repository (no scenarios/ folder, no schema file, no scripts), on a folder of
 * scenes of its own, writing JUnit XML; and {@code diff} failing on a deliberately worse run.
 */
class CliJarIT {
    private static final Path JAR = Path.of(System.getProperty("emini.cliJar", "target/emini-harness-cli.jar"));

    private record Ran(int status, String out) {
    }

    private static Ran jar(Path dir, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-jar", JAR.toAbsolutePath().toString()));
        cmd.addAll(List.of(args));
        Path log = dir.resolve("log-" + System.nanoTime() + ".txt");
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "the jar finished");
        return new Ran(p.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }

    /** A folder outside the repository with two library scenes and one that misses its bound. */
    private static Path project(Path tmp) throws IOException {
        assertFalse(tmp.toAbsolutePath().startsWith(Repo.root()), "the project folder is outside the repository");
        Path scenes = Files.createDirectories(tmp.resolve("physics-tests"));
        Files.copy(Repo.scenarios().resolve("closed-form/projectile-20hz.yaml"), scenes.resolve("projectile.yaml"));
        Files.copy(Repo.scenarios().resolve("closed-form/pendulum-90deg.yaml"), scenes.resolve("pendulum.yaml"));
        return scenes;
    }

    /** The projectile at 2 ticks per second with one iteration (100 px off the parabola): its 10 px bound on the parabola is missed (a worse engine build). */
    private static void coarsen(Path scene) throws IOException {
        String text = Files.readString(scene, StandardCharsets.UTF_8);
        Files.writeString(scene, text.replace("world: {ticksPerSecond: 20}", "world: {ticksPerSecond: 2, iterations: 1}"), StandardCharsets.UTF_8);
    }

    @Test
    void runsAFolderOfScenesOutsideTheRepositoryAndWritesJUnitXml(@TempDir Path tmp) throws Exception {
        Path scenes = project(tmp);
        Ran ok = jar(tmp, "run", "--junit", "ci/junit.xml", "--reports", "out", "physics-tests");
        assertEquals(0, ok.status(), ok.out());
        Document xml = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(tmp.resolve("ci/junit.xml").toFile());
        Element suite = xml.getDocumentElement();
        assertEquals("2", suite.getAttribute("tests"));
        assertEquals("0", suite.getAttribute("failures"));
        NodeList cases = xml.getElementsByTagName("testcase");
        assertEquals("physics-tests/pendulum", ((Element) cases.item(0)).getAttribute("name"), "scene ids relative to the working folder");
        assertTrue(Files.isRegularFile(tmp.resolve("out/results.json")));

        coarsen(scenes.resolve("projectile.yaml"));
        Ran bad = jar(tmp, "run", "--junit", "ci/junit.xml", "--reports", "out2", "physics-tests");
        assertEquals(1, bad.status(), bad.out());
        xml = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(tmp.resolve("ci/junit.xml").toFile());
        assertEquals("1", xml.getDocumentElement().getAttribute("failures"));
        assertEquals(1, xml.getElementsByTagName("failure").getLength());

        // -k keeps the pendulum alone (exit 0); --fail-fast stops at the failing projectile, which runs after it.
        assertEquals(0, jar(tmp, "run", "-k", "pendulum", "--reports", "out3", "physics-tests").status());
        Ran k = jar(tmp, "run", "-k", "*/proj*", "-k", "pend", "--fail-fast", "--jobs", "1", "--reports", "out4", "physics-tests");
        assertEquals(1, k.status(), k.out());
        assertEquals(2, jar(tmp, "run", "-k", "no-such-scene", "physics-tests").status(), "-k matching nothing is a usage error");
    }

    @Test
    void diffFailsOnADeliberatelyWorseRun(@TempDir Path tmp) throws Exception {
        Path scenes = project(tmp);
        assertEquals(0, jar(tmp, "run", "--reports", "old", "physics-tests").status());
        Ran same = jar(tmp, "diff", "old", "old");
        assertEquals(0, same.status(), same.out());
        coarsen(scenes.resolve("projectile.yaml"));
        assertEquals(1, jar(tmp, "run", "--reports", "new", "physics-tests").status());
        Ran worse = jar(tmp, "diff", "old", "new");
        assertEquals(1, worse.status(), worse.out());
        assertTrue(worse.out().contains("verdict") && worse.out().contains("physics-tests/projectile") && worse.out().contains("pass -> FAIL"),
                worse.out());
        assertEquals(0, jar(tmp, "diff", "new", "old").status(), "the other way round it is an improvement");
        assertEquals(3, jar(tmp, "diff", "old", "missing").status(), "an unreadable run is status 3");
    }

    @Test
    void helpListsTheExitStatuses(@TempDir Path tmp) throws Exception {
        for (String command : List.of("run", "compare", "diff", "validate")) {
            Ran help = jar(tmp, command, "--help");
            assertEquals(0, help.status());
            assertTrue(help.out().contains("Exit status:") && help.out().contains("70"), command + ": " + help.out());
        }
    }
}
