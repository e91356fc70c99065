package org.emini.designer;

import java.util.List;
import java.util.Map;

/**
 * One JSON object of the page's document, read with the place it came from, so a missing or wrong
 * field is named in the message ("bodies[3].x: missing").
 */
final class Doc {
    private final Map<?, ?> map;
    private final String where;

    Doc(Object value, String where) {
        if (!(value instanceof Map)) {
            throw new IllegalArgumentException(where + ": expected an object");
        }
        this.map = (Map<?, ?>) value;
        this.where = where;
    }

    String where() {
        return where;
    }

    boolean has(String key) {
        return map.get(key) != null;
    }

    int integer(String key) {
        Object v = map.get(key);
        if (!(v instanceof Long)) {
            throw new IllegalArgumentException(where + "." + key + ": " + (v == null ? "missing" : "not an integer"));
        }
        long l = (Long) v;
        if (l < Integer.MIN_VALUE || l > Integer.MAX_VALUE) {
            throw new IllegalArgumentException(where + "." + key + ": " + l + " is outside the 32-bit range");
        }
        return (int) l;
    }

    int integer(String key, int fallback) {
        return map.get(key) == null ? fallback : integer(key);
    }

    String string(String key) {
        Object v = map.get(key);
        if (v == null) {
            return "";
        }
        if (!(v instanceof String)) {
            throw new IllegalArgumentException(where + "." + key + ": not a string");
        }
        return (String) v;
    }

    Doc object(String key) {
        return new Doc(map.get(key), where + "." + key);
    }

    List<?> list(String key) {
        Object v = map.get(key);
        if (v == null) {
            return java.util.Collections.emptyList();
        }
        if (!(v instanceof List)) {
            throw new IllegalArgumentException(where + "." + key + ": expected an array");
        }
        return (List<?>) v;
    }

    int[] integers(String key) {
        List<?> l = list(key);
        int[] out = new int[l.size()];
        for (int i = 0; i < out.length; i++) {
            Object v = l.get(i);
            if (!(v instanceof Long) || (Long) v != (int) (long) (Long) v) {
                throw new IllegalArgumentException(where + "." + key + "[" + i + "]: not a 32-bit integer");
            }
            out[i] = (int) (long) (Long) v;
        }
        return out;
    }
}
