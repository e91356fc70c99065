package org.emini.harness.scenario;

import com.fasterxml.jackson.databind.JsonNode;

/** Names of scene elements that may be left unnamed, given one way for the reader and the builders. */
public final class ElementNames {
    private ElementNames() {
    }

    /**
     * A particle emitter's name: its {@code name}, or {@code emitterI} for the I-th entry of
     * {@code particles} (counted from 0).
     */
    public static String emitter(JsonNode emitter, int index) {
        return emitter.has("name") ? emitter.get("name").asText() : "emitter" + index;
    }
}
