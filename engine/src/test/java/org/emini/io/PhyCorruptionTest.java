package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Every truncation and every single-bit flip of every reference file, and of generated files
 * holding every record type, is read or refused with a located error.
 */
class PhyCorruptionTest {
    /** The reference files and one generated file per layout family (version 1, 5 and 10). */
    private static List<byte[]> inputs() throws Exception {
        List<byte[]> all = new ArrayList<>();
        for (Path p : ReferenceWorlds.all()) {
            all.add(Files.readAllBytes(p));
        }
        Random r = new Random(9);
        for (int v : new int[] {0x01F0, 0x0500, PhyVersion.CURRENT}) {
            all.add(new PhyWriter().write(RandomDocuments.generate(r, v)));
        }
        return all;
    }

    @Test
    void everyTruncationIsRefusedUnlessItEndsAtASectionBoundary() throws Exception {
        PhyReader reader = new PhyReader();
        for (byte[] file : inputs()) {
            int accepted = 0;
            for (int cut = 0; cut < file.length; cut++) {
                byte[] part = Arrays.copyOf(file, cut);
                boolean ok = Corruption.readOrRefuse(reader, part);
                // readOrRefuse checked that an accepted cut is a complete, shorter file.
                accepted += ok ? 1 : 0;
                if (cut < 4) {
                    assertFalse(ok, "a cut inside the version word is refused");
                }
            }
            assertTrue(accepted <= 32, "only cuts between sections are complete files, got " + accepted);
        }
    }

    @Test
    void aTruncatedRecordIsRefusedAtTheEndOfData() throws Exception {
        ReferenceWorlds.require();
        byte[] file = ReferenceWorlds.bytes("rhabarber-small.phy");
        // 0x00B4..: body 0 of the bodies section; cut in the middle of its position.
        byte[] part = Arrays.copyOf(file, 0x9A + 3);
        PhyFormatException e = org.junit.jupiter.api.Assertions.assertThrows(PhyFormatException.class,
                () -> new PhyReader().read(part));
        assertEquals(part.length - 1, e.getOffset(), e.getMessage());
        assertTrue(e.getExpected().startsWith("body 0 position"), e.getMessage());
        assertEquals("end of data after 1 byte", e.getFound());
    }

    @Test
    void everyBitFlipIsReadOrRefused() throws Exception {
        PhyReader strict = new PhyReader();
        int refused = 0;
        int total = 0;
        for (byte[] file : inputs()) {
            for (int i = 0; i < file.length; i++) {
                for (int bit = 0; bit < 8; bit++) {
                    byte[] flipped = file.clone();
                    flipped[i] ^= (byte) (1 << bit);
                    refused += Corruption.readOrRefuse(strict, flipped) ? 0 : 1;
                    total++;
                }
            }
        }
        assertTrue(refused > 0 && refused < total, refused + " of " + total + " flips refused");
    }
}
