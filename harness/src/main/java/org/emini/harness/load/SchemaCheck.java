package org.emini.harness.load;

import com.fasterxml.jackson.databind.JsonNode;
import com.networknt.schema.JsonNodePath;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SchemaValidatorsConfig;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Validates scenario documents against {@code scenarios/scenario.schema.json} with the networknt
 * JSON Schema validator (draft 2020-12) and turns its messages into located {@link Problem}s.
 */
public final class SchemaCheck {
    private final JsonSchema schema;

    private SchemaCheck(JsonSchema schema) {
        this.schema = schema;
    }

    /** Loads the schema from a file (normally {@code scenarios/scenario.schema.json}). */
    public static SchemaCheck fromFile(Path schemaFile) {
        try (InputStream in = Files.newInputStream(schemaFile)) {
            return fromStream(in);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the scenario schema " + schemaFile, e);
        }
    }

    /** Loads the schema from a stream. */
    public static SchemaCheck fromStream(InputStream in) {
        JsonSchemaFactory factory = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012);
        SchemaValidatorsConfig config = SchemaValidatorsConfig.builder().build();
        return new SchemaCheck(factory.getSchema(in, config));
    }

    /**
     * Validates a parsed document.
     *
     * @return the problems, ordered by line; empty when the document is valid
     */
    public List<Problem> check(String file, JsonNode root, SourceMap sourceMap) {
        Set<ValidationMessage> messages = schema.validate(root);
        Set<String> seen = new LinkedHashSet<>();
        Set<JsonPath> failedValues = new java.util.HashSet<>();
        for (ValidationMessage m : messages) {
            if (!isUnknownKey(m)) {
                failedValues.add(toPath(m.getInstanceLocation()));
            }
        }
        List<Problem> problems = new ArrayList<>();
        for (ValidationMessage m : messages) {
            JsonPath path = toPath(m.getInstanceLocation());
            if (isUnknownKey(m) && m.getProperty() != null) {
                // When a branch of an if/then fails (a required key missing, a value out of its range), its
                // keys are reported as "unevaluated" too; the real complaint is the other one, so keep only that.
                if ("unevaluatedProperties".equals(m.getType()) && failedWithin(failedValues, path)) {
                    continue;
                }
                // The validator names the object; point at the key itself.
                path = path.key(m.getProperty());
                // A known key whose value failed its subschema is also reported as "not evaluated"
                // (annotations of failed branches are dropped): keep only the real complaint.
                if (failedValues.contains(path)) {
                    continue;
                }
            }
            int[] at = sourceMap.locate(path);
            String text = isUnknownKey(m) && m.getProperty() != null
                    ? "unknown key '" + m.getProperty() + "' (not allowed here)"
                    : stripLocation(m.getMessage(), m.getInstanceLocation().toString());
            if (seen.add(path + "|" + text)) {
                problems.add(new Problem(file, at[0], at[1], path.toString(), text));
            }
        }
        problems.sort(Comparator.comparingInt(Problem::line).thenComparingInt(Problem::column)
                .thenComparing(Problem::message));
        return problems;
    }

    /** Whether a value at or under the path failed its subschema. */
    private static boolean failedWithin(Set<JsonPath> failed, JsonPath path) {
        for (JsonPath f : failed) {
            if (f.elements().size() >= path.elements().size()
                    && f.elements().subList(0, path.elements().size()).equals(path.elements())) {
                return true;
            }
        }
        return false;
    }

    private static JsonPath toPath(JsonNodePath p) {
        List<Object> elements = new ArrayList<>();
        for (int i = 0; i < p.getNameCount(); i++) {
            elements.add(p.getElement(i));
        }
        return JsonPath.of(elements);
    }

    private static boolean isUnknownKey(ValidationMessage m) {
        return "additionalProperties".equals(m.getType()) || "unevaluatedProperties".equals(m.getType());
    }

    // The validator prefixes messages with the instance location; we print our own path instead.
    private static String stripLocation(String message, String location) {
        String prefix = location + ": ";
        return message.startsWith(prefix) ? message.substring(prefix.length()) : message;
    }
}
