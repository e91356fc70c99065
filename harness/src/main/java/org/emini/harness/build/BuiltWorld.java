package org.emini.harness.build;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.scenario.Scenario;
import org.emini.particle.ParticleEmitter;

/** An engine world built from a scene, with its bodies by scene name (in creation order). */
public final class BuiltWorld {
    private final Scenario scenario;
    private final World world;
    private final Map<String, Body> bodies = new LinkedHashMap<>();
    private final Map<String, ParticleEmitter> emitters = new LinkedHashMap<>();

    BuiltWorld(Scenario scenario, World world) {
        this.scenario = scenario;
        this.world = world;
    }

    void add(String name, Body body) {
        bodies.put(name, body);
    }

    void addEmitter(String name, ParticleEmitter emitter) {
        emitters.put(name, emitter);
    }

    /** The scene it was built from. */
    public Scenario scenario() {
        return scenario;
    }

    /** The engine world. */
    public World world() {
        return world;
    }

    /** Bodies by scene name, in creation order. */
    public Map<String, Body> bodies() {
        return Collections.unmodifiableMap(bodies);
    }

    /** The body with a scene name (the loader has checked that it exists). */
    public Body body(String name) {
        Body b = bodies.get(name);
        if (b == null) {
            throw new IllegalArgumentException("no body named " + name);
        }
        return b;
    }

    /** Particle emitters by scene name (ElementNames.emitter), in the order of {@code particles}. */
    public Map<String, ParticleEmitter> emitters() {
        return Collections.unmodifiableMap(emitters);
    }
}
