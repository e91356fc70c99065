package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Set;
import org.emini.dynamics.Landscape;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.Section;

/**
 * The landscape ({@code landscape}): its material and segments, added in order to the world's own
 * {@link Landscape} ({@code World.getLandscape()}). {@code face} is the engine's facing: {@code left}
 * blocks bodies on the left-hand side of the direction from → to (on the y-down screen: above a
 * segment drawn left to right), {@code right} the other side, {@code none} both.
 */
final class LandscapeBuilder implements ElementBuilder {
    private static final Set<String> KEYS = Set.of("friction", "elasticity", "segments");
    private static final Set<String> SEGMENT_KEYS = Set.of("name", "from", "to", "face");

    @Override
    public void build(Section section, BuiltWorld world) throws UnsupportedElementException {
        JsonNode n = section.node();
        SectionKeys.only("landscape", n, section.path(), KEYS);
        Landscape landscape = world.world().getLandscape();
        Located.at(section.path().key("friction"),
                () -> landscape.setFriction((float) n.path("friction").asDouble(Landscape.DEFAULT_FRICTION)));
        Located.at(section.path().key("elasticity"),
                () -> landscape.setElasticity((float) n.path("elasticity").asDouble(Landscape.DEFAULT_ELASTICITY)));
        JsonNode segments = n.get("segments");
        for (int i = 0; i < segments.size(); i++) {
            JsonNode s = segments.get(i);
            JsonPath p = section.path().key("segments").index(i);
            SectionKeys.only("landscape segment", s, p, SEGMENT_KEYS);
            JsonNode from = s.get("from");
            JsonNode to = s.get("to");
            Located.at(p, () -> landscape.addSegment((float) from.get(0).asDouble(), (float) from.get(1).asDouble(),
                    (float) to.get(0).asDouble(), (float) to.get(1).asDouble(), face(s.path("face").asText("none"))));
        }
    }

    private static int face(String face) {
        return switch (face) {
            case "left" -> Landscape.FACE_LEFT;
            case "right" -> Landscape.FACE_RIGHT;
            default -> Landscape.FACE_NONE;
        };
    }
}
