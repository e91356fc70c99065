package org.emini.bench.engine;

import java.util.List;

/** The engines the benchmark knows, by id. */
public final class Engines {
    /** Every engine id, Emini first. */
    public static final List<String> ALL = List.of("emini", "emini-2t", "dyn4j", "jbox2d", "gdx-box2d");

    private Engines() {
    }

    /** A fresh adapter for an engine id. */
    public static BenchEngine create(String id) {
        switch (id) {
            case "emini":
                return new EminiEngine(1);
            case "emini-2t":
                return new EminiEngine(2);
            case "dyn4j":
                return new Dyn4jEngine();
            case "jbox2d":
                return new JBox2dEngine();
            case "gdx-box2d":
                return new GdxBox2dEngine();
            default:
                throw new IllegalArgumentException("unknown engine " + id + "; known: " + ALL);
        }
    }
}
