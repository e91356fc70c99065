package org.emini.harness.build;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The builder of each element section, in build order. When the engine gains an element, replace its
 * {@link NotYetInEngine} entry with the element's builder.
 */
final class ElementBuilders {
    private ElementBuilders() {
    }

    static Map<String, ElementBuilder> all() {
        Map<String, ElementBuilder> builders = new LinkedHashMap<>();
        builders.put("world.simulationArea", new NotYetInEngine("world.simulationArea"));
        builders.put("landscape", new NotYetInEngine("landscape"));
        builders.put("joints", new ConstraintBuilders.Joints());
        builders.put("springs", new ConstraintBuilders.Springs());
        builders.put("motors", new ConstraintBuilders.Motors());
        builders.put("particles", new ParticleBuilder());
        return builders;
    }
}
