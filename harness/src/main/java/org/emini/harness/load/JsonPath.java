package org.emini.harness.load;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * An immutable location inside a scenario document: a list of object keys and array indices.
 * Printed as a JSON path ({@code $.bodies[2].shape}), the notation the schema validator uses too.
 */
public final class JsonPath {
    /** The document root. */
    public static final JsonPath ROOT = new JsonPath(Collections.emptyList());

    private final List<Object> elements;

    private JsonPath(List<Object> elements) {
        this.elements = elements;
    }

    /** Builds a path from keys (String) and indices (Integer). */
    public static JsonPath of(List<?> elements) {
        return new JsonPath(List.copyOf(elements));
    }

    /** The path of an object member. */
    public JsonPath key(String key) {
        List<Object> next = new ArrayList<>(elements);
        next.add(key);
        return new JsonPath(Collections.unmodifiableList(next));
    }

    /** The path of an array element. */
    public JsonPath index(int index) {
        List<Object> next = new ArrayList<>(elements);
        next.add(index);
        return new JsonPath(Collections.unmodifiableList(next));
    }

    /** The enclosing path, or the root itself. */
    public JsonPath parent() {
        return elements.isEmpty() ? this : new JsonPath(elements.subList(0, elements.size() - 1));
    }

    /** Keys and indices from the root. */
    public List<Object> elements() {
        return elements;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof JsonPath p && p.elements.equals(elements);
    }

    @Override
    public int hashCode() {
        return elements.hashCode();
    }

    @Override
    public String toString() {
        StringBuilder out = new StringBuilder("$");
        for (Object e : elements) {
            if (e instanceof Integer i) {
                out.append('[').append(i).append(']');
            } else {
                String k = (String) e;
                if (k.matches("[A-Za-z_$][A-Za-z0-9_$]*")) {
                    out.append('.').append(k);
                } else {
                    out.append("['").append(k.replace("'", "\\'")).append("']");
                }
            }
        }
        return out.toString();
    }
}
