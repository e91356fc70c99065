package org.emini.harness.build;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The builder of each element section, in build order (after the world settings, shapes and bodies).
 * Every section the schema describes has one; a builder meets a key it does not read with an
 * {@link UnsupportedElementException} ({@link SectionKeys}).
 */
final class ElementBuilders {
    private ElementBuilders() {
    }

    static Map<String, ElementBuilder> all() {
        Map<String, ElementBuilder> builders = new LinkedHashMap<>();
        builders.put("world.simulationArea", new SimulationAreaBuilder());
        builders.put("landscape", new LandscapeBuilder());
        builders.put("joints", new JointBuilder());
        builders.put("springs", new ConstraintBuilders.Springs());
        builders.put("motors", new ConstraintBuilders.Motors());
        builders.put("particles", new ParticleBuilder());
        return builders;
    }
}
