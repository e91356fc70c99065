package org.emini.harness.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import org.emini.harness.load.JsonPath;

/**
 * A part of the scene kept as written, for elements whose builders read it themselves (joints,
 * springs, motors, landscape, particles, closed-form models, the oracle's settings).
 *
 * @param node the validated JSON
 * @param path where it is written
 */
public record Section(JsonNode node, JsonPath path) {
}
