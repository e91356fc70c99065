package org.emini.dynamics;

/**
 * How many contacts each pair has (a pair of body parts, or a body part and a landscape segment), so
 * that "is this pair already in contact?" costs O(1) rather than a walk of a body's contact list: in
 * a crowd every body has hundreds of contacts, and the walks made the first tick of 1,000 circles
 * created in one spot cubic (18 s). Parts are named by their keys ({@link PartKeys}); a pair has one
 * contact.
 *
 * <p>Open addressing with linear probing over long keys; 0 marks an empty slot (no key is 0). The
 * table doubles at half full and is never shrunk, so steady-state ticks allocate nothing; removal
 * shifts the following entries back, so no tombstones build up. Nothing depends on identity
 * hashes, so the table, and the engine, stay deterministic.
 */
final class PairCounts {
    private long[] keys = new long[64];
    private int[] counts = new int[64];
    private int size;

    /** The key of two parts, by their part keys, in either order. */
    static long parts(int keyA, int keyB) {
        return keyA < keyB ? (long) keyA << 32 | keyB : (long) keyB << 32 | keyA;
    }

    /** The key of a part and a landscape segment slot (the sign bit keeps it apart from part pairs). */
    static long segment(int partKey, int segmentSlot) {
        return Long.MIN_VALUE | (long) partKey << 32 | segmentSlot;
    }

    boolean contains(long key) {
        long[] k = keys;
        int mask = k.length - 1;
        for (int i = slot(key, mask); k[i] != 0L; i = (i + 1) & mask) {
            if (k[i] == key) {
                return true;
            }
        }
        return false;
    }

    /** Counts one more contact of the pair. */
    void add(long key) {
        if (2 * (size + 1) > keys.length) {
            grow();
        }
        long[] k = keys;
        int mask = k.length - 1;
        int i = slot(key, mask);
        while (k[i] != 0L && k[i] != key) {
            i = (i + 1) & mask;
        }
        if (k[i] == 0L) {
            k[i] = key;
            size++;
        }
        counts[i]++;
    }

    /** Counts one contact of the pair fewer; the pair leaves with its last contact. */
    void remove(long key) {
        long[] k = keys;
        int mask = k.length - 1;
        int i = slot(key, mask);
        while (k[i] != key) {
            if (k[i] == 0L) {
                throw new IllegalStateException("PairCounts.remove: no pair " + Long.toHexString(key));
            }
            i = (i + 1) & mask;
        }
        if (--counts[i] > 0) {
            return;
        }
        size--;
        // Backward-shift deletion: move up each later entry of the run that may sit in the hole.
        int hole = i;
        for (int j = (i + 1) & mask; k[j] != 0L; j = (j + 1) & mask) {
            int home = slot(k[j], mask);
            if (((j - home) & mask) >= ((j - hole) & mask)) {
                k[hole] = k[j];
                counts[hole] = counts[j];
                hole = j;
            }
        }
        k[hole] = 0L;
        counts[hole] = 0;
    }

    private void grow() {
        long[] oldKeys = keys;
        int[] oldCounts = counts;
        keys = new long[2 * oldKeys.length];
        counts = new int[keys.length];
        int mask = keys.length - 1;
        for (int j = 0; j < oldKeys.length; j++) {
            long key = oldKeys[j];
            if (key != 0L) {
                int i = slot(key, mask);
                while (keys[i] != 0L) {
                    i = (i + 1) & mask;
                }
                keys[i] = key;
                counts[i] = oldCounts[j];
            }
        }
    }

    /** A home slot from a 64-bit mix (MurmurHash3's finaliser), so nearby slots spread out. */
    private static int slot(long key, int mask) {
        long h = key;
        h ^= h >>> 33;
        h *= 0xff51afd7ed558ccdL;
        h ^= h >>> 33;
        h *= 0xc4ceb9fe1a85ec53L;
        h ^= h >>> 33;
        return (int) h & mask;
    }
}
