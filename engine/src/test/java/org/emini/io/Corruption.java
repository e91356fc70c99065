package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The contract for any input: the reader either refuses it with a located
 * {@link PhyFormatException}, or accepts it as a file the writer reproduces. Any other exception
 * escapes and fails the calling test.
 */
final class Corruption {
    private Corruption() {
    }

    /**
     * Reads the data and checks the outcome.
     *
     * @return true when accepted
     */
    static boolean readOrRefuse(PhyReader reader, byte[] data) {
        PhyWorld w;
        try {
            w = reader.read(data);
        } catch (PhyFormatException e) {
            assertTrue(e.getOffset() >= 0 && e.getOffset() <= data.length,
                    () -> "offset " + e.getOffset() + " within the " + data.length + " bytes: " + e.getMessage());
            assertFalse(e.getExpected().isEmpty(), "the error says what was expected");
            assertTrue(e.getMessage().startsWith("byte " + e.getOffset() + ": expected "), e::getMessage);
            return false;
        }
        byte[] again = new PhyWriter().write(w);
        try {
            assertEquals(w, reader.read(again), "an accepted input is written back as the same model");
        } catch (PhyFormatException e) {
            throw new AssertionError("the writer's output of an accepted input is refused: " + e.getMessage(), e);
        }
        if (!repeatsReplacedSections(w)) {
            assertArrayEquals(data, again, () -> "an accepted input is written back byte for byte: "
                    + RandomDocuments.hex(data));
        }
        return true;
    }

    /** A repeated landscape or world section: the earlier record is replaced, so only the model survives. */
    private static boolean repeatsReplacedSections(PhyWorld w) {
        int landscapes = 0;
        int worlds = 0;
        for (PhySection s : w.getLayout()) {
            landscapes += s.getTag() == PhySection.LANDSCAPE ? 1 : 0;
            worlds += s.getTag() == PhySection.WORLD ? 1 : 0;
        }
        return landscapes > 1 || worlds > 1;
    }
}
