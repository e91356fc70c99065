package org.emini.harness.build;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.dynamics.Body;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.Section;

/**
 * Keeps the bodies of joints ({@code collide: false}, the default) and springs ({@code collide: false})
 * from colliding, with the only tool the engine offers: collision layer bits (two bodies sharing a bit
 * never collide). The bits must not change which other pairs collide, so a pair gets a bit that the
 * scene's own {@code layers} leave free, shared only with pairs whose bodies may all pass through each
 * other anyway. When 32 bits cannot express the scene (a chain of more than the free bits, a net of
 * joints), the scene is unsupported, naming the first joint or spring left without a bit: reusing a
 * bit would stop unrelated bodies colliding, in silence.
 */
public final class CollisionBits {
    private final List<Body> members = new ArrayList<>();
    private final List<Integer> bitOfMember = new ArrayList<>();
    private final Set<Long> apart = new HashSet<>();
    private final Map<Body, Integer> index = new IdentityHashMap<>();

    private CollisionBits(Collection<Body> bodies) {
        for (Body b : bodies) {
            index.put(b, index.size());
        }
    }

    /** A pair to keep apart and where the scene asks for it. */
    private record Pair(Body a, Body b, JsonPath path) {
    }

    /**
     * Adds the bits to the bodies of every non-colliding joint and spring of the scene.
     *
     * @throws UnsupportedElementException when the free bits cannot keep every pair apart exactly
     */
    static void apply(BuiltWorld world) throws UnsupportedElementException {
        List<Pair> pairs = new ArrayList<>();
        pairs(world, "joints", false, pairs);
        pairs(world, "springs", true, pairs);
        apply(world.bodies().values(), pairs);
    }

    /**
     * The same for pairs given directly, in the order a scene would list them (joints, then springs):
     * the world fuzzer builds its worlds through this, so they match their scene files bit for bit.
     *
     * @param bodies every body of the world, in the scene's order
     * @param pairs the two bodies of each joint or spring that must not collide
     * @throws UnsupportedElementException when the free bits cannot keep every pair apart exactly
     */
    public static void applyTo(Collection<Body> bodies, List<Body[]> pairs) throws UnsupportedElementException {
        List<Pair> located = new ArrayList<>();
        for (int i = 0; i < pairs.size(); i++) {
            Body[] p = pairs.get(i);
            if (p[0] != p[1]) {
                located.add(new Pair(p[0], p[1], JsonPath.ROOT.index(i)));
            }
        }
        apply(bodies, located);
    }

    private static void apply(Collection<Body> bodies, List<Pair> pairs) throws UnsupportedElementException {
        if (pairs.isEmpty()) {
            return;
        }
        CollisionBits bits = new CollisionBits(bodies);
        for (Pair p : pairs) {
            bits.apart.add(bits.key(p.a(), p.b()));
        }
        int used = 0;
        for (Body b : bodies) {
            used |= b.getCollisionLayers();
        }
        List<Integer> free = new ArrayList<>();
        for (int bit = 31; bit >= 0; bit--) {
            if ((used & (1 << bit)) == 0) {
                free.add(bit);
            }
        }
        List<Integer> taken = new ArrayList<>();
        for (Pair p : pairs) {
            if (!mayCollide(p.a(), p.b())) {
                continue;
            }
            Integer bit = bits.sharedBit(p, taken);
            if (bit == null) {
                if (taken.size() == free.size()) {
                    throw new UnsupportedElementException("collide: false on more joints and springs than collision "
                            + "layer bits can express (the scene's layers leave " + free.size() + " bits free, all taken "
                            + "by the pairs before this one; the engine has no per-joint collision switch)", p.path());
                }
                bit = free.get(taken.size());
                taken.add(bit);
            }
            bits.join(p.a(), bit);
            bits.join(p.b(), bit);
        }
        for (int i = 0; i < bits.members.size(); i++) {
            bits.members.get(i).addCollisionLayer(bits.bitOfMember.get(i));
        }
    }

    private static void pairs(BuiltWorld world, String section, boolean collideByDefault, List<Pair> out) {
        Section s = world.scenario().elements().get(section);
        if (s == null) {
            return;
        }
        for (int i = 0; i < s.node().size(); i++) {
            JsonNode n = s.node().get(i);
            Body a = world.bodies().get(n.get("bodyA").asText());
            Body b = world.bodies().get(n.get("bodyB").asText());
            // A body joined to itself is the constraint builder's to refuse.
            if (a != null && b != null && a != b && !n.path("collide").asBoolean(collideByDefault)) {
                out.add(new Pair(a, b, s.path().index(i)));
            }
        }
    }

    /** The engine's rule, before any bit is added: a dynamic body, both interacting, no shared layer. */
    private static boolean mayCollide(Body a, Body b) {
        return (a.isDynamic() || b.isDynamic()) && a.isInteracting() && b.isInteracting()
                && (a.getCollisionLayers() & b.getCollisionLayers()) == 0;
    }

    /** Whether the scene lets the two bodies pass through each other. */
    private boolean keptApart(Body a, Body b) {
        return a == b || !mayCollide(a, b) || apart.contains(key(a, b));
    }

    /** A bit already given out that both bodies can join without stopping a collision the scene wants. */
    private Integer sharedBit(Pair p, List<Integer> taken) {
        for (int bit : taken) {
            boolean fits = true;
            for (int i = 0; i < members.size() && fits; i++) {
                if (bitOfMember.get(i) == bit) {
                    Body m = members.get(i);
                    fits = keptApart(m, p.a()) && keptApart(m, p.b());
                }
            }
            if (fits) {
                return bit;
            }
        }
        return null;
    }

    private void join(Body body, int bit) {
        for (int i = 0; i < members.size(); i++) {
            if (members.get(i) == body && bitOfMember.get(i) == bit) {
                return;
            }
        }
        members.add(body);
        bitOfMember.add(bit);
    }

    private long key(Body a, Body b) {
        int i = index.get(a);
        int j = index.get(b);
        return i < j ? (long) i << 32 | j : (long) j << 32 | i;
    }
}
