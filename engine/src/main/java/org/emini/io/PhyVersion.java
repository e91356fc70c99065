package org.emini.io;

/**
 * The version word at the start of a world file and the field tests the original loader makes on
 * it. Most tests compare the raw word, some its masked version index; they are reproduced exactly
 * (they differ from a plain version comparison only for words with a non-zero low byte at a
 * boundary, or for words with bits above the version byte).
 */
public final class PhyVersion {
    /** The version word the current World Designer writes (version 10). */
    public static final int CURRENT = 0x0A00;
    /** The mask that extracts the version index byte from a word. */
    public static final int MASK = 0xFF00;

    private PhyVersion() {
    }

    /**
     * Whether the original loader accepts the word: 0x0100 ≤ (word &amp; 0xFF00) ≤ 0x0A00.
     *
     * @param word the version word
     * @return true for versions 1 to 10
     */
    public static boolean isSupported(int word) {
        int masked = word & MASK;
        return masked >= 0x0100 && masked <= 0x0A00;
    }

    /**
     * The version index, (word &amp; 0xFF00) &gt;&gt; 8.
     *
     * @param word the version word
     * @return 1 to 10 for a supported word
     */
    public static int index(int word) {
        return (word & MASK) >> 8;
    }

    /**
     * Whether sections carry tag bytes: all versions but 1 (masked test).
     *
     * @param word the version word
     * @return false for version 1 (fixed section order)
     */
    public static boolean isTagged(int word) {
        return (word & MASK) != 0x0100;
    }

    /**
     * Whether a shape record starts with a legacy id byte: word ≤ 0x0200 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean shapeHasLegacyId(int word) {
        return word <= 0x0200;
    }

    /**
     * Whether an event record has a legacy id byte instead of the trigger-once byte, and no
     * constraint filter: (word &amp; 0xFF00) &lt; 0x0400 (masked test).
     *
     * @param word the version word
     * @return true for the old event layout
     */
    public static boolean eventHasLegacyId(int word) {
        return (word & MASK) < 0x0400;
    }

    /**
     * Whether a body record starts with a legacy mass: word &lt; 0x0500 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean bodyHasLegacyMass(int word) {
        return word < 0x0500;
    }

    /**
     * Whether a shape record holds its mass: word ≥ 0x0500 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean shapeHasMass(int word) {
        return word >= 0x0500;
    }

    /**
     * Whether shape and body records end with a user-data string: word &gt; 0x0600 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean shapeAndBodyHaveUserData(int word) {
        return word > 0x0600;
    }

    /**
     * Whether joint, spring, motor, event, particle-emitter and world records end with a user-data
     * string: word &gt; 0x0700 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean othersHaveUserData(int word) {
        return word > 0x0700;
    }

    /**
     * Whether a shapes section also holds the multishape list: word &gt; 0x0800 (raw test).
     *
     * @param word the version word
     * @return true when present
     */
    public static boolean hasMultiShapes(int word) {
        return word > 0x0800;
    }

    /**
     * Whether the world record holds linear and rotational damping separately: word &gt; 0x0900
     * (raw test). Older words store one retention factor (1 − damping) for both.
     *
     * @param word the version word
     * @return true for the new encoding
     */
    public static boolean hasSeparateDamping(int word) {
        return word > 0x0900;
    }

    /**
     * The word as the format document writes it.
     *
     * @param word the version word
     * @return e.g. "0x00000A00"
     */
    public static String toString(int word) {
        String hex = Integer.toHexString(word).toUpperCase(java.util.Locale.ROOT);
        StringBuilder b = new StringBuilder("0x");
        for (int i = hex.length(); i < 8; i++) {
            b.append('0');
        }
        return b.append(hex).toString();
    }
}
