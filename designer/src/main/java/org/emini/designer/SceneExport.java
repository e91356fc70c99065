package org.emini.designer;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;

/**
 * Opens a scene file (YAML or JSON) for the page (JVM only; {@code ./emini designer SCENE} runs it):
 * the harness reads and validates it (the schema's messages are printed and the exit status is 1
 * when it is invalid), converts it to a world file as {@code harness convert} does, and writes the
 * page's document with the scene's tick rate and iterations, and what a world file cannot hold, as
 * a script the page loads from the file system ({@code index.html#open=FILE}).
 *
 * <pre>java ... org.emini.designer.SceneExport SCENE OUT.js</pre>
 */
public final class SceneExport {
    private SceneExport() {
    }

    /**
     * Writes OUT.js.
     *
     * @param args the scene file and the script to write
     * @throws IOException if a file cannot be read or written
     */
    public static void main(String[] args) throws IOException {
        Path schema = Path.of("scenarios", "scenario.schema.json");
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(schema), schema.toAbsolutePath().getParent());
        ScenarioLoader.Loaded loaded = loader.load(Path.of(args[0]));
        if (!loaded.ok()) {
            for (Problem p : loaded.problems()) {
                System.err.println(p);
            }
            System.exit(1);
        }
        Scenario scene = loaded.scenario();
        ScenarioToWorld.Result r = ScenarioToWorld.convert(scene);
        StringBuilder js = new StringBuilder("window.EMINI_OPEN = {\"format\":\"emini-designer\",\"scene\":");
        Json.quote(js, args[0]);
        js.append(",\"ticksPerSecond\":").append(Math.round(1 / scene.world().timestep()))
                .append(",\"iterations\":").append(scene.world().iterations()).append(",\"notConverted\":[");
        for (int i = 0; i < r.notConverted().size(); i++) {
            js.append(i > 0 ? "," : "");
            Json.quote(js, r.notConverted().get(i));
        }
        js.append("],\"document\":").append(DocJson.write(r.world())).append("};\n");
        Files.write(Path.of(args[1]), js.toString().getBytes(StandardCharsets.UTF_8));
        for (String n : r.notConverted()) {
            System.out.println("not in a world file: " + n);
        }
    }
}
