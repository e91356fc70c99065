package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.SolverSettings;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * Every engine tunable the schema lets a scene set ({@code world.solver}) reaches the engine's
 * {@link SolverSettings}: a key the schema accepts and the builder drops would run the scene at the
 * default without a word.
 */
class SolverKeysTest {
    @Test
    void everySolverKeyOfTheSchemaSetsItsSetting() throws Exception {
        JsonObject schema = JsonParser.parseString(Files.readString(Repo.schema())).getAsJsonObject();
        JsonObject solver = schema.getAsJsonObject("$defs").getAsJsonObject("world").getAsJsonObject("properties")
            .getAsJsonObject("solver").getAsJsonObject("properties");
        List<String> keys = new ArrayList<>(solver.keySet());
        assertTrue(keys.contains("speculativeSweep") && keys.size() > 10, "solver keys " + keys);
        for (String key : keys) {
            // 3 is valid for every tunable (the length scale too) and differs from every default.
            Scenario s = Scenes.valid(key + ".yaml", "world: {solver: {" + key + ": 3}}",
                "bodies: [{name: ball, shape: {type: circle, radius: 5}}]", "run: {duration: 1}");
            SolverSettings built = WorldBuilder.build(s).world().getSolverSettings();
            Method getter = SolverSettings.class.getMethod("get" + Character.toUpperCase(key.charAt(0)) + key.substring(1));
            assertEquals(3.0, ((Number) getter.invoke(built)).doubleValue(), 1e-6, key);
        }
    }
}
