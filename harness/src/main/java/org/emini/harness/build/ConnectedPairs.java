package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.scenario.Section;

/**
 * Keeps the bodies of joints ({@code collide: false}, the default) and springs ({@code collide: false})
 * from colliding, with the engine's pair switch ({@link World#disableCollision}), which affects no
 * other pair. (Collision layer bits, the original's only tool, ran out after 32 joints and then, when
 * reused, stopped unrelated bodies colliding.)
 */
public final class ConnectedPairs {
    private ConnectedPairs() {
    }

    /** Disables the collision of every non-colliding joint's and spring's bodies in a built scene. */
    static void apply(BuiltWorld world) {
        disable(world, "joints", false);
        disable(world, "springs", true);
    }

    /**
     * The same for pairs given directly (the world fuzzer's recipes): pairs[i] = {a, b}.
     *
     * @param world the world
     * @param pairs the two bodies of each joint or spring that must not collide
     */
    public static void applyTo(World world, List<Body[]> pairs) {
        for (Body[] p : pairs) {
            if (p[0] != p[1]) {
                world.disableCollision(p[0], p[1]);
            }
        }
    }

    private static void disable(BuiltWorld world, String section, boolean collideByDefault) {
        Section s = world.scenario().elements().get(section);
        if (s == null) {
            return;
        }
        for (int i = 0; i < s.node().size(); i++) {
            JsonNode n = s.node().get(i);
            if (!n.has("bodyA")) {
                continue; // a mouse joint holds one body
            }
            Body a = world.bodies().get(n.get("bodyA").asText());
            Body b = world.bodies().get(n.get("bodyB").asText());
            // A body joined to itself is the constraint builder's to refuse.
            if (a != null && b != null && a != b && !n.path("collide").asBoolean(collideByDefault)) {
                world.world().disableCollision(a, b);
            }
        }
    }
}
