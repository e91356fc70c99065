package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Set;
import org.emini.dynamics.Body;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.ElementNames;
import org.emini.harness.scenario.Section;
import org.emini.particle.ParticleEmitter;

/**
 * Particle emitters ({@code particles}): one engine {@link ParticleEmitter} per entry, with the
 * original designer's defaults (scenarios/README.md, Particles). Spreads are the engine's deviations
 * (the full width of the uniform draw); angles are given in degrees. An emitter without a seed gets
 * the engine's default seed plus its index in the list, as the world-file builder does, so two
 * emitters do not draw the same numbers.
 */
final class ParticleBuilder implements ElementBuilder {
    private static final Set<String> KEYS = Set.of("name", "body", "from", "to", "maxCount", "rate", "rateSpread",
            "lifetime", "lifetimeSpread", "speed", "speedSpread", "angleDeg", "angleSpreadDeg", "axesFixed",
            "elasticity", "gravityFactor", "damping", "collide", "seed");

    @Override
    public void build(Section section, BuiltWorld world) throws UnsupportedElementException {
        JsonNode list = section.node();
        for (int i = 0; i < list.size(); i++) {
            JsonNode n = list.get(i);
            JsonPath path = section.path().index(i);
            SectionKeys.only("particles", n, path, KEYS);
            Body body = n.has("body") ? world.body(n.get("body").asText()) : null;
            ParticleEmitter e = Located.at(path.key("maxCount"), () -> new ParticleEmitter(n.path("maxCount").asInt(100), body));
            JsonNode from = n.get("from");
            JsonNode to = n.has("to") ? n.get("to") : from;
            Located.at(path.key("from"), () -> e.setEmitSegment(f(from.get(0)), f(from.get(1)), f(to.get(0)), f(to.get(1))));
            Located.at(path.key("rate"), () -> e.setCreationRate(num(n, "rate", 20), num(n, "rateSpread", 0)));
            Located.at(path.key("lifetime"), () -> e.setLifetime(num(n, "lifetime", 2), num(n, "lifetimeSpread", 0)));
            Located.at(path.key("speed"), () -> e.setSpeed(num(n, "speed", 10), num(n, "speedSpread", 0)));
            Located.at(path.key("angleDeg"), () -> e.setAngle((float) Math.toRadians(n.path("angleDeg").asDouble(0)),
                    (float) Math.toRadians(n.path("angleSpreadDeg").asDouble(0))));
            e.setAxesFixed(n.path("axesFixed").asBoolean(false));
            Located.at(path.key("elasticity"), () -> e.setElasticity(num(n, "elasticity", 1)));
            Located.at(path.key("gravityFactor"), () -> e.setGravityFactor(num(n, "gravityFactor", 1)));
            Located.at(path.key("damping"), () -> e.setDamping(num(n, "damping", 0)));
            e.setCanCollide(n.path("collide").asBoolean(true));
            e.setSeed(n.has("seed") ? n.get("seed").asLong() : ParticleEmitter.DEFAULT_SEED + i);
            world.world().addParticleEmitter(e);
            world.addEmitter(ElementNames.emitter(n, i), e);
        }
    }

    private static float f(JsonNode v) {
        return (float) v.asDouble();
    }

    private static float num(JsonNode n, String key, double dflt) {
        return (float) n.path(key).asDouble(dflt);
    }
}
