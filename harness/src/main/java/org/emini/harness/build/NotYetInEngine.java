package org.emini.harness.build;

import org.emini.harness.scenario.Section;

/** The builder of an element the engine does not offer yet: the scene runs to {@code unsupported}. */
final class NotYetInEngine implements ElementBuilder {
    private final String element;

    NotYetInEngine(String element) {
        this.element = element;
    }

    @Override
    public void build(Section section, BuiltWorld world) throws UnsupportedElementException {
        throw new UnsupportedElementException(element, section.path());
    }
}
