package org.emini.bench.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code ./emini bench --quick} on one small scene and one scaling point, end to end: JMH in this JVM,
 * the scene checks, bench.json, the page and the plots. Checks that it runs and what it writes, never
 * how fast anything is.
 */
class QuickBenchTest {
    @Test
    void quickRunWritesJsonPageAndPlots(@TempDir Path dir) throws Exception {
        int status = new CommandLine(new BenchMain()).execute("--quick", "--scenes", "bench/pyramid-20",
            "--engines", "emini,jbox2d", "--scaling", "100", "--reports", dir.toString());
        assertEquals(0, status);
        JsonObject r = JsonParser.parseString(Files.readString(dir.resolve("bench.json"), StandardCharsets.UTF_8)).getAsJsonObject();
        assertEquals("emini-bench", r.get("format").getAsString());
        assertEquals("quick", r.get("mode").getAsString());
        JsonArray scenes = r.getAsJsonArray("scenes");
        assertEquals(1, scenes.size());
        JsonArray results = scenes.get(0).getAsJsonObject().getAsJsonArray("results");
        assertEquals(2, results.size());
        for (int i = 0; i < results.size(); i++) {
            JsonObject m = results.get(i).getAsJsonObject();
            assertEquals("ok", m.get("status").getAsString(), m.toString());
            assertTrue(m.get("msPerTick").getAsDouble() > 0, m.toString());
            assertTrue(m.get("cpuMsPerTick").getAsDouble() > 0, m.toString());
            assertEquals("stable", m.getAsJsonObject("check").get("verdict").getAsString(), m.toString());
            assertEquals(20, m.getAsJsonObject("check").get("ticks").getAsInt());
        }
        assertEquals(2, r.getAsJsonArray("scaling").size());
        // Only the engines asked for run: no out-of-process engine here, and the report says so.
        assertEquals(0, r.getAsJsonObject("external").size(), r.get("external").toString());
        String html = Files.readString(dir.resolve("index.html"), StandardCharsets.UTF_8);
        assertTrue(html.contains("scenes.svg") && html.contains("scaling.svg"), "page shows both plots");
        assertTrue(html.contains("20-row pyramid"));
        for (String f : new String[] {"scenes.svg", "scenes.png", "scaling.svg", "scaling.png"}) {
            assertTrue(Files.size(dir.resolve(f)) > 1000, f);
        }
    }
}
