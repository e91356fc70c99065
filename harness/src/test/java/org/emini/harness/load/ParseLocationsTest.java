package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.harness.Scenes;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Errors of the text itself name the file, line and column (issue 14: 986 errors had none). */
class ParseLocationsTest {

    private static Problem onlyFile(Path file) {
        ScenarioLoader.Loaded loaded = Scenes.loader().load(file);
        assertFalse(loaded.ok());
        assertEquals(1, loaded.problems().size(), loaded.problems().toString());
        return loaded.problems().get(0);
    }

    @Test
    void invalidUtf8IsLocated(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("bytes.yaml");
        byte[] head = "run: {duration: 1}\ndescription: \"ab".getBytes(StandardCharsets.UTF_8);
        byte[] bytes = java.util.Arrays.copyOf(head, head.length + 2);
        bytes[head.length] = (byte) 0xff;
        bytes[head.length + 1] = '"';
        Files.write(file, bytes);
        Problem p = onlyFile(file);
        assertEquals(2, p.line(), p.toString());
        assertEquals(17, p.column(), p.toString());
        assertTrue(p.message().contains("not UTF-8") && p.message().contains("0xFF"), p.message());
    }

    @Test
    void aControlCharacterIsLocated() {
        ScenarioLoader.Loaded loaded = Scenes.load("ctrl.yaml", "run: {duration: 1}", "description: \"a\u0001b\"");
        assertEquals(1, loaded.problems().size());
        Problem p = loaded.problems().get(0);
        assertEquals(2, p.line(), p.toString());
        assertEquals(16, p.column(), p.toString());
        assertTrue(p.message().contains("U+0001"), p.message());
    }

    @Test
    void aFileTooLargeIsRefusedUnread(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("huge.yaml");
        try (var out = Files.newOutputStream(file)) {
            out.write(new byte[(int) Limits.FILE_BYTES + 1]);
        }
        Problem p = onlyFile(file);
        assertTrue(p.message().contains("more than the " + Limits.FILE_BYTES), p.message());
    }

    @Test
    void aMissingFileSaysSo(@TempDir Path dir) {
        Problem p = onlyFile(dir.resolve("nope.yaml"));
        assertTrue(p.message().contains("no such file"), p.message());
    }

    @Test
    void unreadableNumbersAreLocated() {
        for (String v : List.of("0x1F", "1:20", "0b101")) {
            ScenarioLoader.Loaded loaded = Scenes.load("n.yaml", "run: {duration: " + v + "}");
            assertEquals(1, loaded.problems().size(), v + ": " + loaded.problems());
            Problem p = loaded.problems().get(0);
            assertEquals("$.run.duration", p.path(), v);
            assertEquals(1, p.line(), v);
        }
    }

    /** Every problem the library's parser meets on a sample of broken texts has a line. */
    @Test
    void brokenTextsAllGetALine() {
        for (String text : List.of("run: {duration: 1", "run: [1, 2", "a: *nowhere", "run: {duration: 1}\n\t- x",
                "{\"run\": {\"duration\": 1}", "run: &a {duration: 1}\nother: *a\n!!int x: 1", "? [a]\n: 1")) {
            ScenarioLoader.Loaded loaded = Scenes.loader().load("t.yaml", text, "t");
            assertFalse(loaded.ok(), text);
            for (Problem p : loaded.problems()) {
                assertTrue(p.line() >= 1 && p.column() >= 1, text + " -> " + p);
            }
        }
    }
}
