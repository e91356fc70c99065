package org.emini.harness.build;

import org.emini.harness.load.JsonPath;

/**
 * The scene uses an element the engine does not offer yet. The run reports the scene as
 * {@code unsupported}, naming the element: never a crash, never a pass.
 */
public final class UnsupportedElementException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String element;

    /**
     * @param element the element as the scene names it ({@code joints}, {@code shape type multiShape})
     * @param path where the scene uses it
     */
    public UnsupportedElementException(String element, JsonPath path) {
        super(element + " (at " + path + ") is not in the engine yet");
        this.element = element;
    }

    /** The element's name. */
    public String element() {
        return element;
    }
}
