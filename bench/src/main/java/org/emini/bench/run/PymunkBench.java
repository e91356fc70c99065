package org.emini.bench.run;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.emini.bench.scene.BenchScenes;

/**
 * pymunk, timed from Python through the oracle's scene builder (issue 6). Until {@code oracle-py/}
 * is in the repository there is nothing to time it with, and the report says so.
 */
final class PymunkBench {
    private PymunkBench() {
    }

    static Map<String, Object> run(BenchScenes scenes, BenchPlan.Mode mode, Path out) {
        Map<String, Object> r = new LinkedHashMap<>();
        if (!Files.isDirectory(scenes.root().resolve("oracle-py"))) {
            r.put("status", "pending");
            r.put("message", "the pymunk oracle (oracle-py/, branch oracle) has not landed on main yet; "
                + "pymunk will be timed with its scene builder once it has");
            return r;
        }
        r.put("status", "pending");
        r.put("message", "oracle-py/ is present but bench has no pymunk timing script for it yet");
        return r;
    }
}
