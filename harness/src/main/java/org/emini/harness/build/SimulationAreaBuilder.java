package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Set;
import org.emini.harness.scenario.Section;

/**
 * The simulation area ({@code world.simulationArea}): the x range {@code start..end} over the full
 * height, as the original engine's {@code setSimulationArea(start, end)}, or the rectangle
 * {@code min..max} ({@code setSimulationArea(minX, minY, maxX, maxY)}). Dynamic bodies whose bounding
 * box leaves it are frozen where they are (kept, not integrated, seen by the others as static) and move
 * on with their kept velocity when the area takes them in again.
 */
final class SimulationAreaBuilder implements ElementBuilder {
    private static final Set<String> KEYS = Set.of("start", "end", "min", "max");

    @Override
    public void build(Section section, BuiltWorld world) throws UnsupportedElementException {
        JsonNode n = section.node();
        SectionKeys.only("world.simulationArea", n, section.path(), KEYS);
        Located.at(section.path(), () -> {
            if (n.has("min")) {
                world.world().setSimulationArea((float) n.get("min").get(0).asDouble(),
                        (float) n.get("min").get(1).asDouble(), (float) n.get("max").get(0).asDouble(),
                        (float) n.get("max").get(1).asDouble());
            } else {
                world.world().setSimulationArea((float) n.get("start").asDouble(), (float) n.get("end").asDouble());
            }
        });
    }
}
