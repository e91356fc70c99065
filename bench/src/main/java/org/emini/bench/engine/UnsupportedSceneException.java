package org.emini.bench.engine;

/** A scene uses an element an engine (or its benchmark adapter) does not offer. */
public final class UnsupportedSceneException extends Exception {
    private static final long serialVersionUID = 1L;

    /** @param message what is missing */
    public UnsupportedSceneException(String message) {
        super(message);
    }
}
