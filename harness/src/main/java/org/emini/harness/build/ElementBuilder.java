package org.emini.harness.build;

import org.emini.harness.scenario.Section;

/**
 * Builds one kind of scene element (joints, springs, ...) into a world whose bodies already exist.
 * Each element the engine gains is one small implementation registered in {@link ElementBuilders}.
 */
public interface ElementBuilder {
    /**
     * Adds the element to the world.
     *
     * @param section the element as written (schema-valid; body names already checked)
     * @param world the world with its bodies
     * @throws UnsupportedElementException if the engine cannot express it
     */
    void build(Section section, BuiltWorld world) throws UnsupportedElementException;
}
