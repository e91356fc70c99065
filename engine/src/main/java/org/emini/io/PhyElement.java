package org.emini.io;

import java.nio.charset.Charset;
import java.util.Arrays;

/**
 * A record of a world file that may carry a user-data string (shapes, multishapes, bodies,
 * constraints, events, particle emitters, the world record). The string is kept as its stored
 * bytes, so a file with malformed UTF-8 still round-trips byte for byte; {@link #getUserData()}
 * decodes it as the original does (standard UTF-8, malformed input replaced by U+FFFD).
 */
public abstract class PhyElement {
    private static final Charset UTF_8 = Charset.forName("UTF-8");
    private static final byte[] EMPTY = new byte[0];

    private byte[] userData = EMPTY;

    PhyElement() {
    }

    /**
     * The user-data string, decoded from UTF-8.
     *
     * @return the string; empty when the record has none (or its version stores none)
     */
    public String getUserData() {
        return new String(userData, UTF_8);
    }

    /**
     * Sets the user-data string, stored as UTF-8.
     *
     * @param userData the string; null counts as empty (the designer writes a missing object as
     *     length 0)
     */
    public void setUserData(String userData) {
        this.userData = userData == null ? EMPTY : userData.getBytes(UTF_8);
    }

    /**
     * The user-data string's stored bytes.
     *
     * @return a copy of the bytes
     */
    public byte[] getUserDataBytes() {
        return userData.clone();
    }

    /**
     * Sets the user-data string's stored bytes as they are.
     *
     * @param bytes the bytes (copied); null counts as empty
     */
    public void setUserDataBytes(byte[] bytes) {
        userData = bytes == null ? EMPTY : bytes.clone();
    }

    byte[] userDataBytes() {
        return userData;
    }

    void readUserData(PhyInput in, boolean present) throws PhyFormatException {
        if (present) {
            userData = in.string("user data");
        }
    }

    boolean userDataEquals(PhyElement other) {
        return Arrays.equals(userData, other.userData);
    }

    int userDataHash() {
        return Arrays.hashCode(userData);
    }
}
