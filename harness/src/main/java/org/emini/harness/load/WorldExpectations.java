package org.emini.harness.load;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Map;
import java.util.Set;

/**
 * A world file's expectations file ({@code level.expect.yaml} beside {@code level.phy}): what a scene says
 * that the original's format cannot, merged into the scene converted from the world file. Its keys:
 * {@code description}, {@code knownFailure}, {@code reference} (replacing the converted one: a closed form,
 * oracle settings), and {@code run} with {@code duration} and {@code record} (replacing) and {@code expect}
 * (added after the converted scene's own "stays stable"). scenarios/README.md, World files.
 */
public final class WorldExpectations {
    private static final Set<String> KEYS = Set.of("description", "knownFailure", "reference", "run");
    private static final Set<String> RUN_KEYS = Set.of("duration", "record", "expect");

    private WorldExpectations() {
    }

    /**
     * The converted scene with the expectations file merged in, as JSON text (a YAML reader reads it).
     *
     * @throws IOException if the expectations file cannot be read, is not a map, or has a key it may not
     */
    public static String merge(String convertedYaml, Path sidecar) throws IOException {
        String shown = sidecar.toString();
        SceneText.Decoded decoded = SceneText.decode(shown, Files.readAllBytes(sidecar));
        if (decoded.problem() != null) {
            throw new IOException(shown + ": " + decoded.problem().message());
        }
        DocumentParser.Parsed side = DocumentParser.parse(shown, decoded.text());
        if (!side.ok()) {
            throw new IOException(shown + ": " + side.problems().get(0).message());
        }
        DocumentParser.Parsed scene = DocumentParser.parse("converted", convertedYaml);
        if (!scene.ok() || !side.root().isObject()) {
            throw new IOException(shown + ": not a map of description, knownFailure, reference and run");
        }
        ObjectNode out = ((ObjectNode) scene.root()).deepCopy();
        for (Iterator<Map.Entry<String, JsonNode>> it = side.root().fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            if (!KEYS.contains(e.getKey())) {
                throw new IOException(shown + ": unknown key '" + e.getKey() + "' (description, knownFailure, reference, run)");
            }
            if (!e.getKey().equals("run")) {
                out.set(e.getKey(), e.getValue());
                continue;
            }
            if (!e.getValue().isObject()) {
                throw new IOException(shown + ": run must be a map of duration, record and expect");
            }
            ObjectNode run = out.get("run") instanceof ObjectNode o ? o : out.putObject("run");
            for (Iterator<Map.Entry<String, JsonNode>> r = e.getValue().fields(); r.hasNext(); ) {
                Map.Entry<String, JsonNode> k = r.next();
                if (!RUN_KEYS.contains(k.getKey())) {
                    throw new IOException(shown + ": unknown key 'run." + k.getKey() + "' (duration, record, expect)");
                }
                if (k.getKey().equals("expect") && k.getValue().isArray()) {
                    ArrayNode expect = run.get("expect") instanceof ArrayNode a ? a : run.putArray("expect");
                    k.getValue().forEach(expect::add);
                } else {
                    run.set(k.getKey(), k.getValue());
                }
            }
        }
        return new ObjectMapper().writerWithDefaultPrettyPrinter().writeValueAsString(out);
    }
}
