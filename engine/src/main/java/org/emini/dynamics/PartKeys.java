package org.emini.dynamics;

import java.util.Arrays;
import org.emini.internal.IdPool;

/**
 * The body parts the world's broadphase proxies stand for: every part of a body's shape (one for a
 * plain shape, one per part of a multi-shape) has a proxy, and the proxy's user data is the part's
 * key here, naming its body, its part index and its proxy (Box2D's proxies name shapes the same way).
 *
 * <p>Keys come from an {@link IdPool}: dense, freed ones reused last-freed first, so the same calls
 * give the same keys. The arrays double when full and are never shrunk, so a world whose parts come
 * and go allocates nothing once they have grown.
 */
final class PartKeys {
    private final IdPool ids = new IdPool(16);
    private Body[] body = new Body[16];
    private int[] part = new int[16];
    private int[] proxy = new int[16];

    /** A new key for a part of a body; its proxy is given by {@link #setProxy}. */
    int add(Body b, int partIndex) {
        int key = ids.allocate();
        if (key == body.length) {
            body = Arrays.copyOf(body, 2 * key);
            part = Arrays.copyOf(part, 2 * key);
            proxy = Arrays.copyOf(proxy, 2 * key);
        }
        body[key] = b;
        part[key] = partIndex;
        proxy[key] = -1;
        return key;
    }

    void setProxy(int key, int proxyId) {
        proxy[key] = proxyId;
    }

    void remove(int key) {
        body[key] = null;
        proxy[key] = -1;
        ids.free(key);
    }

    /** The body of a live key. */
    Body body(int key) {
        return body[key];
    }

    /** The part index within its body's shape of a live key. */
    int part(int key) {
        return part[key];
    }

    /** The broadphase proxy of a live key. */
    int proxy(int key) {
        return proxy[key];
    }
}
